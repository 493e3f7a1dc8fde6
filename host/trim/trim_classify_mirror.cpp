// The fp32 mirror of shaders/trim_classify.comp.glsl: the same source text
// (shaders/lib/trim_classify.h) compiled as C++ with -ffp-contract=off, so on lavapipe it
// agrees with the shader bit for bit. Faces with many segments are read through their v bins
// (TrimFace::binCount, built once per set by packTrimSet), as the shader reads them.
#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>

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
  const uint* binWords;
#include "shaders/lib/trim_bin.h"
#include "shaders/lib/trim_classify.h"
};

}  // namespace
}  // namespace mirror::glsl

namespace {

// Queries a thread takes at a time: a node against a few binned segments is well under a
// microsecond, so fewer would be all hand-out.
constexpr size_t kQueriesPerTurn = 256;

class MirrorTrimClassifier final : public TrimClassifier {
 public:
  std::string name() const override { return "mirror (fp32)"; }
  std::vector<uint32_t> classify(const TrimSet& set,
                                 const std::vector<gpu::TrimQuery>& queries) override {
    validateTrimQueries(set, queries);
    mirror::glsl::TrimKernel kernel{set.faces.data(), set.pieces.data(),
                                          set.segments.data(), set.binWords.data()};
    std::vector<uint32_t> out(queries.size());
    // Each query's class is its own: on all cores where a level has enough nodes (on one, the
    // trim pass was 6% of the CPU tree's time on the IDF library).
    parallelForChunks(queries.size(), kQueriesPerTurn,
                      threadsForChunks(queries.size(), kQueriesPerTurn, 0u),
                      [&](size_t begin, size_t end) {
                        for (size_t i = begin; i < end; ++i)
                          out[i] = kernel.classifyTrimNode(queries[i]);
                      });
    return out;
  }
};

}  // namespace

std::unique_ptr<TrimClassifier> makeMirrorTrimClassifier() {
  return std::make_unique<MirrorTrimClassifier>();
}

}  // namespace tessera
