// Storage buffers in host-visible, coherent memory, persistently mapped: the host writes
// inputs and reads results directly. On lavapipe and on GPUs with resizable BAR this is also
// device-local memory; elsewhere the GPU reads it over the bus (fine for Tessera's streams,
// which are read once per dispatch).
#pragma once
#include "vk/backend_only.h"
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "vk/context.h"

namespace tessera::vk {

enum class BufferUse {
  Upload,    // host writes, device reads: prefer device-local + host-visible
  Readback,  // device writes, host reads: prefer host-cached
};

class Buffer {
 public:
  Buffer() = default;
  Buffer(Context& context, VkDeviceSize bytes, BufferUse use,
         VkBufferUsageFlags usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
  ~Buffer();
  Buffer(Buffer&& other) noexcept;
  Buffer& operator=(Buffer&& other) noexcept;
  Buffer(const Buffer&) = delete;
  Buffer& operator=(const Buffer&) = delete;

  VkBuffer handle() const { return buffer_; }
  VkDeviceSize size() const { return size_; }
  void* data() const { return mapped_; }
  template <typename T>
  T* as() const {
    return static_cast<T*>(mapped_);
  }

  template <typename T>
  void upload(const std::vector<T>& values) {
    upload(values.data(), values.size() * sizeof(T));
  }
  void upload(const void* source, size_t bytes);

  template <typename T>
  void download(std::vector<T>& values, size_t count) const {
    values.resize(count);
    download(values.data(), count * sizeof(T));
  }
  void download(void* target, size_t bytes) const;

 private:
  void release();

  Context* context_ = nullptr;
  VkBuffer buffer_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  VkDeviceSize size_ = 0;
  void* mapped_ = nullptr;
  bool coherent_ = true;
};

// Throws std::length_error naming `what` when one binding of `bytes` is more than a storage
// buffer descriptor may address on this device (maxStorageBufferRange; 128 MiB on lavapipe):
// the caller splits its batch instead of binding a range the driver would clip.
void requireStorageRange(const Context& context, uint64_t bytes, const std::string& what);

// Grows `buffer` (recreating it, with `usage`) when it is smaller than `bytes`; keeps it
// otherwise, so per-level buffers are reused across levels and frames.
void ensureCapacity(Context& context, Buffer& buffer, VkDeviceSize bytes, BufferUse use,
                    VkBufferUsageFlags usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);

}  // namespace tessera::vk
