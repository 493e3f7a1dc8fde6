#version 450
// Two-sided Lambert on the interpolated normal: enough to make the fragment stage do real work.
layout(location = 0) in vec3 normal;
layout(location = 0) out vec4 colour;

void main() {
  float len = length(normal);
  float light = len > 0.0 ? abs(dot(normal / len, normalize(vec3(0.3, -0.5, 0.8)))) : 1.0;
  colour = vec4(vec3(0.2 + 0.8 * light), 1.0);
}
