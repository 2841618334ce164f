// Unlit lines (the grid): a constant colour, blended by its alpha.
#version 330 core

uniform vec4 colour;
out vec4 fragment_colour;

void main() {
  fragment_colour = colour;
}
