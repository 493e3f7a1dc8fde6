#include "cli/cad_job.h"

#include <algorithm>
#include <cctype>
#include <cstdio>

#include "cli/commands.h"
#include "cli/outputs.h"
#include "cli/run_report.h"
#include "cli/stdio.h"
#include "common/stopwatch.h"
#include "io/errors.h"
#include "io/stats_report.h"
#include "vk/context.h"
#ifdef TESSERA_HAVE_CAD
#include "cad/mesh_cad_file.h"
#endif

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

#ifdef TESSERA_HAVE_CAD

CadResult runCadJob(const CadJob& job, ChosenBackend& chosen) {
  // The quad-trees' trim pass on the same device as the trees (null: the CPU mirror).
  const std::unique_ptr<TrimClassifier> trim =
      chosen.context ? makeVulkanTrimClassifier(*chosen.context) : nullptr;
  return meshCadFile(job.input, job.tolerance, job.skipBadFaces, "--skip-bad-faces",
                     chosen.backend, trim.get());
}

#else

CadResult runCadJob(const CadJob& job, ChosenBackend&) {
  throw InputError(InputErrorKind::Syntax, job.input, 0,
                   "this tessera was built without Open CASCADE's data exchange (host/cad/)");
}

#endif

namespace {

double largest(const CadResult& r, double TrimmedFaceStats::*field) {
  double value = 0;
  for (const TrimmedFaceStats& f : r.mesh.faces) value = std::max(value, f.*field);
  return value;
}

}  // namespace

nlohmann::json cadStatsToJson(const CadResult& r) {
  nlohmann::json faces = nlohmann::json::array();
  double parametric = 0, geometric = 0;
  for (const TrimmedFaceStats& f : r.mesh.faces) {
    parametric = std::max(parametric, f.maxParametricDeviation);
    geometric = std::max(geometric, f.maxGeometricDeviation);
    faces.push_back({{"face", f.faceIndex},
                     {"triangles", f.triangles},
                     {"maxDeviation",
                      {{"parametric", f.maxParametricDeviation},
                       {"geometric", f.maxGeometricDeviation}}},
                     // the trim points' distance from the face's surface (an edge gap): the
                     // promise is deviation ≤ δ + this (docs/trimmed_faces.md)
                     {"trimPointOffset", f.maxTrimPointOffset}});
  }
  return {{"schema", "tessera-cad-stats"},  // docs/stats_schema.md, "CAD models"
          {"schemaVersion", 1},
          {"tolerance", {{"delta", r.delta}, {"diagonal", r.diagonal}}},
          {"faces", r.faces},
          {"facesMeshed", r.mesh.faces.size()},
          {"failedFaces", r.failures},
          {"edgeWarnings", r.warnings},
          {"faceWarnings", r.faceWarnings},
          {"edges", r.edges},
          {"sharedPoints", r.sharedPoints},
          {"maxEdgeChordDeviation", r.maxChordDeviation},
          {"triangles", r.mesh.mesh.triangleCount()},
          {"vertices", r.mesh.mesh.vertexCount()},
          {"maxDeviation", {{"parametric", parametric}, {"geometric", geometric}}},
          {"maxTrimPointOffset", largest(r, &TrimmedFaceStats::maxTrimPointOffset)},
          {"timeMs", {{"read", r.readMs}, {"import", r.importMs}, {"mesh", r.meshMs}}},
          {"perFace", faces}};
}

