// The library's own entry points beyond tessera.h (the CAD API, tessera/cad.h) run on a
// Tessellator's backend through this, with its fallback to the CPU and its public errors.
#pragma once
#include <functional>

#include <tessera/tessera.h>

#include "mesh/tessellate.h"

namespace tessera {
namespace vk {
class Context;
}

struct TessellatorAccess {
  // Runs work(backend, context) (context null on the CPU). Under Device::Auto a Vulkan failure
  // moves the tessellator to the CPU and runs work again; std::invalid_argument becomes
  // ArgumentError and Vulkan failures DeviceError, as in Tessellator::tessellate.
  static void run(Tessellator& tessellator,
                  const std::function<void(Backend& backend, vk::Context* context)>& work);
};

}  // namespace tessera
