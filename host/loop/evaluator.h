// Applying Loop stencil tables behind one interface, so tests and tools can swap the backend
// (OpenSubdiv's Osd evaluators): the CPU in double (the reference), the fp32 mirror (bit-exact
// twin of the shader on lavapipe) and Vulkan. Each evaluator is built for one table and one row
// width and keeps what it uploaded; apply() then refines new control data (animation, fitting).
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "loop/stencils.h"

namespace tessera {
namespace vk {
class Context;
}

class StencilEvaluator {
 public:
  virtual ~StencilEvaluator() = default;
  virtual std::string name() const = 0;
  // rows holds rowCount × width floats: the first sourceRows × width are read, the rest are
  // written (levels, limit, tangents: see LoopStencils for where each starts).
  virtual void apply(std::vector<float>& rows) = 0;
  // Device time of the last apply in seconds where measured (Vulkan timestamps, when
  // VulkanStencilOptions::timeGpu asks), else 0.
  virtual double lastDeviceSeconds() const { return 0.0; }
};

// Double arithmetic, rows rounded to float at the end.
std::unique_ptr<StencilEvaluator> makeReferenceStencilEvaluator(const StencilTable& table,
                                                                uint32_t width);
std::unique_ptr<StencilEvaluator> makeMirrorStencilEvaluator(const FloatStencilTable& table,
                                                             uint32_t width);
struct VulkanStencilOptions {
  // The most bytes one device array may take; 0: the device's own bound, the smaller of
  // maxStorageBufferRange and maxMemoryAllocationSize (lavapipe: 128 MiB). A table whose four
  // arrays (offsets, indices, weights, vertex data) all fit is uploaded once and applied in one
  // submission; a larger one goes in slices of rows that each fit (loop/stencil_slices.h), one
  // submission per slice, with the same result bit for bit. Smaller values force slicing (the
  // CLI's --batch-bytes; tests).
  uint64_t maxArrayBytes = 0;
  // GPU timestamps around each submission, for lastDeviceSeconds() (bench_loop): only when
  // asked, as on lavapipe each timestamp costs the rasterizer threads a hand-off.
  bool timeGpu = false;
};

// Builds on `context`'s device; the context must outlive the evaluator. The table is taken by
// value: a sliced evaluator keeps it on the host, so pass a temporary (moved, not copied) for a
// large one. Throws LimitError when one stencil alone does not fit the array bound.
std::unique_ptr<StencilEvaluator> makeVulkanStencilEvaluator(vk::Context& context,
                                                             FloatStencilTable table,
                                                             uint32_t width,
                                                             const VulkanStencilOptions& options = {});

// Throws std::invalid_argument unless rows.size() == rowCount × width.
void checkStencilRows(size_t rowCount, uint32_t width, size_t values);

}  // namespace tessera
