// The patches one tessellation works on, in the layout the backends read: either all bicubic
// polynomial (the BicubicPatch fast path) or general (degree 1..7, rational; general_patch.h).
// The classifier, evaluator and tree interfaces take this one type; each backend dispatches on
// kind() to its own pipeline, so the fast path stays the fast path.
#pragma once
#include <cstddef>
#include <vector>

#include "geometry/general_patch.h"
#include "geometry/patch.h"
#include "shaders/layout.h"

namespace tessera {

class PatchSet {
 public:
  enum class Kind { Bicubic, General };

  PatchSet() = default;  // an empty bicubic set
  // Implicit, so a vector of bicubic patches or a general set can be passed where a set is
  // wanted (the patches are copied; move them in, or build the set once, on hot paths).
  PatchSet(std::vector<gpu::BicubicPatch> bicubic);  // NOLINT(google-explicit-constructor)
  PatchSet(GeneralPatchSet general);                 // NOLINT(google-explicit-constructor)

  Kind kind() const { return kind_; }
  bool isBicubic() const { return kind_ == Kind::Bicubic; }
  size_t size() const { return isBicubic() ? bicubic_.size() : general_.size(); }

  // The patches of one kind; throws std::logic_error when the set is of the other kind.
  const std::vector<gpu::BicubicPatch>& bicubic() const;
  const GeneralPatchSet& general() const;

  // Bytes of the largest array a backend uploads for patches [first, last): the BicubicPatch
  // array, or the larger of the GeneralPatch and control-point arrays.
  size_t bufferBytes(size_t first, size_t last) const;
  // Patches [first, last) as a set of their own (control points renumbered).
  PatchSet subset(size_t first, size_t last) const;

 private:
  Kind kind_ = Kind::Bicubic;
  std::vector<gpu::BicubicPatch> bicubic_;
  GeneralPatchSet general_;
};

// All bicubic polynomial → the fast path, else every patch as a general one (what
// tessellate() does). Throws std::invalid_argument as toGpuPatch / toGeneralPatchSet do.
PatchSet toPatchSet(const std::vector<BezierPatch>& patches);

}  // namespace tessera
