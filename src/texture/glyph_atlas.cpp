// Font texture building as Ogre 1.12's Font::loadResource does it (OgreMain/src/OgreFont.cpp), with
// FreeType as Ogre uses it, and the lookup of the font file.
//
// Why FreeType and not stb_truetype: Ogre rasterises with FreeType's TrueType hinter, which snaps
// glyph heights to the pixel grid. For Liberation Sans at 24 px per em that gives a cell height of
// 28 px and a baseline 24 px below the cell top; stb_truetype, which does not hint, gives 30 and 22.
// The cell height sets the size of every letter on screen (0.1 m per cell) and the baseline their
// height, so the unhinted metrics draw RViz's names 7% smaller and about 2 px too high.
#include "texture/glyph_atlas.h"

#include <ft2build.h>
#include FT_FREETYPE_H
#include FT_OUTLINE_H

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <mutex>

#include "common/error.h"
#include "common/shared_cache.h"

namespace urdfsnap::texture {

namespace {

// ogre1.12.fontdef: "size 18, resolution 96"
constexpr FT_F26Dot6 kSize = 18 * 64;
constexpr FT_UInt kResolution = 96;
// movable_text.cpp setFontName: addCodePointRange(0, 999) before the font is loaded
constexpr char32_t kLastLoadedCodePoint = 999;

// A font face opened once per process, with the cell height and baseline of its glyph texture.
class LoadedFont {
 public:
  explicit LoadedFont(const std::string& path) {
    if (FT_Init_FreeType(&library_)) throw Error("cannot initialise FreeType");
    if (FT_New_Face(library_, path.c_str(), 0, &face_) ||
        FT_Set_Char_Size(face_, kSize, 0, kResolution, kResolution)) {
      FT_Done_FreeType(library_);
      throw Error(path + ": not a font FreeType can read");
    }
    // Font::loadResource's first pass over every loaded code point (26.6 fixed point). It renders
    // each glyph for its bitmap's rows; the hinted outline's box rounded out to whole pixels gives
    // the same rows (checked for all 1000 code points of Liberation Sans) at a fifth of the time.
    FT_Pos max_height = 0, max_bearing = 0;
    for (char32_t c = 0; c <= kLastLoadedCodePoint; ++c) {
      if (FT_Load_Char(face_, c, FT_LOAD_DEFAULT)) continue;
      const FT_GlyphSlot glyph = face_->glyph;
      FT_BBox box{};
      if (glyph->format == FT_GLYPH_FORMAT_OUTLINE) FT_Outline_Get_CBox(&glyph->outline, &box);
      const FT_Pos rows = ((box.yMax + 63) & ~63) - (box.yMin & ~63);   // 26.6, whole pixels
      max_height = std::max<FT_Pos>(2 * rows - glyph->metrics.horiBearingY, max_height);
      max_bearing = std::max(glyph->metrics.horiBearingY, max_bearing);
    }
    cell_height_ = static_cast<int>(max_height >> 6);
    max_bearing_ = static_cast<int>(max_bearing >> 6);
  }
  ~LoadedFont() {
    FT_Done_Face(face_);
    FT_Done_FreeType(library_);
  }
  LoadedFont(const LoadedFont&) = delete;
  LoadedFont& operator=(const LoadedFont&) = delete;

  // The atlas of `code_points`, built once while it is held anywhere.
  std::shared_ptr<const GlyphAtlas> Atlas(const std::set<char32_t>& code_points) const {
    return atlases_.Get(code_points, [&] {
      const std::lock_guard<std::mutex> lock(mutex_);
      return std::make_shared<const GlyphAtlas>(BuildAtlas(code_points));
    });
  }

 private:
  GlyphAtlas BuildAtlas(const std::set<char32_t>& code_points) const;

