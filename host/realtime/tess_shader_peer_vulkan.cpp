// Offscreen draw of bicubic patches through the tessellation stages. The control points are
// read by the vertex shader from a storage buffer (push descriptor), 16 vertices per patch,
// so the draw has no vertex input at all.
#include <cstdint>  // before the generated SPIR-V arrays, which use uint32_t

#include "realtime/tess_shader_peer.h"

#include "tess_peer_capture_geom.h"
#include "tess_peer_capture_tese.h"
#include "tess_peer_frag.h"
#include "tess_peer_tesc.h"
#include "tess_peer_tese.h"
#include "tess_peer_vert.h"
#include "vk/buffer.h"
#include "vk/image.h"
#include "vk/graphics.h"
#include "vk/loader.h"

#include <algorithm>

namespace tessera {

struct TessShaderPeer::Objects {
  explicit Objects(vk::Context& c) : context(c) {}
  ~Objects() {
    const vk::DeviceTable& vk = context.vk();
    VkDevice device = context.device();
    if (query) vk.vkDestroyQueryPool(device, query, nullptr);
    for (Pipeline* p : {&draw, &capture}) {
      if (p->pipeline) vk.vkDestroyPipeline(device, p->pipeline, nullptr);
      if (p->layout) vk.vkDestroyPipelineLayout(device, p->layout, nullptr);
      if (p->setLayout) vk.vkDestroyDescriptorSetLayout(device, p->setLayout, nullptr);
    }
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
  struct Pipeline {
    VkDescriptorSetLayout setLayout = VK_NULL_HANDLE;
    VkPipelineLayout layout = VK_NULL_HANDLE;
    VkPipeline pipeline = VK_NULL_HANDLE;
  };
  Pipeline draw;     // the timed one: vertex, tessellation, fragment
  Pipeline capture;  // made on the first captureFrame: + the recording geometry stage
  vk::Buffer captured, capturedCount;  // TessPeerTriangle records; their count (atomic)
  VkQueryPool query = VK_NULL_HANDLE;
};

namespace {

constexpr VkFormat kColourFormat = VK_FORMAT_R8G8B8A8_UNORM;
constexpr VkFormat kDepthFormat = VK_FORMAT_D16_UNORM;
constexpr VkShaderStageFlags kTessStages =
    VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT | VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT;
// The capture draws at most this many patches a draw: lavapipe's gl_PrimitiveID (the patch
// within the draw) wraps at 256, so each draw's first patch is pushed to the geometry stage.
constexpr uint32_t kCapturePatchesPerDraw = 256;
constexpr uint32_t kCapturePatchBaseOffset = sizeof(gpu::TessPeerPush);

void createPipeline(TessShaderPeer::Objects& d, bool capture);
void recordDraw(TessShaderPeer::Objects& d, VkCommandBuffer cmd, bool capture,
                const glm::mat4& viewProjection);

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
  createPipeline(*d_, false);
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

void TessShaderPeer::setFactorScale(float factorScale) { d_->options.factorScale = factorScale; }

bool TessShaderPeer::capturesTriangles() const {
  return d_->context.enabledFeatures().geometryShader &&
         d_->context.enabledFeatures().vertexPipelineStoresAndAtomics;
}

namespace {
// The draw pipeline reads the control points (binding 0, vertex stage); the capture pipeline
// also writes the triangles (1) and their count (2) from its geometry stage.
void createPipeline(TessShaderPeer::Objects& d, bool capture) {
  const vk::DeviceTable& vk = d.context.vk();
  VkDevice device = d.context.device();
  TessShaderPeer::Objects::Pipeline& p = capture ? d.capture : d.draw;
  const VkDescriptorSetLayoutBinding bindings[3] = {
      {0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_VERTEX_BIT, nullptr},
      {1, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_GEOMETRY_BIT, nullptr},
      {2, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_GEOMETRY_BIT, nullptr}};
  VkDescriptorSetLayoutCreateInfo setInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  setInfo.flags = VK_DESCRIPTOR_SET_LAYOUT_CREATE_PUSH_DESCRIPTOR_BIT_KHR;
  setInfo.bindingCount = capture ? 3 : 1;
  setInfo.pBindings = bindings;
  VK_CHECK(vk.vkCreateDescriptorSetLayout(device, &setInfo, nullptr, &p.setLayout));
  // The capture's geometry stage reads the draw's first patch after TessPeerPush.
  const VkPushConstantRange ranges[2] = {
      {kTessStages, 0, sizeof(gpu::TessPeerPush)},
      {VK_SHADER_STAGE_GEOMETRY_BIT, kCapturePatchBaseOffset, sizeof(uint32_t)}};
  VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layoutInfo.setLayoutCount = 1;
  layoutInfo.pSetLayouts = &p.setLayout;
  layoutInfo.pushConstantRangeCount = capture ? 2 : 1;
  layoutInfo.pPushConstantRanges = ranges;
  VK_CHECK(vk.vkCreatePipelineLayout(device, &layoutInfo, nullptr, &p.layout));

  vk::GraphicsPipelineDesc desc;
  desc.stages = {
      {VK_SHADER_STAGE_VERTEX_BIT, kSpirv_tess_peer_vert, sizeof(kSpirv_tess_peer_vert)},
      {VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT, kSpirv_tess_peer_tesc, sizeof(kSpirv_tess_peer_tesc)},
      {VK_SHADER_STAGE_FRAGMENT_BIT, kSpirv_tess_peer_frag, sizeof(kSpirv_tess_peer_frag)}};
  if (capture) {
    desc.stages.push_back({VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT,
                           kSpirv_tess_peer_capture_tese, sizeof(kSpirv_tess_peer_capture_tese)});
    desc.stages.push_back({VK_SHADER_STAGE_GEOMETRY_BIT, kSpirv_tess_peer_capture_geom,
                           sizeof(kSpirv_tess_peer_capture_geom)});
  } else {
    desc.stages.push_back({VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT, kSpirv_tess_peer_tese,
                           sizeof(kSpirv_tess_peer_tese)});
  }
  desc.topology = VK_PRIMITIVE_TOPOLOGY_PATCH_LIST;
  desc.patchControlPoints = 16;
  desc.extent = {d.options.width, d.options.height};
  desc.depthCompare = VK_COMPARE_OP_LESS_OR_EQUAL;
  desc.layout = p.layout;
  desc.renderPass = d.renderPass;
  p.pipeline = vk::createGraphicsPipeline(d.context, desc);
}

VkWriteDescriptorSet storageWrite(uint32_t binding, const VkDescriptorBufferInfo* buffer) {
  VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
  write.dstBinding = binding;
  write.descriptorCount = 1;
  write.descriptorType = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
  write.pBufferInfo = buffer;
  return write;
}

// One frame's render pass, the primitives query around it.
void recordDraw(TessShaderPeer::Objects& d, VkCommandBuffer cmd, bool capture,
                const glm::mat4& viewProjection) {
  const vk::DeviceTable& vk = d.context.vk();
  const TessShaderPeer::Objects::Pipeline& p = capture ? d.capture : d.draw;
  gpu::TessPeerPush push{};
  for (int c = 0; c < 4; ++c) push.viewProjection[c] = viewProjection[c];
  push.params = glm::vec4(float(d.options.width), float(d.options.height),
                          d.options.tolerancePixels, d.options.maxFactor);
  push.rules = glm::vec4(d.options.factorScale, d.options.collapsedSideScale, 0.0f, 0.0f);
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
  vk.vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, p.pipeline);
  const VkDescriptorBufferInfo buffers[3] = {{d.patches.handle(), 0, VK_WHOLE_SIZE},
                                             {d.captured.handle(), 0, VK_WHOLE_SIZE},
                                             {d.capturedCount.handle(), 0, VK_WHOLE_SIZE}};
  const VkWriteDescriptorSet writes[3] = {storageWrite(0, &buffers[0]),
                                          storageWrite(1, &buffers[1]),
                                          storageWrite(2, &buffers[2])};
  vk.vkCmdPushDescriptorSetKHR(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, p.layout, 0,
                               capture ? 3 : 1, writes);
  vk.vkCmdPushConstants(cmd, p.layout, kTessStages, 0, sizeof push, &push);
  if (!capture && d.patchCount) vk.vkCmdDraw(cmd, 16 * d.patchCount, 1, 0, 0);
  for (uint32_t first = 0; capture && first < d.patchCount; first += kCapturePatchesPerDraw) {
    vk.vkCmdPushConstants(cmd, p.layout, VK_SHADER_STAGE_GEOMETRY_BIT, kCapturePatchBaseOffset,
                          sizeof first, &first);
    vk.vkCmdDraw(cmd, 16 * std::min(kCapturePatchesPerDraw, d.patchCount - first), 1, 16 * first,
                 0);
  }
  vk.vkCmdEndRenderPass(cmd);
  if (d.query) vk.vkCmdEndQuery(cmd, d.query, 0);
}

}  // namespace

uint64_t TessShaderPeer::drawFrame(const glm::mat4& viewProjection) {
  Objects& d = *d_;
  d.context.submitAndWait([&](VkCommandBuffer cmd) { recordDraw(d, cmd, false, viewProjection); });
  uint64_t primitives = 0;
  if (d.query)
    VK_CHECK(d.context.vk().vkGetQueryPoolResults(
        d.context.device(), d.query, 0, 1, sizeof primitives, &primitives, sizeof primitives,
        VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
  return primitives;
}

std::vector<gpu::TessPeerTriangle> TessShaderPeer::captureFrame(const glm::mat4& viewProjection) {
  Objects& d = *d_;
  if (!capturesTriangles())
    throw vk::VulkanUnavailable("device '" + d.context.info().name +
                                "': capturing the peer's triangles needs the geometryShader and "
                                "vertexPipelineStoresAndAtomics features");
  if (!d.capture.pipeline) {
    d.capturedCount = vk::Buffer(d.context, sizeof(uint32_t), vk::BufferUse::Upload);
    createPipeline(d, true);
  }
  // Twice at most: a frame with more triangles than the buffer holds is drawn again into one
  // that holds them all (the count is exact either way).
  for (;;) {
    vk::ensureCapacity(d.context, d.captured, 1024 * sizeof(gpu::TessPeerTriangle),
                       vk::BufferUse::Readback);
    const uint32_t zero = 0;
    d.capturedCount.upload(&zero, sizeof zero);
    d.context.submitAndWait([&](VkCommandBuffer cmd) {
      recordDraw(d, cmd, true, viewProjection);
      VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
      barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
      barrier.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
      d.context.vk().vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_GEOMETRY_SHADER_BIT,
                                          VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &barrier, 0, nullptr,
                                          0, nullptr);
    });
    uint32_t count = 0;
    d.capturedCount.download(&count, sizeof count);
    const VkDeviceSize bytes = VkDeviceSize(count) * sizeof(gpu::TessPeerTriangle);
    if (bytes <= d.captured.size()) {
      std::vector<gpu::TessPeerTriangle> triangles;
      d.captured.download(triangles, count);
      return triangles;
    }
    vk::ensureCapacity(d.context, d.captured, bytes, vk::BufferUse::Readback);
  }
}

}  // namespace tessera
