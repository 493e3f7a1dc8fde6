#include "eval/evaluator.h"

#include <stdexcept>
#include <string>

#include "common/parallel_for.h"
#include "eval/detail/bicubic_mirror.h"
#include "eval/general_mirror.h"

namespace tessera {

gpu::BicubicPatch toGpuPatch(const BezierPatch& patch) {
  if (patch.degreeU != 3 || patch.degreeV != 3 || patch.cp.size() != 16)
    throw std::invalid_argument("toGpuPatch: expected a bicubic patch, got degree " +
                                std::to_string(patch.degreeU) + "x" +
                                std::to_string(patch.degreeV));
  gpu::BicubicPatch out{};
  for (int k = 0; k < 16; ++k) out.cp[k] = gpu::vec4(glm::vec3(patch.cp[k]), 1.0f);
  return out;
}

std::vector<gpu::BicubicPatch> toGpuPatches(const std::vector<BezierPatch>& patches) {
  std::vector<gpu::BicubicPatch> out;
  out.reserve(patches.size());
  for (const BezierPatch& p : patches) out.push_back(toGpuPatch(p));
  return out;
}

void checkQueries(size_t patchCount, const std::vector<gpu::EvalQuery>& queries) {
  for (size_t i = 0; i < queries.size(); ++i)
    if (queries[i].patchIndex >= patchCount)
      throw std::out_of_range("query " + std::to_string(i) + " names patch " +
                              std::to_string(queries[i].patchIndex) + " of " +
                              std::to_string(patchCount));
}

std::vector<gpu::VertexSample> vertexSamples(const std::vector<gpu::EvalSample>& samples) {
  std::vector<gpu::VertexSample> out(samples.size());
  for (size_t i = 0; i < samples.size(); ++i)
    out[i] = {samples[i].position, gpu::vec4(glm::vec3(samples[i].normalKappa), 0.0f)};
  return out;
}

std::vector<gpu::VertexSample> PatchEvaluator::evaluateVertices(
    const PatchSet& patches, const std::vector<gpu::EvalQuery>& queries) {
  return vertexSamples(evaluate(patches, queries));
}

void PatchEvaluator::useVertexSamples(const PatchSet& patches,
                                      std::vector<gpu::EvalQuery>&& queries,
                                      const std::function<void(const gpu::VertexSample*)>& use) {
  if (queries.empty()) return use(nullptr);  // nothing to evaluate: no backend call
  const std::vector<gpu::VertexSample> samples = evaluateVertices(patches, queries);
  std::vector<gpu::EvalQuery>().swap(queries);
  use(samples.data());
}

namespace {

// The samples are independent: a large batch is evaluated on all cores, in chunks taken in
// turn (patches differ in cost only a little; the chunk keeps a thread's queries together).
// Each sample is the same function of its query on any thread, so the bits do not change.
// evaluateChunk(begin, end, out) writes the samples of queries [begin, end) to out[begin, end).
template <typename Sample, typename EvaluateChunk>
std::vector<Sample> evaluateChunks(const std::vector<gpu::EvalQuery>& queries,
                                   const EvaluateChunk& evaluateChunk) {
  constexpr size_t kChunk = 4096;  // below two chunks a thread costs more than it saves
  std::vector<Sample> out(queries.size());
  parallelForChunks(queries.size(), kChunk, queries.size() >= 2 * kChunk ? 0u : 1u,
                    [&](size_t begin, size_t end) { evaluateChunk(begin, end, out.data()); });
  return out;
}

template <typename Sample, typename EvaluateOne>
std::vector<Sample> evaluateAll(const std::vector<gpu::EvalQuery>& queries,
                                const EvaluateOne& evaluateOne) {
  return evaluateChunks<Sample>(queries, [&](size_t begin, size_t end, Sample* out) {
    for (size_t i = begin; i < end; ++i) out[i] = evaluateOne(queries[i]);
  });
}

// A mesh's vertices: its queries come a patch after another, so the patch's tolerance (ε·L²,
// a pass over its control points) is kept while the patch repeats. tolerance(patch) gives it,
// vertex(patch, u, v, tol) one vertex; `patches` is indexed by the queries' patchIndex.
template <typename Patch, typename Tolerance, typename Vertex>
std::vector<gpu::VertexSample> evaluateVerticesPatchByPatch(
    const std::vector<Patch>& patches, const std::vector<gpu::EvalQuery>& queries,
    const Tolerance& tolerance, const Vertex& vertex) {
  checkQueries(patches.size(), queries);
  return evaluateChunks<gpu::VertexSample>(
      queries, [&](size_t begin, size_t end, gpu::VertexSample* out) {
        uint32_t patchIndex = UINT32_MAX;  // the patch whose tolerance `tol` is
        float tol = 0.0f;
        for (size_t i = begin; i < end; ++i) {
          const gpu::EvalQuery& q = queries[i];
          const Patch& patch = patches[q.patchIndex];
          if (q.patchIndex != patchIndex) patchIndex = q.patchIndex, tol = tolerance(patch);
          out[i] = vertex(patch, q.u, q.v, tol);
        }
      });
}

class MirrorEvaluator final : public PatchEvaluator {
 public:
  std::string name() const override { return "cpu-fp32-mirror"; }
  std::vector<gpu::EvalSample> evaluate(const PatchSet& patches,
                                        const std::vector<gpu::EvalQuery>& queries) override {
    return patches.isBicubic() ? evaluateBicubic(patches.bicubic(), queries)
                               : evaluateGeneral(patches.general(), queries);
  }

  std::vector<gpu::VertexSample> evaluateVertices(
      const PatchSet& patches, const std::vector<gpu::EvalQuery>& queries) override {
    if (patches.isBicubic())
      return evaluateVerticesPatchByPatch(
          patches.bicubic(), queries,
          [](const gpu::BicubicPatch& patch) {
            return mirror::bicubicVertexTolerance(patch, kDegenerateEpsFp32);
          },
          [](const gpu::BicubicPatch& patch, float u, float v, float tol) {
            return mirror::bicubicVertex(patch, u, v, tol);
          });
    const gpu::vec4* points = patches.general().points.data();
    return evaluateVerticesPatchByPatch(
        patches.general().patches, queries,
        [points](const gpu::GeneralPatch& patch) {
          return mirror::generalVertexTolerance(patch, points, kDegenerateEpsFp32);
        },
        [points](const gpu::GeneralPatch& patch, float u, float v, float tol) {
          return mirror::evalGeneralVertex(patch, points, u, v, tol);
        });
  }

 private:
  std::vector<gpu::EvalSample> evaluateBicubic(const std::vector<gpu::BicubicPatch>& patches,
                                               const std::vector<gpu::EvalQuery>& queries) {
    checkQueries(patches.size(), queries);
    return evaluateAll<gpu::EvalSample>(queries, [&](const gpu::EvalQuery& q) {
      return mirror::evalBicubicSample(patches[q.patchIndex], q.u, q.v, kDegenerateEpsFp32);
    });
  }

  std::vector<gpu::EvalSample> evaluateGeneral(const GeneralPatchSet& patches,
                                               const std::vector<gpu::EvalQuery>& queries) {
    checkQueries(patches.size(), queries);
    return evaluateAll<gpu::EvalSample>(queries, [&](const gpu::EvalQuery& q) {
      return mirror::evalGeneralSample(patches.patches[q.patchIndex], patches.points.data(), q.u,
                                       q.v, kDegenerateEpsFp32);
    });
  }
};

}  // namespace

std::unique_ptr<PatchEvaluator> makeMirrorEvaluator() { return std::make_unique<MirrorEvaluator>(); }

}  // namespace tessera
