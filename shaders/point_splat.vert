// The rectangles of drawn tiles over which the splatted points (gl/internal/point_splat.h) are
// composited: each corner given in clip space, two triangles per rectangle.
// (A scissor box per tile would do the same, but Mesa places it mirrored in a flipped framebuffer.)
#version 400 core

layout(location = 0) in vec2 corner;

void main() { gl_Position = vec4(corner, 0.0, 1.0); }
