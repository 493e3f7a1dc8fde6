// The Vulkan context that [gpu] test cases share within one process. Validation layers are
// required; every message they send is recorded, and requireValidationClean() fails the test
// on any. No device is a loud failure: a CPU-only run must be asked for explicitly
// (`scripts/test.sh --cpu-only`, which runs `ctest -LE gpu`).
#pragma once
#include "vk/context.h"

namespace tessera::test {

vk::Context& gpuContext();
void requireValidationClean();

}  // namespace tessera::test
