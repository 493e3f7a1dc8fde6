#version 450
// tess_peer.tese.glsl for the capture pipeline (TessShaderPeer::captureFrame): the same vertex,
// plus what the geometry stage records of it: the world position, the tessellator's (u, v) and
// the patch within the draw (gl_PrimitiveID; the geometry stage adds the draw's first patch).
#extension GL_GOOGLE_include_directive : require
#include "layout.h"

layout(quads, equal_spacing, ccw) in;
layout(push_constant) uniform Push { TessPeerPush pc; };
layout(location = 0) out vec3 normal;
layout(location = 1) out vec3 world;
layout(location = 2) out vec2 uv;
layout(location = 3) flat out uint patchIndex;

#include "lib/tess_peer_surface.glsl"

void main() {
  tessPeerSurface(gl_TessCoord.x, gl_TessCoord.y, world, normal);
  uv = gl_TessCoord.xy;
  patchIndex = uint(gl_PrimitiveID);
  mat4 vp = mat4(pc.viewProjection[0], pc.viewProjection[1], pc.viewProjection[2],
                 pc.viewProjection[3]);
  gl_Position = vp * vec4(world, 1.0);
}
