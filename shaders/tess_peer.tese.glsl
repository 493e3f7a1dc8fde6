#version 450
// Evaluates the bicubic patch at the tessellator's (u, v): position to clip space, and the
// normal (Pu × Pv) for shading.
#extension GL_GOOGLE_include_directive : require
#include "layout.h"

layout(quads, equal_spacing, ccw) in;
layout(push_constant) uniform Push { TessPeerPush pc; };
layout(location = 0) out vec3 normal;

vec4 bernstein(float t) {
  float s = 1.0 - t;
  return vec4(s * s * s, 3.0 * t * s * s, 3.0 * t * t * s, t * t * t);
}
vec4 bernsteinDerivative(float t) {
  float s = 1.0 - t;
  return vec4(-3.0 * s * s, 3.0 * s * s - 6.0 * t * s, 6.0 * t * s - 3.0 * t * t, 3.0 * t * t);
}

void main() {
  float u = gl_TessCoord.x, v = gl_TessCoord.y;
  vec4 bu = bernstein(u), bv = bernstein(v), du = bernsteinDerivative(u), dv = bernsteinDerivative(v);
  vec3 p = vec3(0.0), pu = vec3(0.0), pv = vec3(0.0);
  for (int i = 0; i < 4; ++i) {
    vec3 row = vec3(0.0), rowDv = vec3(0.0);
    for (int j = 0; j < 4; ++j) {
      vec3 b = gl_in[i * 4 + j].gl_Position.xyz;
      row += bv[j] * b;
      rowDv += dv[j] * b;
    }
    p += bu[i] * row;
    pu += du[i] * row;
    pv += bu[i] * rowDv;
  }
  normal = cross(pu, pv);
  mat4 vp = mat4(pc.viewProjection[0], pc.viewProjection[1], pc.viewProjection[2],
                 pc.viewProjection[3]);
  gl_Position = vp * vec4(p, 1.0);
}