namespace {

void printCadSummary(FILE* to, const std::string& input, const CadResult& r,
                     const std::string& toleranceText, const ChosenBackend& chosen) {
  std::fprintf(to, "%s: %zu faces (%zu meshed), %zu edges, tolerance %.4g (%s), backend %s%s%s\n",
               input.c_str(), r.faces, r.mesh.faces.size(), r.edges, r.delta,
               toleranceText.c_str(), chosen.backend.name.c_str(), chosen.context ? " on " : "",
               chosen.deviceName().c_str());
  std::fprintf(to,
               "triangles %zu, vertices %zu; measured deviation %.3g geometric, %.3g parametric; "
               "edge chords within %.3g (measured); trim points off their faces by up to %.3g "
               "(the promise: deviation <= tolerance + that)\n",
               r.mesh.mesh.triangleCount(), r.mesh.mesh.vertexCount(),
               largest(r, &TrimmedFaceStats::maxGeometricDeviation),
               largest(r, &TrimmedFaceStats::maxParametricDeviation), r.maxChordDeviation,
               largest(r, &TrimmedFaceStats::maxTrimPointOffset));
  for (const std::string& f : r.failures) std::fprintf(to, "skipped: %s\n", f.c_str());
  for (const std::string& w : r.warnings) std::fprintf(to, "warning: %s\n", w.c_str());
  for (const std::string& w : r.faceWarnings) std::fprintf(to, "warning: %s\n", w.c_str());
  std::fprintf(to, "time: read %.1f ms, faces and edges %.1f ms, mesh %.1f ms\n", r.readMs,
               r.importMs, r.meshMs);
}

}  // namespace

int tessellateCadModel(const CadCommand& c) {
  ToleranceSpec spec;
  checkCommandLine([&] {
    if (!c.method.empty() && c.method != "T" && c.method != "t")
      throw std::invalid_argument("-m " + c.method +
                                  ": a CAD model is meshed to a tolerance (rule T); leave out -m");
    if (!c.tolerance.empty()) spec = parseTolerance(c.tolerance);
    if (spec.pixels)
      throw std::invalid_argument("--tolerance '" + c.tolerance +
                                  "': a CAD model takes a distance or a percentage, not pixels");
    if (c.camera)
      throw std::invalid_argument("--view / --view-projection: not for CAD models (yet)");
    if (c.lowerBound)
      throw std::invalid_argument("--lower-bound: not for CAD models (yet)");
  });
  const StreamFormats formats = parseFormats(c.formats);
  if (c.output == kStdioPath || c.stats == kStdioPath)
    throw CLI::ValidationError("--output", "a CAD model's mesh and report go to files (or --json)");
  if (!c.output.empty()) checkMeshFormat(c.output, formats.output);
  checkOutputs({{"input", c.input}}, {{"-o", c.output}, {"--stats", c.stats}});
  AtomicFileGroup files;

  ChosenBackend chosen = chooseBackend(c.backend, c.device);
  const CadJob job{c.input, spec, c.skipBadFaces};
  CadResult r;
  try {
    r = runCadJob(job, chosen);
  } catch (const vk::VulkanError& e) {
    if (c.backend != "auto" || !chosen.context) throw;
    std::fprintf(stderr, "tessera: the Vulkan device failed (%s); falling back to the CPU backend\n",
                 e.what());
    chosen.backend = makeMirrorBackend();
    chosen.context.reset();
    r = runCadJob(job, chosen);
  }
  if (!c.output.empty()) stageMesh(files, c.output, r.mesh.mesh, formats.output, &r.mesh.triangleFace);
  char diagonal[32];
  std::snprintf(diagonal, sizeof diagonal, "%g", r.diagonal);
  const std::string toleranceText =
      spec.relative ? spec.text + " of the diagonal " + diagonal : "model units";
  if (!c.stats.empty() || c.json) {
    nlohmann::json report = cadStatsToJson(r);
    report["tolerance"]["given"] = spec.text;
    report["run"] = runToJson(c.input, c.output, chosen.backend.name, chosen.context.get());
    emitReport(report, files, c.stats, c.json);
  }
  files.commit();
  if (!c.quiet && !c.json) {
    printCadSummary(stdout, c.input, r, toleranceText, chosen);
    if (!c.output.empty()) std::printf("wrote %s\n", c.output.c_str());
    if (!c.stats.empty()) std::printf("wrote %s\n", c.stats.c_str());
  }
  return kExitOk;
}

}  // namespace tessera::cli
