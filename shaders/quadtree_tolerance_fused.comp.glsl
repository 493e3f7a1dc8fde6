#version 450
// Rule T on bicubic patches in one dispatch a level: quadtree_tolerance_nets.comp.glsl's and
// quadtree_tolerance.comp.glsl's work in one invocation, the mirror's bicubicSecondBounds
// itself, so the decisions are bit-identical to the two dispatches'. Saves a dispatch and a
// barrier a level (lavapipe: a fixed cost each), but its one pipeline compiles on one thread
// where the two compile side by side: the classifier builds it in the background once a second
// tree asks for rule T, and uses it when ready (host/quadtree/classifier_vulkan.cpp). Unrolled
// at build time like the two (TESSERA_THRICE_OPTIMIZED_SHADERS): unoptimized, lavapipe unrolls
// the loops itself and the build took ~210-250 ms of a worker's CPU (bench/HISTORY.md).
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_control_flow_attributes : require
#include "lib/tolerance_bicubic_shader.glsl"  // bindings 0-1, push constants

layout(std430, binding = 2) writeonly buffer Decisions { NodeDecision decisions[]; };

void main() {
  uint index = linearInvocationIndex();
  if (index >= pc.nodeCount) return;
  QuadNode node = fetchNode(index);
  ToleranceTerms terms = bicubicSecondBounds(fetchPatch(node.patchIndex), node.rect);
  decisions[index] = toleranceDecision(terms, node, pc);
}
