// RViz's TF name font: Liberation Sans rasterised into one texture the way Ogre 1.12's Font does for
// RViz's MovableText (ogre_media/fonts/ogre1.12.fontdef: truetype, size 18, resolution 96, so 24
// pixels per em; rasterised with FreeType as Ogre does). GL-free.
#pragma once

#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "texture/texture_image.h"

namespace urdfsnap::texture {

// Where one glyph's cell lies in the texture. A cell is as wide as the glyph's advance and as high
// as the font's tallest cell (Ogre's max_height), with the baseline at the same height in every
// cell; MovableText stretches a cell over one character height.
struct GlyphCell {
  float u0 = 0, v0 = 0, u1 = 0, v1 = 0;   // texture coordinates, v0 the top edge
  float aspect = 0;                       // cell width / cell height (Ogre's getGlyphAspectRatio)
};

struct GlyphAtlas {
  std::shared_ptr<const TextureImage> texture;   // 2 channels: luminance and alpha
  std::map<char32_t, GlyphCell> glyphs;          // only the code points asked for
  float space_aspect = 0;   // a space's width / cell height: MovableText uses a capital A's
};

// Where Debian's fonts-liberation (and other distributions) install Liberation Sans Regular.
const std::vector<std::string>& LiberationSansPaths();

// The first of `candidates` that is a readable file. Throws urdfsnap::Error naming every place
// looked in and the Debian package to install when none is.
std::string FindLiberationSans(const std::vector<std::string>& candidates = LiberationSansPaths());

// Rasterises the glyphs of `code_points` of the font file at `font_path` as Ogre does:
// the cell height and baseline come from all code points 0..999 (RViz adds that range before
// loading, movable_text.cpp), each glyph sits in its cell at its left bearing, clipped to its
// advance, with luminance 255 over its bitmap and the coverage as alpha; cells are one empty texel
// apart. Code points the font has no bitmap for (space, controls) get no cell. The font file is
// opened once per process; an atlas is built once while it is held anywhere (later calls with the
// same font and code points return it). Thread-safe. Throws urdfsnap::Error for an unreadable or invalid
// file.
std::shared_ptr<const GlyphAtlas> BuildGlyphAtlas(const std::string& font_path,
                                                  const std::set<char32_t>& code_points);

}  // namespace urdfsnap::texture
