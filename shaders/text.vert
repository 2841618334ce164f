// Camera-facing text (TF frame names): each corner is the label's anchor in view space moved in the
// image plane, as MovableText turns its quads by the camera's orientation.
#version 330 core

layout(location = 0) in vec2 offset;        // in the camera's image plane, x right, y up, metres
layout(location = 1) in vec2 uv;
layout(location = 2) in vec3 anchor_view;   // the label's anchor point in view space
layout(location = 3) in vec4 colour;        // the label's colour

uniform mat4 projection;

out vec2 glyph_uv;
flat out vec4 label_colour;

void main() {
  gl_Position = projection * vec4(anchor_view + vec3(offset, 0.0), 1.0);
  glyph_uv = uv;
  label_colour = colour;
}
