#version 450
// The tessellation-shader peer (bench case 6): control points straight from a storage buffer
// (BicubicPatch.cp, 16 per patch), world coordinates; the tessellation stages do the rest.
#extension GL_GOOGLE_include_directive : require
#include "layout.h"

layout(std430, binding = 0) readonly buffer Patches { BicubicPatch patches[]; };

void main() {
  gl_Position = vec4(patches[gl_VertexIndex / 16].cp[gl_VertexIndex % 16].xyz, 1.0);
}
