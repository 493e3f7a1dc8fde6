// Compute pipelines built from embedded SPIR-V. Buffers are bound with push descriptors
// (binding i = i-th buffer), parameters go in push constants, variants are chosen with
// specialization constants (all 32-bit).
#pragma once
#include "vk/backend_only.h"
#include <cstdint>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include "vk/buffer.h"
#include "vk/context.h"

namespace tessera::vk {

struct SpecConstant {
  uint32_t id;
  uint32_t value;  // floats via their bit pattern (specFloat)
};
SpecConstant specFloat(uint32_t id, float value);

struct ComputePipelineDesc {
  std::string name;  // for error messages
  const uint32_t* spirv = nullptr;
  size_t spirvBytes = 0;
  uint32_t storageBufferCount = 0;  // bindings 0..count−1
  uint32_t pushConstantBytes = 0;
  std::vector<SpecConstant> specialization;
  // Bit i set: binding i is a uniform texel buffer (vk/texel_view.h), not a storage buffer.
  uint32_t texelBufferMask = 0;
};

class ComputePipeline {
 public:
  ComputePipeline(Context& context, const ComputePipelineDesc& desc);
  ~ComputePipeline();
  ComputePipeline(const ComputePipeline&) = delete;
  ComputePipeline& operator=(const ComputePipeline&) = delete;

  // Binds the pipeline, the buffers (in binding order) and the push constants, then
  // dispatches enough 64-wide workgroups for `invocations`, folded into a 2-D grid when the
  // count exceeds maxComputeWorkGroupCount[0] (shaders use linearInvocationIndex()).
  void dispatch(VkCommandBuffer cmd, std::initializer_list<const Buffer*> buffers,
                const void* pushConstants, uint32_t invocations) const;
  // The same with buffer ranges (an engine's buffers at an offset: engine interop). Offsets
  // must be multiples of minStorageBufferOffsetAlignment.
  void dispatch(VkCommandBuffer cmd, const std::vector<VkDescriptorBufferInfo>& buffers,
                const void* pushConstants, uint32_t invocations) const;

  // One binding of dispatchBindings: a whole storage buffer, or a uniform texel buffer view
  // where the pipeline's texelBufferMask names the binding.
  struct Binding {
    const Buffer* buffer = nullptr;
    VkBufferView texelView = VK_NULL_HANDLE;
    Binding(const Buffer* storage) : buffer(storage) {}  // NOLINT: lists read as buffers
    Binding(VkBufferView view) : texelView(view) {}      // NOLINT
  };
  void dispatchBindings(VkCommandBuffer cmd, std::initializer_list<Binding> bindings,
                        const void* pushConstants, uint32_t invocations) const;

  const std::string& name() const { return name_; }

 private:
  // Binds the pipeline, pushes `writes` as its descriptors, the push constants, and records
  // the dispatch (nothing for 0 invocations): the one path of both dispatch functions.
  void bindAndDispatch(VkCommandBuffer cmd, const std::vector<VkWriteDescriptorSet>& writes,
                       const void* pushConstants, uint32_t invocations) const;

  Context& context_;
  std::string name_;
  uint32_t bufferCount_ = 0;
  uint32_t pushBytes_ = 0;
  uint32_t texelMask_ = 0;
  VkDescriptorType descriptorType(uint32_t binding) const;
  VkDescriptorSetLayout setLayout_ = VK_NULL_HANDLE;
  VkPipelineLayout layout_ = VK_NULL_HANDLE;
  VkPipeline pipeline_ = VK_NULL_HANDLE;
};

// Makes compute-shader writes visible to the next dispatch (compute → compute).
void computeToComputeBarrier(const Context& context, VkCommandBuffer cmd);
// Makes compute-shader writes visible to the host after the fence (compute → host).
void computeToHostBarrier(const Context& context, VkCommandBuffer cmd);

// Timestamp queries around GPU work, in nanoseconds; a no-op where the queue has none.
class GpuTimer {
 public:
  GpuTimer(Context& context, uint32_t maxMarks);
  ~GpuTimer();
  GpuTimer(const GpuTimer&) = delete;
  GpuTimer& operator=(const GpuTimer&) = delete;

  void reset(VkCommandBuffer cmd);
  void mark(VkCommandBuffer cmd, VkPipelineStageFlagBits stage = VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT);
  // Nanoseconds between consecutive marks of the last submission (empty if unsupported).
  std::vector<double> intervalsNs() const;
  bool supported() const { return pool_ != VK_NULL_HANDLE; }

 private:
  Context& context_;
  VkQueryPool pool_ = VK_NULL_HANDLE;
  uint32_t maxMarks_ = 0;
  uint32_t used_ = 0;
};

}  // namespace tessera::vk
