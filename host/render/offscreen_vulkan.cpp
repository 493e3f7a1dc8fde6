#include "render/offscreen.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <stdexcept>
#include <string>

#include "vk/buffer.h"
#include "vk/context.h"
#include "vk/image.h"
#include "vk/graphics.h"
#include "vk/loader.h"

#include "shaders/layout.h"
// The generated headers declare bare uint32_t arrays.
#include <cstdint>
#include "mesh_frag.h"
#include "mesh_vert.h"

namespace tessera {
namespace {

constexpr VkFormat kColourFormat = VK_FORMAT_R8G8B8A8_UNORM;
// D16 is the one depth format every device must support as an attachment; the camera's near
// and far planes hug the bounding sphere, so 16 bits are plenty.
constexpr VkFormat kDepthFormat = VK_FORMAT_D16_UNORM;

// One vertex of the un-indexed triangle list: the two vec4 inputs of mesh.vert.glsl.
struct DrawVertex {
  glm::vec3 position;
  float value;  // the triangle's palette value
  glm::vec3 normal;
  float corner;  // 0, 1 or 2: becomes the barycentric coordinate
};
static_assert(sizeof(DrawVertex) == 32, "DrawVertex: two vec4 attributes");

struct Camera {
  glm::mat4 viewProjection;
  glm::vec3 eye;
  glm::vec3 light;  // unit, towards the light
};

// Looks along `look` at the box centre from the distance at which every box corner falls
// inside the frustum (with a 6% margin): a corner at (x, y) across and z along the view from
// the centre is inside when |x| ≤ tanX·(d + z) and |y| ≤ tanY·(d + z).
Camera frameBox(const BoundingBox& box, const RenderOptions& o) {
  glm::vec3 look = glm::normalize(o.viewDirection);
  glm::vec3 up = o.up;
  float upLength = glm::length(up);
  if (!(upLength > 0.0f) || glm::length(glm::cross(look, up)) < 1e-3f * upLength)  // no up, or along it
    up = std::fabs(look.z) < 0.9f ? glm::vec3(0, 0, 1) : glm::vec3(0, 1, 0);
  glm::vec3 right = glm::normalize(glm::cross(look, up));
  glm::vec3 screenUp = glm::cross(right, look);

  glm::vec3 centre = 0.5f * (box.lo + box.hi);
  float radius = 0.5f * glm::length(box.hi - box.lo);
  if (!(radius > 0.0f)) radius = 1.0f;  // a single point: any distance shows it
  float aspect = float(o.width) / float(o.height);
  float tanY = std::tan(glm::radians(o.verticalFovDegrees) * 0.5f) / 1.06f;
  float tanX = tanY * aspect;
  float distance = 0.0f;
  for (int k = 0; k < 8; ++k) {
    glm::vec3 corner((k & 1) ? box.hi.x : box.lo.x, (k & 2) ? box.hi.y : box.lo.y,
                     (k & 4) ? box.hi.z : box.lo.z);
    glm::vec3 rel = corner - centre;
    float z = glm::dot(rel, look);
    distance = std::max({distance, std::fabs(glm::dot(rel, right)) / tanX - z,
                         std::fabs(glm::dot(rel, screenUp)) / tanY - z});
  }
  distance = std::max(distance, 1e-3f * radius);
  float nearPlane = std::max(distance - 1.01f * radius, 1e-3f * distance);
  float farPlane = distance + 1.01f * radius;

  Camera camera;
  camera.eye = centre - look * distance;
  glm::mat4 view = glm::lookAtRH(camera.eye, centre, screenUp);
  glm::mat4 projection = glm::perspectiveRH_ZO(glm::radians(o.verticalFovDegrees), aspect,
                                               nearPlane, farPlane);
  projection[1][1] = -projection[1][1];  // Vulkan's clip y points down
  camera.viewProjection = projection * view;
  // A key light from the upper left, from behind the viewer: round shapes get a lit and a
  // shaded side while everything in view still faces it a little.
  camera.light = glm::normalize(-look + 0.9f * screenUp - 0.9f * right);
  return camera;
}

}  // namespace

glm::mat4 frameViewProjection(const BoundingBox& box, const RenderOptions& options) {
  return frameBox(box, options).viewProjection;
}

namespace {

std::vector<DrawVertex> unindex(const TriangleMesh& mesh, const std::vector<float>& values) {
  std::vector<DrawVertex> vertices(mesh.indices.size());
  for (size_t t = 0; t < mesh.triangleCount(); ++t) {
    const uint32_t* tri = &mesh.indices[3 * t];
    glm::vec3 p[3] = {mesh.positions[tri[0]], mesh.positions[tri[1]], mesh.positions[tri[2]]};
    glm::vec3 facet = glm::cross(p[1] - p[0], p[2] - p[0]);
    for (int k = 0; k < 3; ++k) {
      glm::vec3 n = mesh.normals.empty() ? glm::vec3(0.0f) : mesh.normals[tri[k]];
      if (glm::dot(n, n) < 1e-12f) n = facet;  // no normal, or none at a degenerate point
      vertices[3 * t + k] = {p[k], values.empty() ? 0.0f : values[t], n, float(k)};
    }
  }
  return vertices;
}

// The Vulkan objects of one draw, destroyed together however far their creation got.
struct DrawObjects {
  explicit DrawObjects(vk::Context& c) : context(c) {}
  ~DrawObjects() {
    const vk::DeviceTable& vk = context.vk();
    VkDevice device = context.device();
    if (pipeline) vk.vkDestroyPipeline(device, pipeline, nullptr);
    if (layout) vk.vkDestroyPipelineLayout(device, layout, nullptr);
    if (framebuffer) vk.vkDestroyFramebuffer(device, framebuffer, nullptr);
    if (renderPass) vk.vkDestroyRenderPass(device, renderPass, nullptr);
  }
  DrawObjects(const DrawObjects&) = delete;
  DrawObjects& operator=(const DrawObjects&) = delete;

