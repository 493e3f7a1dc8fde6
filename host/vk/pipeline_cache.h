// The VkPipelineCache kept on disk between runs: lavapipe JIT-compiles a pipeline on first use
// (~90 ms per pipeline), so a warm cache takes that out of every later process.
// Where: $TESSERA_PIPELINE_CACHE (a file; "off" disables), else $XDG_CACHE_HOME/tessera/, else
// ~/.cache/tessera/, one file per device and driver build (vendor, device, driver version and
// pipelineCacheUUID in the name). Everything here is best effort: a cache that cannot be read
// or written is a slower start, never an error; the driver itself rejects stale data.
#pragma once
#include "vk/backend_only.h"
#include <vulkan/vulkan.h>

#include <string>
#include <vector>

namespace tessera::vk {

// The file for this device, or "" when caching is off or no home directory is known.
std::string pipelineCachePath(const VkPhysicalDeviceProperties& properties);

// The file's bytes (empty when missing or unreadable).
std::vector<char> readPipelineCache(const std::string& path);

// Replaces the file atomically (directory created as needed); failures are ignored.
void writePipelineCache(const std::string& path, const std::vector<char>& data);

}  // namespace tessera::vk
