// What the subcommands share: turning exceptions into one message and a documented exit code,
// choosing the backend (--backend vulkan|cpu|auto), and writing meshes by extension.
#pragma once
#include <functional>
#include <future>
#include <memory>
#include <string>
#include <vector>

#include "io/errors.h"
#include "io/mesh_write_options.h"
#include "mesh/screen_tolerance.h"
#include "mesh/tessellate.h"
#include "vk/context.h"

// CLI::App by name only (commands.h says why).
namespace CLI {
class App;
}  // namespace CLI

namespace tessera::cli {

// Throws CLI::ValidationError naming --output unless `path` ends in .obj, .ply or .glb, or
// `format` (--format: obj, ply or glb) says which; `-` (standard output) needs `format`
// (an InputError, exit 2, otherwise). Called before any work, so a typo costs nothing.
void checkMeshFormat(const std::string& path, const std::string& format = "");
// Writes `mesh` atomically in `format`, or that of `path`'s extension (checked as above);
// to `-`, the whole mesh is built in memory and then written to standard output.
void writeMesh(const std::string& path, const TriangleMesh& mesh, const std::string& format = "",
               const MeshWriteOptions& options = {});

// Runs `body`; prints any exception as "tessera: <message>" on stderr and returns its exit code
// (commands.h). An Io error on one of `outputs` is kExitOutput; `vulkanHint` prefixes a
// VulkanUnavailable message (e.g. "render needs a Vulkan device that draws").
int runReportingErrors(const std::function<int()>& body, const std::vector<std::string>& outputs,
                       const std::string& vulkanHint = "");

// Runs `check`: the command line's validation by the library's own parsers and option checks
// (parseSplitRule, parseTolerance, validateQuadtreeOptions, ...), before any input is read. A
// std::invalid_argument from it is a bad command line (CLI::ValidationError, exit 1), not bad
// input (exit 2): one path for every option, so no option's range is checked twice.
void checkCommandLine(const std::function<void()>& check);

// Adds --memory-budget SIZE (common/memory_budget.h) and --max-input-size SIZE
// (io/input_limit.h) to `command`; a bad SIZE is a usage error (exit 1).
void addResourceLimitOptions(CLI::App& command);

// Adds checks to the numeric options of every subcommand of `app` (single values and lists):
// floating-point ones refuse nan and ±inf (CLI11 parses them as numbers, and CLI::Range lets
// NaN through since every comparison with it is false: an option's range check would be
// skipped); unsigned ones refuse a negative value (CLI11 wraps "-1" to the largest value).
// Call once every command is added.
void refuseBadNumbers(CLI::App& app);

// By extension, case-insensitively: a CAD model (.step/.stp, .iges/.igs, .brep), which
// tessellate, stats, render and info hand to cad_job.h's entry points.
bool isCadInput(const std::string& path);

struct ChosenBackend {
  std::unique_ptr<vk::Context> context;  // null on the CPU backend
  Backend backend;
  std::string deviceName() const { return context ? context->info().name : ""; }
};

// The Vulkan context chooseBackend will take, being made on a worker thread.
using PendingContext = std::future<std::unique_ptr<vk::Context>>;

// Starts making the Vulkan context for chooseBackend(name, device) on a worker thread, so that
// the caller reads its input meanwhile: on lavapipe the context is the largest fixed cost of a
// run (the loader opens every installed driver). None (an invalid future) for "cpu", a name
// chooseBackend refuses, or under a thread cap of 1 (--threads 1, common/thread_cap.h). Its
// errors reach the caller through chooseBackend, in the same order as without it; a pending
// context that is never taken is waited for and destroyed.
PendingContext startMakingContext(const std::string& name, const std::string& device);

// "vulkan": Vulkan or VulkanUnavailable; "cpu": the CPU; "auto": Vulkan if a usable device
// exists, else the CPU with a notice on stderr. Anything else is a usage error. `pending`, from
// startMakingContext with the same name and device, is the context to take.
ChosenBackend chooseBackend(const std::string& name, const std::string& device,
                            PendingContext pending = {});

// Destroys `chosen` (its backend, then its context) on a worker thread, so that lavapipe's
// teardown (joining its threads, unloading the drivers: several ms at the end of a run) goes on
// while the caller writes the mesh; the future's destructor waits for it (without a context it
// is destroyed at once, and the future is empty; so too under --threads 1). Take from the
// context what the report needs first.
std::future<void> releaseInBackground(ChosenBackend&& chosen);

// Runs `work` (a tessellation); a patch it cannot take (std::invalid_argument naming the patch:
// validateTessellationPatch, or an fp32 evaluation that is not finite) becomes an InputError
// naming `input` too, so the message says which file (exit 2 either way).
template <class Work>
auto namingInput(const std::string& input, Work&& work) -> decltype(work()) {
  try {
    return work();
  } catch (const std::invalid_argument& e) {
    throw InputError(InputErrorKind::Range, input, 0, e.what());
  }
}

// Tessellates on the chosen backend. With --backend auto, a Vulkan failure during the run
// (device lost, out of device memory) switches `chosen` to the CPU backend, says so on stderr,
// and runs again there; otherwise the vk::VulkanError propagates. With `view`, rule T runs in
// screen space (options.tolerance in pixels: tessellateScreenTolerance).
Tessellation tessellateWithFallback(ChosenBackend& chosen, const std::string& backendName,
                                    const std::vector<BezierPatch>& patches,
                                    const QuadtreeOptions& options,
                                    const ScreenView* view = nullptr);

}  // namespace tessera::cli
