#include "vk/buffer.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "vk/loader.h"

namespace tessera::vk {
namespace {

uint32_t findMemoryType(const VkPhysicalDeviceMemoryProperties& memory, uint32_t allowed,
                        VkMemoryPropertyFlags required, VkMemoryPropertyFlags preferred) {
  int fallback = -1;
  for (uint32_t i = 0; i < memory.memoryTypeCount; ++i) {
    if (!(allowed & (1u << i))) continue;
    VkMemoryPropertyFlags flags = memory.memoryTypes[i].propertyFlags;
    if ((flags & required) != required) continue;
    if ((flags & preferred) == preferred) return i;
    if (fallback < 0) fallback = static_cast<int>(i);
  }
  if (fallback < 0)
    throw VulkanUnavailable("the device has no host-visible memory type for storage buffers");
  return static_cast<uint32_t>(fallback);
}

}  // namespace

Buffer::Buffer(Context& context, VkDeviceSize bytes, BufferUse use, VkBufferUsageFlags usage)
    : context_(&context), size_(bytes) {
  if (bytes == 0) throw std::invalid_argument("vk::Buffer: zero-sized buffer");
  const DeviceTable& vk = context.vk();
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = bytes;
  info.usage = usage | VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  VK_CHECK(vk.vkCreateBuffer(context.device(), &info, nullptr, &buffer_));
  try {
    VkMemoryRequirements req{};
    vk.vkGetBufferMemoryRequirements(context.device(), buffer_, &req);
    VkMemoryPropertyFlags required =
        VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    VkMemoryPropertyFlags preferred =
        required | (use == BufferUse::Upload ? VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT
                                             : VK_MEMORY_PROPERTY_HOST_CACHED_BIT);
    VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    alloc.allocationSize = req.size;
    alloc.memoryTypeIndex =
        findMemoryType(context.memoryProperties(), req.memoryTypeBits, required, preferred);
    VK_CHECK(vk.vkAllocateMemory(context.device(), &alloc, nullptr, &memory_));
    VK_CHECK(vk.vkBindBufferMemory(context.device(), buffer_, memory_, 0));
    VK_CHECK(vk.vkMapMemory(context.device(), memory_, 0, VK_WHOLE_SIZE, 0, &mapped_));
  } catch (...) {
    release();
    throw;
  }
}

Buffer::~Buffer() { release(); }

void Buffer::release() {
  if (!context_) return;
  const DeviceTable& vk = context_->vk();
  if (mapped_) vk.vkUnmapMemory(context_->device(), memory_);
  if (buffer_) vk.vkDestroyBuffer(context_->device(), buffer_, nullptr);
  if (memory_) vk.vkFreeMemory(context_->device(), memory_, nullptr);
  mapped_ = nullptr;
  buffer_ = VK_NULL_HANDLE;
  memory_ = VK_NULL_HANDLE;
  context_ = nullptr;
  size_ = 0;
}

Buffer::Buffer(Buffer&& other) noexcept { *this = std::move(other); }

Buffer& Buffer::operator=(Buffer&& other) noexcept {
  if (this != &other) {
    release();
    context_ = other.context_;
    buffer_ = other.buffer_;
    memory_ = other.memory_;
    size_ = other.size_;
    mapped_ = other.mapped_;
    coherent_ = other.coherent_;
    other.context_ = nullptr;
    other.buffer_ = VK_NULL_HANDLE;
    other.memory_ = VK_NULL_HANDLE;
    other.mapped_ = nullptr;
    other.size_ = 0;
  }
  return *this;
}

void Buffer::upload(const void* source, size_t bytes) {
  if (bytes > size_)
    throw std::out_of_range("vk::Buffer::upload: " + std::to_string(bytes) + " bytes into " +
                            std::to_string(size_));
  std::memcpy(mapped_, source, bytes);
}

void Buffer::download(void* target, size_t bytes) const {
  if (bytes > size_)
    throw std::out_of_range("vk::Buffer::download: " + std::to_string(bytes) + " bytes from " +
                            std::to_string(size_));
  std::memcpy(target, mapped_, bytes);
}

void requireStorageRange(const Context& context, uint64_t bytes, const std::string& what) {
  const uint64_t limit = context.info().maxStorageBufferRange;
  if (limit == 0 || bytes <= limit) return;
  throw std::length_error(what + ": " + std::to_string(bytes) +
                          " bytes exceed the device's storage buffer range (" +
                          std::to_string(limit) + " bytes); split the batch");
}

void ensureCapacity(Context& context, Buffer& buffer, VkDeviceSize bytes, BufferUse use,
                    VkBufferUsageFlags usage) {
  if (buffer.handle() && buffer.size() >= bytes) return;
  VkDeviceSize grown = buffer.size() ? buffer.size() : 256;
  while (grown < bytes) grown *= 2;
  // Doubling must not push a buffer past what one descriptor can address.
  grown = std::max(bytes, std::min<VkDeviceSize>(grown, context.info().maxStorageBufferRange));
  buffer = Buffer(context, grown, use, usage);
}

}  // namespace tessera::vk
