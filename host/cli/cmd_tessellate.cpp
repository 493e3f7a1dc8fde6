#include <CLI/CLI.hpp>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <future>
#include <memory>
#include <optional>
#include <utility>

#include <nlohmann/json.hpp>

#include "cli/cad_job.h"
#include "cli/camera_options.h"
#include "cli/cli_support.h"
#include "cli/commands.h"
#include "cli/outputs.h"
#include "cli/progress.h"
#include "cli/run_report.h"
#include "cli/setup_report.h"
#include "cli/stdio.h"
#include "cli/streamed_tessellate.h"
#include "cli/tessellate_summary.h"
#include "common/memory_budget.h"
#include "common/thread_cap.h"
#include "io/surface_reader.h"
#include "io/errors.h"
#include "io/gltf_writer.h"
#include "io/obj_writer.h"
#include "io/ply_writer.h"
#include "io/stats_report.h"
#include "mesh/double_vertices.h"
#include "mesh/lower_bound.h"
#include "mesh/result_warnings.h"
#include "mesh/tessellate.h"
#include "quadtree/tolerance.h"
#include "vk/context.h"

namespace tessera::cli {
namespace {

struct TessellateArgs {
  std::string input;
  std::string output;
  std::string method;     // -m: empty means kDefaultRule, or rule T with --tolerance
  std::string tolerance;  // --tolerance: rule T's δ, "0.01" or "0.1%"; empty: the default 0.1%
  float linearity = 0.1f;
  float flatness = 0.1f;
  std::optional<uint32_t> maxDepth;  // --max-depth; else 12 for rules A-D, 30 for T
  int samples = 5;
  std::string grid = "8";  // rule A: "N" (N×N cells) or "NxM" (N along u, M along v)
  size_t nodeBudget = size_t(1) << 24;
  double frontierBudgetMiB = 256;  // QuadtreeOptions::frontierBudgetBytes, in MiB
  std::string backend = "auto";
  std::string device;
  bool quiet = false;
  std::string stats;  // --stats: the JSON report into this file
  bool json = false;  // --json: the JSON report on stdout instead of the summary
  bool deviation = false;  // --deviation: measure the deviation (--no-deviation: don't)
  bool lowerBound = false;  // --lower-bound: N_min and triangles / N_min (rule T's report has it too)
  std::vector<std::string> formats;  // --format: for `-`, or a path whose extension cannot tell
  CameraArgs camera;  // --view / --view-projection / --viewport: the camera of "--tolerance 1px"
  bool skipBadFaces = false;  // CAD models: mesh the faces that converted (cad_job.h)
  MeshOutputArgs mesh;  // --precision
  size_t streamPatches = 0;  // --stream-patches N: write the mesh in groups of N patches
  unsigned threads = 0;      // --threads N: the most CPU threads per parallel step; 0: all
};

// A CAD model (.step, .iges, .brep) goes through host/cad/ and host/trim/ (cad_job.h).
int runCad(const TessellateArgs& a) {
  if (a.streamPatches)
    throw CLI::ValidationError("--stream-patches", "not for CAD models (patch inputs only)");
  // The CAD mesh is fp32 with no patch parameters to carry: the mesh options do not apply.
  if (a.mesh.precision == "double")
    throw CLI::ValidationError("--precision", "double: not for CAD models (yet)");
  if (a.mesh.metadata) throw CLI::ValidationError("--metadata", "not for CAD models (yet)");
  CadCommand c;
  c.input = a.input;
  c.output = a.output;
  c.stats = a.stats;
  c.tolerance = a.tolerance;
  c.method = a.method;
  c.backend = a.backend;
  c.device = a.device;
  c.formats = a.formats;
  c.json = a.json;
  c.quiet = a.quiet;
  c.skipBadFaces = a.skipBadFaces;
  c.camera = a.camera.given();
  c.lowerBound = a.lowerBound;
  return tessellateCadModel(c);
}

// "N" or "NxM" (also "N×M"), each 1..4096: the cells of rule A's uniform grid.
void parseGrid(const std::string& text, int& gridU, int& gridV) {
  const auto bad = [&] {
    return CLI::ValidationError("--grid", "expected N or NxM with 1 ≤ N, M ≤ 4096, got '" + text + "'");
  };
  size_t x = text.find('x');
  size_t sepLength = 1;
  if (x == std::string::npos) {
    x = text.find("×");
    sepLength = std::string("×").size();
  }
  const std::string first = text.substr(0, x);
  const std::string second = x == std::string::npos ? first : text.substr(x + sepLength);
  const auto number = [&](const std::string& s) {
    if (s.empty() || s.size() > 4 || s.find_first_not_of("0123456789") != std::string::npos) throw bad();
    const int n = std::stoi(s);
    if (n < 1 || n > 4096) throw bad();
    return n;
  };
  gridU = number(first);
  gridV = number(second);
}

// The paper's default depth; rule T's is kToleranceMaxDepth (a one-way split is a level).
constexpr uint32_t kPaperMaxDepth = 12;

std::string shortDecimal(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

// The rule without -m: T at the default δ (0.1% of the diagonal): what a user asks first is
// "within δ of the surface", and rule T answers it with a proof and the fewest triangles.
constexpr SplitRule kDefaultRule = SplitRule::Tolerance;

// Without -m: rule T when --tolerance is given, else kDefaultRule. --tolerance belongs to rule
// T only: with -m A..D it would be silently ignored, so it is refused (std::invalid_argument,
// a bad command line through checkCommandLine, like a bad -m).
SplitRule chooseRule(const TessellateArgs& a) {
  if (a.method.empty()) return a.tolerance.empty() ? kDefaultRule : SplitRule::Tolerance;
  const SplitRule rule = parseSplitRule(a.method);
  if (!a.tolerance.empty() && rule != SplitRule::Tolerance)
    throw std::invalid_argument("--tolerance sets the δ of rule T; it does not go with -m " +
                                a.method + " (leave out -m, or give -m T)");
  return rule;
}

int run(const TessellateArgs& a) {
  const ScopedThreadCap cap(a.threads);  // the whole run, a CAD model's included
  if (isCadInput(a.input)) return runCad(a);
  QuadtreeOptions options;
  ToleranceSpec toleranceSpec;
  // Every option is checked before any work, by the library's own checks: a value out of
  // range is a bad command line (exit 1), whatever the input.
  checkCommandLine([&] {
    options.rule = chooseRule(a);
    // Parsed now, resolved (a percentage needs the model's size) once the input is read.
    if (!a.tolerance.empty()) toleranceSpec = parseTolerance(a.tolerance);
    options.linearity = a.linearity;
    options.flatness = a.flatness;
    // Rule T may split one direction per level, so it needs about twice the levels.
    options.maxDepth = a.maxDepth ? *a.maxDepth
                       : options.rule == SplitRule::Tolerance ? kToleranceMaxDepth
                                                              : kPaperMaxDepth;
    options.samples = a.samples;
    parseGrid(a.grid, options.gridU, options.gridV);
    options.nodeBudget = a.nodeBudget;
    options.frontierBudgetBytes = size_t(a.frontierBudgetMiB * 1024.0 * 1024.0);
    QuadtreeOptions checked = options;
    if (checked.rule == SplitRule::Tolerance) checked.tolerance = 1.0;  // δ: parseTolerance
    validateQuadtreeOptions(checked);
    frontierBatchNodes(checked, SIZE_MAX);  // the budget holds a batch at this depth
  });
  const bool ruleT = options.rule == SplitRule::Tolerance;
  std::optional<Camera> camera;
  // A pixel tolerance and a camera come together (rule T in screen space); a misuse is a bad
  // command line (exit 1), as the other misuses of --tolerance are.
  checkCommandLine([&] {
    camera = parseCamera(a.camera);
    if (toleranceSpec.pixels && !camera)
      throw std::invalid_argument("--tolerance '" + a.tolerance +
                                  "' is in pixels: give the camera with --view or "
                                  "--view-projection (and --viewport)");
    if (camera && !toleranceSpec.pixels)
      throw std::invalid_argument("--view / --view-projection: a camera goes with a tolerance in "
                                  "pixels (--tolerance 1px)");
    if (toleranceSpec.pixels && a.lowerBound)
      throw std::invalid_argument("--lower-bound: the lower bound is in model units; it does not "
                                  "go with a tolerance in pixels");
  });
  std::optional<ScreenView> view;
  if (camera) view = ScreenView{*camera, kDefaultEyePlaneDepth};
  const StreamFormats formats = parseFormats(a.formats);
  const bool meshToStdout = a.output == kStdioPath;
  const bool statsToStdout = a.stats == kStdioPath;
  if (meshToStdout + statsToStdout + a.json > 1)
    throw CLI::ValidationError("--output", "only one of -o -, --stats - and --json may use "
                                           "standard output");
  if (!a.output.empty()) checkMeshFormat(a.output, formats.output);
  const MeshWriteOptions writeOptions = meshWriteOptions(a.mesh, a.output, formats.output);
  const std::string inputFormat = surfaceFormat(a.input, formats.input);
  StreamedJob job;
  job.inputName = a.input == kStdioPath ? kStdinName : a.input;
  job.output = a.output;
  job.format = a.output.empty() ? "" : meshFormat(a.output, formats.output);
  job.stats = a.stats;
  job.json = a.json;
  job.quiet = a.quiet;
  job.precisionDouble = writeOptions.precision == MeshPrecision::Double;
  job.metadata = writeOptions.metadata;
  job.camera = camera.has_value();
  job.deviation = a.deviation;
  job.lowerBound = a.lowerBound;
  job.measuredBound = a.lowerBound && !ruleT;
  job.toleranceSpec = toleranceSpec;
  job.patchesPerGroup = a.streamPatches;
  if (a.streamPatches)
    if (const std::string why = whyNotStreamable(job); !why.empty())
      throw CLI::ValidationError("--stream-patches", why);
  // Before the work: no output overwrites the input or another output, and each can be written.
  checkOutputs({{"input", a.input}}, {{"-o", a.output}, {"--stats", a.stats}});
  // The mesh and the report are written together at the end, both or neither.
  AtomicFileGroup files;

  // An input that cannot be opened fails here, before the Vulkan driver is loaded for a job
  // that cannot run; readSurface gives the message (the file and the reason).
  if (a.input != kStdioPath && !std::ifstream(a.input)) readSurface(a.input, inputFormat);
  PendingContext pendingContext = startMakingContext(a.backend, a.device);
  std::vector<BezierPatch> patches = readSurface(a.input, inputFormat);
  if (ruleT)
    options.tolerance =
        toleranceSpec.pixels ? toleranceSpec.value : resolveTolerance(toleranceSpec, patches);
  const std::string& inputName = job.inputName;
  job.thresholds = ruleT ? "tolerance " + describeTolerance(toleranceSpec, options.tolerance)
                         : "linearity " + shortDecimal(a.linearity) + ", flatness " +
                               shortDecimal(a.flatness);
  Progress progress(!a.quiet, progressIntervalSeconds());
  options.onLevel = progress.treeCallback(patches.size());
  options.timeGpu = !a.stats.empty() || a.json;  // the report lists the levels' GPU ms

  ChosenBackend chosen = chooseBackend(a.backend, a.device, std::move(pendingContext));
  const auto stream = [&] {
    options.onLevel = nullptr;  // the levels of one group's tree are not the job's progress
    return namingInput(inputName, [&] {
      return tessellateStreamedToFile(job, patches, options, chosen, files);
    });
  };
  if (a.streamPatches) return stream();

  std::optional<Tessellation> held;
  try {
    held = namingInput(inputName, [&] {
      return tessellateWithFallback(chosen, a.backend, patches, options, view ? &*view : nullptr);
    });
  } catch (const MemoryLimitError& e) {
    // The held mesh does not fit: written group by group it may (docs/hardening.md).
    const std::string why = whyNotStreamable(job);
    if (!why.empty())
      throw MemoryLimitError(std::string(e.what()) + "; it cannot be streamed instead: " + why);
    if (!a.quiet)
      std::fprintf(stderr, "tessera: %s; streaming the mesh in patch groups instead\n", e.what());
    return stream();
  }
  Tessellation& t = *held;
  // The GPU's work is done: what the report and the summary need of the context is taken now,
  // and the context is destroyed while the mesh is written.
  const std::string backendName = chosen.backend.name;
  const std::string deviceName = chosen.deviceName();
  const nlohmann::json runJson = runToJson(inputName, a.output, backendName, chosen.context.get());
  const nlohmann::json setupJson = setupToJson(chosen.context.get());
  const std::optional<vk::ContextTimings> setupTimings =
      chosen.context ? std::optional(chosen.context->timings()) : std::nullopt;
  const std::future<void> released = releaseInBackground(std::move(chosen));
  if (writeOptions.precision == MeshPrecision::Double && !a.output.empty())
    evaluateVerticesInDouble(t.mesh, patches);
  if (writeOptions.metadata) t.mesh.trianglePatchIds = t.trianglePatch;
  if (!a.output.empty() && !meshToStdout)
    stageMesh(files, a.output, t.mesh, formats.output, nullptr, writeOptions);
  // The deviation from the true surface (both metrics, host/mesh/deviation.h) is what the
  // thresholds are for, but measuring it can cost more than the tessellation (89% of a
  // 2000-teapot run), so it is measured only with --deviation; reports then show null.
  const bool wantReport = !a.stats.empty() || a.json;
  const bool summary = !a.quiet && !a.json;
  // The lower bound's δ: rule T's requested one, else the measured distance to the surface
  // (the mesh is within it), so --lower-bound with another rule measures the deviation.
  // Rule T puts the bound in its report; the plain summary computes it only when asked (it can
  // cost several times the tessellation of a small model: the teapot 57 ms against 12 ms).
  const bool wantBound =
      ((a.lowerBound && (wantReport || summary)) || (ruleT && wantReport)) && !view;
  std::optional<PatchDeviation> deviation, geometric;
  if ((a.deviation || (wantBound && !ruleT)) && (wantReport || summary)) {
    progress.update("measuring the deviation from the surface");
    deviation = measureDeviationPerPatch(t, patches);
    geometric =
        measureDeviationPerPatch(t, patches, deviation->subdivisions, DeviationMetric::Geometric);
  }
  // Degenerate but valid results: warned about, not refused (host/mesh/result_warnings.h).
  std::vector<double> geometricPerPatch;
  if (geometric)
    for (const DeviationReport& r : geometric->perPatch) geometricPerPatch.push_back(r.maxDeviation);
  const std::vector<ResultWarning> warnings =
      findResultWarnings(t, patches, geometric ? &geometricPerPatch : nullptr,
                         ruleT && !view ? options.tolerance : 0.0);
  if (!a.quiet)
    for (const ResultWarning& w : warnings)
      std::fprintf(stderr, "tessera: warning: %s\n", w.message.c_str());
  std::optional<TriangleLowerBound> bound;
  if (wantBound) {
    const double delta = ruleT ? options.tolerance : geometric->total.maxDeviation;
    progress.update("integrating the triangle lower bound");
    if (delta > 0.0) bound = asymptoticTriangleLowerBound(patches, delta);  // 0: an exact mesh
  }
  if (wantReport) {
    nlohmann::json report = statsToJson(t, deviation ? &*deviation : nullptr);
    if (geometric) addGeometricDeviation(report, *geometric);
    else addUnmeasuredGeometricDeviation(report);
    if (bound) addLowerBound(report, *bound);
    else addUncomputedLowerBound(report);
    if (ruleT) addToleranceReport(report, t, toleranceSpec, options.tolerance);
    addWarnings(report, warnings);
    report["run"] = runJson;
    report["run"]["options"] = optionsToJson(options);
    report["setup"] = setupJson;
    emitReport(report, files, a.stats, a.json);
  }
  files.commit();
  if (summary) {
    // With the mesh or the report on standard output, the summary goes to stderr.
    FILE* const to = meshToStdout || statsToStdout ? stderr : stdout;
    const TessellationStats& s = t.stats;
    printRunLine(to, inputName, s, options.rule, job.thresholds, backendName, deviceName);
    printCountsLine(to, s);
    // Rule T's leaves each carry their proven bound (QuadLeaf::flatness): the largest of them
    // is what the mesh is proven within, measured or not.
    if (view) {
      const ScreenLeafCounts leaves = screenLeafCounts(t.tree);
      std::fprintf(to,
                   "proven within %.4g px on screen (largest bound of %zu leaves in view; "
                   "tolerance %.4g px)%s; %zu leaves culled off-screen, %zu cut by the near plane "
                   "(unproven)\n",
                   leaves.largestBound, leaves.proven + leaves.other, options.tolerance,
                   leaves.largestBound <= options.tolerance ? "" : " — ABOVE the tolerance",
                   leaves.culled, leaves.eyePlane);
    } else if (ruleT) {
      printProvenLine(to, largestLeafBound(t.tree), options.tolerance, t.stats.diagonalFans);
    }
    if (deviation)
      std::fprintf(to,
                   "max deviation %.3g geometric (mean %.3g), %.3g parametric (mean %.3g); %zu "
                   "samples\n",
                   geometric->total.maxDeviation, geometric->total.meanDeviation,
                   deviation->total.maxDeviation, deviation->total.meanDeviation,
                   deviation->total.samples);
    if (bound) printLowerBoundLine(to, *bound, s.triangles);
    printTimesLine(to, s);
    if (setupTimings) printSetup(to, *setupTimings);
    if (deviation)
      std::fprintf(to, "deviation measured in %.1f ms (parametric) + %.1f ms (geometric)\n",
                   deviation->ms, geometric->ms);
    if (!a.output.empty() && !meshToStdout) std::fprintf(to, "wrote %s\n", a.output.c_str());
    if (!a.stats.empty() && !statsToStdout) std::fprintf(to, "wrote %s\n", a.stats.c_str());
  }
  // Last, once everything else succeeded: standard output gets the whole mesh or nothing.
  if (meshToStdout) writeMesh(a.output, t.mesh, formats.output, writeOptions);
  return kExitOk;
}

// The options `tessellate` and `stats` share.
void addTessellateOptions(CLI::App* cmd, TessellateArgs& args) {
  cmd->add_option("input", args.input,
                  "input surface file (.bpt, .grid or .json), or a CAD model (.step/.stp, "
                  ".iges/.igs, .brep); - reads standard input (needs --format)")
      ->required();
  cmd->add_option("--format", args.formats,
                  "the format where no extension tells it (- or another name): bpt, grid or "
                  "json for the input, obj, ply or glb for the output; give one or both")
      ->delimiter(',');
  cmd->add_option("-m,--method", args.method,
                  "split rule: T to a tolerance (the default), or the paper's A uniform grid, "
                  "B midpoint, C sampled κ max, D true κ max");
  cmd->add_option("--tolerance", args.tolerance,
                  "rule T: the largest distance from the surface, in model units (0.01) or as a "
                  "percentage of the control points' bounding-box diagonal (0.1%), or in pixels "
                  "on screen (1px, needs --view or --view-projection); default 0.1%. Not with "
                  "-m A..D");
  addCameraOptions(cmd, args.camera);
  cmd->add_option("--linearity", args.linearity, "rules B-D: edge linearity threshold (1 - Ti·Tj)")
      ->capture_default_str();
  cmd->add_option("--flatness", args.flatness, "rules B-D: flatness threshold (1 - Ni·Nj)")
      ->capture_default_str();
  cmd->add_option("--max-depth", args.maxDepth,
                  "maximum quad-tree depth (default 12 for rules A-D, 30 for T)");
  cmd->add_option("--samples", args.samples, "S of rules C and D (S×S samples per node)")
      ->capture_default_str();
  cmd->add_option("--grid", args.grid, "rule A's cells per patch: N (N×N) or NxM (N along u)")
      ->capture_default_str();
  cmd->add_option("--node-budget", args.nodeBudget, "most quad-tree nodes before stopping")
      ->capture_default_str();
  cmd->add_option("--frontier-budget", args.frontierBudgetMiB,
                  "MiB the quad-tree frontier may hold; larger levels go in batches")
      ->capture_default_str()
      ->check(CLI::Range(0.01, 1048576.0));
  cmd->add_option("--backend", args.backend, "vulkan, cpu, or auto (Vulkan if a device exists)")
      ->capture_default_str();
  cmd->add_option("--device", args.device, "Vulkan device index or part of its name");
  cmd->add_option("--threads", args.threads,
                  "the most CPU threads each parallel step uses (0: all cores); 1 runs "
                  "everything on the main thread. The mesh is the same whatever N. The Vulkan "
                  "driver's own threads are its own (lavapipe: LP_NUM_THREADS)")
      ->capture_default_str();
  cmd->add_flag("-q,--quiet", args.quiet, "print nothing on success (no progress either)");
  cmd->add_flag("--deviation,!--no-deviation", args.deviation,
                "measure the mesh's deviation from the true surface, geometric and parametric. "
                "Off by default: it can cost more than the tessellation (89% of a 2000-teapot "
                "run); without it the summary omits it and reports show null");
  cmd->add_flag("--skip-bad-faces", args.skipBadFaces,
                "CAD models (.step, .iges, .brep): mesh the faces that converted and list the "
                "others, instead of refusing the model");
  cmd->add_flag("--lower-bound", args.lowerBound,
                "report the asymptotic lower bound on the triangles of any mesh within δ and "
                "this mesh's triangles over it (docs/lower_bound.md). δ is rule T's tolerance, "
                "else the measured distance to the surface (measures the deviation). Rule T's "
                "report (--stats, --json) has it without this option");
}

}  // namespace

void addTessellateCommand(CLI::App& app, int& exitCode) {
  static TessellateArgs args;
  CLI::App* cmd = app.add_subcommand("tessellate", "Tessellate a surface file into a triangle mesh");
  addTessellateOptions(cmd, args);
  cmd->add_option("-o,--output", args.output,
                  "output mesh (.obj, .ply or .glb, chosen by extension); - writes it to "
                  "standard output (needs --format) and the summary to stderr");
  cmd->add_option("--stats", args.stats,
                  "write the statistics report (JSON, docs/stats_schema.md) to this file (- for "
                  "standard output)");
  cmd->add_flag("--json", args.json,
                "print the statistics report (JSON) to stdout instead of the summary");
  addMeshOutputOptions(cmd, args.mesh);
  cmd->add_option("--stream-patches", args.streamPatches,
                  "write the mesh group by group, N patches a group (each with the patches "
                  "sharing its sides), instead of holding it whole; chosen by itself (group "
                  "size automatic) when the held mesh exceeds --memory-budget. .obj and .ply "
                  "only; not with --deviation, --precision double, --metadata or a camera")
      ->check(CLI::PositiveNumber);
  cmd->callback([&exitCode] {
    exitCode = runReportingErrors([] { return run(args); },
                                  {args.output, args.stats, kStdoutName});
  });
}

// `tessera stats`: tessellate and print the statistics report (JSON), writing no mesh.
void addStatsCommand(CLI::App& app, int& exitCode) {
  static TessellateArgs args;
  CLI::App* cmd = app.add_subcommand(
      "stats", "Tessellate and print statistics as JSON (depth, leaves, triangles, deviation, time)");
  addTessellateOptions(cmd, args);
  cmd->callback([&exitCode] {
    args.json = true;
    exitCode = runReportingErrors([] { return run(args); }, {kStdoutName});
  });
}


}  // namespace tessera::cli