  vk::Context& context;
  VkRenderPass renderPass = VK_NULL_HANDLE;
  VkFramebuffer framebuffer = VK_NULL_HANDLE;
  VkPipelineLayout layout = VK_NULL_HANDLE;
  VkPipeline pipeline = VK_NULL_HANDLE;
};

void createPipeline(DrawObjects& d, VkSampleCountFlagBits samples, VkExtent2D extent) {
  const vk::Context& context = d.context;
  VkPushConstantRange range{VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                            sizeof(gpu::MeshDrawPush)};
  VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layoutInfo.pushConstantRangeCount = 1;
  layoutInfo.pPushConstantRanges = &range;
  VK_CHECK(context.vk().vkCreatePipelineLayout(context.device(), &layoutInfo, nullptr, &d.layout));

  vk::GraphicsPipelineDesc desc;
  desc.stages = {{VK_SHADER_STAGE_VERTEX_BIT, kSpirv_mesh_vert, sizeof kSpirv_mesh_vert},
                 {VK_SHADER_STAGE_FRAGMENT_BIT, kSpirv_mesh_frag, sizeof kSpirv_mesh_frag}};
  desc.bindings = {{0, sizeof(DrawVertex), VK_VERTEX_INPUT_RATE_VERTEX}};
  desc.attributes = {{0, 0, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(DrawVertex, position)},
                     {1, 0, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(DrawVertex, normal)}};
  desc.extent = extent;
  desc.samples = samples;
  desc.layout = d.layout;
  desc.renderPass = d.renderPass;
  d.pipeline = vk::createGraphicsPipeline(context, desc);
}

void checkOptions(const TriangleMesh& mesh, const std::vector<float>& values,
                  const RenderOptions& o) {
  auto fail = [](const std::string& why) { throw std::invalid_argument("renderMesh: " + why); };
  if (o.width < 1 || o.height < 1 || o.width > kMaxRenderExtent || o.height > kMaxRenderExtent)
    fail("size " + std::to_string(o.width) + "x" + std::to_string(o.height) + " outside 1.." +
         std::to_string(kMaxRenderExtent));
  if (o.samples != 1 && o.samples != 4)
    fail("samples " + std::to_string(o.samples) + ": expected 1 or 4");
  if (!(glm::length(o.viewDirection) > 0.0f) || !std::isfinite(glm::length(o.viewDirection)))
    fail("the view direction must be a finite non-zero vector");
  if (!(o.verticalFovDegrees > 1.0f && o.verticalFovDegrees < 170.0f))
    fail("vertical field of view " + std::to_string(o.verticalFovDegrees) + " outside 1..170");
  if (!values.empty() && values.size() != mesh.triangleCount())
    fail(std::to_string(values.size()) + " values for " +
         std::to_string(mesh.triangleCount()) + " triangles");
  if (o.colour != RenderOptions::Colour::Shaded && values.empty() && mesh.triangleCount() > 0)
    fail(std::string(o.colour == RenderOptions::Colour::Depth ? "depth" : "patch") +
         " colouring needs a value for every triangle");
  if (o.frame && o.frame->empty()) fail("the frame box is empty");
}

}  // namespace

std::array<uint8_t, 3> paletteColour(RenderOptions::Colour colour, int value) {
  using gpu::vec3;
  static const vec3 depth[] = {TESSERA_DEPTH_PALETTE};
  static const vec3 patch[] = {TESSERA_PATCH_PALETTE};
  static_assert(std::size(depth) == gpu::kDepthPaletteSize &&
                std::size(patch) == gpu::kPatchPaletteSize, "palette sizes");
  value = std::max(value, 0);
  vec3 c = colour == RenderOptions::Colour::Depth   ? depth[std::min(value, gpu::kDepthPaletteSize - 1)]
           : colour == RenderOptions::Colour::Patch ? patch[value % gpu::kPatchPaletteSize]
                                                    : vec3(TESSERA_PORCELAIN);
  return {uint8_t(std::lround(c.x * 255)), uint8_t(std::lround(c.y * 255)),
          uint8_t(std::lround(c.z * 255))};
}

BoundingBox boundingBox(const TriangleMesh& mesh) {
  BoundingBox box;
  for (uint32_t i : mesh.indices) box.add(mesh.positions[i]);
  return box;
}

std::vector<uint8_t> renderMesh(vk::Context& context, const TriangleMesh& mesh,
                                const std::vector<float>& perTriangleValue,
                                const RenderOptions& options) {
  mesh.validate();
  checkOptions(mesh, perTriangleValue, options);
  if (!context.queueSupportsGraphics())
    throw vk::VulkanUnavailable("device '" + context.info().name +
                                "' has no queue that draws: rendering needs a graphics queue");
  const auto width = uint32_t(options.width), height = uint32_t(options.height);
  const auto samples = static_cast<VkSampleCountFlagBits>(options.samples);
  const bool resolve = samples != VK_SAMPLE_COUNT_1_BIT;

  BoundingBox box = options.frame ? *options.frame : boundingBox(mesh);
  if (box.empty()) box.add(glm::vec3(0.0f));
  Camera camera = frameBox(box, options);
  gpu::MeshDrawPush push{};
  for (int c = 0; c < 4; ++c) push.viewProjection[c] = camera.viewProjection[c];
  push.eye = glm::vec4(camera.eye, 1.0f);
  push.light = glm::vec4(camera.light, 0.2f);  // w: ambient
  push.colourMode = options.colour == RenderOptions::Colour::Depth   ? gpu::kColourDepth
                    : options.colour == RenderOptions::Colour::Patch ? gpu::kColourPatch
                                                                     : gpu::kColourShaded;
  push.wireframe = options.wireframe ? 1u : 0u;
  push.wireWidth = options.wireWidth;

  vk::Image colour(context, {width, height, kColourFormat,
                             resolve ? VkImageUsageFlags(VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT)
                                     : VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT |
                                           VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                             VK_IMAGE_ASPECT_COLOR_BIT, samples});
  vk::Image depth(context, {width, height, kDepthFormat,
                            VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, VK_IMAGE_ASPECT_DEPTH_BIT,
                            samples});
  vk::Image resolved;
  if (resolve)
    resolved = vk::Image(context, {width, height, kColourFormat,
                                   VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT |
                                       VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                                   VK_IMAGE_ASPECT_COLOR_BIT, VK_SAMPLE_COUNT_1_BIT});
  const vk::Image& picture = resolve ? resolved : colour;

  DrawObjects d(context);
  d.renderPass = vk::createColourDepthRenderPass(context, kColourFormat, kDepthFormat, samples);
  VkImageView views[3] = {colour.view(), depth.view(), resolved.view()};
  VkFramebufferCreateInfo framebufferInfo{VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO};
  framebufferInfo.renderPass = d.renderPass;
  framebufferInfo.attachmentCount = resolve ? 3 : 2;
  framebufferInfo.pAttachments = views;
  framebufferInfo.width = width;
  framebufferInfo.height = height;
  framebufferInfo.layers = 1;
  VK_CHECK(context.vk().vkCreateFramebuffer(context.device(), &framebufferInfo, nullptr,
                                            &d.framebuffer));
  createPipeline(d, samples, {width, height});

  std::vector<DrawVertex> vertices = unindex(mesh, perTriangleValue);
  vk::Buffer vertexBuffer;
  if (!vertices.empty()) {
    vertexBuffer = vk::Buffer(context, vertices.size() * sizeof(DrawVertex),
                              vk::BufferUse::Upload, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
    vertexBuffer.upload(vertices);
  }
  vk::Buffer readback(context, VkDeviceSize(width) * height * 4, vk::BufferUse::Readback,
                      VK_BUFFER_USAGE_TRANSFER_DST_BIT);

  context.submitAndWait([&](VkCommandBuffer cmd) {
    const vk::DeviceTable& vk = context.vk();
    VkClearValue clears[3]{};
    for (int c = 0; c < 4; ++c) clears[0].color.float32[c] = kRenderBackground[c] / 255.0f;
    clears[1].depthStencil = {1.0f, 0};
    VkRenderPassBeginInfo begin{VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO};
    begin.renderPass = d.renderPass;
    begin.framebuffer = d.framebuffer;
    begin.renderArea = {{0, 0}, {width, height}};
    begin.clearValueCount = 2;
    begin.pClearValues = clears;
    vk.vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
    if (!vertices.empty()) {
      vk.vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, d.pipeline);
      vk.vkCmdPushConstants(cmd, d.layout, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT,
                            0, sizeof push, &push);
      VkBuffer buffer = vertexBuffer.handle();
      VkDeviceSize offset = 0;
      vk.vkCmdBindVertexBuffers(cmd, 0, 1, &buffer, &offset);
      vk.vkCmdDraw(cmd, uint32_t(vertices.size()), 1, 0, 0);
    }
    vk.vkCmdEndRenderPass(cmd);

    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {width, height, 1};
    vk.vkCmdCopyImageToBuffer(cmd, picture.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                              readback.handle(), 1, &region);
    VkMemoryBarrier toHost{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
    toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
    vk.vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0,
                            1, &toHost, 0, nullptr, 0, nullptr);
  });

  std::vector<uint8_t> pixels;
  readback.download(pixels, size_t(width) * height * 4);
  return pixels;
}

std::vector<float> triangleLevels(const Tessellation& t) {
  const TriangleMesh& mesh = t.mesh;
  const std::vector<QuadLeaf>& leaves = t.tree.leaves;
  if (t.trianglePatch.size() != mesh.triangleCount() ||
      t.cornerUv.size() != 3 * mesh.triangleCount())
    throw std::invalid_argument("triangleLevels: " + std::to_string(t.trianglePatch.size()) +
                                " triangle patches and " + std::to_string(t.cornerUv.size()) +
                                " corner (u, v) for " + std::to_string(mesh.triangleCount()) +
                                " triangles");
  // Leaves in buckets of a cells×cells grid over each patch's parameter square, about one
  // leaf per cell, so each lookup tests a handful of rectangles.
  uint32_t patchCount = 0;
  for (const QuadLeaf& leaf : leaves) patchCount = std::max(patchCount, leaf.patchIndex + 1);
  const int cells = std::clamp(
      int(std::ceil(std::sqrt(double(leaves.size()) / std::max(patchCount, 1u)))), 1, 256);
  auto cellOf = [cells](float s) { return std::clamp(int(s * float(cells)), 0, cells - 1); };
  std::vector<std::vector<uint32_t>> buckets(size_t(patchCount) * cells * cells);
  for (uint32_t i = 0; i < leaves.size(); ++i) {
    const gpu::vec4& r = leaves[i].rect;
    for (int cu = cellOf(r.x); cu <= cellOf(r.z); ++cu)
      for (int cv = cellOf(r.y); cv <= cellOf(r.w); ++cv)
        buckets[(size_t(leaves[i].patchIndex) * cells + cu) * cells + cv].push_back(i);
  }

  std::vector<float> levels(mesh.triangleCount());
  for (size_t k = 0; k < levels.size(); ++k) {
    uint32_t patch = t.trianglePatch[k];
    glm::vec2 centroid = (t.cornerUv[3 * k] + t.cornerUv[3 * k + 1] + t.cornerUv[3 * k + 2]) / 3.0f;
    const QuadLeaf* found = nullptr;
    if (patch < patchCount)
      for (uint32_t i : buckets[(size_t(patch) * cells + cellOf(centroid.x)) * cells +
                                cellOf(centroid.y)]) {
        const gpu::vec4& r = leaves[i].rect;
        if (centroid.x >= r.x && centroid.x <= r.z && centroid.y >= r.y && centroid.y <= r.w) {
          found = &leaves[i];
          break;
        }
      }
    if (!found)
      throw std::invalid_argument("triangleLevels: triangle " + std::to_string(k) + " (patch " +
                                  std::to_string(patch) + ", centroid " +
                                  std::to_string(centroid.x) + ", " +
                                  std::to_string(centroid.y) + ") lies in no leaf");
    levels[k] = float(found->level);
  }
  return levels;
}

std::vector<float> trianglePatchIds(const Tessellation& t) {
  if (t.trianglePatch.size() != t.mesh.triangleCount())
    throw std::invalid_argument("trianglePatchIds: " + std::to_string(t.trianglePatch.size()) +
                                " triangle patches for " +
                                std::to_string(t.mesh.triangleCount()) + " triangles");
  return std::vector<float>(t.trianglePatch.begin(), t.trianglePatch.end());
}

}  // namespace tessera
