#version 450
// Draws an un-indexed triangle list (host/render/offscreen_vulkan.cpp): every triangle has its own three
// vertices, so each can carry its corner number (the barycentric coordinate for the wireframe)
// and its triangle's palette value without a geometry shader, which lavapipe lacks.
#extension GL_GOOGLE_include_directive : require
#include "layout.h"

layout(location = 0) in vec4 positionValue;  // xyz world position, w = the triangle's value
layout(location = 1) in vec4 normalCorner;   // xyz vertex normal, w = corner 0, 1 or 2

layout(push_constant) uniform Push { MeshDrawPush pc; };

layout(location = 0) out vec3 worldPosition;
layout(location = 1) out vec3 worldNormal;
layout(location = 2) out vec3 barycentric;
layout(location = 3) flat out float triangleValue;

void main() {
  mat4 viewProjection =
      mat4(pc.viewProjection[0], pc.viewProjection[1], pc.viewProjection[2], pc.viewProjection[3]);
  gl_Position = viewProjection * vec4(positionValue.xyz, 1.0);
  worldPosition = positionValue.xyz;
  worldNormal = normalCorner.xyz;
  int corner = int(normalCorner.w);
  barycentric = vec3(corner == 0 ? 1.0 : 0.0, corner == 1 ? 1.0 : 0.0, corner == 2 ? 1.0 : 0.0);
  triangleValue = positionValue.w;
}
