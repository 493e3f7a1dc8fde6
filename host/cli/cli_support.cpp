#include "cli/cli_support.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <sstream>

#include "cli/commands.h"
#include "cli/stdio.h"
#include "io/errors.h"
#include "io/gltf_writer.h"
#include "io/obj_writer.h"
#include "io/ply_writer.h"

namespace tessera::cli {

int runReportingErrors(const std::function<int()>& body, const std::vector<std::string>& outputs,
                       const std::string& vulkanHint) {
  try {
    return body();
  } catch (const InputError& e) {
    std::fprintf(stderr, "tessera: %s\n", e.what());
    bool isOutput = false;
    for (const std::string& o : outputs) isOutput = isOutput || (!o.empty() && e.file() == o);
    return e.kind() == InputErrorKind::Io && isOutput ? kExitOutput : kExitBadInput;
  } catch (const vk::VulkanUnavailable& e) {
    std::fprintf(stderr, "tessera: %s%s%s\n", vulkanHint.c_str(), vulkanHint.empty() ? "" : ": ",
                 e.what());
    return kExitNoVulkan;
  } catch (const vk::VulkanError& e) {
    std::fprintf(stderr, "tessera: the Vulkan device failed: %s (try --backend cpu)\n", e.what());
    return kExitDevice;
  } catch (const TessellationLimitError& e) {
    std::fprintf(stderr, "tessera: %s\n", e.what());
    return kExitLimit;
  } catch (const CLI::ValidationError& e) {
    std::fprintf(stderr, "tessera: %s\n", e.what());
    return kExitUsage;
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "tessera: %s\n", e.what());
    return kExitBadInput;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "tessera: internal error: %s\n", e.what());
    return kExitInternal;
  }
}

ChosenBackend chooseBackend(const std::string& name, const std::string& device) {
  ChosenBackend chosen;
  if (name == "cpu") {
    chosen.backend = makeMirrorBackend();
    return chosen;
  }
  if (name != "vulkan" && name != "auto")
    throw CLI::ValidationError("--backend", "expected vulkan, cpu or auto, got '" + name + "'");
  try {
    vk::ContextOptions options;
    options.device = device;
    chosen.context = std::make_unique<vk::Context>(options);
    chosen.backend = makeVulkanBackend(*chosen.context);
  } catch (const vk::VulkanUnavailable& e) {
    if (name == "vulkan") throw;
    std::fprintf(stderr, "tessera: no Vulkan (%s); using the CPU backend\n", e.what());
    chosen.context.reset();
    chosen.backend = makeMirrorBackend();
  }
  return chosen;
}

}  // namespace tessera::cli

namespace tessera::cli {

Tessellation tessellateWithFallback(ChosenBackend& chosen, const std::string& backendName,
                                    const std::vector<BezierPatch>& patches,
                                    const QuadtreeOptions& options) {
  try {
    return tessellate(patches, options, chosen.backend);
  } catch (const vk::VulkanError& e) {
    if (backendName != "auto" || !chosen.context) throw;
    std::fprintf(stderr, "tessera: the Vulkan device failed (%s); falling back to the CPU backend\n",
                 e.what());
    chosen.backend = makeMirrorBackend();
    chosen.context.reset();
    return tessellate(patches, options, chosen.backend);
  }
}

void checkMeshFormat(const std::string& path, const std::string& format) {
  meshFormat(path, format);
}

void writeMesh(const std::string& path, const TriangleMesh& mesh, const std::string& format) {
  const std::string chosen = meshFormat(path, format);
  if (path == kStdioPath) {
    // Built whole first, so a failing writer leaves standard output empty.
    std::ostringstream bytes(std::ios::binary);
    if (chosen == "obj")
      writeObj(bytes, mesh);
    else if (chosen == "ply")
      writePly(bytes, mesh);
    else
      writeGlb(bytes, mesh);
    writeStdout(bytes.str());
  } else if (chosen == "obj") {
    writeObjFile(path, mesh);
  } else if (chosen == "ply") {
    writePlyFile(path, mesh);
  } else {
    writeGlbFile(path, mesh);
  }
}

}  // namespace tessera::cli
