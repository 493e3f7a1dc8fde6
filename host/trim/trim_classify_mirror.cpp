// The fp32 mirror of shaders/trim_classify.comp.glsl: the same source text
// (shaders/lib/trim_classify.h) compiled as C++ with -ffp-contract=off, so on lavapipe it
// agrees with the shader bit for bit.
#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>

#include "common/glsl_builtins.h"
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

// One face's segments for the nodes of one classify() call, so that a node reads only those
// that can matter to it: each node's answer depends only on the segments that meet its grown
// rectangle's v range [g_v0, g_v1] or cross the v of its centre (classifyTrimNode: the others
// fail the segment-box test's first comparisons and the ray's half-open v test), and not on
// their order (any one meeting the box makes it crossing; else the parity of the crossings).
// So the node runs the shared text on a face of those segments alone, and decides as on the
// whole face bit for bit. Segments short in v (at most 1/64 of the face's v range) are sorted by
// their lower v, so those a v range can reach are one run; the long ones every node reads.
class FaceSegmentIndex {
 public:
  FaceSegmentIndex(const gpu::TrimFace& face, const gpu::vec4* segments) : face_(face) {
    const float range = face.box.w - face.box.y;
    std::vector<std::pair<float, gpu::vec4>> shortOnes;
    for (uint32_t k = 0; k < face.segmentCount; ++k) {
      const gpu::vec4 s = segments[face.firstSegment + k];
      const float lo = std::min(s.y, s.w), hi = std::max(s.y, s.w);
      if (double(hi) - double(lo) <= double(range) / 64) {
        shortOnes.push_back({lo, s});
        longestShort_ = std::max(longestShort_, double(hi) - double(lo));
      } else {
        long_.push_back(s);
      }
    }
    std::sort(shortOnes.begin(), shortOnes.end(),
              [](const auto& a, const auto& b) { return a.first < b.first; });
    for (const auto& [lo, s] : shortOnes) {
      lows_.push_back(lo);
      short_.push_back(s);
    }
  }

  // The segments whose v extent meets [lo, hi], every one once (and a few more), into `out`.
  void candidates(float lo, float hi, std::vector<gpu::vec4>& out) const {
    out = long_;
    // A short segment reaching lo starts at lo − its extent or above; a margin for the
    // rounding of that difference in double keeps every such segment in the run.
    const double from = double(lo) - longestShort_ - (std::abs(double(lo)) + longestShort_) * 1e-9;
    const auto first = std::lower_bound(lows_.begin(), lows_.end(), from,
                                        [](float v, double x) { return double(v) < x; });
    const auto last = std::upper_bound(lows_.begin(), lows_.end(), hi);
    for (auto it = first; it < last; ++it) out.push_back(short_[size_t(it - lows_.begin())]);
  }

  const gpu::TrimFace& face() const { return face_; }

 private:
  gpu::TrimFace face_;
  std::vector<float> lows_;           // the short segments' lower v, ascending
  std::vector<gpu::vec4> short_;      // in that order
  std::vector<gpu::vec4> long_;
  double longestShort_ = 0;
};

// Faces with fewer segments, or fewer nodes in a call, are scanned whole: sorting would cost
// more than it saves.
constexpr uint32_t kIndexedSegments = 32;
constexpr size_t kIndexedNodes = 16;

class MirrorTrimClassifier final : public TrimClassifier {
 public:
  std::string name() const override { return "mirror (fp32)"; }
  std::vector<uint32_t> classify(const TrimSet& set,
                                 const std::vector<gpu::TrimQuery>& queries) override {
    validateTrimQueries(set, queries);
    mirror::glsl::TrimKernel kernel{set.faces.data(), set.pieces.data(),
                                          set.segments.data()};
    std::vector<size_t> nodesOfFace(set.faces.size(), 0);
    for (const gpu::TrimQuery& q : queries) ++nodesOfFace[set.pieces[q.piece].face];
    std::vector<std::unique_ptr<FaceSegmentIndex>> indices(set.faces.size());
    for (size_t f = 0; f < set.faces.size(); ++f)
      if (set.faces[f].segmentCount >= kIndexedSegments && nodesOfFace[f] >= kIndexedNodes)
        indices[f] = std::make_unique<FaceSegmentIndex>(set.faces[f], set.segments.data());
    std::vector<uint32_t> out(queries.size());
    for (size_t i = 0; i < queries.size(); ++i) {
      const gpu::TrimPiece& piece = set.pieces[queries[i].piece];
      const FaceSegmentIndex* index = indices[piece.face].get();
      out[i] = index ? classifyIndexed(kernel, *index, piece, queries[i])
                     : kernel.classifyTrimNode(queries[i]);
    }
    return out;
  }

 private:
  // classifyTrimNode on a face of the segments that can matter to the node (FaceSegmentIndex).
  uint32_t classifyIndexed(mirror::glsl::TrimKernel& kernel, const FaceSegmentIndex& index,
                           const gpu::TrimPiece& piece, const gpu::TrimQuery& query) {
    const gpu::TrimFace& face = index.face();
    // The node's v range as classifyTrimNode finds it: the grown rectangle and the centre.
    const gpu::vec4 rect = kernel.trimFaceRect(piece.rect, query.rect);
    const float grownLo = rect.y - face.margin, grownHi = rect.w + face.margin;
    const float sumV = rect.y + rect.w;
    const float centre = sumV * 0.5f;
    if (!std::isfinite(grownLo) || !std::isfinite(grownHi) || !std::isfinite(centre))
      return kernel.classifyTrimNode(query);
    index.candidates(std::min(grownLo, centre), std::max(grownHi, centre), candidates_);
    // No segment can matter: the whole face's loop finds none meeting the box and no crossing.
    if (candidates_.empty()) return gpu::kTrimOutside;
    gpu::TrimFace local = face;
    local.firstSegment = 0;
    local.segmentCount = uint32_t(candidates_.size());
    gpu::TrimPiece localPiece = piece;
    localPiece.face = 0;
    gpu::TrimQuery localQuery = query;
    localQuery.piece = 0;
    mirror::glsl::TrimKernel narrowed{&local, &localPiece, candidates_.data()};
    return narrowed.classifyTrimNode(localQuery);
  }

  std::vector<gpu::vec4> candidates_;
};

}  // namespace

std::unique_ptr<TrimClassifier> makeMirrorTrimClassifier() {
  return std::make_unique<MirrorTrimClassifier>();
}

}  // namespace tessera