  mutable std::mutex mutex_;   // a FreeType face serves one thread at a time
  mutable SharedCache<std::set<char32_t>, GlyphAtlas> atlases_;
  FT_Library library_ = nullptr;
  FT_Face face_ = nullptr;
  int cell_height_ = 0;        // Ogre's max_height >> 6: the max over glyphs of 2 * rows - bearing
  int max_bearing_ = 0;        // Ogre's mTtfMaxBearingY >> 6: the baseline's distance from a cell top
};

GlyphAtlas LoadedFont::BuildAtlas(const std::set<char32_t>& code_points) const {
  // one row of cells with an empty texel between them and around them (Ogre's char_spacer)
  int width = 1;
  for (char32_t c : code_points) {
    if (!FT_Load_Char(face_, c, FT_LOAD_DEFAULT)) width += static_cast<int>(face_->glyph->advance.x >> 6) + 1;
  }
  auto texture = std::make_shared<TextureImage>();
  texture->channels = 2;
  texture->width = width;
  texture->height = cell_height_ + 2;
  texture->texels.assign(static_cast<size_t>(texture->width) * texture->height * 2, 0);

  GlyphAtlas atlas;
  const float w = static_cast<float>(texture->width), h = static_cast<float>(texture->height);
  const int top = 1;
  int left = 1;
  for (char32_t c : code_points) {
    if (FT_Load_Char(face_, c, FT_LOAD_RENDER)) continue;
    const FT_GlyphSlot glyph = face_->glyph;
    const int advance = static_cast<int>(glyph->advance.x >> 6);
    if (!glyph->bitmap.buffer) continue;   // Ogre gives such glyphs (space) no cell
    // OgreFont.cpp: the bitmap starts at the left bearing (at least 0) and is cut at the advance,
    // its top at the cell's baseline minus its bearing; white wherever the bitmap is, the coverage
    // as alpha. Rows that would leave the cell are cut (Ogre would write into its neighbours).
    const int x_bearing = static_cast<int>(glyph->metrics.horiBearingX >> 6);
    const int x_offset = std::max(0, x_bearing);
    const int start = x_offset - x_bearing;
    const int columns = std::min(static_cast<int>(glyph->bitmap.width) - start, advance - x_offset);
    const int y_offset = max_bearing_ - static_cast<int>(glyph->metrics.horiBearingY >> 6);
    for (int j = 0; j < static_cast<int>(glyph->bitmap.rows); ++j) {
      if (y_offset + j < 0 || y_offset + j >= cell_height_) continue;
      const unsigned char* source = glyph->bitmap.buffer + j * glyph->bitmap.pitch + start;
      std::uint8_t* texel =
          &texture->texels[(static_cast<size_t>(top + y_offset + j) * texture->width + left + x_offset) * 2];
      for (int k = 0; k < columns; ++k, texel += 2) {
        texel[0] = 0xFF;
        texel[1] = source[k];
      }
    }
    atlas.glyphs[c] = {left / w, top / h, (left + advance) / w, (top + cell_height_) / h,
                       static_cast<float>(advance) / static_cast<float>(cell_height_)};
    left += advance + 1;
  }
  // movable_text.cpp: a space is as wide as a capital A
  if (!FT_Load_Char(face_, U'A', FT_LOAD_DEFAULT)) {
    atlas.space_aspect = static_cast<float>(face_->glyph->advance.x >> 6) / static_cast<float>(cell_height_);
  }
  atlas.texture = std::move(texture);
  return atlas;
}

std::shared_ptr<const LoadedFont> LoadFont(const std::string& path) {
  static std::mutex mutex;
  static std::map<std::string, std::shared_ptr<const LoadedFont>> cache;
  const std::lock_guard<std::mutex> lock(mutex);
  auto& font = cache[path];
  if (!font) {
    if (!std::ifstream(path).good()) throw Error(path + ": cannot read the font file");
    font = std::make_shared<const LoadedFont>(path);
  }
  return font;
}

}  // namespace

const std::vector<std::string>& LiberationSansPaths() {
  static const std::vector<std::string> paths = {
      "/usr/share/fonts/truetype/liberation/LiberationSans-Regular.ttf",    // Debian fonts-liberation
      "/usr/share/fonts/truetype/liberation2/LiberationSans-Regular.ttf",   // Debian fonts-liberation2
      "/usr/share/fonts/liberation-sans/LiberationSans-Regular.ttf",        // Fedora
      "/usr/share/fonts/liberation/LiberationSans-Regular.ttf",
      "/usr/share/fonts/TTF/LiberationSans-Regular.ttf",                    // Arch
  };
  return paths;
}

std::string FindLiberationSans(const std::vector<std::string>& candidates) {
  std::string looked;
  for (const auto& path : candidates) {
    std::error_code error;
    if (std::filesystem::is_regular_file(path, error) && std::ifstream(path).good()) return path;
    looked += (looked.empty() ? "" : ", ") + path;
  }
  throw Error("TF frame names need the font Liberation Sans (Debian package fonts-liberation), "
              "not found in: " + looked + "; install it or hide the names with --no-tf-names");
}

std::shared_ptr<const GlyphAtlas> BuildGlyphAtlas(const std::string& font_path,
                                                  const std::set<char32_t>& code_points) {
  return LoadFont(font_path)->Atlas(code_points);
}

}  // namespace urdfsnap::texture
