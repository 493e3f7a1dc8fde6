// Division counts for many rational patches at once: the fp32 `split` method on Vulkan
// (shaders/division_count.comp.glsl) and its bit-exact C++ mirror, behind one packing step.
// The double reference is patchDivisions (host/division/count.h); parity band:
// docs/rational_division.md.
#pragma once
#include <memory>
#include <vector>

#include "division/count.h"
#include "geometry/patch.h"
#include "shaders/layout.h"

namespace tessera {
namespace vk {
class Context;
}

// The patches as the shader reads them: headers and one array of homogeneous points (fp32).
// Throws std::invalid_argument naming the patch for a degree outside 1..7, a wrong point
// count, a non-finite coordinate or all weights zero (validateDivisionInput).
struct DivisionBatch {
  std::vector<gpu::DivisionPatch> patches;
  std::vector<gpu::vec4> points;
};
DivisionBatch packDivisionBatch(const std::vector<RationalBezierPatch>& patches);
// Appends curves as patches of degree (K, 0): the shader's v-loops then run once and its
// (i, j) pair loop over (K+1)² points instead of a patch's (K+1)²(M+1)², and the result's nu is
// the curve's count (curveDivisions), nv = 1. Same validation, naming the curve.
void appendDivisionCurves(DivisionBatch& batch, const std::vector<RationalBezierCurve>& curves);

gpu::DivisionPush divisionPush(const DivisionOptions& options, size_t patchCount);

class DivisionCounter {
 public:
  virtual ~DivisionCounter() = default;
  virtual std::vector<gpu::DivisionResult> count(const DivisionBatch& batch,
                                                 const DivisionOptions& options) = 0;
};

std::unique_ptr<DivisionCounter> makeMirrorDivisionCounter();  // fp32, the shader's twin
std::unique_ptr<DivisionCounter> makeVulkanDivisionCounter(vk::Context& context);

}  // namespace tessera
