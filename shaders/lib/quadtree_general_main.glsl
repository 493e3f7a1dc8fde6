// The body of quadtree_general.comp.glsl and its rule-B-only and rule-T-only variants
// (quadtree_general_midpoint.comp.glsl, quadtree_general_tolerance.comp.glsl): the
// quad-tree classification of general patches (degree 1..7 each way, polynomial or rational):
// one invocation per node finds the split point (rule: specialization constant 0) and decides
// leaf or split. The same lib/quadtree_classify.h, evaluating by lib/general_eval.h.
#include "layout.h"
#include "lib/shared_glsl_cpp.h"

layout(constant_id = 0) const uint kRule = kSplitRuleMidpoint;
layout(constant_id = 1) const int kSamples = 5;  // S of rule C/D (S×S samples per node)

layout(std430, binding = 0) readonly buffer Patches { GeneralPatch patches[]; };
layout(std430, binding = 1) readonly buffer Nodes { QuadNode nodes[]; };
layout(std430, binding = 2) writeonly buffer Decisions { NodeDecision decisions[]; };
layout(std430, binding = 3) readonly buffer Points { vec4 controlPoints[]; };

#include "lib/bicubic_eval.h"
#include "lib/general_eval.h"
#ifndef CLASSIFY_MIDPOINT_ONLY  // rule T
#include "lib/division_count.h"
#include "lib/tolerance_bound.h"
#include "lib/tolerance_net.h"
#include "lib/tolerance_general.h"
#define CLASSIFY_SECOND_BOUNDS generalSecondBounds
#endif
#define CLASSIFY_PATCH GeneralPatch
#define CLASSIFY_EVAL evalGeneral
#define CLASSIFY_SCALE generalScale
#include "lib/quadtree_classify.h"
#include "lib/dispatch.glsl"

layout(push_constant) uniform Push { ClassifyPush pc; };

void main() {
  uint index = linearInvocationIndex();
  if (index >= pc.nodeCount) return;
  QuadNode node = nodes[index];
  decisions[index] = classifyNode(patches[node.patchIndex], node, kRule, kSamples, pc);
}
