// `urdfsnap docs --check`: a committed page against a fresh one, file by file: the text files
// (README.md, index.html) exactly, the pictures with the snapshot tolerances (a re-render on
// another CPU passes, a moved joint does not), animations frame by frame with a looser tolerance.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "image/image_diff.h"

namespace urdfsnap::docs {

// How far a frame of an animation may be from the committed one. GIF frames are dithered to one
// palette by error diffusion, so a render that rounds a few edge pixels differently (another CPU)
// changes the dithering pattern (and can move a palette entry) beyond the pixels that changed.
// Measured on mrm's page rendered with GALLIUM_OVERRIDE_CPU_CAPS=sse2 against the default CPU:
// every GIF differs in its bytes, a few pixels by up to 27, mean delta at most 0.005 per frame.
// Lossy WebP (stills and animations are read the same way) moves its block choices when one input
// pixel changes: mrm's tightly fitted TF picture, whose label text is all sharp edges, one pixel
// apart as PNG, decodes with no pixel 32 apart but a mean delta of 0.32. The limits sit well
// above that; a changed joint moves many pixels by more than 32, and the tables catch limits too.
inline constexpr image::DiffTolerance kAnimationTolerance{32, 0.002, 1.0};

// What differs, one line per file: "README.md: line 40 differs: ...", "joints/a/upper.png: max
// delta 96, ...", "joints/b/lower.png: missing from the committed page", "...: not in a fresh
// page". Empty when the committed page is up to date.
std::vector<std::string> ComparePages(const std::filesystem::path& committed, const std::filesystem::path& fresh,
                                      const image::DiffTolerance& tolerance = {});

}  // namespace urdfsnap::docs
