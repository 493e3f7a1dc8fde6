#include "cli/cli_support.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <new>
#include <sstream>

#include "cli/commands.h"
#include "cli/stdio.h"
#include "common/memory_budget.h"
#include "common/thread_cap.h"
#include "io/errors.h"
#include "io/gltf_writer.h"
#include "io/input_limit.h"
#include "io/obj_writer.h"
#include "io/ply_writer.h"

namespace tessera::cli {

bool isCadInput(const std::string& path) {
  std::string lower = path;
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  for (const std::string ext : {".step", ".stp", ".iges", ".igs", ".brep"})
    if (lower.size() > ext.size() && lower.compare(lower.size() - ext.size(), ext.size(), ext) == 0)
      return true;
  return false;
}

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
  } catch (const LimitError& e) {  // the node budget, the memory budget, the input size
    std::fprintf(stderr, "tessera: %s\n", e.what());
    return kExitLimit;
  } catch (const std::bad_alloc&) {
    // An allocation no estimate foresaw (or the machine has less free than it said): still a
    // limit reached, not a bug.
    std::fprintf(stderr,
                 "tessera: out of memory (the memory budget is %s; the machine could not "
                 "give that much: lower it with --memory-budget SIZE so the run stops early, "
                 "or free memory)\n",
                 formatByteSize(memoryBudget()).c_str());
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

void addResourceLimitOptions(CLI::App& command) {
  command.add_option_function<std::string>(
      "--memory-budget",
      [](const std::string& text) {
        checkCommandLine([&] { setMemoryBudget(parseByteSize(text)); });
      },
      "stop with exit 4 when a stage's estimate exceeds SIZE (e.g. 512M, 4G; default: half of "
      "the smallest of free memory, the cgroup limit and ulimit -v)")
      ->type_name("SIZE");
  command.add_option_function<std::string>(
      "--max-input-size",
      [](const std::string& text) {
        checkCommandLine([&] { setMaxInputBytes(parseByteSize(text)); });
      },
      "refuse input files larger than SIZE with exit 4 (default 1G)")
      ->type_name("SIZE");
}

void checkCommandLine(const std::function<void()>& check) {
  try {
    check();
  } catch (const std::invalid_argument& e) {
    throw CLI::ValidationError(e.what());
  }
}

namespace {

// The text as CLI11 would read a floating-point value; true when it is a number that is not
// finite (nan, inf, or a decimal beyond the double range, which strtod turns into ±inf).
bool isNonFiniteNumber(const std::string& text) {
  if (text.empty()) return false;
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size() && !std::isfinite(value);
}

}  // namespace

void refuseBadNumbers(CLI::App& app) {
  const CLI::Validator finite(
      [](std::string& text) {
        return isNonFiniteNumber(text) ? "'" + text + "' is not a finite number" : std::string();
      },
      "");
  const CLI::Validator unsignedNumber(
      [](std::string& text) {
        return text.find('-') != std::string::npos ? "'" + text + "' is negative" : std::string();
      },
      "");
  for (CLI::App* command : app.get_subcommands([](CLI::App*) { return true; }))
    for (CLI::Option* option : command->get_options([](CLI::Option*) { return true; })) {
      // CLI11 names the type of float and double options (and of lists of them) "FLOAT", of
      // unsigned ones "UINT"; the validators' descriptions may follow after a ':'.
      const std::string type = option->get_type_name();
      if (type.rfind("FLOAT", 0) == 0) option->check(finite);
      if (type.rfind("UINT", 0) == 0) option->check(unsignedNumber);
    }
}

namespace {

std::unique_ptr<vk::Context> makeContext(const std::string& device) {
  vk::ContextOptions options;
  options.device = device;
  return std::make_unique<vk::Context>(options);
}

}  // namespace

PendingContext startMakingContext(const std::string& name, const std::string& device) {
  // Under --threads 1 chooseBackend makes it on this thread.
  if ((name != "vulkan" && name != "auto") || !helperThreadsAllowed()) return {};
  return std::async(std::launch::async, makeContext, device);
}

ChosenBackend chooseBackend(const std::string& name, const std::string& device,
                            PendingContext pending) {
  ChosenBackend chosen;
  if (name == "cpu") {
    chosen.backend = makeMirrorBackend();
    return chosen;
  }
  if (name != "vulkan" && name != "auto")
    throw CLI::ValidationError("--backend", "expected vulkan, cpu or auto, got '" + name + "'");
  try {
    chosen.context = pending.valid() ? pending.get() : makeContext(device);
    chosen.backend = makeVulkanBackend(*chosen.context);
  } catch (const vk::VulkanUnavailable& e) {
    if (name == "vulkan") throw;
    std::fprintf(stderr, "tessera: no Vulkan (%s); using the CPU backend\n", e.what());
    chosen.context.reset();
    chosen.backend = makeMirrorBackend();
  }
  return chosen;
}

std::future<void> releaseInBackground(ChosenBackend&& chosen) {
  // The CPU backend (nothing slow to destroy), or --threads 1: released here, no thread.
  if (!chosen.context || !helperThreadsAllowed()) {
    ChosenBackend released = std::move(chosen);
    return {};
  }
  return std::async(std::launch::async, [held = std::move(chosen)]() mutable {
    ChosenBackend released = std::move(held);  // its members go in reverse order: backend first
  });
}

}  // namespace tessera::cli

namespace tessera::cli {

Tessellation tessellateWithFallback(ChosenBackend& chosen, const std::string& backendName,
                                    const std::vector<BezierPatch>& patches,
                                    const QuadtreeOptions& options, const ScreenView* view) {
  const auto run = [&] {
    return view ? tessellateScreenTolerance(patches, options, *view, chosen.backend)
                : tessellate(patches, options, chosen.backend);
  };
  try {
    return run();
  } catch (const vk::VulkanError& e) {
    if (backendName != "auto" || !chosen.context) throw;
    std::fprintf(stderr, "tessera: the Vulkan device failed (%s); falling back to the CPU backend\n",
                 e.what());
    chosen.backend = makeMirrorBackend();
    chosen.context.reset();
    return run();
  }
}

void checkMeshFormat(const std::string& path, const std::string& format) {
  meshFormat(path, format);
}

void writeMesh(const std::string& path, const TriangleMesh& mesh, const std::string& format,
               const MeshWriteOptions& options) {
  const std::string chosen = meshFormat(path, format);
  if (path == kStdioPath) {
    // Built whole first, so a failing writer leaves standard output empty: held twice (the
    // stream and its copy), at most ~140 bytes of OBJ text per vertex (v, vn, vt lines of
    // 16-character numbers) and ~100 per triangle (f a/a/a b/b/b c/c/c); PLY and GLB are less.
    requireWithinMemoryBudget(
        2 * (uint64_t(mesh.vertexCount()) * 140 + uint64_t(mesh.triangleCount()) * 100),
        "writing the mesh of " + std::to_string(mesh.triangleCount()) +
            " triangles to standard output (a file is written as it goes)");
    std::ostringstream bytes(std::ios::binary);
    if (chosen == "obj")
      writeObj(bytes, mesh, options);
    else if (chosen == "ply")
      writePly(bytes, mesh, options);
    else
      writeGlb(bytes, mesh);
    writeStdout(bytes.str());
  } else if (chosen == "obj") {
    writeObjFile(path, mesh, options);
  } else if (chosen == "ply") {
    writePlyFile(path, mesh, options);
  } else {
    writeGlbFile(path, mesh);
  }
}

}  // namespace tessera::cli
