// The TF name font and MovableText's layout: atlas cells, centring, hanging below the anchor, spaces,
// unknown characters, UTF-8, and the error for a missing font (unit).
#include <gtest/gtest.h>

#include "common/error.h"
#include "texture/glyph_atlas.h"
#include "scene/text_layout.h"

namespace urdfsnap::scene {
namespace {

texture::GlyphAtlas Atlas(const std::vector<std::string>& texts) {
  return *texture::BuildGlyphAtlas(texture::FindLiberationSans(), CodePointsOf(texts));
}

// the luminance-alpha texel at (x, y)
std::pair<int, int> Texel(const texture::TextureImage& t, int x, int y) {
  const size_t i = (static_cast<size_t>(y) * t.width + x) * 2;
  return {t.texels[i], t.texels[i + 1]};
}

TEST(GlyphAtlasTest, CellsShareOneHeightAndHoldTheirGlyphsOnly) {
  const texture::GlyphAtlas atlas = Atlas({"base_link", "Wj|"});
  const texture::TextureImage& t = *atlas.texture;
  ASSERT_EQ(t.channels, 2);
  ASSERT_EQ(t.texels.size(), static_cast<size_t>(t.width) * t.height * 2);
  // every character but the space has a cell; all cells span the same rows
  for (char32_t c : std::u32string(U"base_linkWj|A")) ASSERT_TRUE(atlas.glyphs.count(c)) << char(c);
  EXPECT_FALSE(atlas.glyphs.count(U' '));
  std::vector<bool> in_cell(t.width, false);
  for (const auto& [c, cell] : atlas.glyphs) {
    EXPECT_FLOAT_EQ(cell.v0, atlas.glyphs.at(U'A').v0);
    EXPECT_FLOAT_EQ(cell.v1, atlas.glyphs.at(U'A').v1);
    const int left = static_cast<int>(std::lround(cell.u0 * t.width));
    const int right = static_cast<int>(std::lround(cell.u1 * t.width));
    // aspect is the cell's width over its height, in texels
    EXPECT_NEAR(cell.aspect, double(right - left) / ((cell.v1 - cell.v0) * t.height), 1e-4);
    for (int x = left; x < right; ++x) in_cell[x] = true;
  }
  // a glyph is opaque somewhere in its cell; outside the cells (spacers, borders) all is empty
  int covered = 0;
  for (int y = 0; y < t.height; ++y) {
    for (int x = 0; x < t.width; ++x) {
      const auto [luminance, alpha] = Texel(t, x, y);
      if (!in_cell[x]) {
        ASSERT_EQ(alpha, 0) << x << "," << y;
      }
      if (alpha > 0) {
        EXPECT_EQ(luminance, 255);
      }
      covered += alpha == 255;
    }
  }
  EXPECT_GT(covered, 50);
}

TEST(GlyphAtlasTest, HeightAndBaselineAreOgresHintedOnes) {
  // Ogre's FreeType pass over code points 0..999 of Liberation Sans at 24 px per em: cells 28 texels
  // high (from 'ý', 2·23 − 18); an 'l' (17 rows above the baseline) starts 24 − 17 = 7 rows down
  const texture::GlyphAtlas atlas = Atlas({"l"});
  const texture::TextureImage& t = *atlas.texture;
  const texture::GlyphCell& l = atlas.glyphs.at(U'l');
  EXPECT_NEAR((l.v1 - l.v0) * t.height, 28, 1e-3);
  const int top = static_cast<int>(std::lround(l.v0 * t.height));
  const int x = static_cast<int>(std::lround(l.u0 * t.width)) + 2;
  int first_row = -1;
  for (int y = 0; y < t.height && first_row < 0; ++y) {
    if (Texel(t, x, y).second > 128) first_row = y;
  }
  EXPECT_EQ(first_row - top, 7);
}

TEST(TextLayoutTest, CentredOnTheAnchorAndHangingBelowIt) {
  const texture::GlyphAtlas atlas = Atlas({"arm"});
  const std::vector<GlyphQuad> quads = LayOutText(atlas, "arm", 0.1f);
  ASSERT_EQ(quads.size(), 3u);
  EXPECT_NEAR(quads.front().min.x(), -quads.back().max.x(), 1e-6);
  for (size_t i = 0; i < quads.size(); ++i) {
    EXPECT_FLOAT_EQ(quads[i].max.y(), 0);
    EXPECT_FLOAT_EQ(quads[i].min.y(), -0.1f);
    if (i > 0) {
      EXPECT_FLOAT_EQ(quads[i].min.x(), quads[i - 1].max.x());
    }
  }
  const texture::GlyphCell& m = atlas.glyphs.at(U'm');
  EXPECT_NEAR(quads[2].max.x() - quads[2].min.x(), m.aspect * 0.1, 1e-6);
  EXPECT_EQ(quads[2].uv_min, Eigen::Vector2f(m.u0, m.v1));
  EXPECT_EQ(quads[2].uv_max, Eigen::Vector2f(m.u1, m.v0));
}

// movable_text.cpp: a newline starts a line char_height + 0.01 lower at the widest line's left
// edge; V_CENTER centres the whole block of lines on the anchor.
TEST(TextLayoutTest, LinesStartAtTheWidestLinesLeftEdgeAndTheBlockIsCentred) {
  const texture::GlyphAtlas atlas = Atlas({"mm\nl"});
  const std::vector<GlyphQuad> quads = LayOutText(atlas, "mm\nl", 0.2f, TextAnchor::kCentre);
  ASSERT_EQ(quads.size(), 3u);   // no quad for the newline
  const float width = 2 * atlas.glyphs.at(U'm').aspect * 0.2f, height = 0.2f + 0.2f + 0.01f;
  EXPECT_NEAR(quads[0].min.x(), -width / 2, 1e-6);
  EXPECT_NEAR(quads[1].max.x(), width / 2, 1e-6);
  EXPECT_NEAR(quads[2].min.x(), -width / 2, 1e-6);   // 'l' starts the second line at the left
  EXPECT_NEAR(quads[0].max.y(), height / 2, 1e-6);
  EXPECT_NEAR(quads[2].max.y(), height / 2 - 0.21f, 1e-6);
  EXPECT_NEAR(quads[2].min.y(), -height / 2, 1e-6);
}

TEST(TextLayoutTest, SpaceIsAsWideAsACapitalAAndUnknownCharactersAreOneHeight) {
  const texture::GlyphAtlas atlas = Atlas({"a b"});
  const std::vector<GlyphQuad> spaced = LayOutText(atlas, "a b", 1.f);
  ASSERT_EQ(spaced.size(), 2u);
  EXPECT_NEAR(spaced[1].min.x() - spaced[0].max.x(), atlas.space_aspect, 1e-6);
  EXPECT_NEAR(atlas.space_aspect, atlas.glyphs.at(U'A').aspect, 1e-6);
  // '#' has no cell in this atlas: a gap of one height, as Ogre's aspect ratio 1 for it
  const std::vector<GlyphQuad> gap = LayOutText(atlas, "a#b", 1.f);
  ASSERT_EQ(gap.size(), 2u);
  EXPECT_NEAR(gap[1].min.x() - gap[0].max.x(), 1.0, 1e-6);
}

TEST(TextLayoutTest, DecodesUtf8AndKeepsStrayBytes) {
  EXPECT_EQ(DecodeUtf8("a\xC3\xBD\xE2\x82\xAC"), std::u32string(U"a\u00FD\u20AC"));
  EXPECT_EQ(DecodeUtf8("\xC3"), std::u32string(U"\u00C3"));
  EXPECT_EQ(DecodeUtf8("\xFFx"), std::u32string(U"\u00FFx"));
}

TEST(GlyphAtlasTest, EachSetOfCodePointsIsBuiltOnce) {
  const std::string font = texture::FindLiberationSans();
  const auto first = texture::BuildGlyphAtlas(font, {U'a', U'b'});
  EXPECT_EQ(texture::BuildGlyphAtlas(font, {U'b', U'a'}), first);
  EXPECT_NE(texture::BuildGlyphAtlas(font, {U'a'}), first);
}

TEST(GlyphAtlasTest, MissingFontNamesEveryPlaceAndThePackage) {
  try {
    texture::FindLiberationSans({"/nonexistent/a.ttf", "/nonexistent/b.ttf"});
    FAIL() << "no error";
  } catch (const Error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("/nonexistent/a.ttf, /nonexistent/b.ttf"), std::string::npos) << what;
    EXPECT_NE(what.find("fonts-liberation"), std::string::npos) << what;
    EXPECT_NE(what.find("--no-tf-names"), std::string::npos) << what;
  }
  EXPECT_THROW(texture::BuildGlyphAtlas("/nonexistent/font.ttf", {U'a'}), Error);
}

}  // namespace
}  // namespace urdfsnap::scene
