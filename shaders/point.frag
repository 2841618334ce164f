// The fragment programs of RViz's point-cloud materials (ogre_media/materials/glsl120), chosen by
// `shape`: 0 flat_color.frag (Points, Flat Squares): the point's colour; 1 smooth_square.frag
// (Squares, Boxes): the outer ~3% of the square (smoothstep 0.45..0.48 from the centre) is the
// colour minus 0.2, or plus 0.2 when |rgb| < 0.5; 2 shaded_circle.frag (Spheres): a disc of
// diameter 1 whose colour falls to 0.8 of the point's at the rim, the corners outside it dropped
// (the material's alpha_rejection).
#version 330 core

in vec4 point_colour;
in vec2 square_uv;
out vec4 fragment_colour;

uniform int shape;

void main() {
  vec3 c = point_colour.rgb;
  float ax = square_uv.x - 0.5;
  float ay = square_uv.y - 0.5;
  if (shape == 1) {
    float blend = smoothstep(-0.48, -0.45, ay) * (1.0 - smoothstep(0.45, 0.48, ay)) *
                  smoothstep(-0.48, -0.45, ax) * (1.0 - smoothstep(0.45, 0.48, ax));
    c = blend * c + (sign(0.5 - length(c)) * vec3(0.2) + c) * (1.0 - blend);
  } else if (shape == 2) {
    float a = (0.25 - (ax * ax + ay * ay)) * 4.0;
    if (a <= 0.0) discard;
    c = mix(0.8 * c, c, a);
  }
  fragment_colour = vec4(c, point_colour.a);
}
