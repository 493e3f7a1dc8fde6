// A count of live Vulkan objects, for tests that check a long-lived Context holds a bounded set
// of them (an engine calls Tessera every frame for hours): while an ObjectCensus is open, every
// Context created has its dispatch table's create/allocate and destroy/free entries wrapped
// (as vk/fault_injection.h wraps its entries), and live() is what those calls left alive.
// The wrappers and the counts are process-wide, for tests: one census at a time, one driver
// among the counted contexts. Command buffers freed with their pool count as freed.
#pragma once
#include <array>
#include <string>

namespace tessera::vk {

struct DeviceTable;

enum class ObjectKind {
  Buffer, DeviceMemory, BufferView, Image, ImageView, Fence, Semaphore, Event, QueryPool,
  CommandPool, CommandBuffer, Pipeline, PipelineLayout, DescriptorSetLayout, DescriptorPool,
  ShaderModule, RenderPass, Framebuffer, Sampler,
  Count
};

struct LiveObjects {
  std::array<long, size_t(ObjectKind::Count)> count{};
  long operator[](ObjectKind kind) const { return count[size_t(kind)]; }
  bool operator==(const LiveObjects& other) const { return count == other.count; }
  bool operator!=(const LiveObjects& other) const { return !(*this == other); }
  // "3 Buffer, 1 CommandPool, ..." (kinds with none left out), for test messages.
  std::string describe() const;
};

class ObjectCensus {
 public:
  ObjectCensus();  // throws std::logic_error when another census is open
  ~ObjectCensus();
  ObjectCensus(const ObjectCensus&) = delete;
  ObjectCensus& operator=(const ObjectCensus&) = delete;
  // Objects alive now among those of contexts created while a census was open.
  LiveObjects live() const;
};

// Called by loadDeviceTable (vk/loader.cpp): wraps the table's entries while a census is open.
void countObjectsWhileCensusOpen(DeviceTable& table);

}  // namespace tessera::vk
