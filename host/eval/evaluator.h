// Point evaluation of patches (bicubic, and general ones: general_patch.h) behind one
// interface, so tests and tools can swap the backend (as OpenSubdiv's Osd evaluators do):
// the fp32 mirror (CPU, bit-exact twin of the shader on lavapipe) and Vulkan. The double-precision kernel (bezier.h, surface_normal.h,
// curvature.h) is the accuracy reference and is used directly.
#pragma once
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "geometry/general_patch.h"
#include "geometry/patch.h"
#include "eval/patch_set.h"
#include "shaders/layout.h"

namespace tessera {
namespace vk {
class Context;
}

// ε of docs/conventions.md for fp32 evaluation.
constexpr float kDegenerateEpsFp32 = 1e-5f;

class PatchEvaluator {
 public:
  virtual ~PatchEvaluator() = default;
  virtual std::string name() const = 0;
  // One sample per query, in query order. Query patch indices must be < patches.size().
  // Bicubic sets take the BicubicPatch kernel, general ones (degree 1..7, polynomial or
  // rational; general_patch.h) the general kernel.
  virtual std::vector<gpu::EvalSample> evaluate(const PatchSet& patches,
                                                const std::vector<gpu::EvalQuery>& queries) = 0;
  // What a mesh keeps of each sample: the same position and normal bits as evaluate()'s, for
  // less work where a backend has a variant for it (bicubic sets: eval_vertices.comp.glsl and
  // its mirror; general sets on the mirror: shaders/lib/general_vertex.h); elsewhere
  // evaluate()'s samples, cut down.
  virtual std::vector<gpu::VertexSample> evaluateVertices(
      const PatchSet& patches, const std::vector<gpu::EvalQuery>& queries);
  // evaluateVertices' samples, handed to `use` (one per query, valid during the call) where
  // the backend holds them: Vulkan's mapped readback buffer, so a mesh copies what it keeps
  // straight out of it instead of through a vector allocated, filled and freed per call
  // (1.1 MiB at the tea set's 10⁻³). The queries are freed before `use` runs, as they were
  // before a mesh was assembled (a huge mesh's are ~64 MiB). No queries: `use(nullptr)`, and
  // the backend is not called.
  virtual void useVertexSamples(const PatchSet& patches, std::vector<gpu::EvalQuery>&& queries,
                                const std::function<void(const gpu::VertexSample*)>& use);
  // Announces that evaluate() (prepare) or evaluateVertices() / useVertexSamples()
  // (prepareVertices) will be called
  // for patches like these, so a backend may start its one-time setup (Vulkan: building the
  // pipeline on a worker thread) while the caller builds the quad-tree. Optional: both
  // evaluations work without it.
  virtual void prepare(const PatchSet& patches) { (void)patches; }
  virtual void prepareVertices(const PatchSet& patches) { prepare(patches); }
};

// The position and normal of each sample (evaluateVertices' default).
std::vector<gpu::VertexSample> vertexSamples(const std::vector<gpu::EvalSample>& samples);

std::unique_ptr<PatchEvaluator> makeMirrorEvaluator();
// Evaluates on `context`'s device; the context must outlive the evaluator.
std::unique_ptr<PatchEvaluator> makeVulkanEvaluator(vk::Context& context);

// Converts a degree-3×3 patch to the GPU layout (positions rounded to float).
// Throws std::invalid_argument for any other degree.
gpu::BicubicPatch toGpuPatch(const BezierPatch& patch);
std::vector<gpu::BicubicPatch> toGpuPatches(const std::vector<BezierPatch>& patches);

// Throws std::out_of_range naming the first query whose patch index is out of range.
void checkQueries(size_t patchCount, const std::vector<gpu::EvalQuery>& queries);

}  // namespace tessera
