// Camera-facing text (TF frame names): each corner is the label's anchor in view space moved in the
// image plane, as MovableText turns its quads by the camera's orientation.
#version 330 core

layout(location = 0) in vec2 offset;   // in the camera's image plane, x right, y up, metres
layout(location = 1) in vec2 uv;

uniform vec3 anchor_view;              // the anchor point in view space
uniform mat4 projection;

out vec2 glyph_uv;

void main() {
  gl_Position = projection * vec4(anchor_view + vec3(offset, 0.0), 1.0);
  glyph_uv = uv;
}
