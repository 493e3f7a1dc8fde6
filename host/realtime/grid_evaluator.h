// Uniform P×P grids of bicubic patches (position + unit normal, 32 bytes a vertex) — the
// evaluation throughput case of bench/ and the bulk path for rule A. Three backends behind one
// interface: the fp32 mirror on one thread, the same on all cores, and Vulkan
// (shaders/grid_eval.comp.glsl), bit-identical to the mirror on lavapipe.
#pragma once
#include <memory>
#include <string>
#include <vector>

#include "shaders/layout.h"

namespace tessera {
namespace vk {
class Context;
}

class GridEvaluator {
 public:
  virtual ~GridEvaluator() = default;
  virtual std::string name() const = 0;
  // Evaluates every patch's P×P grid (P = pointsPerSide ≥ 2): vertex (i, j) of patch p at
  // index (p·P + i)·P + j, u = i/(P−1), v = j/(P−1). The result is owned by the evaluator and
  // valid until the next call; on Vulkan it is the mapped output buffer itself (no copy).
  // Throws std::invalid_argument for P < 2, std::length_error when the output exceeds what one
  // buffer may hold (maxStorageBufferRange on Vulkan).
  virtual const gpu::GridVertex* evaluate(const std::vector<gpu::BicubicPatch>& patches,
                                          uint32_t pointsPerSide) = 0;
};

// threads = 0: all hardware threads.
std::unique_ptr<GridEvaluator> makeMirrorGridEvaluator(unsigned threads = 1);
// The context must outlive the evaluator.
std::unique_ptr<GridEvaluator> makeVulkanGridEvaluator(vk::Context& context);

// Throws std::invalid_argument when pointsPerSide < 2 (both backends check).
void validateGridPointsPerSide(uint32_t pointsPerSide);

// Number of vertices evaluate() produces.
inline size_t gridVertexCount(size_t patches, uint32_t pointsPerSide) {
  return patches * size_t(pointsPerSide) * pointsPerSide;
}

}  // namespace tessera
