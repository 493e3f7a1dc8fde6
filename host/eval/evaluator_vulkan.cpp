// The Vulkan backend of PatchEvaluator: one dispatch of shaders/eval.comp.glsl (bicubic) or
// eval_general.comp.glsl (general patches) per call, or of eval_vertices.comp.glsl for a bicubic
// set's mesh vertices; buffers kept and grown between calls.
// Each pipeline is made on first use, or on a worker thread from prepare() on.
#include <cstdint>  // before the generated SPIR-V array, which uses uint32_t

#include <memory>

#include "eval_comp.h"
#include "eval_general_comp.h"
#include "eval_vertices_comp.h"
#include "eval/evaluator.h"
#include "vk/background_pipeline.h"
#include "vk/buffer.h"

namespace tessera {
namespace {

// eval_vertices.comp's runs (layout.h, VertexEvalPush): consecutive queries on one patch, at
// most kVertexRunLength each; the mesh's queries come a patch at a time, so runs are mostly full.
std::vector<uint32_t> vertexRuns(const std::vector<gpu::EvalQuery>& queries) {
  std::vector<uint32_t> starts;
  starts.reserve(queries.size() / gpu::kVertexRunLength + 2);
  for (uint32_t i = 0; i < queries.size(); ++i)
    if (starts.empty() || i - starts.back() == gpu::kVertexRunLength ||
        queries[i].patchIndex != queries[starts.back()].patchIndex)
      starts.push_back(i);
  starts.push_back(uint32_t(queries.size()));
  return starts;
}

class VulkanEvaluator final : public PatchEvaluator {
 public:
  explicit VulkanEvaluator(vk::Context& context)
      : context_(context),
        bicubic_(context, {"eval.comp", kSpirv_eval_comp, sizeof(kSpirv_eval_comp), 3,
                           sizeof(gpu::EvalPush), {}}),
        general_(context, {"eval_general.comp", kSpirv_eval_general_comp,
                           sizeof(kSpirv_eval_general_comp), 4, sizeof(gpu::EvalPush), {}}),
        vertices_(context, {"eval_vertices.comp", kSpirv_eval_vertices_comp,
                            sizeof(kSpirv_eval_vertices_comp), 4, sizeof(gpu::VertexEvalPush),
                            {}}) {}

  std::string name() const override { return "vulkan:" + context_.info().name; }

  void prepare(const PatchSet& patches) override {
    (patches.isBicubic() ? bicubic_ : general_).start();
  }

  void prepareVertices(const PatchSet& patches) override {
    (patches.isBicubic() ? vertices_ : general_).start();
  }

  std::vector<gpu::EvalSample> evaluate(const PatchSet& patches,
                                        const std::vector<gpu::EvalQuery>& queries) override {
    return patches.isBicubic() ? evaluateBicubic(patches.bicubic(), queries)
                               : evaluateGeneral(patches.general(), queries);
  }

  std::vector<gpu::VertexSample> evaluateVertices(
      const PatchSet& patches, const std::vector<gpu::EvalQuery>& queries) override {
    if (!patches.isBicubic()) return PatchEvaluator::evaluateVertices(patches, queries);
    checkQueries(patches.bicubic().size(), queries);
    if (queries.empty()) return {};
    dispatchVertices(patches.bicubic(), queries);
    return readBack<gpu::VertexSample>(queries.size());
  }

  void useVertexSamples(const PatchSet& patches, std::vector<gpu::EvalQuery>&& queries,
                        const std::function<void(const gpu::VertexSample*)>& use) override {
    if (!patches.isBicubic() || queries.empty())
      return PatchEvaluator::useVertexSamples(patches, std::move(queries), use);
    checkQueries(patches.bicubic().size(), queries);
    dispatchVertices(patches.bicubic(), queries);
    std::vector<gpu::EvalQuery>().swap(queries);
    releaseHuge({&patches_, &queries_, &runs_});
    // Read in place (the buffer is mapped and coherent, as download() reads it); a huge one
    // goes after, also when `use` throws.
    const struct ReleaseAfterUse {
      VulkanEvaluator& evaluator;
      ~ReleaseAfterUse() { evaluator.releaseHuge({&evaluator.samples_}); }
    } release{*this};
    use(samples_.as<const gpu::VertexSample>());
  }

 private:
  // eval_vertices.comp run on `queries`, its results left in samples_.
  void dispatchVertices(const std::vector<gpu::BicubicPatch>& patches,
                        const std::vector<gpu::EvalQuery>& queries) {
    uploadBicubic(patches, queries.size() * sizeof(gpu::VertexSample));
    const std::vector<uint32_t> runStarts = vertexRuns(queries);
    vk::ensureCapacity(context_, runs_, runStarts.size() * sizeof(uint32_t), vk::BufferUse::Upload);
    runs_.upload(runStarts);
    const gpu::VertexEvalPush push{uint32_t(runStarts.size() - 1), kDegenerateEpsFp32, 0, 0};
    dispatch(vertices_.get(), {&patches_, &queries_, &samples_, &runs_}, queries, &push,
             push.runCount);
  }

