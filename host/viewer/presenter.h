// Draws a frame into the window: the mesh (shaders/mesh.*.glsl, as tessera render draws it)
// and the overlay text on top, then presents. One frame in flight: present() returns when the
// GPU is done, so the caller may rewrite the vertex buffers for the next frame at once.
#pragma once
#include "vk/backend_only.h"
#include <cstdint>
#include <memory>
#include <vector>

#include "shaders/layout.h"
#include "viewer/draw_vertex.h"
#include "viewer/swapchain.h"
#include "vk/buffer.h"
#include "vk/context.h"
#include "vk/image.h"

namespace tessera::viewer {

class Window;

// A draw: `vertexCount` DrawVertex of `buffer` as a triangle list with `push`.
struct DrawCall {
  VkBuffer buffer = VK_NULL_HANDLE;
  uint32_t vertexCount = 0;
  gpu::MeshDrawPush push{};
};

class Presenter {
 public:
  // `copyable`: frames can be read back (screenshots).
  Presenter(vk::Context& context, Window& window, VkSurfaceKHR surface, bool copyable);
  ~Presenter();
  Presenter(const Presenter&) = delete;
  Presenter& operator=(const Presenter&) = delete;

  VkExtent2D extent() const { return swapchain_->extent(); }

  // Draws `calls` in order (depth-tested, one depth buffer) and presents. With `screenshot`,
  // the picture is also copied back as RGBA8, rows top first. Returns false when the window
  // changed size and the frame was dropped (the swapchain is made again: draw again with the
  // new extent()).
  bool present(const std::vector<DrawCall>& calls, std::vector<uint8_t>* screenshot);

 private:
  void createTargets();  // swapchain, depth image, framebuffers, pipeline
  void destroyTargets();
  void recreate();
  void release();

  vk::Context& context_;
  Window& window_;
  VkSurfaceKHR surface_;
  bool copyable_;
  VkFormat depthFormat_ = VK_FORMAT_D16_UNORM;
  std::unique_ptr<Swapchain> swapchain_;
  vk::Image depth_;
  VkRenderPass renderPass_ = VK_NULL_HANDLE;
  std::vector<VkFramebuffer> framebuffers_;
  VkPipelineLayout layout_ = VK_NULL_HANDLE;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
  VkCommandPool pool_ = VK_NULL_HANDLE;
  VkCommandBuffer commands_ = VK_NULL_HANDLE;
  VkSemaphore imageAvailable_ = VK_NULL_HANDLE;
  std::vector<VkSemaphore> renderFinished_;  // one per swapchain image: present may hold it
  VkFence done_ = VK_NULL_HANDLE;
  vk::Buffer readback_;
};

}  // namespace tessera::viewer
