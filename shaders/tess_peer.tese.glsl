#version 450
// Evaluates the bicubic patch at the tessellator's (u, v): position to clip space, and the
// normal (Pu × Pv) for shading.
#extension GL_GOOGLE_include_directive : require
#include "layout.h"

layout(quads, equal_spacing, ccw) in;
layout(push_constant) uniform Push { TessPeerPush pc; };
layout(location = 0) out vec3 normal;

#include "lib/tess_peer_surface.glsl"

void main() {
  vec3 p;
  tessPeerSurface(gl_TessCoord.x, gl_TessCoord.y, p, normal);
  mat4 vp = mat4(pc.viewProjection[0], pc.viewProjection[1], pc.viewProjection[2],
                 pc.viewProjection[3]);
  gl_Position = vp * vec4(p, 1.0);
}
