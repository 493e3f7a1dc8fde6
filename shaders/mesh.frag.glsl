#version 450
// Lambert plus ambient with the interpolated vertex normal, lit from both sides (the normal
// is turned towards the eye), base colour by MeshDrawPush.colourMode, and an optional
// wireframe drawn from the barycentric coordinates: a fragment within wireWidth pixels of an
// edge (distance measured with fwidth, so lines keep their width at any distance) is darkened.
#extension GL_GOOGLE_include_directive : require
#include "layout.h"

layout(push_constant) uniform Push { MeshDrawPush pc; };

layout(location = 0) in vec3 worldPosition;
layout(location = 1) in vec3 worldNormal;
layout(location = 2) in vec3 barycentric;
layout(location = 3) flat in float triangleValue;

layout(location = 0) out vec4 outColour;

const vec3 kDepthPalette[kDepthPaletteSize] = vec3[](TESSERA_DEPTH_PALETTE);
const vec3 kPatchPalette[kPatchPaletteSize] = vec3[](TESSERA_PATCH_PALETTE);
const vec3 kPorcelain = TESSERA_PORCELAIN;

// Shading happens in linear light; the attachment is UNORM holding sRGB-encoded values
// (what PNG viewers assume), so colours are decoded before and encoded after (gamma 2.2).
vec3 toLinear(vec3 c) { return pow(c, vec3(2.2)); }
vec3 toDisplay(vec3 c) { return pow(c, vec3(1.0 / 2.2)); }

vec3 baseColour() {
  int value = max(int(triangleValue + 0.5), 0);
  if (pc.colourMode == kColourDepth) return kDepthPalette[min(value, kDepthPaletteSize - 1)];
  if (pc.colourMode == kColourPatch) return kPatchPalette[value % kPatchPaletteSize];
  return kPorcelain;
}

void main() {
  if (pc.colourMode == kColourFlat) {  // overlay text and its backdrop: no light, no wires
    outColour = vec4(vec3(triangleValue), 1.0);
    return;
  }
  vec3 n = worldNormal;
  // Opposite vertex normals can cancel; the facet normal stands in for them.
  if (dot(n, n) < 1e-12) n = cross(dFdx(worldPosition), dFdy(worldPosition));
  n = normalize(n);
  vec3 toEye = pc.eye.xyz - worldPosition;
  if (dot(n, toEye) < 0.0) n = -n;
  float ambient = pc.light.w;
  float lambert = max(dot(n, pc.light.xyz), 0.0);
  vec3 colour = toLinear(baseColour()) * (ambient + (1.0 - ambient) * lambert);
  colour = toDisplay(colour);

  if (pc.wireframe != 0u) {
    vec3 pixels = barycentric / max(fwidth(barycentric), vec3(1e-6));  // distance to each edge
    float edgeDistance = min(pixels.x, min(pixels.y, pixels.z));
    float coverage = 1.0 - smoothstep(0.5 * pc.wireWidth - 0.5, 0.5 * pc.wireWidth + 0.5,
                                      edgeDistance);
    // Lines in a dark shade of the surface's own colour: where triangles crowd, the colour
    // (the level, the patch) still shows.
    colour = mix(colour, 0.25 * colour, coverage);
  }
  outColour = vec4(colour, 1.0);
}
