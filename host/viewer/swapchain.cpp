#include "viewer/swapchain.h"

#include <algorithm>
#include <string>

#include "viewer/window.h"
#include "vk/loader.h"

namespace tessera::viewer {
namespace {

// The surface queries are instance functions of VK_KHR_surface, which the context's own
// instance table does not carry: fetched here from the loader.
template <typename Function>
Function instanceFunction(const vk::Context& context, const char* name) {
  auto f = reinterpret_cast<Function>(vkGetInstanceProcAddr(context.instance(), name));
  if (!f)
    throw WindowSystemUnavailable(std::string("no window system: the Vulkan instance lacks ") +
                                  name + " (VK_KHR_surface not enabled?)");
  return f;
}

}  // namespace

bool queueCanPresent(const vk::Context& context, VkSurfaceKHR surface) {
  auto support = instanceFunction<PFN_vkGetPhysicalDeviceSurfaceSupportKHR>(
      context, "vkGetPhysicalDeviceSurfaceSupportKHR");
  VkBool32 supported = VK_FALSE;
  VK_CHECK(support(context.physicalDevice(), context.queueFamily(), surface, &supported));
  return supported == VK_TRUE;
}

void destroySurface(const vk::Context& context, VkSurfaceKHR surface) {
  if (surface)
    instanceFunction<PFN_vkDestroySurfaceKHR>(context, "vkDestroySurfaceKHR")(context.instance(),
                                                                            surface, nullptr);
}

Swapchain::Swapchain(vk::Context& context, VkSurfaceKHR surface, VkExtent2D extent,
                     bool copyable, VkSwapchainKHR old)
    : context_(context) {
  VkPhysicalDevice physical = context.physicalDevice();
  VkSurfaceCapabilitiesKHR caps{};
  VK_CHECK(instanceFunction<PFN_vkGetPhysicalDeviceSurfaceCapabilitiesKHR>(
      context, "vkGetPhysicalDeviceSurfaceCapabilitiesKHR")(physical, surface, &caps));
  auto formatsOf = instanceFunction<PFN_vkGetPhysicalDeviceSurfaceFormatsKHR>(
      context, "vkGetPhysicalDeviceSurfaceFormatsKHR");
  uint32_t count = 0;
  VK_CHECK(formatsOf(physical, surface, &count, nullptr));
  std::vector<VkSurfaceFormatKHR> formats(count);
  VK_CHECK(formatsOf(physical, surface, &count, formats.data()));
  auto chosen = std::find_if(formats.begin(), formats.end(), [](const VkSurfaceFormatKHR& f) {
    return (f.format == VK_FORMAT_B8G8R8A8_UNORM || f.format == VK_FORMAT_R8G8B8A8_UNORM) &&
           f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR;
  });
  if (chosen == formats.end())
    throw WindowSystemUnavailable("no window system: the surface offers no 8-bit UNORM format");
  format_ = chosen->format;

  auto modesOf = instanceFunction<PFN_vkGetPhysicalDeviceSurfacePresentModesKHR>(
      context, "vkGetPhysicalDeviceSurfacePresentModesKHR");
  VK_CHECK(modesOf(physical, surface, &count, nullptr));
  std::vector<VkPresentModeKHR> modes(count);
  VK_CHECK(modesOf(physical, surface, &count, modes.data()));
  // Frames/s on the overlay should be the tessellator's, not the display's: no vsync when the
  // surface allows it (FIFO is the one mode every surface has).
  for (VkPresentModeKHR preferred : {VK_PRESENT_MODE_MAILBOX_KHR, VK_PRESENT_MODE_IMMEDIATE_KHR})
    if (std::find(modes.begin(), modes.end(), preferred) != modes.end()) {
      presentMode_ = preferred;
      break;
    }

  extent_ = caps.currentExtent.width != UINT32_MAX ? caps.currentExtent : extent;
  extent_.width = std::clamp(extent_.width, caps.minImageExtent.width, caps.maxImageExtent.width);
  extent_.height =
      std::clamp(extent_.height, caps.minImageExtent.height, caps.maxImageExtent.height);
  VkImageUsageFlags usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
  if (copyable) {
    if (!(caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_SRC_BIT))
      throw WindowSystemUnavailable("the surface's images cannot be copied: no screenshots");
    usage |= VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  }

  VkSwapchainCreateInfoKHR info{VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR};
  info.surface = surface;
  info.minImageCount = caps.maxImageCount == 0 ? caps.minImageCount + 1
                                               : std::min(caps.minImageCount + 1, caps.maxImageCount);
  info.imageFormat = format_;
  info.imageColorSpace = chosen->colorSpace;
  info.imageExtent = extent_;
  info.imageArrayLayers = 1;
  info.imageUsage = usage;
  info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.preTransform = caps.currentTransform;
  info.compositeAlpha = (caps.supportedCompositeAlpha & VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR)
                            ? VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR
                            : VkCompositeAlphaFlagBitsKHR(caps.supportedCompositeAlpha &
                                                          -caps.supportedCompositeAlpha);
  info.presentMode = presentMode_;
  info.clipped = VK_TRUE;
  info.oldSwapchain = old;
  const vk::DeviceTable& vk = context.vk();
  VK_CHECK(vk.vkCreateSwapchainKHR(context.device(), &info, nullptr, &swapchain_));

  try {
    createViews();
  } catch (...) {
    release();  // a constructor that throws runs no destructor
    throw;
  }
}

void Swapchain::createViews() {
  const vk::DeviceTable& vk = context_.vk();
  uint32_t count = 0;
  VK_CHECK(vk.vkGetSwapchainImagesKHR(context_.device(), swapchain_, &count, nullptr));
  images_.resize(count);
  VK_CHECK(vk.vkGetSwapchainImagesKHR(context_.device(), swapchain_, &count, images_.data()));
  for (VkImage image : images_) {
    VkImageViewCreateInfo view{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    view.image = image;
    view.viewType = VK_IMAGE_VIEW_TYPE_2D;
    view.format = format_;
    view.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    views_.push_back(VK_NULL_HANDLE);
    VK_CHECK(vk.vkCreateImageView(context_.device(), &view, nullptr, &views_.back()));
  }
}

Swapchain::~Swapchain() { release(); }

void Swapchain::release() {
  const vk::DeviceTable& vk = context_.vk();
  for (VkImageView view : views_)
    if (view) vk.vkDestroyImageView(context_.device(), view, nullptr);
  if (swapchain_) vk.vkDestroySwapchainKHR(context_.device(), swapchain_, nullptr);
}

}  // namespace tessera::viewer
