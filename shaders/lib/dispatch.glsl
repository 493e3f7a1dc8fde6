// Workgroup shape of every 1-D compute shader, and the flat invocation index. Dispatches wider
// than maxComputeWorkGroupCount[0] are folded into a 2-D grid of workgroups by
// vk::ComputePipeline::dispatch; linearInvocationIndex() unfolds it.
// Include after layout.h (for kLocalSize), before any use of the index.
layout(local_size_x = kLocalSize) in;

uint linearInvocationIndex() {
  return (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * kLocalSize +
         gl_LocalInvocationID.x;
}
