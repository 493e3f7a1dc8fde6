// 2-D images in device memory with one view over the whole image: render targets (colour,
// depth, multisampled or not) for host/render/offscreen_vulkan.cpp. The host never maps them; pixels reach it
// through vkCmdCopyImageToBuffer into a vk::Buffer.
#pragma once
#include "vk/backend_only.h"
#include <cstdint>

#include "vk/context.h"

namespace tessera::vk {

struct ImageDesc {
  uint32_t width = 0, height = 0;
  VkFormat format = VK_FORMAT_R8G8B8A8_UNORM;
  VkImageUsageFlags usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
  VkImageAspectFlags aspect = VK_IMAGE_ASPECT_COLOR_BIT;  // of the view
  VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
};

class Image {
 public:
  Image() = default;
  // Throws std::invalid_argument for a zero extent, VulkanError when a call fails.
  Image(Context& context, const ImageDesc& desc);
  ~Image();
  Image(Image&& other) noexcept;
  Image& operator=(Image&& other) noexcept;
  Image(const Image&) = delete;
  Image& operator=(const Image&) = delete;

  VkImage handle() const { return image_; }
  VkImageView view() const { return view_; }
  const ImageDesc& desc() const { return desc_; }

 private:
  void release();

  Context* context_ = nullptr;
  ImageDesc desc_;
  VkImage image_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  VkImageView view_ = VK_NULL_HANDLE;
};

}  // namespace tessera::vk
