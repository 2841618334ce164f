// Composites the splatted points (gl/internal/point_splat.h): run per sample (gl_SampleID), each
// sample takes its texel's depth (gl_FragDepth, depth-tested against what is drawn) and colour, or
// nothing where no point covers it. A pixel's samples lie side by side in the texture; a texel is
// the depth's float bits and the rgba8 colour.
#version 400 core

uniform usampler2D texels;
uniform int samples;
out vec4 fragment_colour;

void main() {
  uvec2 texel = texelFetch(texels, ivec2(int(gl_FragCoord.x) * samples + gl_SampleID, int(gl_FragCoord.y)), 0).xy;
  float depth = uintBitsToFloat(texel.x);
  if (depth > 1.0) discard;
  fragment_colour = unpackUnorm4x8(texel.y);
  gl_FragDepth = depth;
}
