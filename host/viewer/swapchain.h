// A swapchain on the window's surface, with one image view per image. Made again (a new
// Swapchain) when the window's size changes or presentation reports it out of date.
#pragma once
#include "vk/backend_only.h"
#include <vector>

#include "vk/context.h"

namespace tessera::viewer {

class Swapchain {
 public:
  // `extent` is used when the surface leaves the size to the swapchain (X11 does not).
  // With `copyable` the images can be copied from (screenshots): WindowSystemUnavailable when
  // the surface does not allow it. The colour format is 8-bit UNORM (BGRA or RGBA): the mesh
  // shader writes sRGB-encoded values itself, as for tessera render.
  Swapchain(vk::Context& context, VkSurfaceKHR surface, VkExtent2D extent, bool copyable,
            VkSwapchainKHR old = VK_NULL_HANDLE);
  ~Swapchain();
  Swapchain(const Swapchain&) = delete;
  Swapchain& operator=(const Swapchain&) = delete;

  VkSwapchainKHR handle() const { return swapchain_; }
  VkFormat format() const { return format_; }
  VkExtent2D extent() const { return extent_; }
  const std::vector<VkImage>& images() const { return images_; }
  const std::vector<VkImageView>& views() const { return views_; }
  VkPresentModeKHR presentMode() const { return presentMode_; }

 private:
  void createViews();
  void release();

  vk::Context& context_;
  VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
  VkFormat format_ = VK_FORMAT_UNDEFINED;
  VkExtent2D extent_{};
  VkPresentModeKHR presentMode_ = VK_PRESENT_MODE_FIFO_KHR;
  std::vector<VkImage> images_;
  std::vector<VkImageView> views_;
};

// True when the context's queue can present to `surface`.
bool queueCanPresent(const vk::Context& context, VkSurfaceKHR surface);
void destroySurface(const vk::Context& context, VkSurfaceKHR surface);

}  // namespace tessera::viewer
