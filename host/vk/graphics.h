// Graphics pipelines and render passes for offscreen drawing (tessera render, the
// tessellation-shader peer). One colour and one depth attachment, drawn into images that are
// copied to the host afterwards; pipelines are built from embedded SPIR-V.
#pragma once
#include "vk/backend_only.h"
#include <cstddef>
#include <cstdint>
#include <vector>

#include "vk/context.h"

namespace tessera::vk {

// Attachments 0 colour and 1 depth, both `samples`; with multisampling, 2 is the
// single-sample resolve target. The picture (colour, or the resolve target) ends in
// `pictureLayout`: TRANSFER_SRC_OPTIMAL for a copy to the host, PRESENT_SRC_KHR for a swapchain
// image. Dependencies order the clears after earlier draws into the same attachments (frame
// after frame) and a copy after the last write.
VkRenderPass createColourDepthRenderPass(
    const Context& context, VkFormat colour, VkFormat depth, VkSampleCountFlagBits samples,
    VkImageLayout pictureLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL);

struct ShaderStage {
  VkShaderStageFlagBits stage;
  const uint32_t* spirv;
  size_t bytes;
};

struct GraphicsPipelineDesc {
  std::vector<ShaderStage> stages;
  std::vector<VkVertexInputBindingDescription> bindings;
  std::vector<VkVertexInputAttributeDescription> attributes;
  VkPrimitiveTopology topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
  uint32_t patchControlPoints = 0;  // > 0 with tessellation stages (topology PATCH_LIST)
  VkExtent2D extent{};              // fixed viewport and scissor
  VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
  VkCompareOp depthCompare = VK_COMPARE_OP_LESS;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkRenderPass renderPass = VK_NULL_HANDLE;
};

// No face culling (open surfaces show both sides), depth test and write on, colour written
// whole. Shader modules live only during the call. Uses the context's pipeline cache.
VkPipeline createGraphicsPipeline(const Context& context, const GraphicsPipelineDesc& desc);

}  // namespace tessera::vk
