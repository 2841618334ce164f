// Composites the splatted points (gl/internal/point_splat.h): run per sample (gl_SampleID), each
// sample takes its depth (gl_FragDepth, depth-tested against what is drawn) and colour, or nothing
// where no point covers it. The buffer texture holds, tile by tile (rows of `tiles_x` tiles of
// 2^`tile_bits` pixels square, bottom first), each tile's samples in turn as rows of (depth's
// float bits, rgba8 colour) pairs (PointSplat::Cover), one fetch a sample. Shifts, not divisions:
// llvmpipe divides vectors of integers lane by lane.
#version 400 core

uniform usamplerBuffer texels;
uniform int samples;
uniform int tile_bits;
uniform int tiles_x;
out vec4 fragment_colour;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  ivec2 within = pixel & ((1 << tile_bits) - 1);
  int tile = (pixel.y >> tile_bits) * tiles_x + (pixel.x >> tile_bits);
  uvec2 texel = texelFetch(texels, ((((tile * samples + gl_SampleID) << tile_bits) + within.y) << tile_bits) + within.x).xy;
  float depth = uintBitsToFloat(texel.x);
  if (depth > 1.0) discard;
  fragment_colour = unpackUnorm4x8(texel.y);
  gl_FragDepth = depth;
}
