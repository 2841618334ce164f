// Robot surfaces: the colour interpolated from the lit vertices (Gouraud), times the material's
// texture when it has one (Ogre's default texture unit modulates).
#version 330 core

in vec4 vertex_colour;
in vec2 texture_uv;
out vec4 fragment_colour;

uniform bool textured;
uniform sampler2D image;

void main() {
  fragment_colour = textured ? vertex_colour * texture(image, texture_uv) : vertex_colour;
}
