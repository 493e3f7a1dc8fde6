#include "vk/image.h"

#include <stdexcept>
#include <string>
#include <utility>

#include "vk/loader.h"

namespace tessera::vk {
namespace {

// Device-local when the device has it (every GPU; lavapipe's one heap is both), else any type
// the image accepts.
uint32_t imageMemoryType(const VkPhysicalDeviceMemoryProperties& memory, uint32_t allowed) {
  int fallback = -1;
  for (uint32_t i = 0; i < memory.memoryTypeCount; ++i) {
    if (!(allowed & (1u << i))) continue;
    if (memory.memoryTypes[i].propertyFlags & VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT) return i;
    if (fallback < 0) fallback = static_cast<int>(i);
  }
  if (fallback < 0) throw VulkanUnavailable("the device has no memory type for render images");
  return static_cast<uint32_t>(fallback);
}

}  // namespace

Image::Image(Context& context, const ImageDesc& desc) : context_(&context), desc_(desc) {
  if (desc.width == 0 || desc.height == 0)
    throw std::invalid_argument("vk::Image: zero extent " + std::to_string(desc.width) + "x" +
                                std::to_string(desc.height));
  const DeviceTable& vk = context.vk();
  VkImageCreateInfo info{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = desc.format;
  info.extent = {desc.width, desc.height, 1};
  info.mipLevels = 1;
  info.arrayLayers = 1;
  info.samples = desc.samples;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = desc.usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  VK_CHECK(vk.vkCreateImage(context.device(), &info, nullptr, &image_));
  try {
    VkMemoryRequirements req{};
    vk.vkGetImageMemoryRequirements(context.device(), image_, &req);
    VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
    alloc.allocationSize = req.size;
    alloc.memoryTypeIndex = imageMemoryType(context.memoryProperties(), req.memoryTypeBits);
    VK_CHECK(vk.vkAllocateMemory(context.device(), &alloc, nullptr, &memory_));
    VK_CHECK(vk.vkBindImageMemory(context.device(), image_, memory_, 0));

    VkImageViewCreateInfo viewInfo{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    viewInfo.image = image_;
    viewInfo.viewType = VK_IMAGE_VIEW_TYPE_2D;
    viewInfo.format = desc.format;
    viewInfo.subresourceRange = {desc.aspect, 0, 1, 0, 1};
    VK_CHECK(vk.vkCreateImageView(context.device(), &viewInfo, nullptr, &view_));
  } catch (...) {
    release();
    throw;
  }
}

Image::~Image() { release(); }

void Image::release() {
  if (!context_) return;
  const DeviceTable& vk = context_->vk();
  if (view_) vk.vkDestroyImageView(context_->device(), view_, nullptr);
  if (image_) vk.vkDestroyImage(context_->device(), image_, nullptr);
  if (memory_) vk.vkFreeMemory(context_->device(), memory_, nullptr);
  view_ = VK_NULL_HANDLE;
  image_ = VK_NULL_HANDLE;
  memory_ = VK_NULL_HANDLE;
  context_ = nullptr;
}

Image::Image(Image&& other) noexcept { *this = std::move(other); }

Image& Image::operator=(Image&& other) noexcept {
  if (this != &other) {
    release();
    context_ = std::exchange(other.context_, nullptr);
    desc_ = other.desc_;
    image_ = std::exchange(other.image_, VK_NULL_HANDLE);
    memory_ = std::exchange(other.memory_, VK_NULL_HANDLE);
    view_ = std::exchange(other.view_, VK_NULL_HANDLE);
  }
  return *this;
}

}  // namespace tessera::vk
