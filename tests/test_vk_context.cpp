#include <catch2/catch.hpp>

#include <cstdlib>
#include <stdexcept>
#include <string>

#include <type_traits>
#include <vector>

#include "gpu_test_context.h"
#include "vk/buffer.h"
#include "vk/device_select.h"

using namespace tessera;

// VK_NO_PROTOTYPES belongs to the Vulkan backend alone (volk, host/vk/loader.h): a user of the
// library includes its headers and still sees vulkan.h's prototypes, not volk's pointers.
#ifdef VK_NO_PROTOTYPES
#error "VK_NO_PROTOTYPES leaked from the Tessera library to its users"
#endif
static_assert(std::is_function_v<decltype(::vkCreateInstance)>,
              "vkCreateInstance is a prototype here, not volk's global function pointer");

TEST_CASE("a Vulkan context comes up with validation layers on", "[gpu][vk]") {
  vk::Context& context = test::gpuContext();
  REQUIRE(context.validationEnabled());
  REQUIRE(context.device() != VK_NULL_HANDLE);
  REQUIRE(context.info().usable);
  REQUIRE(context.info().maxStorageBufferRange >= (1u << 27));  // 128 MiB on lavapipe
  // Vulkan 1.1's maintenance3 limit, which bounds one allocation (2 GiB on lavapipe); the
  // Loop stencil evaluator splits its arrays by it (host/loop/evaluator.h).
  REQUIRE(context.info().maxMemoryAllocationSize >= (1u << 27));
  test::requireValidationClean();
}

TEST_CASE("a context keeps a bounded log of validation messages and counts them all", "[gpu][vk]") {
  // An engine's debug build runs one context for hours with validation on: a repeated message
  // must not grow the log without end. Messages here are injected through the messenger's
  // own entry point, so no real validation error is needed.
  size_t delivered = 0;
  vk::ContextOptions options;
  options.onValidationMessage = [&](const std::string&) { ++delivered; };
  vk::Context context(options);
  const size_t sent = vk::Context::kKeptValidationMessages + 1000;
  for (size_t i = 0; i < sent; ++i) context.reportValidationMessage("message " + std::to_string(i));
  REQUIRE(delivered == sent);  // the callback still sees every one
  REQUIRE(context.validationMessageCount() == sent);
  const std::vector<std::string> log = context.validationMessages();
  REQUIRE(log.size() == vk::Context::kKeptValidationMessages + 1);
  REQUIRE(log.front() == "message 0");
  REQUIRE(log[vk::Context::kKeptValidationMessages - 1] ==
          "message " + std::to_string(vk::Context::kKeptValidationMessages - 1));
  REQUIRE(log.back() == "(1000 more validation messages, not kept)");
}

TEST_CASE("buffers round-trip data and grow on demand", "[gpu][vk]") {
  vk::Context& context = test::gpuContext();
  vk::Buffer buffer;
  vk::ensureCapacity(context, buffer, 1000, vk::BufferUse::Upload);
  REQUIRE(buffer.size() >= 1000);
  std::vector<uint32_t> values(250);
  for (uint32_t i = 0; i < values.size(); ++i) values[i] = i * 7919u;
  buffer.upload(values);
  std::vector<uint32_t> back;
  buffer.download(back, values.size());
  REQUIRE(back == values);
  VkBuffer before = buffer.handle();
  vk::ensureCapacity(context, buffer, 500, vk::BufferUse::Upload);
  REQUIRE(buffer.handle() == before);  // big enough: kept
  vk::ensureCapacity(context, buffer, 5000, vk::BufferUse::Upload);
  REQUIRE(buffer.size() >= 5000);
  REQUIRE_THROWS_AS(buffer.upload(values.data(), buffer.size() + 1), std::out_of_range);
  test::requireValidationClean();
}

// Every Vulkan backend checks a binding against the device's range before it allocates, so
// an oversized batch is a clear error naming the stage, not a clipped descriptor.
TEST_CASE("a binding past the device's storage buffer range is refused by name", "[gpu][vk]") {
  vk::Context& context = test::gpuContext();
  const uint64_t limit = context.info().maxStorageBufferRange;
  INFO("device " << context.info().name << ", range " << limit);
  REQUIRE(limit > 0);
  REQUIRE_NOTHROW(vk::requireStorageRange(context, limit, "test stage"));
  try {
    vk::requireStorageRange(context, limit + 1, "test stage");
    FAIL("no error one byte past the range");
  } catch (const std::length_error& e) {
    const std::string message = e.what();
    CHECK(message.find("test stage") == 0);
    CHECK(message.find(std::to_string(limit + 1)) != std::string::npos);
    CHECK(message.find(std::to_string(limit) + " bytes") != std::string::npos);
  }
}

// Dispatch tables are per context (host/vk/loader.h): a second instance and device that come
// and go leave the first working.
TEST_CASE("a second Vulkan context comes and goes while the first keeps working", "[gpu][vk]") {
  vk::Context& first = test::gpuContext();
  const std::vector<uint32_t> values = {1, 2, 3, 5, 8, 13, 21};
  auto roundTrip = [&](vk::Context& context) {
    vk::Buffer buffer;
    vk::ensureCapacity(context, buffer, values.size() * sizeof(uint32_t), vk::BufferUse::Upload);
    buffer.upload(values);
    std::vector<uint32_t> back;
    buffer.download(back, values.size());
    return back;
  };
  {
    vk::ContextOptions options;
    options.validation = vk::Validation::Required;
    vk::Context second(options);
    REQUIRE(second.device() != first.device());
    REQUIRE(&second.vk() != &first.vk());
    REQUIRE(roundTrip(second) == values);
    REQUIRE(roundTrip(first) == values);
    REQUIRE(second.validationMessages().empty());
  }
  REQUIRE(roundTrip(first) == values);
  test::requireValidationClean();
}

TEST_CASE("device selection ranks discrete over integrated over CPU and honours a selector",
          "[vk]") {
  std::vector<vk::DeviceInfo> devices(3);
  devices[0] = {0, "llvmpipe (LLVM 15)", VK_PHYSICAL_DEVICE_TYPE_CPU};
  devices[1] = {1, "Intel UHD 630", VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU};
  devices[2] = {2, "NVIDIA H100", VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU};
  for (auto& d : devices) d.usable = true;
  REQUIRE(vk::selectDevice(devices, "") == 2);
  REQUIRE(vk::selectDevice(devices, "0") == 0);
  REQUIRE(vk::selectDevice(devices, "LLVMPIPE") == 0);
  REQUIRE(vk::selectDevice(devices, "intel") == 1);
  devices[2].usable = false;
  devices[2].unusableReason = "missing device extension VK_KHR_push_descriptor";
  REQUIRE(vk::selectDevice(devices, "") == 1);
  REQUIRE_THROWS_WITH(vk::selectDevice(devices, "nvidia"),
                      Catch::Contains("missing device extension"));
  REQUIRE_THROWS_WITH(vk::selectDevice(devices, "radeon"), Catch::Contains("no Vulkan device matches"));
  REQUIRE_THROWS_WITH(vk::selectDevice({}, ""), Catch::Contains("mesa-vulkan-drivers"));
}
