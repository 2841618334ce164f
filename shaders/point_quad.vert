// Squares, Flat Squares and Spheres of RViz's point clouds (glsl150/billboard.geom): a square of
// `size` metres facing the camera per point, its corners moved from the centre in the camera's
// image plane. Each point is four vertices (its position and colour in each), 4k to 4k + 3; which
// corner a vertex is comes from gl_VertexID & 3 (corners in triangle-strip order: (-,-), (+,-),
// (-,+), (+,+)).
#version 330 core

layout(location = 0) in vec3 position;
layout(location = 1) in vec4 rgba;

uniform mat4 model_view;
uniform mat4 projection;
uniform float size;   // metres; billboard.geom takes size.x for both sides

out vec4 point_colour;
out vec2 square_uv;

void main() {
  int corner = gl_VertexID & 3;
  vec2 uv = vec2(float(corner & 1), float(corner >> 1));
  vec4 centre = model_view * vec4(position, 1.0);
  gl_Position = projection * (centre + vec4((uv - 0.5) * size, 0.0, 0.0));
  point_colour = rgba;
  square_uv = uv;
}
