#include "gpu_test_context.h"

#include <catch2/catch.hpp>

#include <memory>
#include <string>

namespace tessera::test {

namespace {
std::unique_ptr<vk::Context> context;
std::string failure;
}  // namespace

vk::Context& gpuContext() {
  if (!context && failure.empty()) {
    try {
      vk::ContextOptions options;
      options.validation = vk::Validation::Required;
      context = std::make_unique<vk::Context>(options);
      const vk::DeviceInfo& info = context->info();
      WARN("GPU tests on " << info.name << " (" << info.typeName() << ", driver "
                           << info.driverName << " " << info.driverInfo << ")");
    } catch (const std::exception& e) {
      failure = e.what();
    }
  }
  if (!context)
    FAIL("no Vulkan context for a GPU test: " << failure
                                              << "\nRun `scripts/test.sh --cpu-only` to skip GPU "
                                                 "tests deliberately.");
  return *context;
}

bool exactMirrorArithmetic() { return gpuContext().info().isLavapipe(); }

void releaseGpuContext() { context.reset(); }

void requireValidationClean() {
  auto messages = gpuContext().validationMessages();
  for (const auto& m : messages) UNSCOPED_INFO(m);
  REQUIRE(messages.empty());
}

}  // namespace tessera::test
