// The Vulkan backend's fixed cost (vk::ContextTimings) in the stats report's `setup` section
// and as one line of the text summary.
#pragma once
#include <cstdio>

#include <nlohmann/json.hpp>

#include "vk/context.h"

namespace tessera::cli {

// Null without a context (the CPU backend).
nlohmann::json setupToJson(const vk::Context* context);

void printSetup(FILE* to, const vk::ContextTimings& t);

}  // namespace tessera::cli
