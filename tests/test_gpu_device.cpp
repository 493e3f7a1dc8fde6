// Names the Vulkan device the GPU tests run on, once per test run: CTest runs this hidden case
// as "gpu: the Vulkan device of the GPU tests" (tests/CMakeLists.txt), which passes only when
// the line is printed, and scripts/test.sh repeats the line from CTest's log, so a CI log
// shows whether the GPU tests ran on lavapipe or on a GPU.
#include <catch2/catch.hpp>

#include <cstdio>

#include "gpu_test_context.h"

using namespace tessera;

TEST_CASE("the Vulkan device of the GPU tests", "[.][gpu-device]") {
  const vk::DeviceInfo& info = test::gpuContext().info();
  REQUIRE(!info.name.empty());
  std::printf("Vulkan device of the GPU tests: %s (%s, driver %s %s)%s\n", info.name.c_str(),
              info.typeName().c_str(), info.driverName.c_str(), info.driverInfo.c_str(),
              info.isLavapipe() ? ": lavapipe, the CPU Vulkan driver" : "");
  test::requireValidationClean();
}
