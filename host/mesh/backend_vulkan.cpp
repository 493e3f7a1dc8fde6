// The Vulkan Backend of tessellate(): the quad-tree classifier and the patch evaluator on one
// device (declared in mesh/tessellate.h, which core code includes without Vulkan).
#include "mesh/tessellate.h"

namespace tessera {

Backend makeVulkanBackend(vk::Context& context, size_t hostLevelNodes) {
  // Small levels on the host: a submission costs the device more than the mirror takes for them.
  auto classifier = withSmallLevelsOnHost(makeVulkanClassifier(context), hostLevelNodes);
  auto evaluator = makeVulkanEvaluator(context);
  return {"vulkan", std::move(classifier), std::move(evaluator)};
}

}  // namespace tessera
