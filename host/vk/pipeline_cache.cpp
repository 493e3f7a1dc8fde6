#include "vk/pipeline_cache.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "io/atomic_file.h"

namespace tessera::vk {

std::string pipelineCachePath(const VkPhysicalDeviceProperties& properties) {
  std::filesystem::path dir;
  if (const char* file = std::getenv("TESSERA_PIPELINE_CACHE"))
    return std::string(file) == "off" ? std::string() : std::string(file);
  if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg)
    dir = std::filesystem::path(xdg) / "tessera";
  else if (const char* home = std::getenv("HOME"); home && *home)
    dir = std::filesystem::path(home) / ".cache" / "tessera";
  else
    return {};
  char name[96];
  std::snprintf(name, sizeof name, "pipelines-%04x-%04x-%08x-", properties.vendorID,
                properties.deviceID, properties.driverVersion);
  std::string file = name;
  for (uint8_t byte : properties.pipelineCacheUUID) {
    std::snprintf(name, sizeof name, "%02x", byte);
    file += name;
  }
  return (dir / (file + ".bin")).string();
}

std::vector<char> readPipelineCache(const std::string& path) {
  if (path.empty()) return {};
  std::ifstream in(path, std::ios::binary);
  if (!in) return {};
  return std::vector<char>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void writePipelineCache(const std::string& path, const std::vector<char>& data) {
  if (path.empty() || data.empty()) return;
  try {
    std::error_code ignored;
    std::filesystem::create_directories(std::filesystem::path(path).parent_path(), ignored);
    writeFileAtomically(path, [&](std::ostream& out) { out.write(data.data(), data.size()); });
  } catch (const std::exception&) {
    // A cache we cannot write only costs the next run its compile time.
  }
}

}  // namespace tessera::vk
