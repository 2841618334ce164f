// Composites the splatted points (gl/internal/point_splat.h): run per sample (gl_SampleID), each
// sample takes its depth (gl_FragDepth, depth-tested against what is drawn) and colour, or nothing
// where no point covers it. The texture holds the splat's tiles of 2^`tile_bits` pixels square
// where they lie in the image, each tile's planes one above the other: per sample the depths'
// float bits, then the rgba8 colours (PointSetDrawing::Composite). Shifts, not divisions: llvmpipe
// divides vectors of integers lane by lane.
#version 400 core

uniform usampler2D texels;
uniform int samples;
uniform int tile_bits;
out vec4 fragment_colour;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  int tile = 1 << tile_bits;
  int row = (((pixel.y >> tile_bits) * samples + gl_SampleID) * 2 << tile_bits) + (pixel.y & (tile - 1));
  float depth = uintBitsToFloat(texelFetch(texels, ivec2(pixel.x, row), 0).x);
  if (depth > 1.0) discard;
  fragment_colour = unpackUnorm4x8(texelFetch(texels, ivec2(pixel.x, row + tile), 0).x);
  gl_FragDepth = depth;
}
