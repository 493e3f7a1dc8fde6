#include "vk/pipeline.h"

#include "shaders/layout.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>

#include "common/stopwatch.h"
#include "vk/loader.h"

namespace tessera::vk {

SpecConstant specFloat(uint32_t id, float value) {
  uint32_t bits = 0;
  std::memcpy(&bits, &value, sizeof bits);
  return {id, bits};
}

ComputePipeline::ComputePipeline(Context& context, const ComputePipelineDesc& desc)
    : context_(context),
      name_(desc.name),
      bufferCount_(desc.storageBufferCount),
      pushBytes_(desc.pushConstantBytes),
      texelMask_(desc.texelBufferMask) {
  const Stopwatch stopwatch;
  const DeviceTable& vk = context.vk();
  VkDevice device = context.device();

  std::vector<VkDescriptorSetLayoutBinding> bindings(bufferCount_);
  for (uint32_t i = 0; i < bufferCount_; ++i) {
    bindings[i].binding = i;
    bindings[i].descriptorType = descriptorType(i);
    bindings[i].descriptorCount = 1;
    bindings[i].stageFlags = VK_SHADER_STAGE_COMPUTE_BIT;
  }
  VkDescriptorSetLayoutCreateInfo setInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  setInfo.flags = VK_DESCRIPTOR_SET_LAYOUT_CREATE_PUSH_DESCRIPTOR_BIT_KHR;
  setInfo.bindingCount = bufferCount_;
  setInfo.pBindings = bindings.data();
  VK_CHECK(vk.vkCreateDescriptorSetLayout(device, &setInfo, nullptr, &setLayout_));

  VkPushConstantRange range{VK_SHADER_STAGE_COMPUTE_BIT, 0, pushBytes_};
  VkPipelineLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO};
  layoutInfo.setLayoutCount = 1;
  layoutInfo.pSetLayouts = &setLayout_;
  layoutInfo.pushConstantRangeCount = pushBytes_ ? 1 : 0;
  layoutInfo.pPushConstantRanges = &range;
  VK_CHECK(vk.vkCreatePipelineLayout(device, &layoutInfo, nullptr, &layout_));

  VkShaderModuleCreateInfo moduleInfo{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO};
  moduleInfo.codeSize = desc.spirvBytes;
  moduleInfo.pCode = desc.spirv;
  VkShaderModule module = VK_NULL_HANDLE;
  VK_CHECK(vk.vkCreateShaderModule(device, &moduleInfo, nullptr, &module));

