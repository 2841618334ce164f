// Robot surfaces: the colour interpolated from the lit vertices (Gouraud), times the material's
// texture once per texture unit showing it (each of Ogre's fixed-function units modulates the
// result of the one before).
#version 330 core

in vec4 vertex_colour;
in vec2 texture_uv;
out vec4 fragment_colour;

uniform int texture_units;   // 0 for an untextured surface
uniform sampler2D image;

void main() {
  fragment_colour = vertex_colour;
  if (texture_units > 0) {
    vec4 texel = texture(image, texture_uv);
    for (int unit = 0; unit < texture_units; ++unit) fragment_colour *= texel;
  }
}
