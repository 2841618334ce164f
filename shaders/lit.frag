// Robot surfaces: the colour interpolated from the lit vertices (Gouraud); with TEXTURED, times the
// material's texture once per texture unit showing it (each of Ogre's fixed-function units
// modulates the result of the one before).
#version 330 core

in vec4 vertex_colour;
out vec4 fragment_colour;

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
}
