// The band of rows over which the splatted points (gl/internal/point_splat.h) are composited: a
// full-width rectangle from clip-space y `rows`.x to `rows`.y, vertices 0..3 as a triangle strip.
// (A scissor box would do the same, but Mesa places it mirrored in a flipped framebuffer.)
#version 400 core

uniform vec2 rows;

void main() {
  gl_Position = vec4(float(gl_VertexID & 1) * 2.0 - 1.0, (gl_VertexID & 2) != 0 ? rows.y : rows.x, 0.0, 1.0);
}
