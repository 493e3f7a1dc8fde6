// The Vulkan Backend of tessellate(): the quad-tree classifier and the patch evaluator on one
// device (declared in mesh/tessellate.h, which core code includes without Vulkan).
#include "mesh/tessellate.h"

namespace tessera {

Backend makeVulkanBackend(vk::Context& context) {
  auto classifier = makeVulkanClassifier(context);
  auto evaluator = makeVulkanEvaluator(context);
  return {"vulkan", std::move(classifier), std::move(evaluator)};
}

}  // namespace tessera
