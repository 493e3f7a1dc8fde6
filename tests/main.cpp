// The Catch2 runner for all of tessera_tests. The shared Vulkan context of the [gpu] cases is
// destroyed when the session ends, before exit: left to the static destructors, every GPU test
// process ended in SIGSEGV after its summary on an H100 (NVIDIA 580.159.04) on 2026-11-27.
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

#include "gpu_test_context.h"

int main(int argc, char* argv[]) {
  const int result = Catch::Session().run(argc, argv);
  tessera::test::releaseGpuContext();
  return result;
}