  // The patches uploaded, and room for the queries and `resultBytes` of results.
  void uploadBicubic(const std::vector<gpu::BicubicPatch>& patches, size_t resultBytes) {
    vk::ensureCapacity(context_, patches_, patches.size() * sizeof(gpu::BicubicPatch),
                       vk::BufferUse::Upload);
    vk::ensureCapacity(context_, samples_, resultBytes, vk::BufferUse::Readback);
    patches_.upload(patches);
  }

  std::vector<gpu::EvalSample> evaluateBicubic(const std::vector<gpu::BicubicPatch>& patches,
                                               const std::vector<gpu::EvalQuery>& queries) {
    checkQueries(patches.size(), queries);
    if (queries.empty()) return {};
    uploadBicubic(patches, queries.size() * sizeof(gpu::EvalSample));
    const gpu::EvalPush push{uint32_t(queries.size()), kDegenerateEpsFp32, 0, 0};
    return run<gpu::EvalSample>(bicubic_.get(), {&patches_, &queries_, &samples_}, queries, &push,
                                push.queryCount);
  }

  std::vector<gpu::EvalSample> evaluateGeneral(const GeneralPatchSet& patches,
                                               const std::vector<gpu::EvalQuery>& queries) {
    checkQueries(patches.size(), queries);
    if (queries.empty()) return {};
    vk::ensureCapacity(context_, patches_, patches.size() * sizeof(gpu::GeneralPatch),
                       vk::BufferUse::Upload);
    vk::ensureCapacity(context_, points_, patches.points.size() * sizeof(gpu::vec4),
                       vk::BufferUse::Upload);
    vk::ensureCapacity(context_, samples_, queries.size() * sizeof(gpu::EvalSample),
                       vk::BufferUse::Readback);
    patches_.upload(patches.patches);
    points_.upload(patches.points);
    const gpu::EvalPush push{uint32_t(queries.size()), kDegenerateEpsFp32, 0, 0};
    return run<gpu::EvalSample>(general_.get(), {&patches_, &queries_, &samples_, &points_},
                                queries, &push, push.queryCount);
  }

  // Uploads the queries, dispatches `invocations` and reads back one result per query.
  template <typename Sample>
  std::vector<Sample> run(vk::ComputePipeline& pipeline,
                          std::initializer_list<const vk::Buffer*> buffers,
                          const std::vector<gpu::EvalQuery>& queries, const void* push,
                          uint32_t invocations) {
    dispatch(pipeline, buffers, queries, push, invocations);
    return readBack<Sample>(queries.size());
  }

  // Uploads the queries and dispatches `invocations`; the results are in samples_ after.
  void dispatch(vk::ComputePipeline& pipeline, std::initializer_list<const vk::Buffer*> buffers,
                const std::vector<gpu::EvalQuery>& queries, const void* push,
                uint32_t invocations) {
    vk::ensureCapacity(context_, queries_, queries.size() * sizeof(gpu::EvalQuery),
                       vk::BufferUse::Upload);
    queries_.upload(queries);
    context_.submitAndWait([&](VkCommandBuffer cmd) {
      pipeline.dispatch(cmd, buffers, push, invocations);
      vk::computeToHostBarrier(context_, cmd);
    });
  }

  template <typename Sample>
  std::vector<Sample> readBack(size_t count) {
    std::vector<Sample> out;
    samples_.download(out, count);
    releaseHugeBuffers();
    return out;
  }

  // The buffers are kept from call to call, so that repeated evaluations do not allocate, up
  // to kKeptBufferBytes each. A larger one is freed after its call instead of sitting beside
  // the mesh its results become: a 10⁶-patch sheet's patches, queries and samples are
  // ~0.45 GiB, host memory on lavapipe (bench/HISTORY.md, "The largest scene's peak memory").
  static constexpr VkDeviceSize kKeptBufferBytes = VkDeviceSize(64) << 20;
  void releaseHugeBuffers() { releaseHuge({&points_, &patches_, &queries_, &samples_, &runs_}); }
  static void releaseHuge(std::initializer_list<vk::Buffer*> buffers) {
    for (vk::Buffer* buffer : buffers)
      if (buffer->size() > kKeptBufferBytes) *buffer = vk::Buffer();
  }

  vk::Context& context_;
  vk::BackgroundPipeline bicubic_;
  vk::BackgroundPipeline general_;
  vk::BackgroundPipeline vertices_;
  vk::Buffer points_;
  vk::Buffer patches_;
  vk::Buffer queries_;
  vk::Buffer samples_;
  vk::Buffer runs_;
};

}  // namespace

std::unique_ptr<PatchEvaluator> makeVulkanEvaluator(vk::Context& context) {
  return std::make_unique<VulkanEvaluator>(context);
}

}  // namespace tessera
