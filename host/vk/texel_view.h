// A uniform texel buffer view of a whole vk::Buffer in one 16-byte format (RGBA32UI, say), for
// shaders that read a buffer by texelFetch instead of as a storage buffer. Why: lavapipe (Mesa
// 22.3) loads a storage buffer at an index that differs per invocation one lane at a time,
// with a bounds test per component (~70 instructions a lane for a vec4), while a texel fetch
// gathers the 8 lanes' texels at once; rule T's bicubic shaders spent about two thirds of their
// instructions on such loads (bench/HISTORY.md, rule T section, `levels15`).
#pragma once
#include "vk/backend_only.h"

#include "vk/buffer.h"
#include "vk/context.h"

namespace tessera::vk {

class TexelView {
 public:
  TexelView(Context& context, VkFormat format) : context_(context), format_(format) {}
  ~TexelView();
  TexelView(const TexelView&) = delete;
  TexelView& operator=(const TexelView&) = delete;

  // The view of `buffer` (its whole 16-byte texels, at most maxTexelBufferElements), made again
  // when the buffer is not the one of the last call (ensureCapacity replaced it with a larger
  // one: a handle may be reused, a handle and size of the same vk::Buffer may not). The buffer
  // must have VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT.
  VkBufferView viewOf(const Buffer& buffer);

 private:
  void release();

  Context& context_;
  VkFormat format_;
  VkBufferView view_ = VK_NULL_HANDLE;
  VkBuffer viewedBuffer_ = VK_NULL_HANDLE;
  VkDeviceSize viewedSize_ = 0;
};

// Bytes of 16-byte texels (RGBA32UI, RGBA32F) one view may address on this device.
VkDeviceSize maxTexelViewBytes(const Context& context);

}  // namespace tessera::vk
