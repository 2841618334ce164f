// Robot surfaces: the colour interpolated from the lit vertices (Gouraud); with TEXTURED, times the
// material's texture once per texture unit showing it (each of Ogre's fixed-function units
// modulates the result of the one before). With LABELS, a second output holds the link label and
// the depth (metres, as the bits of a float) for the label and depth images, which take one sample
// of each pixel (gl/internal/framebuffer.h): unsigned integers, so no sample is blended with another.
#version 330 core

in vec4 vertex_colour;
layout(location = 0) out vec4 fragment_colour;

#ifdef LABELS
flat in uint vertex_label;
in float view_depth;
layout(location = 1) out uvec2 fragment_label_depth;
#endif

#ifdef TEXTURED
in vec2 texture_uv;
uniform int texture_units;   // at least 1
uniform sampler2D image;
#endif

void main() {
  fragment_colour = vertex_colour;
#ifdef TEXTURED
  vec4 texel = texture(image, texture_uv);
  for (int unit = 0; unit < texture_units; ++unit) fragment_colour *= texel;
#endif
#ifdef LABELS
  fragment_label_depth = uvec2(vertex_label, floatBitsToUint(view_depth));
#endif
}
