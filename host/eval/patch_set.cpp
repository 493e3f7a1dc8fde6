#include "eval/patch_set.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "eval/evaluator.h"

namespace tessera {

PatchSet::PatchSet(std::vector<gpu::BicubicPatch> bicubic)
    : kind_(Kind::Bicubic), bicubic_(std::move(bicubic)) {}

PatchSet::PatchSet(GeneralPatchSet general) : kind_(Kind::General), general_(std::move(general)) {}

const std::vector<gpu::BicubicPatch>& PatchSet::bicubic() const {
  if (!isBicubic()) throw std::logic_error("PatchSet::bicubic() on a general patch set");
  return bicubic_;
}

const GeneralPatchSet& PatchSet::general() const {
  if (isBicubic()) throw std::logic_error("PatchSet::general() on a bicubic patch set");
  return general_;
}

size_t PatchSet::bufferBytes(size_t first, size_t last) const {
  if (isBicubic()) return (last - first) * sizeof(gpu::BicubicPatch);
  size_t points = 0;
  for (size_t p = first; p < last; ++p)
    points += size_t(general_.patches[p].degreeU + 1) * size_t(general_.patches[p].degreeV + 1);
  return std::max((last - first) * sizeof(gpu::GeneralPatch), points * sizeof(gpu::vec4));
}

PatchSet PatchSet::subset(size_t first, size_t last) const {
  if (isBicubic())
    return PatchSet(std::vector<gpu::BicubicPatch>(bicubic_.begin() + long(first),
                                                   bicubic_.begin() + long(last)));
  GeneralPatchSet subset;
  for (size_t p = first; p < last; ++p) {
    gpu::GeneralPatch patch = general_.patches[p];
    const size_t count = size_t(patch.degreeU + 1) * size_t(patch.degreeV + 1);
    const auto begin = general_.points.begin() + long(patch.firstPoint);
    patch.firstPoint = uint32_t(subset.points.size());
    subset.points.insert(subset.points.end(), begin, begin + long(count));
    subset.patches.push_back(patch);
  }
  return PatchSet(std::move(subset));
}

PatchSet toPatchSet(const std::vector<BezierPatch>& patches) {
  if (std::all_of(patches.begin(), patches.end(), isBicubicPolynomial))
    return PatchSet(toGpuPatches(patches));
  return PatchSet(toGeneralPatchSet(patches));
}

}  // namespace tessera
