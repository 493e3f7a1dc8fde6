#include "cli/streamed_tessellate.h"

#include <cstdio>
#include <optional>

#include <nlohmann/json.hpp>

#include "cli/commands.h"
#include "cli/run_report.h"
#include "cli/setup_report.h"
#include "common/memory_budget.h"
#include "cli/stdio.h"
#include "cli/tessellate_summary.h"
#include "io/mesh_stream_writer.h"
#include "io/stats_report.h"
#include "mesh/lower_bound.h"
#include "mesh/streamed_tessellation.h"

namespace tessera::cli {

std::string whyNotStreamable(const StreamedJob& job) {
  if (job.output.empty()) return "no mesh output (-o) to stream to";
  if (job.output == kStdioPath) return "a mesh on standard output is written whole (-o -)";
  if (job.precisionDouble) return "--precision double evaluates the whole mesh again";
  if (job.metadata) return "--metadata is not written while streaming";
  if (job.camera) return "a screen tolerance (--view, --view-projection) needs the whole tree";
  if (job.deviation) return "--deviation measures the whole mesh";
  if (job.measuredBound) return "--lower-bound with rules A–D measures the whole mesh's deviation";
  return "";
}

int tessellateStreamedToFile(const StreamedJob& job, const std::vector<BezierPatch>& patches,
                             const QuadtreeOptions& options, ChosenBackend& chosen,
                             AtomicFileGroup& files) {
  MeshStreamWriter writer(job.format == "obj"   ? MeshStreamWriter::Format::Obj
                          : job.format == "ply" ? MeshStreamWriter::Format::Ply
                                                : MeshStreamWriter::Format::Glb,
                          job.output);
  const StreamedTessellationStats streamed =
      tessellateStreamed(patches, options, chosen.backend, job.patchesPerGroup,
                         [&](const MeshChunk& chunk) { writer.add(chunk); });
  files.stage(job.output, [&](std::ostream& out) { writer.finish(out); });
  const TessellationStats& s = streamed.totals;
  const bool ruleT = options.rule == SplitRule::Tolerance;
  const bool wantReport = !job.stats.empty() || job.json;
  const bool summary = !job.quiet && !job.json;
  std::optional<TriangleLowerBound> bound;  // rule T's needs only the patches and δ
  if (ruleT && (wantReport || (summary && job.lowerBound)))
    bound = asymptoticTriangleLowerBound(patches, options.tolerance);
  const bool statsToStdout = job.stats == kStdioPath;
  if (wantReport) {
    nlohmann::json report = statsToJson(s);
    addUnmeasuredGeometricDeviation(report);
    if (bound) addLowerBound(report, *bound);
    else addUncomputedLowerBound(report);
    report["patches"] = nullptr;
    report["tolerance"] = nullptr;
    if (ruleT)
      addToleranceBound(report, job.toleranceSpec, options.tolerance, streamed.largestLeafBound,
                        s.diagonalFans);
    addWarnings(report, {});
    report["streamed"] = {
        {"groups", streamed.groups},
        {"patchesPerGroup", streamed.patchesPerGroup},
        {"seamVertices", streamed.seamVertices},
        {"largestGroupBytes", streamed.largestGroupBytes},
        {"notComputed", {"patches", "levels", "warnings", "deviation"}}};
    report["run"] = runToJson(job.inputName, job.output, chosen.backend.name,
                              chosen.context.get());
    report["run"]["options"] = optionsToJson(options);
    report["setup"] = setupToJson(chosen.context.get());
    emitReport(report, files, job.stats, job.json);
  }
  files.commit();
  if (summary) {
    FILE* const to = statsToStdout ? stderr : stdout;
    printRunLine(to, job.inputName, s, options.rule, job.thresholds, chosen.backend.name,
                 chosen.deviceName());
    std::fprintf(to,
                 "streamed in %zu groups of up to %zu patches (largest group's estimate %s, "
                 "at most %zu seam vertices held for welding)\n",
                 streamed.groups, streamed.patchesPerGroup,
                 formatByteSize(streamed.largestGroupBytes).c_str(), streamed.seamVertices);
    printCountsLine(to, s);
    if (ruleT) printProvenLine(to, streamed.largestLeafBound, options.tolerance, s.diagonalFans);
    if (bound && job.lowerBound) printLowerBoundLine(to, *bound, s.triangles);
    printTimesLine(to, s);
    if (chosen.context) printSetup(to, chosen.context->timings());
    std::fprintf(to, "wrote %s\n", job.output.c_str());
    if (!job.stats.empty() && !statsToStdout) std::fprintf(to, "wrote %s\n", job.stats.c_str());
  }
  return kExitOk;
}

}  // namespace tessera::cli
