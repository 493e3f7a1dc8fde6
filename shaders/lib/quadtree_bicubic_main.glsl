// The body of quadtree.comp.glsl and its rule-B-only variant (quadtree_midpoint.comp.glsl):
// one invocation per node of a frontier level of bicubic patches finds the split point (rule:
// specialization constant 0) and decides leaf or split, or by rule T its proven deviation bound
// (lib/tolerance_bound.h) against δ. The arithmetic lives in lib/quadtree_classify.h, shared with the fp32 mirror.
#include "layout.h"
#include "lib/shared_glsl_cpp.h"
#include "lib/bicubic_eval.h"
#ifndef CLASSIFY_MIDPOINT_ONLY
#define TOLERANCE_ROW_ORDER 4  // bicubic rows: lib/tolerance_bound.h
#include "lib/tolerance_bound.h"  // rule T
#endif
#include "lib/quadtree_classify.h"
#include "lib/dispatch.glsl"

layout(constant_id = 0) const uint kRule = kSplitRuleMidpoint;
layout(constant_id = 1) const int kSamples = 5;  // S of rule C/D (S×S samples per node)

layout(std430, binding = 0) readonly buffer Patches { BicubicPatch patches[]; };
layout(std430, binding = 1) readonly buffer Nodes { QuadNode nodes[]; };
layout(std430, binding = 2) writeonly buffer Decisions { NodeDecision decisions[]; };

layout(push_constant) uniform Push { ClassifyPush pc; };

void main() {
  uint index = linearInvocationIndex();
  if (index >= pc.nodeCount) return;
  QuadNode node = nodes[index];
  decisions[index] = classifyNode(patches[node.patchIndex], node, kRule, kSamples, pc);
}
