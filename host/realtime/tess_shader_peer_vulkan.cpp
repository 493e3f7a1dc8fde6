// Offscreen draw of bicubic patches through the tessellation stages. The control points are
// read by the vertex shader from a storage buffer (push descriptor), 16 vertices per patch,
// so the draw has no vertex input at all.
#include <cstdint>  // before the generated SPIR-V arrays, which use uint32_t

#include "realtime/tess_shader_peer.h"

#include "tess_peer_frag.h"
#include "tess_peer_tesc.h"
#include "tess_peer_tese.h"
#include "tess_peer_vert.h"
#include "vk/buffer.h"
#include "vk/image.h"
#include "vk/graphics.h"
#include "vk/loader.h"

namespace tessera {

struct TessShaderPeer::Objects {
  explicit Objects(vk::Context& c) : context(c) {}
  ~Objects() {
    const vk::DeviceTable& vk = context.vk();
    VkDevice device = context.device();
    if (query) vk.vkDestroyQueryPool(device, query, nullptr);
    if (pipeline) vk.vkDestroyPipeline(device, pipeline, nullptr);
    if (layout) vk.vkDestroyPipelineLayout(device, layout, nullptr);
    if (setLayout) vk.vkDestroyDescriptorSetLayout(device, setLayout, nullptr);
    if (framebuffer) vk.vkDestroyFramebuffer(device, framebuffer, nullptr);
    if (renderPass) vk.vkDestroyRenderPass(device, renderPass, nullptr);
  }
  vk::Context& context;
  TessPeerOptions options;
  uint32_t patchCount = 0;
  vk::Buffer patches;
  vk::Image colour, depth;
  VkRenderPass renderPass = VK_NULL_HANDLE;
  VkFramebuffer framebuffer = VK_NULL_HANDLE;
  VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkPipeline pipeline = VK_NULL_HANDLE;
  VkQueryPool query = VK_NULL_HANDLE;
};

namespace {

constexpr VkFormat kColourFormat = VK_FORMAT_R8G8B8A8_UNORM;
constexpr VkFormat kDepthFormat = VK_FORMAT_D16_UNORM;
constexpr VkShaderStageFlags kTessStages =
    VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT | VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT;

void createPipelineFor(TessShaderPeer::Objects& d);

}  // namespace

TessShaderPeer::TessShaderPeer(vk::Context& context, const std::vector<gpu::BicubicPatch>& patches,
                               const TessPeerOptions& options)
    : d_(std::make_unique<Objects>(context)) {
  if (!context.enabledFeatures().tessellationShader || !context.queueSupportsGraphics())
    throw vk::VulkanUnavailable("device '" + context.info().name +
                                "' has no tessellation shaders or no graphics queue");
  d_->options = options;
  d_->patchCount = uint32_t(patches.size());
  d_->patches = vk::Buffer(context, std::max<size_t>(1, patches.size()) * sizeof(gpu::BicubicPatch),
                           vk::BufferUse::Upload);
  if (!patches.empty()) d_->patches.upload(patches);
  // TRANSFER_SRC: the shared render pass leaves the picture ready for a copy.
  d_->colour = vk::Image(context, {options.width, options.height, kColourFormat,
                                   VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT |
                                       VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                   VK_IMAGE_ASPECT_COLOR_BIT,
                                   VK_SAMPLE_COUNT_1_BIT});
  d_->depth = vk::Image(context, {options.width, options.height, kDepthFormat,
                                  VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                                  VK_IMAGE_ASPECT_DEPTH_BIT, VK_SAMPLE_COUNT_1_BIT});
  d_->renderPass =
      vk::createColourDepthRenderPass(context, kColourFormat, kDepthFormat, VK_SAMPLE_COUNT_1_BIT);
  VkImageView views[2] = {d_->colour.view(), d_->depth.view()};
  VkFramebufferCreateInfo fb{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
  fb.renderPass = d_->renderPass;
  fb.attachmentCount = 2;
  fb.pAttachments = views;
  fb.width = options.width;
  fb.height = options.height;
  fb.layers = 1;
  VK_CHECK(context.vk().vkCreateFramebuffer(context.device(), &fb, nullptr, &d_->framebuffer));
  createPipelineFor(*d_);
  if (context.enabledFeatures().pipelineStatisticsQuery) {
    VkQueryPoolCreateInfo q{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
    q.queryType = VK_QUERY_TYPE_PIPELINE_STATISTICS;
    q.queryCount = 1;
    q.pipelineStatistics = VK_QUERY_PIPELINE_STATISTIC_CLIPPING_INVOCATIONS_BIT;
    VK_CHECK(context.vk().vkCreateQueryPool(context.device(), &q, nullptr, &d_->query));
  }
}

TessShaderPeer::~TessShaderPeer() = default;

bool TessShaderPeer::countsTriangles() const { return d_->query != VK_NULL_HANDLE; }

namespace {
void createPipelineFor(TessShaderPeer::Objects& d) {
  const vk::DeviceTable& vk = d.context.vk();
  VkDevice device = d.context.device();
  VkDescriptorSetLayoutBinding binding{0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1,
                                       VK_SHADER_STAGE_VERTEX_BIT, nullptr};
  VkDescriptorSetLayoutCreateInfo setInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  setInfo.flags = VK_DESCRIPTOR_SET_LAYOUT_CREATE_PUSH_DESCRIPTOR_BIT_KHR;
  setInfo.bindingCount = 1;
  setInfo.pBindings = &binding;
  VK_CHECK(vk.vkCreateDescriptorSetLayout(device, &setInfo, nullptr, &d.setLayout));
  VkPushConstantRange range{kTessStages, 0, sizeof(gpu::TessPeerPush)};
  VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layoutInfo.setLayoutCount = 1;
  layoutInfo.pSetLayouts = &d.setLayout;
  layoutInfo.pushConstantRangeCount = 1;
  layoutInfo.pPushConstantRanges = &range;
  VK_CHECK(vk.vkCreatePipelineLayout(device, &layoutInfo, nullptr, &d.layout));

  vk::GraphicsPipelineDesc desc;
  desc.stages = {
      {VK_SHADER_STAGE_VERTEX_BIT, kSpirv_tess_peer_vert, sizeof(kSpirv_tess_peer_vert)},
      {VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT, kSpirv_tess_peer_tesc, sizeof(kSpirv_tess_peer_tesc)},
      {VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT, kSpirv_tess_peer_tese, sizeof(kSpirv_tess_peer_tese)},
      {VK_SHADER_STAGE_FRAGMENT_BIT, kSpirv_tess_peer_frag, sizeof(kSpirv_tess_peer_frag)}};
  desc.topology = VK_PRIMITIVE_TOPOLOGY_PATCH_LIST;
  desc.patchControlPoints = 16;
  desc.extent = {d.options.width, d.options.height};
  desc.depthCompare = VK_COMPARE_OP_LESS_OR_EQUAL;
  desc.layout = d.layout;
  desc.renderPass = d.renderPass;
  d.pipeline = vk::createGraphicsPipeline(d.context, desc);
}
}  // namespace

uint64_t TessShaderPeer::drawFrame(const glm::mat4& viewProjection) {
  Objects& d = *d_;
  const vk::DeviceTable& vk = d.context.vk();
  gpu::TessPeerPush push{};
  for (int c = 0; c < 4; ++c) push.viewProjection[c] = viewProjection[c];
  push.params = glm::vec4(float(d.options.width), float(d.options.height),
                          d.options.tolerancePixels, d.options.maxFactor);
  d.context.submitAndWait([&](VkCommandBuffer cmd) {
    if (d.query) vk.vkCmdResetQueryPool(cmd, d.query, 0, 1);
    VkClearValue clears[2]{};
    clears[0].color = {{0.96f, 0.96f, 0.97f, 1.0f}};
    clears[1].depthStencil = {1.0f, 0};
    VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    begin.renderPass = d.renderPass;
    begin.framebuffer = d.framebuffer;
    begin.renderArea = {{0, 0}, {d.options.width, d.options.height}};
    begin.clearValueCount = 2;
    begin.pClearValues = clears;
    if (d.query) vk.vkCmdBeginQuery(cmd, d.query, 0, 0);
    vk.vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
    vk.vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, d.pipeline);
    VkDescriptorBufferInfo buffer{d.patches.handle(), 0, VK_WHOLE_SIZE};
    VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
    write.dstBinding = 0;
    write.descriptorCount = 1;
    write.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    write.pBufferInfo = &buffer;
    vk.vkCmdPushDescriptorSetKHR(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, d.layout, 0, 1, &write);
    vk.vkCmdPushConstants(cmd, d.layout, kTessStages, 0, sizeof push, &push);
    if (d.patchCount) vk.vkCmdDraw(cmd, 16 * d.patchCount, 1, 0, 0);
    vk.vkCmdEndRenderPass(cmd);
    if (d.query) vk.vkCmdEndQuery(cmd, d.query, 0);
  });
  uint64_t primitives = 0;
  if (d.query)
    VK_CHECK(vk.vkGetQueryPoolResults(d.context.device(), d.query, 0, 1, sizeof primitives,
                                      &primitives, sizeof primitives,
                                      VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
  return primitives;
}

}  // namespace tessera
