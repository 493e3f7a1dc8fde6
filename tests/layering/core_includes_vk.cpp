// Must NOT compile: core code including the Vulkan layer (tests/CMakeLists.txt builds this with
// only tessera_core's usage requirements and expects host/vk/backend_only.h's #error).
#include "vk/context.h"

int coreCodeThatReachesForVulkan() { return 0; }
