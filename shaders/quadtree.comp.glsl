#version 450
// Classifies one frontier level of the quad-tree: one invocation per node finds the split
// point (rule B, C or D: specialization constant 0) and decides leaf or split, or
// by rule T its proven deviation bound (lib/tolerance_bound.h) against δ. The arithmetic
// lives in lib/quadtree_classify.h, shared with the fp32 mirror.
#extension GL_GOOGLE_include_directive : require
#include "layout.h"
#include "lib/shared_glsl_cpp.h"
#include "lib/bicubic_eval.h"
#include "lib/tolerance_bound.h"
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
