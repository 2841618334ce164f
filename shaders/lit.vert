// Robot surfaces: RViz's fixed-function Gouraud lighting, evaluated per vertex.
// One white directional head-light along the camera's view direction, no ambient, no specular:
// colour = emissive + diffuse * max(0, n . l), clamped to 1 as fixed-function lighting is, where l
// points from the surface back to the camera. Drawn instanced: each instance's matrices and
// material are vertex attributes (gl/internal/gpu_mesh.h, MeshInstance), so that many markers of
// one shape are one draw (RViz's Ogre draws each marker on its own; the pixels are the same).
// Compiled twice (gl/scene_renderer.cpp): with TEXTURED defined for textured surfaces, and
// without, where no texture coordinate is fetched or interpolated (a third less to set up and
// interpolate per triangle); with LABELS defined (scene_renderer.cpp's one-draw path) it also
// passes on the instance's link label and the vertex's depth along the view axis, for the label
// and depth images drawn in the same pass.
#version 330 core

layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;

// per instance
layout(location = 3) in mat4 model_view_projection;
layout(location = 7) in mat3 normal_to_view;   // inverse transpose of the model-view matrix (handles scaling)
layout(location = 10) in vec4 diffuse;         // rgba; alpha is passed through for blending
layout(location = 11) in vec3 emissive;        // the material's self-illumination

out vec4 vertex_colour;

#ifdef TEXTURED
layout(location = 2) in vec2 uv;
out vec2 texture_uv;
#endif

#ifdef LABELS
layout(location = 12) in uint label;   // per instance: 1 + the link's index
uniform vec4 clip_to_view_depth;       // dot with a clip-space position: its view-space depth (-z)
flat out uint vertex_label;
out float view_depth;
#endif

void main() {
  gl_Position = model_view_projection * vec4(position, 1.0);
  // the light shines along -z in view space, so n . l is the view-space normal's z
  vec3 n = normalize(normal_to_view * normal);
  vertex_colour = vec4(min(emissive + diffuse.rgb * max(0.0, n.z), vec3(1.0)), diffuse.a);
#ifdef TEXTURED
  texture_uv = uv;
#endif
#ifdef LABELS
  vertex_label = label;
  view_depth = dot(clip_to_view_depth, gl_Position);
#endif
}
