// Quad-tree nodes against trim loops (issue 17): each node rectangle of a face's Bézier piece
// is outside the face's material, inside it, or crossing a trim loop. One interface, three
// backends: the double reference (the specification), the fp32 mirror and Vulkan
// (shaders/trim_classify.comp.glsl), the last two one text (shaders/lib/trim_classify.h) and
// equal bit for bit on lavapipe. The rule and its fp32 margin: docs/trimmed_faces.md,
// "Classifying nodes against trim loops (GPU)".
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "shaders/layout.h"
#include "trim/trimmed_face.h"

namespace tessera {
namespace vk {
class Context;
}

// The faces' loops as segments and the pieces' rectangles, in the buffers' fp32 form and in
// double for the reference. Piece k is quad-tree patch k.
struct TrimSet {
  std::vector<gpu::TrimFace> faces;
  std::vector<gpu::TrimPiece> pieces;
  std::vector<gpu::vec4> segments;            // (a.u, a.v, b.u, b.v), fp32
  std::vector<uint32_t> binWords;             // the faces' v bins (gpu::TrimFace::firstBin)
  std::vector<glm::dvec4> segmentsDouble;     // the same segments in double
  std::vector<glm::dvec4> pieceRectsDouble;   // each piece's (u0, v0, u1, v1) in double
};

// One piece of a face as packTrimSet takes it: its face (index into the loops) and rectangle.
struct TrimPieceRect {
  uint32_t face = 0;
  glm::dvec4 rect{0.0, 0.0, 1.0, 1.0};  // u0, v0, u1, v1 in the face's (u, v), u0 < u1, v0 < v1
};

// The margin m of a face whose coordinates (segments and piece rectangles) are at most U in
// magnitude: 2⁻¹⁸·U, rounded up to fp32 (the derivation needs more than 17·2⁻²⁴·U).
float trimMargin(double scale);

// faceLoops[f] = face f's closed loops (point k joins k + 1, the last joins the first).
// Throws std::invalid_argument naming the face, loop and point for a non-finite or fp32-
// overflowing coordinate, and the piece for a bad face index or an empty or non-finite rectangle.
TrimSet packTrimSet(const std::vector<std::vector<std::vector<glm::dvec2>>>& faceLoops,
                    const std::vector<TrimPieceRect>& pieces);
// Every face's pieces in order, face after face (the patch order of the face's tree).
TrimSet packTrimSet(const TrimmedModel& model);

// Throws std::out_of_range naming the first query whose piece is not in `set`.
void validateTrimQueries(const TrimSet& set, const std::vector<gpu::TrimQuery>& queries);

// The double reference for one query, with the node rectangle grown by `grow` face units on
// every side (0: the rule itself; the tests grow it to bound the mirror's band).
uint32_t classifyTrimNodeReference(const TrimSet& set, const gpu::TrimQuery& query,
                                   double grow = 0.0);

class TrimClassifier {
 public:
  virtual ~TrimClassifier() = default;
  virtual std::string name() const = 0;
  // One gpu::kTrim* per query, in order. Throws as validateTrimQueries does.
  virtual std::vector<uint32_t> classify(const TrimSet& set,
                                         const std::vector<gpu::TrimQuery>& queries) = 0;
  // classify() in two halves, for a caller with other work to submit meanwhile (the trimmed
  // quad-tree's level classification): startClassify takes the queries (neither argument is
  // read after it returns), finishClassify returns what classify() would have. A device
  // backend submits at the start and waits at the finish; by default the start does it all.
  // Nothing else is called on the classifier between the two halves.
  virtual void startClassify(const TrimSet& set, const std::vector<gpu::TrimQuery>& queries) {
    started_ = classify(set, queries);
  }
  virtual std::vector<uint32_t> finishClassify() { return std::move(started_); }
  // Announces the set that the following startClassify calls pass, unchanged, until the next
  // beginSet or classify (the trimmed quad-tree's levels): a device backend uploads it here,
  // once, instead of at every level. The set must outlive those calls.
  virtual void beginSet(const TrimSet& /*set*/) {}

 private:
  std::vector<uint32_t> started_;
};

std::unique_ptr<TrimClassifier> makeReferenceTrimClassifier();  // double, the specification
std::unique_ptr<TrimClassifier> makeMirrorTrimClassifier();     // fp32, the shader's twin
std::unique_ptr<TrimClassifier> makeVulkanTrimClassifier(vk::Context& context);

}  // namespace tessera
