// MovableText's layout rules: lines of text centred on or hanging below an anchor.
#include "scene/text_layout.h"

#include <algorithm>

namespace urdfsnap::scene {

std::u32string DecodeUtf8(const std::string& text) {
  std::u32string out;
  for (size_t i = 0; i < text.size();) {
    const auto byte = static_cast<unsigned char>(text[i]);
    const int length = byte < 0x80 ? 1 : (byte >> 5) == 0x6 ? 2 : (byte >> 4) == 0xE ? 3 : (byte >> 3) == 0x1E ? 4 : 0;
    char32_t c = length == 1 ? byte : length == 2 ? byte & 0x1F : length == 3 ? byte & 0x0F : byte & 0x07;
    bool valid = length > 0 && i + length <= text.size();
    for (int k = 1; valid && k < length; ++k) {
      const auto next = static_cast<unsigned char>(text[i + k]);
      valid = (next & 0xC0) == 0x80;
      c = (c << 6) | (next & 0x3F);
    }
    out.push_back(valid ? c : byte);
    i += valid ? length : 1;
  }
  return out;
}

std::set<char32_t> CodePointsOf(const std::vector<std::string>& texts) {
  std::set<char32_t> code_points = {U'A'};
  for (const auto& text : texts) {
    for (char32_t c : DecodeUtf8(text)) code_points.insert(c);
  }
  return code_points;
}

std::vector<GlyphQuad> LayOutText(const texture::GlyphAtlas& atlas, const std::string& text, float char_height,
                                  TextAnchor anchor) {
  constexpr float kLineSpacing = 0.01f;   // MovableText's mLineSpacing
  const std::u32string characters = DecodeUtf8(text);
  // Ogre's Font::getGlyphAspectRatio is 1 for a code point without a cell
  const auto advance = [&](char32_t c) {
    if (c == U' ') return atlas.space_aspect * char_height;
    const auto it = atlas.glyphs.find(c);
    return (it == atlas.glyphs.end() ? 1.f : it->second.aspect) * char_height;
  };
  // the block's size first, to place it (H_CENTER: starting_left = -total_width / 2)
  float width = 0, line_width = 0, height = char_height;
  for (char32_t c : characters) {
    if (c == U'\n') {
      height += char_height + kLineSpacing;
      line_width = 0;
    } else {
      line_width += advance(c);
    }
    width = std::max(width, line_width);
  }
  std::vector<GlyphQuad> quads;
  const float start = -width / 2;
  float left = start, top = anchor == TextAnchor::kCentre ? height / 2 : 0.f;
  for (char32_t c : characters) {
    if (c == U'\n') {
      left = start;
      top -= char_height + kLineSpacing;
      continue;
    }
    const float right = left + advance(c);
    if (const auto it = atlas.glyphs.find(c); c != U' ' && it != atlas.glyphs.end()) {
      const texture::GlyphCell& cell = it->second;
      quads.push_back({{left, top - char_height}, {right, top}, {cell.u0, cell.v1}, {cell.u1, cell.v0}});
    }
    left = right;
  }
  return quads;
}

}  // namespace urdfsnap::scene
