#include "viewer/presenter.h"

#include <cstddef>
#include <cstring>

#include "render/offscreen.h"
#include "viewer/window.h"
#include "vk/graphics.h"
#include "vk/loader.h"

// The generated headers declare bare uint32_t arrays.
#include "mesh_frag.h"
#include "mesh_vert.h"

namespace tessera::viewer {
namespace {

// D32 when the device has it: the orbit camera's near plane comes close when zoomed in, where
// 16 bits would fight. D16 is the depth format every device must support.
VkFormat chooseDepthFormat(const vk::Context& context) {
  auto properties = reinterpret_cast<PFN_vkGetPhysicalDeviceFormatProperties>(
      vkGetInstanceProcAddr(context.instance(), "vkGetPhysicalDeviceFormatProperties"));
  VkFormatProperties p{};
  properties(context.physicalDevice(), VK_FORMAT_D32_SFLOAT, &p);
  return (p.optimalTilingFeatures & VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT)
             ? VK_FORMAT_D32_SFLOAT
             : VK_FORMAT_D16_UNORM;
}

void imageBarrier(const vk::DeviceTable& vk, VkCommandBuffer cmd, VkImage image,
                  VkImageLayout from, VkImageLayout to, VkPipelineStageFlags srcStage,
                  VkAccessFlags srcAccess, VkPipelineStageFlags dstStage, VkAccessFlags dstAccess) {
  VkImageMemoryBarrier barrier{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER};
  barrier.srcAccessMask = srcAccess;
  barrier.dstAccessMask = dstAccess;
  barrier.oldLayout = from;
  barrier.newLayout = to;
  barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.image = image;
  barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
  vk.vkCmdPipelineBarrier(cmd, srcStage, dstStage, 0, 0, nullptr, 0, nullptr, 1, &barrier);
}

}  // namespace

Presenter::Presenter(vk::Context& context, Window& window, VkSurfaceKHR surface, bool copyable)
    : context_(context), window_(window), surface_(surface), copyable_(copyable) {
  const vk::DeviceTable& vk = context.vk();
  VkDevice device = context.device();
  depthFormat_ = chooseDepthFormat(context);
  // Until createTargets, a throw leaks these few objects with the failing context.
  VkCommandPoolCreateInfo poolInfo{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO};
  poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
  poolInfo.queueFamilyIndex = context.queueFamily();
  VK_CHECK(vk.vkCreateCommandPool(device, &poolInfo, nullptr, &pool_));
  VkCommandBufferAllocateInfo allocate{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO};
  allocate.commandPool = pool_;
  allocate.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
  allocate.commandBufferCount = 1;
  VK_CHECK(vk.vkAllocateCommandBuffers(device, &allocate, &commands_));
  VkSemaphoreCreateInfo semaphoreInfo{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
  VK_CHECK(vk.vkCreateSemaphore(device, &semaphoreInfo, nullptr, &imageAvailable_));
  VkFenceCreateInfo fenceInfo{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
  VK_CHECK(vk.vkCreateFence(device, &fenceInfo, nullptr, &done_));
  try {
    createTargets();
  } catch (...) {
    release();  // a constructor that throws runs no destructor
    throw;
  }
}

Presenter::~Presenter() { release(); }

void Presenter::release() {
  const vk::DeviceTable& vk = context_.vk();
  vk.vkDeviceWaitIdle(context_.device());
  destroyTargets();
  swapchain_.reset();
  if (done_) vk.vkDestroyFence(context_.device(), done_, nullptr);
  if (imageAvailable_) vk.vkDestroySemaphore(context_.device(), imageAvailable_, nullptr);
  if (pool_) vk.vkDestroyCommandPool(context_.device(), pool_, nullptr);
}

void Presenter::createTargets() {
  const vk::DeviceTable& vk = context_.vk();
  VkDevice device = context_.device();
  int width = 0, height = 0;
  window_.framebufferSize(width, height);
  VkSwapchainKHR old = swapchain_ ? swapchain_->handle() : VK_NULL_HANDLE;
  auto next = std::make_unique<Swapchain>(context_, surface_,
                                          VkExtent2D{uint32_t(width), uint32_t(height)},
                                          copyable_, old);
  swapchain_ = std::move(next);
  const VkExtent2D extent = swapchain_->extent();
  depth_ = vk::Image(context_, {extent.width, extent.height, depthFormat_,
                                VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                                VK_IMAGE_ASPECT_DEPTH_BIT, VK_SAMPLE_COUNT_1_BIT});
  // vk/graphics.h's colour + depth pass, the colour ending ready to present.
  renderPass_ = vk::createColourDepthRenderPass(context_, swapchain_->format(), depthFormat_,
                                                VK_SAMPLE_COUNT_1_BIT,
                                                VK_IMAGE_LAYOUT_PRESENT_SRC_KHR);
  for (VkImageView view : swapchain_->views()) {
    VkImageView attachments[2] = {view, depth_.view()};
    VkFramebufferCreateInfo info{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
    info.renderPass = renderPass_;
    info.attachmentCount = 2;
    info.pAttachments = attachments;
    info.width = extent.width;
    info.height = extent.height;
    info.layers = 1;
    framebuffers_.push_back(VK_NULL_HANDLE);
    VK_CHECK(vk.vkCreateFramebuffer(device, &info, nullptr, &framebuffers_.back()));
    VkSemaphoreCreateInfo semaphoreInfo{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    renderFinished_.push_back(VK_NULL_HANDLE);
    VK_CHECK(vk.vkCreateSemaphore(device, &semaphoreInfo, nullptr, &renderFinished_.back()));
  }

  VkPushConstantRange range{VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                            sizeof(gpu::MeshDrawPush)};
  VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layoutInfo.pushConstantRangeCount = 1;
  layoutInfo.pPushConstantRanges = &range;
  VK_CHECK(vk.vkCreatePipelineLayout(device, &layoutInfo, nullptr, &layout_));
  vk::GraphicsPipelineDesc desc;
  desc.stages = {{VK_SHADER_STAGE_VERTEX_BIT, kSpirv_mesh_vert, sizeof kSpirv_mesh_vert},
                 {VK_SHADER_STAGE_FRAGMENT_BIT, kSpirv_mesh_frag, sizeof kSpirv_mesh_frag}};
  desc.bindings = {{0, sizeof(DrawVertex), VK_VERTEX_INPUT_RATE_VERTEX}};
  desc.attributes = {{0, 0, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(DrawVertex, position)},
                     {1, 0, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(DrawVertex, normal)}};
  desc.extent = extent;
  desc.layout = layout_;
  desc.renderPass = renderPass_;
  pipeline_ = vk::createGraphicsPipeline(context_, desc);
  if (copyable_)
    readback_ = vk::Buffer(context_, VkDeviceSize(extent.width) * extent.height * 4,
                           vk::BufferUse::Readback, VK_BUFFER_USAGE_TRANSFER_DST_BIT);
}

void Presenter::destroyTargets() {
  const vk::DeviceTable& vk = context_.vk();
  VkDevice device = context_.device();
  if (pipeline_) vk.vkDestroyPipeline(device, pipeline_, nullptr);
  if (layout_) vk.vkDestroyPipelineLayout(device, layout_, nullptr);
  for (VkFramebuffer f : framebuffers_) vk.vkDestroyFramebuffer(device, f, nullptr);
  for (VkSemaphore s : renderFinished_) vk.vkDestroySemaphore(device, s, nullptr);
  if (renderPass_) vk.vkDestroyRenderPass(device, renderPass_, nullptr);
  pipeline_ = VK_NULL_HANDLE;
  layout_ = VK_NULL_HANDLE;
  renderPass_ = VK_NULL_HANDLE;
  framebuffers_.clear();
  renderFinished_.clear();
  depth_ = vk::Image();
}

void Presenter::recreate() {
  VK_CHECK(context_.vk().vkDeviceWaitIdle(context_.device()));
  destroyTargets();
  createTargets();  // the old swapchain is retired into the new one, then destroyed
}

bool Presenter::present(const std::vector<DrawCall>& calls, std::vector<uint8_t>* screenshot) {
  const vk::DeviceTable& vk = context_.vk();
  VkDevice device = context_.device();
  uint32_t index = 0;
  VkResult acquired = vk.vkAcquireNextImageKHR(device, swapchain_->handle(), UINT64_MAX,
                                               imageAvailable_, VK_NULL_HANDLE, &index);
  if (acquired == VK_ERROR_OUT_OF_DATE_KHR) {
    recreate();
    return false;
  }
  if (acquired != VK_SUBOPTIMAL_KHR) VK_CHECK(acquired);
  const VkExtent2D extent = swapchain_->extent();
  const VkImage image = swapchain_->images()[index];

  VK_CHECK(vk.vkResetCommandBuffer(commands_, 0));
  VkCommandBufferBeginInfo begin{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO};
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  VK_CHECK(vk.vkBeginCommandBuffer(commands_, &begin));
  VkClearValue clears[2]{};
  for (int c = 0; c < 4; ++c) clears[0].color.float32[c] = kRenderBackground[c] / 255.0f;
  clears[1].depthStencil = {1.0f, 0};
  VkRenderPassBeginInfo pass{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
  pass.renderPass = renderPass_;
  pass.framebuffer = framebuffers_[index];
  pass.renderArea = {{0, 0}, extent};
  pass.clearValueCount = 2;
  pass.pClearValues = clears;
  vk.vkCmdBeginRenderPass(commands_, &pass, VK_SUBPASS_CONTENTS_INLINE);
  vk.vkCmdBindPipeline(commands_, VK_PIPELINE_BIND_POINT_GRAPHICS, pipeline_);
  for (const DrawCall& call : calls) {
    if (call.vertexCount == 0) continue;
    vk.vkCmdPushConstants(commands_, layout_,
                          VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                          sizeof call.push, &call.push);
    VkDeviceSize offset = 0;
    vk.vkCmdBindVertexBuffers(commands_, 0, 1, &call.buffer, &offset);
    vk.vkCmdDraw(commands_, call.vertexCount, 1, 0, 0);
  }
  vk.vkCmdEndRenderPass(commands_);
  if (screenshot) {
    imageBarrier(vk, commands_, image, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR,
                 VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT, 0,
                 VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {extent.width, extent.height, 1};
    vk.vkCmdCopyImageToBuffer(commands_, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                              readback_.handle(), 1, &region);
    // Back to the layout present expects; the copy only read the image.
    imageBarrier(vk, commands_, image, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                 VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, VK_PIPELINE_STAGE_TRANSFER_BIT, 0,
                 VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT, 0);
    VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vk.vkCmdPipelineBarrier(commands_, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT,
                            0, 1, &toHost, 0, nullptr, 0, nullptr);
  }
  VK_CHECK(vk.vkEndCommandBuffer(commands_));

  // The acquire semaphore guards the first write to the image: the render pass's layout
  // change and clear (colour attachment output), or the copy that follows them.
  VkPipelineStageFlags waitStage = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT;
  VkSubmitInfo submit{VK_STRUCTURE_TYPE_SUBMIT_INFO};
  submit.waitSemaphoreCount = 1;
  submit.pWaitSemaphores = &imageAvailable_;
  submit.pWaitDstStageMask = &waitStage;
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &commands_;
  submit.signalSemaphoreCount = 1;
  submit.pSignalSemaphores = &renderFinished_[index];
  VK_CHECK(vk.vkQueueSubmit(context_.queue(), 1, &submit, done_));

  VkPresentInfoKHR presentInfo{VK_STRUCTURE_TYPE_PRESENT_INFO_KHR};
  presentInfo.waitSemaphoreCount = 1;
  presentInfo.pWaitSemaphores = &renderFinished_[index];
  VkSwapchainKHR swapchain = swapchain_->handle();
  presentInfo.swapchainCount = 1;
  presentInfo.pSwapchains = &swapchain;
  presentInfo.pImageIndices = &index;
  VkResult presented = vk.vkQueuePresentKHR(context_.queue(), &presentInfo);
  // One frame in flight: the caller rewrites vertex buffers next, and the readback is read now.
  VK_CHECK(vk.vkWaitForFences(device, 1, &done_, VK_TRUE, UINT64_MAX));
  VK_CHECK(vk.vkResetFences(device, 1, &done_));

  if (screenshot) {
    readback_.download(*screenshot, size_t(extent.width) * extent.height * 4);
    if (swapchain_->format() == VK_FORMAT_B8G8R8A8_UNORM)
      for (size_t p = 0; p < screenshot->size(); p += 4) std::swap((*screenshot)[p], (*screenshot)[p + 2]);
  }
  if (presented == VK_ERROR_OUT_OF_DATE_KHR || presented == VK_SUBOPTIMAL_KHR) {
    recreate();
    return true;
  }
  VK_CHECK(presented);
  return true;
}

}  // namespace tessera::viewer
