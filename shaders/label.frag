// The depth and link-label images: exact values per pixel, no blending (one sample per pixel).
#version 330 core

in float view_depth;

uniform uint label;   // 1 + the link's index

layout(location = 0) out uint fragment_label;
layout(location = 1) out float fragment_depth;   // metres

void main() {
  fragment_label = label;
  fragment_depth = view_depth;
}
