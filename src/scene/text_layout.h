// Text as RViz's MovableText lays it out (src/rviz/ogre_helpers/movable_text.cpp _setupGeometry):
// one textured quad per character in a plane that faces the camera. GL-free.
#pragma once

#include <set>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "texture/glyph_atlas.h"

namespace urdfsnap::scene {

// One character's quad in the text plane (x right, y up, metres) and its texture cell.
struct GlyphQuad {
  Eigen::Vector2f min, max;          // lower left and upper right corners
  Eigen::Vector2f uv_min, uv_max;    // texture coordinates at min (u0, v1) and max (u1, v0)
};

// The code points of UTF-8 `text`; a byte that does not start a valid sequence stands for itself.
std::u32string DecodeUtf8(const std::string& text);

// The characters of every text, plus 'A' (whose width a space takes): what an atlas must hold.
std::set<char32_t> CodePointsOf(const std::vector<std::string>& texts);

// MovableText's vertical alignments: V_BELOW (the block hangs below the anchor: TF names) and
// V_CENTER (the block is centred on it: TEXT_VIEW_FACING markers).
enum class TextAnchor { kBelow, kCentre };

// Lays out `text` as MovableText with H_CENTER does: each character a cell `char_height` high and
// `aspect * char_height` wide, a space as wide as an 'A', a character without a cell in `atlas` a
// gap one character height wide (as in Ogre). A '\n' starts a new line char_height + 0.01 lower
// (mLineSpacing); every line starts at the left edge of the widest one, which is centred on the
// anchor.
std::vector<GlyphQuad> LayOutText(const texture::GlyphAtlas& atlas, const std::string& text, float char_height,
                                  TextAnchor anchor = TextAnchor::kBelow);

}  // namespace urdfsnap::scene
