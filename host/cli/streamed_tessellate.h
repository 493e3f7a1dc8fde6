// `tessera tessellate` writing the mesh group by group (mesh/streamed_tessellation.h,
// io/mesh_stream_writer.h): forced by --stream-patches N, or chosen when the held mesh's
// estimate exceeds the memory budget. What needs the whole mesh is refused (exit 1 when forced)
// or leaves the budget's exit 4 standing, with the reason (docs/hardening.md).
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "cli/cli_support.h"
#include "geometry/patch.h"
#include "io/atomic_file.h"
#include "quadtree/quadtree.h"
#include "quadtree/tolerance.h"

namespace tessera::cli {

// What a streamed run is asked for; the checks of cmd_tessellate.cpp are done.
struct StreamedJob {
  std::string inputName;
  std::string output;
  std::string format;  // of the output: what meshFormat gave
  std::string stats;   // --stats path (or -), empty for none
  bool json = false;
  bool quiet = false;
  bool precisionDouble = false, metadata = false, camera = false, deviation = false;
  bool lowerBound = false;       // --lower-bound: printed in the summary (rule T)
  bool measuredBound = false;    // --lower-bound with rules A–D: needs the measured deviation
  std::string thresholds;  // for the summary: "tolerance 0.1% (…)" or "linearity …, flatness …"
  ToleranceSpec toleranceSpec;
  size_t patchesPerGroup = 0;  // 0: sized automatically
};

// Empty when `job` can be streamed (to .obj, .ply or .glb), else why not ("--deviation
// measures the whole mesh", …).
std::string whyNotStreamable(const StreamedJob& job);

// Tessellates `patches` in groups into job.output (staged in `files`, committed here with the
// report) and reports as the held run does (totals, times; per-patch counts, deviation and
// warnings are not computed, which the report says). Returns the exit code.
int tessellateStreamedToFile(const StreamedJob& job, const std::vector<BezierPatch>& patches,
                             const QuadtreeOptions& options, ChosenBackend& chosen,
                             AtomicFileGroup& files);

}  // namespace tessera::cli
