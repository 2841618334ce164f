// Robot geometry for the depth and link-label images: positions only, and each fragment's distance
// from the camera along its viewing axis (view space looks down -z).
#version 330 core

layout(location = 0) in vec3 position;

uniform mat4 model_view;
uniform mat4 projection;

out float view_depth;

void main() {
  vec4 p = model_view * vec4(position, 1.0);
  view_depth = -p.z;
  gl_Position = projection * p;
}
