#version 450
// eval_vertices.comp.glsl for general patches: position and unit normal only (VertexSample),
// eval_general.comp's bits from first partials (the higher partials only at degenerate points,
// no κ). One invocation per run of consecutive queries on one patch (VertexEvalPush, layout.h):
// the patch's length scale, a pass over its control points, is taken once a run. The
// arithmetic lives in lib/general_vertex.h, shared with the fp32 mirror.
#extension GL_GOOGLE_include_directive : require
#include "layout.h"
#include "lib/shared_glsl_cpp.h"

layout(std430, binding = 0) readonly buffer Patches { GeneralPatch patches[]; };
layout(std430, binding = 1) readonly buffer Queries { EvalQuery queries[]; };
layout(std430, binding = 2) writeonly buffer Vertices { VertexSample vertices[]; };
layout(std430, binding = 3) readonly buffer Runs { uint runStarts[]; };
layout(std430, binding = 4) readonly buffer Points { vec4 controlPoints[]; };

#include "lib/bicubic_eval.h"
#include "lib/general_eval.h"
#include "lib/general_vertex.h"
#include "lib/dispatch.glsl"

layout(push_constant) uniform Push { VertexEvalPush pc; };

void main() {
  uint run = linearInvocationIndex();
  if (run >= pc.runCount) return;
  uint first = runStarts[run];
  uint end = runStarts[run + 1u];
  GeneralPatch gp = patches[queries[first].patchIndex];
  float tol = generalTolerance(gp, pc.degenerateEps);
  for (uint i = first; i < end; ++i) {
    EvalQuery q = queries[i];
    vertices[i] = generalVertex(gp, q.u, q.v, tol);
  }
}
