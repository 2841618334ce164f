// Robot surfaces: outputs the colour interpolated from the lit vertices (Gouraud).
#version 330 core

in vec4 vertex_colour;
out vec4 fragment_colour;

void main() {
  fragment_colour = vertex_colour;
}
