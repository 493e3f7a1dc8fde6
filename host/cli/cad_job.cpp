// tessera-cad's side of the CAD seam (cad_job.h): the entry points run the model here,
// through host/cad/ and Open CASCADE. tessera links cad_handoff.cpp in their place.
#include "cli/cad_job.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <stdexcept>

#include "cad/instances.h"
#include "cad/mesh_cad_file.h"
#include "cad/to_trimmed.h"
#include "cli/cli_support.h"
#include "cli/commands.h"
#include "cli/outputs.h"
#include "cli/run_report.h"
#include "cli/stdio.h"
#include "io/errors.h"
#include "io/stats_report.h"
#include "trim/mesher.h"
#include "vk/context.h"

namespace tessera::cli {
namespace {

struct CadJob {
  std::string input;
  ToleranceSpec tolerance;    // model units or a share of the model's diagonal; not pixels
  bool skipBadFaces = false;  // write the faces that converted when some did not
  // An assembly's copies in the mesh (OBJ, PLY, a picture) or only listed (a .glb draws them
  // as nodes, a run with no mesh output needs none): cad/mesh_cad_file.h.
  CopyPlacement copies = CopyPlacement::InMesh;
};

// What a CAD run gives: the mesh, δ, counts, failures and warnings (cad/mesh_cad_file.h).
using CadResult = CadMeshRun;

// Reads and meshes the model on chosen's backend. A face that does not convert is an
// InputError naming the file and every failed face, unless job.skipBadFaces (then the faces
// are listed in CadResult::failures and the others meshed).
CadResult runCadJob(const CadJob& job, ChosenBackend& chosen) {
  // The quad-trees' trim pass on the same device as the trees (null: the CPU mirror).
  const std::unique_ptr<TrimClassifier> trim =
      chosen.context ? makeVulkanTrimClassifier(*chosen.context) : nullptr;
  return meshCadFile(job.input, job.tolerance, job.skipBadFaces, "--skip-bad-faces", chosen.backend,
                     trim.get(), 0, job.copies);
}

double largest(const CadResult& r, double TrimmedFaceStats::*field) {
  double value = 0;
  for (const TrimmedFaceStats& f : r.mesh.faces) value = std::max(value, f.*field);
  return value;
}

// The statistics report of a CAD run: δ, faces, edges, triangles, deviation per face.
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
          {"emptyFaces", r.emptyFaces},
          {"readerWarnings", r.readerWarnings},
          {"edgeWarnings", r.warnings},
          {"faceWarnings", r.faceWarnings},
          {"edges", r.edges},
          {"sharedPoints", r.sharedPoints},
          // an assembly's parts placed more than once, meshed once and moved (docs/cad.md)
          {"instancedParts", r.instancedParts()},
          {"instanceCopies", r.instanceCopies()},
          {"maxEdgeChordDeviation", r.maxChordDeviation},
          {"triangles", r.modelTriangles()},
          {"vertices", r.modelVertices()},
          {"maxDeviation", {{"parametric", parametric}, {"geometric", geometric}}},
          {"maxTrimPointOffset", largest(r, &TrimmedFaceStats::maxTrimPointOffset)},
          {"timeMs", {{"read", r.readMs}, {"import", r.importMs}, {"mesh", r.meshMs}}},
          {"perFace", faces}};
}

