// Robot surfaces: RViz's fixed-function Gouraud lighting, evaluated per vertex.
// One white directional head-light along the camera's view direction, no ambient, no specular:
// colour = diffuse * max(0, n . l), where l points from the surface back to the camera.
#version 330 core

layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;

uniform mat4 model_view_projection;
uniform mat3 normal_to_view;   // inverse transpose of the model-view matrix (handles scaling)
uniform vec4 diffuse;          // rgba; alpha is passed through for blending

out vec4 vertex_colour;

void main() {
  gl_Position = model_view_projection * vec4(position, 1.0);
  // the light shines along -z in view space, so n . l is the view-space normal's z
  vec3 n = normalize(normal_to_view * normal);
  vertex_colour = vec4(diffuse.rgb * max(0.0, n.z), diffuse.a);
}
