#include "vk/texel_view.h"

#include <algorithm>

#include "vk/errors.h"
#include "vk/loader.h"

namespace tessera::vk {

namespace {
constexpr VkDeviceSize kTexelBytes = 16;  // RGBA32UI, RGBA32F
}  // namespace

VkDeviceSize maxTexelViewBytes(const Context& context) {
  return VkDeviceSize(context.info().maxTexelBufferElements) * kTexelBytes;
}

TexelView::~TexelView() { release(); }

void TexelView::release() {
  if (view_) context_.vk().vkDestroyBufferView(context_.device(), view_, nullptr);
  view_ = VK_NULL_HANDLE;
}

VkBufferView TexelView::viewOf(const Buffer& buffer) {
  if (view_ && viewedBuffer_ == buffer.handle() && viewedSize_ == buffer.size()) return view_;
  release();
  VkBufferViewCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_VIEW_CREATE_INFO};
  info.buffer = buffer.handle();
  info.format = format_;
  info.offset = 0;
  info.range = std::min(buffer.size() / kTexelBytes * kTexelBytes, maxTexelViewBytes(context_));
  VK_CHECK(context_.vk().vkCreateBufferView(context_.device(), &info, nullptr, &view_));
  viewedBuffer_ = buffer.handle();
  viewedSize_ = buffer.size();
  return view_;
}

}  // namespace tessera::vk
