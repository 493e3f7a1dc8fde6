// The library's own entry points beyond tessera.h (the CAD API, tessera/cad.h) run on a
// Tessellator's backend through this, with its fallback to the CPU and its public errors.
#pragma once
#include <functional>

#include <tessera/tessera.h>

#include "mesh/tessellate.h"

namespace tessera {
namespace vk {
class Context;
struct ExternalDevice;
}
class TrimClassifier;

struct TessellatorAccess {
  // A Tessellator on an engine's device (tessera/vulkan.h); the public errors as the others.
  static Tessellator onDevice(const vk::ExternalDevice& device, const TessellatorOptions& options);
  // Runs work(backend, context) (context null on the CPU). Under Device::Auto a Vulkan failure
  // moves the tessellator to the CPU and runs work again; std::invalid_argument becomes
  // ArgumentError and Vulkan failures DeviceError, as in Tessellator::tessellate.
  static void run(Tessellator& tessellator,
                  const std::function<void(Backend& backend, vk::Context* context)>& work);
  // The tessellator's Vulkan trim classifier (trimmed faces, tessera/cad.h), made at the first
  // call and kept with its pipeline and buffers for the next ones, as the backend keeps its
  // own; null on the CPU (also after a fallback).
  static TrimClassifier* trimClassifier(Tessellator& tessellator);
};

}  // namespace tessera
