// Points style of RViz's point clouds (rviz/ogre_helpers/point_cloud.cpp, material
// rviz/PointCloudPoint, glsl120/point.vert): one GL point of `point_size` pixels per position.
#version 330 core

layout(location = 0) in vec3 position;
layout(location = 1) in vec4 rgba;

uniform mat4 model_view_projection;
uniform float point_size;   // pixels

out vec4 point_colour;
out vec2 square_uv;

void main() {
  gl_Position = model_view_projection * vec4(position, 1.0);
  gl_PointSize = point_size;
  point_colour = rgba;
  square_uv = vec2(0.5);
}
