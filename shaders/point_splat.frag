// Composites the splatted points (gl/internal/point_splat.h): run per sample (gl_SampleID), each
// sample takes its texel's colour and depth (gl_FragDepth, depth-tested against what is drawn), or
// nothing where no point covers it. A pixel's samples lie side by side in the textures.
#version 400 core

uniform sampler2D colours;
uniform sampler2D depths;
uniform int samples;
out vec4 fragment_colour;

void main() {
  ivec2 at = ivec2(int(gl_FragCoord.x) * samples + gl_SampleID, int(gl_FragCoord.y));
  float depth = texelFetch(depths, at, 0).r;
  if (depth > 1.0) discard;
  fragment_colour = texelFetch(colours, at, 0);
  gl_FragDepth = depth;
}
