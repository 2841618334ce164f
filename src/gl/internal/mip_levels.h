// The mipmap levels of an RGBA8 texture made on the CPU exactly as Mesa's llvmpipe makes them for
// glGenerateMipmap, so that a texture's levels can be uploaded instead of generated. llvmpipe
// generates a level by drawing it with a bilinear sample of the level above at each texel's
// centre; a side that halves evenly puts that centre between two texels, where llvmpipe's 8-bit
// interpolation, a + (((b - a) * 128 + 128) >> 8), is the average of a and b rounded up, first
// along rows, then between them. A side of 1 samples its only texel and a side of 3 going to 1 its
// middle one (weight 0 on its neighbour). Other odd sides sample between texels at other weights,
// which this does not follow: the caller generates those on the GPU (MipLevelsExact). Generating
// on the CPU saves llvmpipe's compiling of its blit shaders (a variant per texture size class) and
// drawing every level, in every process that uploads the texture. GL-free.
#pragma once

#include <cstdint>
#include <vector>

namespace urdfsnap::gl {

// Whether NextMipLevel makes every level of a width x height texture, down to 1x1: at each level
// every side is even, 1 or 3 (false for an empty texture).
bool MipLevelsExact(int width, int height);

// The number of levels of a full mipmap chain of a width x height texture (1 + log2 of the longer
// side, rounded down), as GL counts them.
int MipLevelCount(int width, int height);

// The level below the RGBA8 level `texels` (width x height, rows first): max(1, width / 2) x
// max(1, height / 2) texels, as llvmpipe draws it. Meant for the sides MipLevelsExact accepts.
std::vector<std::uint8_t> NextMipLevel(const std::vector<std::uint8_t>& texels, int width, int height);

}  // namespace urdfsnap::gl
