// Boxes of RViz's point clouds (glsl150/box.geom with WITH_LIGHTING): a box of `size` metres
// along `axes` per point, each face shaded by a fixed lightness instead of a light. Each point is
// 24 vertices (its position and colour in each), 24k to 24k + 23, four per face: face
// f = (gl_VertexID / 4) % 6 spans the axes side, side + 1 and side
// + 2 (side = f % 3) and lies on the positive side of the third for f < 3, the negative for f >= 3,
// its corners in box.geom's triangle-strip order, so that every face winds counter-clockwise seen
// from outside.
#version 330 core

layout(location = 0) in vec3 position;
layout(location = 1) in vec4 rgba;

uniform mat4 model_view_projection;
uniform vec3 size;   // metres along the box axes
uniform mat3 axes;   // the box axes in the fixed frame

out vec4 point_colour;
out vec2 square_uv;

// box.geom's lightness[6]: faces +z, +x, +y, -z, -x, -y in this order
const float kLightness[6] = float[](0.9, 0.5, 0.6, 0.6, 1.0, 0.4);

void main() {
  int face = (gl_VertexID >> 2) % 6;
  int corner = gl_VertexID & 3;
  int side = face % 3;
  vec3 t;   // box.geom's tex: the corner in the face's (x, y, z) axes, each -1 or +1
  if (face < 3) {
    t = vec3((corner & 1) != 0 ? 1.0 : -1.0, (corner & 2) != 0 ? 1.0 : -1.0, 1.0);
  } else {
    t = vec3((corner & 2) != 0 ? 1.0 : -1.0, (corner & 1) != 0 ? 1.0 : -1.0, -1.0);
  }
  vec3 offset;   // axes side, side + 1, side + 2 take t.x, t.y, t.z
  offset[side] = t.x;
  offset[(side + 1) % 3] = t.y;
  offset[(side + 2) % 3] = t.z;
  gl_Position = model_view_projection * vec4(position + axes * (offset * size * 0.5), 1.0);
  point_colour = vec4(rgba.rgb * kLightness[face], rgba.a);
  square_uv = t.xy * 0.5 + 0.5;
}
