#include <catch2/catch.hpp>

#include <cstdlib>

#include "gpu_test_context.h"
#include "vk/buffer.h"
#include "vk/device_select.h"

using namespace tessera;

TEST_CASE("a Vulkan context comes up with validation layers on", "[gpu][vk]") {
  vk::Context& context = test::gpuContext();
  REQUIRE(context.validationEnabled());
  REQUIRE(context.device() != VK_NULL_HANDLE);
  REQUIRE(context.info().usable);
  REQUIRE(context.info().maxStorageBufferRange >= (1u << 27));  // 128 MiB on lavapipe
  test::requireValidationClean();
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
