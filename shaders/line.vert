// Unlit lines and flat triangles (the grid, paths, marker ribbons, triangle lists): positions in
// the fixed frame, a colour per vertex.
#version 330 core

layout(location = 0) in vec3 position;
layout(location = 1) in vec4 colour;

uniform mat4 model_view_projection;
out vec4 vertex_colour;

void main() {
  vertex_colour = colour;
  gl_Position = model_view_projection * vec4(position, 1.0);
}
