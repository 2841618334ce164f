// Camera-facing text: the label colour modulated by the luminance-alpha glyph texture, unlit, as
// Ogre's font material (vertex colour times texture) draws it.
#version 330 core

in vec2 glyph_uv;
flat in vec4 label_colour;
out vec4 fragment_colour;

uniform sampler2D glyphs;   // luminance in r, alpha in g

void main() {
  vec2 la = texture(glyphs, glyph_uv).rg;
  fragment_colour = label_colour * vec4(la.r, la.r, la.r, la.g);
}