void printCadSummary(FILE* to, const std::string& input, const CadResult& r,
                     const std::string& toleranceText, const ChosenBackend& chosen) {
  std::string empty;
  if (!r.emptyFaces.empty()) empty = ", " + std::to_string(r.emptyFaces.size()) + " of zero area";
  std::fprintf(to, "%s: %zu faces (%zu meshed%s), %zu edges, tolerance %.4g (%s), backend %s%s%s\n",
               input.c_str(), r.faces, r.mesh.faces.size(), empty.c_str(), r.edges, r.delta,
               toleranceText.c_str(), chosen.backend.name.c_str(), chosen.context ? " on " : "",
               chosen.deviceName().c_str());
  std::fprintf(to,
               "triangles %zu, vertices %zu; measured deviation %.3g geometric, %.3g parametric; "
               "edge chords within %.3g (measured); trim points off their faces by up to %.3g "
               "(the promise: deviation <= tolerance + that)\n",
               size_t(r.modelTriangles()), size_t(r.modelVertices()),
               largest(r, &TrimmedFaceStats::maxGeometricDeviation),
               largest(r, &TrimmedFaceStats::maxParametricDeviation), r.maxChordDeviation,
               largest(r, &TrimmedFaceStats::maxTrimPointOffset));
  if (r.instanceCopies() != 0)
    std::fprintf(to,
                 "assembly: %zu part%s placed more than once, meshed once and moved to %zu "
                 "more places\n",
                 r.instancedParts(), r.instancedParts() == 1 ? "" : "s", r.instanceCopies());
  for (const std::string& f : r.failures) std::fprintf(to, "skipped: %s\n", f.c_str());
  for (const std::string& f : r.emptyFaces)
    std::fprintf(to, "empty: %s (no triangles)\n", f.c_str());
  for (const std::string& w : r.readerWarnings) std::fprintf(to, "warning: %s\n", w.c_str());
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
  checkCommandLine([&] {
    if (c.output == kStdioPath || c.stats == kStdioPath)
      throw std::invalid_argument("--output: a CAD model's mesh and report go to files (or --json)");
  });
  if (!c.output.empty()) checkMeshFormat(c.output, formats.output);
  checkOutputs({{"input", c.input}}, {{"-o", c.output}, {"--stats", c.stats}});
  AtomicFileGroup files;

  ChosenBackend chosen = chooseBackend(c.backend, c.device);
  // The .glb draws the copies from the plan: only OBJ and PLY need them in the mesh.
  const bool flatOutput = !c.output.empty() && meshFormat(c.output, formats.output) != "glb";
  const CadJob job{c.input, spec, c.skipBadFaces,
                   flatOutput ? CopyPlacement::InMesh : CopyPlacement::Listed};
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
  if (!c.output.empty())
    stageMesh(files, c.output, r.mesh.mesh, formats.output, &r.mesh.triangleFace, {},
              r.glbInstances.placements.empty() ? nullptr : &r.glbInstances);
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

int renderCadModel(const CadRenderCommand& c) {
  checkOutputs({{"input", c.input}}, {{"-o", c.output}});
  vk::ContextOptions vkOptions;
  vkOptions.device = c.device;
  ChosenBackend chosen;
  chosen.context = std::make_unique<vk::Context>(vkOptions);
  if (!chosen.context->queueSupportsGraphics())
    throw vk::VulkanUnavailable("device '" + chosen.deviceName() +
                                "' cannot draw (no graphics queue); choose another with --device");
  chosen.backend = makeVulkanBackend(*chosen.context);
  const CadResult r = runCadJob({c.input, c.tolerance, false}, chosen);
  std::vector<float> values;
  if (c.options.colour == RenderOptions::Colour::Patch)
    values.assign(r.mesh.triangleFace.begin(), r.mesh.triangleFace.end());
  const std::vector<uint8_t> picture = renderMesh(*chosen.context, r.mesh.mesh, values, c.options);
  writePicture(c.output, picture, c.options.width, c.options.height);
  if (!c.quiet) {
    FILE* const to = c.output == kStdioPath ? stderr : stdout;
    std::fprintf(to, "%s: %zu faces, %zu triangles, tolerance %.4g, on %s\n", c.input.c_str(),
                 r.mesh.faces.size(), r.mesh.mesh.triangleCount(), r.delta,
                 chosen.deviceName().c_str());
    std::fprintf(to, "wrote %s (%dx%d)\n", c.output == kStdioPath ? kStdoutName : c.output.c_str(),
                 c.options.width, c.options.height);
  }
  return kExitOk;
}

int describeCadModel(const std::string& path) {
  const CadFile file = readCadFile(path);
  // δ as `tessera tessellate` takes it (an assembly's diagonal from its parts' placed boxes).
  const InstancePlan plan = planCadInstances(file);
  const double delta = kDefaultRelativeTolerance * plannedModelDiagonal(plan, file);
  const CadImport in = toTrimmedModel(file, delta);
  std::printf(
      "%s: %d faces (%zu converted, %zu of zero area, %zu failed), %d edges, %d vertices, "
      "%zu shared points at δ %g\n",
      path.c_str(), in.faces.Extent(), in.model.faces.size(), in.emptyFaces.size(),
      in.failures.size(), in.edges.Extent(), in.vertices.Extent(), in.model.sharedPoints.size(),
      delta);
  if (!plan.copies.empty())
    std::printf(
        "assembly: %zu part%s placed more than once; tessellate meshes each once and "
        "moves it to %zu more places\n",
        plan.parts.size(), plan.parts.size() == 1 ? "" : "s", plan.copies.size());
  for (const auto& failure : in.failures) std::printf("failed: %s\n", failure.message.c_str());
  for (const auto& face : in.emptyFaces)
    std::printf("empty: %s (no triangles)\n", face.message.c_str());
  for (const auto& warning : file.readerWarnings) std::printf("warning: %s\n", warning.c_str());
  for (const auto& warning : in.warnings) std::printf("warning: %s\n", warning.message.c_str());
  return kExitOk;
}

}  // namespace tessera::cli
