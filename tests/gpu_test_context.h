// The Vulkan context that [gpu] test cases share within one process. Validation layers are
// required; every message they send is recorded, and requireValidationClean() fails the test
// on any. No device is a loud failure: a CPU-only run must be asked for explicitly
// (`scripts/test.sh --cpu-only`, which runs `ctest -LE gpu`).
#pragma once
#include "vk/context.h"

namespace tessera::test {

vk::Context& gpuContext();
void requireValidationClean();
// Whether the device rounds as the fp32 mirror does. Lavapipe does (no fused multiply-adds, a
// correctly rounded division), so there a GPU result must equal the mirror's bit for bit. Other
// drivers fuse and divide within Vulkan's 2.5 ulp: there a test reports its mirror differences
// and checks what holds on any device (the double reference's band, decisions explained by
// the ambiguity band, watertightness, the tolerance, the same answer from both of the GPU's own paths).
bool exactMirrorArithmetic();
// Destroys the shared context (tests/main.cpp, after the last test): before exit() and the
// driver's own exit handlers, not among the static destructors after them.
void releaseGpuContext();

}  // namespace tessera::test
