// The fp32 mirror of shaders/trim_classify.comp.glsl: the same source text
// (shaders/lib/trim_classify.h) compiled as C++ with -ffp-contract=off, so on lavapipe it
// agrees with the shader bit for bit.
#include <algorithm>

#include "common/glsl_builtins.h"
#include "common/parallel_for.h"
#include "trim/trim_classifier.h"

namespace tessera {
namespace mirror::glsl {
namespace {

#include "shaders/lib/shared_glsl_cpp.h"

// The shader's storage buffers, as members of the same names, so that the shared text reads
// them unchanged.
struct TrimKernel {
  const TrimFace* faces;
  const TrimPiece* pieces;
  const vec4* segments;
#include "shaders/lib/trim_classify.h"
};

}  // namespace
}  // namespace mirror::glsl

namespace {

class MirrorTrimClassifier final : public TrimClassifier {
 public:
  std::string name() const override { return "mirror (fp32)"; }
  std::vector<uint32_t> classify(const TrimSet& set,
                                 const std::vector<gpu::TrimQuery>& queries) override {
    validateTrimQueries(set, queries);
    mirror::glsl::TrimKernel kernel{set.faces.data(), set.pieces.data(),
                                          set.segments.data()};
    std::vector<uint32_t> out(queries.size());
    // On all cores, in chunks from a shared counter: a node costs its face's segment count.
    // At least 256 nodes a thread, as the node classifier: fewer are not worth a thread start.
    const auto threads =
        unsigned(std::min<size_t>((queries.size() + 255) / 256, resolveThreadCount(0)));
    parallelForChunks(queries.size(), 64, std::max(1u, threads), [&](size_t begin, size_t end) {
      for (size_t i = begin; i < end; ++i) out[i] = kernel.classifyTrimNode(queries[i]);
    });
    return out;
  }
};

}  // namespace

std::unique_ptr<TrimClassifier> makeMirrorTrimClassifier() {
  return std::make_unique<MirrorTrimClassifier>();
}

}  // namespace tessera
