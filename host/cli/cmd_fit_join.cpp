// tessera fit | join: fitting a Loop control mesh to a target surface, refining until a
// tolerance, and joining or pasting two control meshes (docs/loop.md).
#include <CLI/CLI.hpp>

#include <cstdio>
#include <limits>
#include <stdexcept>

#include "cli/cli_support.h"
#include "cli/commands.h"
#include "cli/loop_args.h"
#include "io/errors.h"
#include "io/obj_reader.h"
#include "io/png_writer.h"
#include "io/vertex_selection.h"
#include "loop/bvh.h"
#include "loop/fit_refine.h"
#include "loop/join.h"
#include "quadtree/tolerance.h"
#include "render/join_picture.h"
#include "vk/context.h"

namespace tessera::cli {
namespace {

// The axis-aligned bounding box diagonal of `positions`: what a relative --tolerance refers to.
double diagonalOf(const std::vector<glm::dvec3>& positions) {
  glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
  for (const glm::dvec3& p : positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
  return positions.empty() ? 0.0 : glm::length(hi - lo);
}

}  // namespace

int runFit(const LoopArgs& a) {
  checkMeshFormat(a.output);
  const MeshWriteOptions writeOptions = meshWriteOptions(a.mesh, a.output);
  ToleranceSpec toleranceSpec;
  checkCommandLine([&] {
    toleranceSpec = parseTolerance(a.tolerance);
    if (toleranceSpec.pixels)
      throw std::invalid_argument("--tolerance: fit takes a distance or a percentage of the "
                                  "target's diagonal, not pixels ('" + a.tolerance + "')");
  });
  checkOutputs({{"cage", a.input}, {"target", a.target}}, {{"-o", a.output}});
  LoopShape cage = readControlMesh(a.input);
  const PolygonMesh target = readObj(a.target);
  validateTriangles(target, a.target);
  std::vector<uint32_t> triangles;
  for (const auto& f : target.faces) triangles.insert(triangles.end(), f.begin(), f.end());
  const TriangleBvh bvh(target.positions, triangles);
  const double diagonal = diagonalOf(target.positions);
  const double tolerance = toleranceSpec.relative ? toleranceSpec.value * diagonal : toleranceSpec.value;
  if (!(tolerance > 0))
    throw InputError(InputErrorKind::Topology, a.target, 0,
                     "all the target's points are the same, so a relative --tolerance is 0");
  LoopRefiningFitOptions options;
  options.fit.lambda = a.lambda;
  options.fit.energyThreshold = a.threshold;
  options.fit.maxIterations = a.iterations;
  options.tolerance = tolerance;
  options.maxRounds = a.maxRounds;
  options.maxTriangles = a.maxTriangles;
  const size_t trianglesIn = cage.topology.triangles.size() / 3;
  const LoopRefiningFitReport report = fitLoopRefining(cage, bvh, options);
  writeMesh(a.output, loopMesh(cage.positions, cage.topology.triangles, {}), "", writeOptions);
  const std::string tol = describeTolerance(toleranceSpec, tolerance);
  for (size_t i = 0; i < report.rounds.size(); ++i) {
    const LoopFitRound& r = report.rounds[i];
    std::printf("round %zu: %zu triangles, E %.6g -> %.6g in %d steps, max |p_inf - q| %.6g, "
                "limit surface within %.6g of the target\n",
                i + 1, r.triangles, r.fit.energy.front(), r.fit.energy.back(), r.fit.iterations,
                r.fit.maxDistance, r.distance);
  }
  // Stopped by a bound with the surface still too far: written, but said (exit 0).
  if (!report.reached) {
    std::fflush(stdout);  // after the rounds it sums up
    const bool byRounds = report.stoppedBy == "rounds";
    std::fprintf(stderr,
                 "tessera: warning: the fit stopped at the bound of %s with the limit surface "
                 "%.6g from the target, above the tolerance %s (raise %s or the tolerance)\n",
                 byRounds ? (std::to_string(a.maxRounds) + " rounds").c_str()
                          : (std::to_string(a.maxTriangles) + " control triangles").c_str(),
                 report.distance, tol.c_str(), byRounds ? "--max-rounds" : "--max-triangles");
  }
  std::printf("fit %s to %s: %zu %s, %zu -> %zu triangles, limit surface within %.6g of the "
              "target (tolerance %s%s): wrote %s\n",
              a.input.c_str(), a.target.c_str(), report.rounds.size(),
              report.rounds.size() == 1 ? "round" : "rounds", trianglesIn,
              cage.topology.triangles.size() / 3, report.distance, tol.c_str(),
              report.reached ? "" : ", not reached", a.output.c_str());
  return kExitOk;
}

int runJoin(const LoopArgs& a) {
  checkMeshFormat(a.output);
  const MeshWriteOptions writeOptions = meshWriteOptions(a.mesh, a.output);
  checkOutputs({{"first", a.input}, {"second", a.target}, {"--paste-vertex-file", a.pasteFile}},
               {{"-o", a.output}, {"--picture", a.picture}});
  LoopShape first = readControlMesh(a.input);
  const LoopShape second = readControlMesh(a.target);
  if (!a.cut.empty()) {
    if (a.cut.size() != 4) throw CLI::ValidationError("--paste-plane", "needs nx ny nz d");
    first = cutByPlane(first, {a.cut[0], a.cut[1], a.cut[2]}, a.cut[3]);
  }
  if (!a.pasteList.empty() || !a.pasteFile.empty()) {
    const uint32_t count = first.topology.vertexCount;
    std::vector<uint32_t> chosen;
    if (!a.pasteFile.empty()) chosen = readVertexSelection(a.pasteFile, count);  // exit 2
    if (!a.pasteList.empty()) {
      std::vector<uint32_t> listed;
      try {
        listed = parseVertexList(a.pasteList, count);
      } catch (const std::invalid_argument& e) {  // a number past this mesh: still the option
        throw CLI::ValidationError("--paste-vertices", e.what());
      }
      chosen.insert(chosen.end(), listed.begin(), listed.end());
    }
    try {
      first = cutByVertices(first, chosen);
    } catch (const std::invalid_argument& e) {  // the selection holds no one region to paste
      if (a.pasteFile.empty()) throw CLI::ValidationError("--paste-vertices", e.what());
      throw InputError(InputErrorKind::Topology, a.pasteFile, 0, e.what());
    }
  }
  LoopJoinOptions options;
  options.levelsA = a.levelsA.value_or(-1);
  options.levelsB = a.levelsB.value_or(-1);
  const LoopJoinResult r = joinLoopMeshes(first, second, options);
  // The mesh and the picture are written together, both or neither.
  AtomicFileGroup files;
  stageMesh(files, a.output, loopMesh(r.mesh.positions, r.mesh.topology.triangles, {}), "",
            nullptr, writeOptions);
  std::string drawnOn;
  if (!a.picture.empty()) {
    vk::ContextOptions vkOptions;
    vkOptions.device = a.device;
    vk::Context context(vkOptions);
    const int panel = 640, height = 480;
    const std::vector<uint8_t> rgba = renderJoinPicture(context, first, second, r, panel, height);
    files.stage(a.picture, [&](std::ostream& out) { writePng(out, rgba, 3 * panel, height); });
    drawnOn = context.info().name;
  }
  files.commit();
  if (!a.picture.empty())
    std::printf("drew %s (inputs, placement, result) on %s\n", a.picture.c_str(), drawnOn.c_str());
  const LoopJoinReport& p = r.report;
  std::printf("join %s + %s: levels %d/%d, triangles %zu -> %zu (bridge %zu), %zu vertices "
              "fitted, %zu unchanged, max |p_inf - original| %.3g: wrote %s\n",
              a.input.c_str(), a.target.c_str(), p.levelsA, p.levelsB, p.trianglesIn,
              p.trianglesOut, p.bridgeTriangles, p.fittedVertices, p.unchangedVertices,
              p.maxDeviation, a.output.c_str());
  return kExitOk;
}

}  // namespace tessera::cli
