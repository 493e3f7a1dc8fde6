#version 450
// The capture pipeline's geometry stage (TessShaderPeer::captureFrame): records every triangle
// the tessellator made (world corners, their (u, v), the patch) in a storage buffer, so that
// the host can measure the peer's screen-space error as it measures Tessera's, and passes the
// triangle on unchanged to be drawn. Past the buffer's capacity triangles are only counted.
#extension GL_GOOGLE_include_directive : require
#include "layout.h"

layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;
layout(location = 0) in vec3 normalIn[];
layout(location = 1) in vec3 world[];
layout(location = 2) in vec2 uv[];
layout(location = 3) flat in uint patchIndex[];
layout(location = 0) out vec3 normal;

// The capture draws at most 256 patches a draw (TessShaderPeer::captureFrame): lavapipe's
// gl_PrimitiveID wraps at 256 within one draw. The draw's first patch comes from here.
layout(push_constant) uniform CapturePush { layout(offset = 96) uint patchBase; } capture;
layout(std430, binding = 1) writeonly buffer Triangles { TessPeerTriangle triangles[]; };
layout(std430, binding = 2) buffer Count { uint count; };

void main() {
  uint slot = atomicAdd(count, 1u);
  if (slot < uint(triangles.length())) {
    for (int k = 0; k < 3; ++k) triangles[slot].corners[k] = vec4(world[k], 0.0);
    triangles[slot].uv01 = vec4(uv[0], uv[1]);
    triangles[slot].uv2 = uv[2];
    triangles[slot].patchIndex = capture.patchBase + patchIndex[0];
    triangles[slot].pad = 0u;
  }
  for (int k = 0; k < 3; ++k) {
    gl_Position = gl_in[k].gl_Position;
    normal = normalIn[k];
    EmitVertex();
  }
  EndPrimitive();
}
