// The double reference of the trim classification (trim_classifier.h): the rule of
// shaders/lib/trim_classify.h with no margin, on the double loops and the piece rectangles
// in double; the specification the fp32 mirror and the GPU are checked against.
#include <algorithm>

#include "trim/trim_classifier.h"

namespace tessera {
namespace {

double orient(const glm::dvec4& s, double px, double py) {
  return (s.z - s.x) * (py - s.y) - (s.w - s.y) * (px - s.x);
}

// Separating axes: the bounding boxes overlap and the corners are not strictly on one side.
bool segmentMeetsBox(const glm::dvec4& s, const glm::dvec4& box) {
  if (std::max(s.x, s.z) < box.x || std::min(s.x, s.z) > box.z || std::max(s.y, s.w) < box.y ||
      std::min(s.y, s.w) > box.w)
    return false;
  int positive = 0, negative = 0;
  for (int k = 0; k < 4; ++k) {
    const double side = orient(s, (k & 1) ? box.z : box.x, (k & 2) ? box.w : box.y);
    if (side > 0) ++positive;
    else if (side < 0) ++negative;
    else return true;
  }
  return positive > 0 && negative > 0;
}

class ReferenceTrimClassifier final : public TrimClassifier {
 public:
  std::string name() const override { return "reference (double)"; }
  std::vector<uint32_t> classify(const TrimSet& set,
                                 const std::vector<gpu::TrimQuery>& queries) override {
    validateTrimQueries(set, queries);
    std::vector<uint32_t> out(queries.size());
    for (size_t i = 0; i < queries.size(); ++i) out[i] = classifyTrimNodeReference(set, queries[i]);
    return out;
  }
};

}  // namespace

uint32_t classifyTrimNodeReference(const TrimSet& set, const gpu::TrimQuery& query, double grow) {
  const gpu::TrimFace& face = set.faces[set.pieces[query.piece].face];
  if (face.segmentCount == 0) return gpu::kTrimInside;
  const glm::dvec4& piece = set.pieceRectsDouble[query.piece];
  const glm::dvec4 node(query.rect);
  const glm::dvec4 rect(piece.x + node.x * (piece.z - piece.x), piece.y + node.y * (piece.w - piece.y),
                        piece.x + node.z * (piece.z - piece.x), piece.y + node.w * (piece.w - piece.y));
  const glm::dvec4 grown(rect.x - grow, rect.y - grow, rect.z + grow, rect.w + grow);
  const double cu = 0.5 * (rect.x + rect.z), cv = 0.5 * (rect.y + rect.w);
  bool inside = false;
  for (uint32_t k = 0; k < face.segmentCount; ++k) {
    const glm::dvec4& s = set.segmentsDouble[face.firstSegment + k];
    if (segmentMeetsBox(s, grown)) return gpu::kTrimCrossing;
    if ((s.y > cv) != (s.w > cv) && (orient(s, cu, cv) > 0) == (s.w > s.y)) inside = !inside;
  }
  return inside ? gpu::kTrimInside : gpu::kTrimOutside;
}

std::unique_ptr<TrimClassifier> makeReferenceTrimClassifier() {
  return std::make_unique<ReferenceTrimClassifier>();
}

}  // namespace tessera
