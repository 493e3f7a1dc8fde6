#include "vk/object_census.h"

#include <atomic>
#include <mutex>
#include <stdexcept>
#include <unordered_map>

#include "vk/loader.h"

namespace tessera::vk {
namespace {

std::atomic<bool> censusOpen{false};
std::array<std::atomic<long>, size_t(ObjectKind::Count)> liveCounts{};

void add(ObjectKind kind, long n) { liveCounts[size_t(kind)] += n; }

// One create/destroy pair of the common shape (device, info, callbacks, handle out) and
// (device, handle, callbacks). The real entries are kept at the first wrap: one driver.
template <ObjectKind Kind, typename Info, typename Handle>
struct Counted {
  using Create = VkResult(VKAPI_PTR*)(VkDevice, const Info*, const VkAllocationCallbacks*,
                                      Handle*);
  using Destroy = void(VKAPI_PTR*)(VkDevice, Handle, const VkAllocationCallbacks*);
  static inline Create realCreate = nullptr;
  static inline Destroy realDestroy = nullptr;

  static VKAPI_ATTR VkResult VKAPI_CALL create(VkDevice device, const Info* info,
                                               const VkAllocationCallbacks* callbacks,
                                               Handle* handle) {
    const VkResult result = realCreate(device, info, callbacks, handle);
    if (result == VK_SUCCESS) add(Kind, 1);
    return result;
  }
  static VKAPI_ATTR void VKAPI_CALL destroy(VkDevice device, Handle handle,
                                            const VkAllocationCallbacks* callbacks) {
    if (handle != VK_NULL_HANDLE) add(Kind, -1);
    realDestroy(device, handle, callbacks);
  }
  static void wrap(Create& createEntry, Destroy& destroyEntry) {
    if (!createEntry || !destroyEntry) return;
    if (createEntry != &create) realCreate = createEntry;
    if (destroyEntry != &destroy) realDestroy = destroyEntry;
    createEntry = &create;
    destroyEntry = &destroy;
  }
};

// Pipelines come in arrays, created with a cache.
template <typename Info>
struct CountedPipelines {
  using Create = VkResult(VKAPI_PTR*)(VkDevice, VkPipelineCache, uint32_t, const Info*,
                                      const VkAllocationCallbacks*, VkPipeline*);
  static inline Create real = nullptr;
  static VKAPI_ATTR VkResult VKAPI_CALL create(VkDevice device, VkPipelineCache cache,
                                               uint32_t count, const Info* infos,
                                               const VkAllocationCallbacks* callbacks,
                                               VkPipeline* pipelines) {
    const VkResult result = real(device, cache, count, infos, callbacks, pipelines);
    for (uint32_t i = 0; i < count; ++i)  // those that failed are null
      if (pipelines[i] != VK_NULL_HANDLE) add(ObjectKind::Pipeline, 1);
    return result;
  }
  static void wrap(Create& entry) {
    if (!entry) return;
    if (entry != &create) real = entry;
    entry = &create;
  }
};

// Command buffers: counted per pool, since destroying a pool frees what it allocated.
std::mutex poolsMutex;
std::unordered_map<VkCommandPool, long> buffersOfPool;
PFN_vkAllocateCommandBuffers realAllocateCommandBuffers = nullptr;
PFN_vkFreeCommandBuffers realFreeCommandBuffers = nullptr;
PFN_vkDestroyCommandPool realDestroyCommandPool = nullptr;

VKAPI_ATTR VkResult VKAPI_CALL allocateCommandBuffers(VkDevice device,
                                                      const VkCommandBufferAllocateInfo* info,
                                                      VkCommandBuffer* buffers) {
  const VkResult result = realAllocateCommandBuffers(device, info, buffers);
  if (result == VK_SUCCESS) {
    std::lock_guard<std::mutex> lock(poolsMutex);
    buffersOfPool[info->commandPool] += info->commandBufferCount;
    add(ObjectKind::CommandBuffer, info->commandBufferCount);
  }
  return result;
}

VKAPI_ATTR void VKAPI_CALL freeCommandBuffers(VkDevice device, VkCommandPool pool, uint32_t count,
                                              const VkCommandBuffer* buffers) {
  long freed = 0;
  for (uint32_t i = 0; i < count; ++i) freed += buffers[i] != VK_NULL_HANDLE;
  {
    std::lock_guard<std::mutex> lock(poolsMutex);
    buffersOfPool[pool] -= freed;
    add(ObjectKind::CommandBuffer, -freed);
  }
  realFreeCommandBuffers(device, pool, count, buffers);
}

VKAPI_ATTR void VKAPI_CALL destroyCommandPool(VkDevice device, VkCommandPool pool,
                                              const VkAllocationCallbacks* callbacks) {
  if (pool != VK_NULL_HANDLE) {
    std::lock_guard<std::mutex> lock(poolsMutex);
    const auto found = buffersOfPool.find(pool);
    if (found != buffersOfPool.end()) {
      add(ObjectKind::CommandBuffer, -found->second);
      buffersOfPool.erase(found);
    }
    add(ObjectKind::CommandPool, -1);
  }
  realDestroyCommandPool(device, pool, callbacks);
}

PFN_vkCreateCommandPool realCreateCommandPool = nullptr;
VKAPI_ATTR VkResult VKAPI_CALL createCommandPool(VkDevice device,
                                                 const VkCommandPoolCreateInfo* info,
                                                 const VkAllocationCallbacks* callbacks,
                                                 VkCommandPool* pool) {
  const VkResult result = realCreateCommandPool(device, info, callbacks, pool);
  if (result == VK_SUCCESS) add(ObjectKind::CommandPool, 1);
  return result;
}

PFN_vkDestroyPipeline realDestroyPipeline = nullptr;
VKAPI_ATTR void VKAPI_CALL destroyPipeline(VkDevice device, VkPipeline pipeline,
                                           const VkAllocationCallbacks* callbacks) {
  if (pipeline != VK_NULL_HANDLE) add(ObjectKind::Pipeline, -1);
  realDestroyPipeline(device, pipeline, callbacks);
}

template <typename Entry>
void replace(Entry& entry, Entry& real, Entry wrapper) {
  if (!entry) return;
  if (entry != wrapper) real = entry;
  entry = wrapper;
}

constexpr const char* kKindNames[] = {
    "Buffer", "DeviceMemory", "BufferView", "Image", "ImageView", "Fence", "Semaphore", "Event",
    "QueryPool", "CommandPool", "CommandBuffer", "Pipeline", "PipelineLayout",
    "DescriptorSetLayout", "DescriptorPool", "ShaderModule", "RenderPass", "Framebuffer",
    "Sampler"};
static_assert(sizeof kKindNames / sizeof kKindNames[0] == size_t(ObjectKind::Count));

}  // namespace

std::string LiveObjects::describe() const {
  std::string text;
  for (size_t k = 0; k < count.size(); ++k) {
    if (count[k] == 0) continue;
    if (!text.empty()) text += ", ";
    text += std::to_string(count[k]) + " " + kKindNames[k];
  }
  return text.empty() ? "none" : text;
}

ObjectCensus::ObjectCensus() {
  if (censusOpen.exchange(true)) throw std::logic_error("ObjectCensus: one at a time");
}

ObjectCensus::~ObjectCensus() { censusOpen = false; }

LiveObjects ObjectCensus::live() const {
  LiveObjects objects;
  for (size_t k = 0; k < objects.count.size(); ++k) objects.count[k] = liveCounts[k];
  return objects;
}

void countObjectsWhileCensusOpen(DeviceTable& t) {
  if (!censusOpen) return;
  using K = ObjectKind;
  Counted<K::Buffer, VkBufferCreateInfo, VkBuffer>::wrap(t.vkCreateBuffer, t.vkDestroyBuffer);
  Counted<K::DeviceMemory, VkMemoryAllocateInfo, VkDeviceMemory>::wrap(t.vkAllocateMemory,
                                                                       t.vkFreeMemory);
  Counted<K::BufferView, VkBufferViewCreateInfo, VkBufferView>::wrap(t.vkCreateBufferView,
                                                                     t.vkDestroyBufferView);
  Counted<K::Image, VkImageCreateInfo, VkImage>::wrap(t.vkCreateImage, t.vkDestroyImage);
  Counted<K::ImageView, VkImageViewCreateInfo, VkImageView>::wrap(t.vkCreateImageView,
                                                                  t.vkDestroyImageView);
  Counted<K::Fence, VkFenceCreateInfo, VkFence>::wrap(t.vkCreateFence, t.vkDestroyFence);
  Counted<K::Semaphore, VkSemaphoreCreateInfo, VkSemaphore>::wrap(t.vkCreateSemaphore,
                                                                  t.vkDestroySemaphore);
  Counted<K::Event, VkEventCreateInfo, VkEvent>::wrap(t.vkCreateEvent, t.vkDestroyEvent);
  Counted<K::QueryPool, VkQueryPoolCreateInfo, VkQueryPool>::wrap(t.vkCreateQueryPool,
                                                                  t.vkDestroyQueryPool);
  Counted<K::PipelineLayout, VkPipelineLayoutCreateInfo, VkPipelineLayout>::wrap(
      t.vkCreatePipelineLayout, t.vkDestroyPipelineLayout);
  Counted<K::DescriptorSetLayout, VkDescriptorSetLayoutCreateInfo, VkDescriptorSetLayout>::wrap(
      t.vkCreateDescriptorSetLayout, t.vkDestroyDescriptorSetLayout);
  Counted<K::DescriptorPool, VkDescriptorPoolCreateInfo, VkDescriptorPool>::wrap(
      t.vkCreateDescriptorPool, t.vkDestroyDescriptorPool);
  Counted<K::ShaderModule, VkShaderModuleCreateInfo, VkShaderModule>::wrap(
      t.vkCreateShaderModule, t.vkDestroyShaderModule);
  Counted<K::RenderPass, VkRenderPassCreateInfo, VkRenderPass>::wrap(t.vkCreateRenderPass,
                                                                     t.vkDestroyRenderPass);
  Counted<K::Framebuffer, VkFramebufferCreateInfo, VkFramebuffer>::wrap(t.vkCreateFramebuffer,
                                                                        t.vkDestroyFramebuffer);
  Counted<K::Sampler, VkSamplerCreateInfo, VkSampler>::wrap(t.vkCreateSampler,
                                                            t.vkDestroySampler);
  CountedPipelines<VkComputePipelineCreateInfo>::wrap(t.vkCreateComputePipelines);
  CountedPipelines<VkGraphicsPipelineCreateInfo>::wrap(t.vkCreateGraphicsPipelines);
  replace(t.vkDestroyPipeline, realDestroyPipeline, PFN_vkDestroyPipeline(&destroyPipeline));
  replace(t.vkCreateCommandPool, realCreateCommandPool, PFN_vkCreateCommandPool(&createCommandPool));
  replace(t.vkDestroyCommandPool, realDestroyCommandPool,
          PFN_vkDestroyCommandPool(&destroyCommandPool));
  replace(t.vkAllocateCommandBuffers, realAllocateCommandBuffers,
          PFN_vkAllocateCommandBuffers(&allocateCommandBuffers));
  replace(t.vkFreeCommandBuffers, realFreeCommandBuffers,
          PFN_vkFreeCommandBuffers(&freeCommandBuffers));
}

}  // namespace tessera::vk
