#version 450
// Per-edge tessellation factors from a screen-space rule: a cubic's chord error with n uniform
// segments is at most (1/8)·max|C''|/n² ≤ (1/8)·6·max|Δ²b| / n² (second differences of its
// control points), so n = ceil(sqrt(0.75·max|Δ²b|/tol)) with the control points in pixels.
// Outer factors come from each edge's own four points (two patches sharing an edge compute the
// same factor: no cracks); inner ones from the largest over the net's rows and columns.
// Patches entirely outside one clip plane get factor 0 (discarded); a patch with a control
// point behind the eye plane cannot be projected and gets the maximum factor.
// Two tuning knobs (TessPeerPush.rules), as engines tune such shaders: a scale on every factor
// before rounding up (the rule gives each direction the whole tolerance and ignores the twist,
// so its grids overshoot it), and a collapsed side (four equal control points: a pole, shared
// with no other patch's side) taking a multiple of the inner factor along it instead of its
// own 1, whose ring of one segment fans long, twisted triangles from the pole.
#extension GL_GOOGLE_include_directive : require
#include "layout.h"

layout(vertices = 16) out;
layout(push_constant) uniform Push { TessPeerPush pc; };

vec2 toPixels(vec4 clip) { return (clip.xy / clip.w * 0.5 + 0.5) * pc.params.xy; }

float segments(vec2 a, vec2 b, vec2 c, vec2 d) {
  float m = max(length(a - 2.0 * b + c), length(b - 2.0 * c + d));
  return clamp(ceil(pc.rules.x * sqrt(0.75 * m / pc.params.z)), 1.0, pc.params.w);
}

bool collapsed(int a, int b, int c, int d) {
  vec4 p = gl_in[a].gl_Position;
  return pc.rules.y > 0.0 && p == gl_in[b].gl_Position && p == gl_in[c].gl_Position &&
         p == gl_in[d].gl_Position;
}

void main() {
  gl_out[gl_InvocationID].gl_Position = gl_in[gl_InvocationID].gl_Position;
  if (gl_InvocationID != 0) return;
  mat4 vp = mat4(pc.viewProjection[0], pc.viewProjection[1], pc.viewProjection[2],
                 pc.viewProjection[3]);
  vec2 s[16];
  // 1 while every point so far is outside: x<-w, y<-w, z<0, w<=0 / x>w, y>w, z>w.
  vec4 allOutLow = vec4(1.0), allOutHigh = vec4(1.0);
  bool behind = false;
  for (int k = 0; k < 16; ++k) {
    vec4 c = vp * gl_in[k].gl_Position;
    allOutLow = min(allOutLow, vec4(bvec4(c.x < -c.w, c.y < -c.w, c.z < 0.0, c.w <= 0.0)));
    allOutHigh = min(allOutHigh, vec4(bvec4(c.x > c.w, c.y > c.w, c.z > c.w, false)));
    behind = behind || c.w <= 1e-6;
    s[k] = behind ? vec2(0.0) : toPixels(c);
  }
  if (max(max(allOutLow.x, allOutLow.y), max(allOutLow.z, allOutLow.w)) > 0.5 ||
      max(allOutHigh.x, max(allOutHigh.y, allOutHigh.z)) > 0.5) {
    gl_TessLevelOuter[0] = gl_TessLevelOuter[1] = gl_TessLevelOuter[2] = gl_TessLevelOuter[3] = 0.0;
    gl_TessLevelInner[0] = gl_TessLevelInner[1] = 0.0;
    return;
  }
  if (behind) {
    float m = pc.params.w;
    gl_TessLevelOuter[0] = gl_TessLevelOuter[1] = gl_TessLevelOuter[2] = gl_TessLevelOuter[3] = m;
    gl_TessLevelInner[0] = gl_TessLevelInner[1] = m;
    return;
  }
  // b_ij = s[i*4 + j], u along i. Quad domain: outer 0..3 = edges u=0, v=0, u=1, v=1.
  float inU = 1.0, inV = 1.0;
  for (int k = 0; k < 4; ++k) {
    inU = max(inU, segments(s[k], s[4 + k], s[8 + k], s[12 + k]));
    inV = max(inV, segments(s[4 * k], s[4 * k + 1], s[4 * k + 2], s[4 * k + 3]));
  }
  gl_TessLevelInner[0] = inU;
  gl_TessLevelInner[1] = inV;
  // Sides u = 0 and 1 run along v, sides v = 0 and 1 along u.
  float poleU = min(pc.rules.y * inU, pc.params.w), poleV = min(pc.rules.y * inV, pc.params.w);
  gl_TessLevelOuter[0] = collapsed(0, 1, 2, 3) ? poleV : segments(s[0], s[1], s[2], s[3]);
  gl_TessLevelOuter[1] = collapsed(0, 4, 8, 12) ? poleU : segments(s[0], s[4], s[8], s[12]);
  gl_TessLevelOuter[2] = collapsed(12, 13, 14, 15) ? poleV : segments(s[12], s[13], s[14], s[15]);
  gl_TessLevelOuter[3] = collapsed(3, 7, 11, 15) ? poleU : segments(s[3], s[7], s[11], s[15]);
}