  std::vector<VkSpecializationMapEntry> entries;
  std::vector<uint32_t> values;
  for (const SpecConstant& c : desc.specialization) {
    entries.push_back({c.id, static_cast<uint32_t>(values.size() * 4), 4});
    values.push_back(c.value);
  }
  VkSpecializationInfo spec{static_cast<uint32_t>(entries.size()), entries.data(),
                            values.size() * 4, values.data()};
  VkComputePipelineCreateInfo info{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
  info.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
  info.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
  info.stage.module = module;
  info.stage.pName = "main";
  info.stage.pSpecializationInfo = entries.empty() ? nullptr : &spec;
  info.layout = layout_;
  VkResult result =
      vk.vkCreateComputePipelines(device, context.pipelineCache(), 1, &info, nullptr, &pipeline_);
  vk.vkDestroyShaderModule(device, module, nullptr);
  if (result != VK_SUCCESS) {
    vk.vkDestroyPipelineLayout(device, layout_, nullptr);
    vk.vkDestroyDescriptorSetLayout(device, setLayout_, nullptr);
    throw VulkanError("vkCreateComputePipelines(" + name_ + ")", result);
  }
  context.notePipelineCreated(stopwatch.elapsedMs());
}

ComputePipeline::~ComputePipeline() {
  const DeviceTable& vk = context_.vk();
  vk.vkDestroyPipeline(context_.device(), pipeline_, nullptr);
  vk.vkDestroyPipelineLayout(context_.device(), layout_, nullptr);
  vk.vkDestroyDescriptorSetLayout(context_.device(), setLayout_, nullptr);
}

void ComputePipeline::dispatch(VkCommandBuffer cmd, std::initializer_list<const Buffer*> buffers,
                               const void* pushConstants, uint32_t invocations) const {
  std::vector<VkDescriptorBufferInfo> infos;
  infos.reserve(buffers.size());
  for (const Buffer* b : buffers) infos.push_back({b->handle(), 0, VK_WHOLE_SIZE});
  dispatch(cmd, infos, pushConstants, invocations);
}

namespace {
// One binding's descriptor write, its buffer or view filled in by the caller.
VkWriteDescriptorSet bindingWrite(uint32_t binding, VkDescriptorType type) {
  VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
  write.dstBinding = binding;
  write.descriptorCount = 1;
  write.descriptorType = type;
  return write;
}
}  // namespace

VkDescriptorType ComputePipeline::descriptorType(uint32_t binding) const {
  return (texelMask_ >> binding) & 1u ? VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER
                                      : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
}

void ComputePipeline::dispatchBindings(VkCommandBuffer cmd, std::initializer_list<Binding> bindings,
                                       const void* pushConstants, uint32_t invocations) const {
  if (bindings.size() != bufferCount_)
    throw std::invalid_argument(name_ + ": expected " + std::to_string(bufferCount_) +
                                " bindings, got " + std::to_string(bindings.size()));
  std::vector<VkDescriptorBufferInfo> infos(bindings.size());
  std::vector<VkBufferView> views(bindings.size());
  std::vector<VkWriteDescriptorSet> writes(bindings.size());
  uint32_t i = 0;
  for (const Binding& b : bindings) {
    const VkDescriptorType type = descriptorType(i);
    const bool texel = type != VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    if (texel != (b.texelView != VK_NULL_HANDLE))
      throw std::invalid_argument(name_ + ": binding " + std::to_string(i) + " must be a " +
                                  (texel ? "texel buffer view" : "storage buffer"));
    writes[i] = bindingWrite(i, type);
    if (texel) {
      views[i] = b.texelView;
      writes[i].pTexelBufferView = &views[i];
    } else {
      infos[i] = {b.buffer->handle(), 0, VK_WHOLE_SIZE};
      writes[i].pBufferInfo = &infos[i];
    }
    ++i;
  }
  bindAndDispatch(cmd, writes, pushConstants, invocations);
}

void ComputePipeline::dispatch(VkCommandBuffer cmd,
                               const std::vector<VkDescriptorBufferInfo>& infos,
                               const void* pushConstants, uint32_t invocations) const {
  if (infos.size() != bufferCount_)
    throw std::invalid_argument(name_ + ": expected " + std::to_string(bufferCount_) +
                                " buffers, got " + std::to_string(infos.size()));
  if (texelMask_)
    throw std::invalid_argument(name_ + ": has texel buffer bindings (dispatchBindings)");
  for (const VkDescriptorBufferInfo& info : infos)
    if (info.offset % context_.minStorageBufferOffsetAlignment() != 0)
      throw std::invalid_argument(name_ + ": buffer offset " + std::to_string(info.offset) +
                                  " is not a multiple of minStorageBufferOffsetAlignment (" +
                                  std::to_string(context_.minStorageBufferOffsetAlignment()) +
                                  ")");
  std::vector<VkWriteDescriptorSet> writes(infos.size());
  for (uint32_t i = 0; i < infos.size(); ++i) {
    writes[i] = bindingWrite(i, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
    writes[i].pBufferInfo = &infos[i];
  }
  bindAndDispatch(cmd, writes, pushConstants, invocations);
}

void ComputePipeline::bindAndDispatch(VkCommandBuffer cmd,
                                      const std::vector<VkWriteDescriptorSet>& writes,
                                      const void* pushConstants, uint32_t invocations) const {
  if (invocations == 0) return;
  const DeviceTable& vk = context_.vk();
  vk.vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipeline_);
  vk.vkCmdPushDescriptorSetKHR(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, layout_, 0,
                               static_cast<uint32_t>(writes.size()), writes.data());
  if (pushBytes_)
    vk.vkCmdPushConstants(cmd, layout_, VK_SHADER_STAGE_COMPUTE_BIT, 0, pushBytes_,
                          pushConstants);
  const uint32_t localSize = gpu::kLocalSize;
  uint32_t groups = (invocations + localSize - 1) / localSize;
  uint32_t maxX = std::max<uint32_t>(1, context_.info().maxComputeWorkGroupCountX);
  uint32_t groupsX = std::min(groups, maxX);
  uint32_t groupsY = (groups + groupsX - 1) / groupsX;
  vk.vkCmdDispatch(cmd, groupsX, groupsY, 1);
}

namespace {
void memoryBarrier(const Context& context, VkCommandBuffer cmd, VkPipelineStageFlags dstStage,
                   VkAccessFlags dstAccess) {
  VkMemoryBarrier barrier{VK_STRUCTURE_TYPE_MEMORY_BARRIER};
  barrier.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
  barrier.dstAccessMask = dstAccess;
  context.vk().vkCmdPipelineBarrier(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, dstStage, 0, 1,
                                    &barrier, 0, nullptr, 0, nullptr);
}
}  // namespace

void computeToComputeBarrier(const Context& context, VkCommandBuffer cmd) {
  memoryBarrier(context, cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
}

void computeToHostBarrier(const Context& context, VkCommandBuffer cmd) {
  memoryBarrier(context, cmd, VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT);
}

GpuTimer::GpuTimer(Context& context, uint32_t maxMarks) : context_(context), maxMarks_(maxMarks) {
  if (!context.timestampsSupported() || maxMarks == 0) return;
  VkQueryPoolCreateInfo info{VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO};
  info.queryType = VK_QUERY_TYPE_TIMESTAMP;
  info.queryCount = maxMarks;
  VK_CHECK(context.vk().vkCreateQueryPool(context.device(), &info, nullptr, &pool_));
}

GpuTimer::~GpuTimer() {
  if (pool_) context_.vk().vkDestroyQueryPool(context_.device(), pool_, nullptr);
}

void GpuTimer::reset(VkCommandBuffer cmd) {
  used_ = 0;
  if (pool_) context_.vk().vkCmdResetQueryPool(cmd, pool_, 0, maxMarks_);
}

void GpuTimer::mark(VkCommandBuffer cmd, VkPipelineStageFlagBits stage) {
  if (!pool_) return;
  if (used_ >= maxMarks_) throw std::out_of_range("GpuTimer: more marks than reserved");
  context_.vk().vkCmdWriteTimestamp(cmd, stage, pool_, used_++);
}

std::vector<double> GpuTimer::intervalsNs() const {
  std::vector<double> intervals;
  if (!pool_ || used_ < 2) return intervals;
  std::vector<uint64_t> ticks(used_);
  VK_CHECK(context_.vk().vkGetQueryPoolResults(
      context_.device(), pool_, 0, used_, ticks.size() * sizeof(uint64_t), ticks.data(),
      sizeof(uint64_t), VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
  uint64_t mask = context_.timestampValidBits() >= 64
                      ? ~0ull
                      : ((1ull << context_.timestampValidBits()) - 1);
  for (uint32_t i = 1; i < used_; ++i)
    intervals.push_back(static_cast<double>((ticks[i] - ticks[i - 1]) & mask) *
                        context_.info().timestampPeriodNs);
  return intervals;
}

}  // namespace tessera::vk
