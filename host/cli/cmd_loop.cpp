// tessera loop | limit | fit | join: Loop subdivision surfaces from OBJ control meshes
// (docs/loop.md). Output by extension: .obj, .ply or .glb.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>

#include "cli/cli_support.h"
#include "cli/commands.h"
#include "cli/outputs.h"
#include "common/memory_budget.h"
#include "io/errors.h"
#include "io/gltf_writer.h"
#include "io/obj_reader.h"
#include "io/obj_writer.h"
#include "io/ply_writer.h"
#include "io/vertex_selection.h"
#include "loop/evaluator.h"
#include "loop/fit_refine.h"
#include "loop/join.h"
#include "loop/limit.h"
#include "render/join_picture.h"
#include "io/png_writer.h"
#include "quadtree/tolerance.h"
#include "vk/context.h"
#include "loop/stencils.h"

namespace tessera::cli {
namespace {

// A triangle control mesh from OBJ; topology errors name the file and the face's line.
LoopShape readControlMesh(const std::string& path,
                          LoopBoundary boundary = LoopBoundary::EdgeAndCorner) {
  PolygonMesh polygons = readObj(path);
  validateTriangles(polygons, path);
  validateManifold(polygons, path);
  validateNoIsolatedVertices(polygons, path);
  LoopShape shape;
  shape.name = std::filesystem::path(path).stem().string();
  shape.positions = polygons.positions;
  shape.topology.vertexCount = uint32_t(polygons.positions.size());
  shape.topology.boundary = boundary;
  for (const auto& face : polygons.faces)
    shape.topology.triangles.insert(shape.topology.triangles.end(), face.begin(), face.end());
  try {
    buildLoopTopology(shape.topology);
  } catch (const LoopTopologyError& e) {
    const int line = e.face() < polygons.faceLines.size() ? polygons.faceLines[e.face()] : 0;
    throw InputError(InputErrorKind::Topology, path, line, e.what());
  }
  return shape;
}

TriangleMesh loopMesh(const std::vector<glm::dvec3>& positions,
                      const std::vector<uint32_t>& triangles, const std::vector<glm::dvec3>& normals) {
  TriangleMesh mesh;
  for (const auto& p : positions) mesh.positions.push_back(glm::vec3(p));
  for (const auto& n : normals) mesh.normals.push_back(glm::vec3(n));
  mesh.positionsDouble = positions;  // what --precision double writes
  mesh.normalsDouble = normals;
  mesh.indices = triangles;
  return mesh;
}

struct LoopArgs {
  std::string input, target, output, backend = "auto", device;
  int levels = 2;
  bool limit = false;
  double lambda = 1.0, threshold = 0.0;
  int iterations = 100;
  std::string tolerance = "0.1%";  // fit: ε, model units or a percentage of the target's diagonal
  int maxRounds = 5;               // fit: rounds of fitting, each after a subdivision but the first
  size_t maxTriangles = 100000;    // fit: no subdivision past this many control triangles
  std::optional<int> levelsA, levelsB;  // join; unset: chosen by area (LoopJoinOptions)
  std::vector<double> cut;  // paste: nx ny nz d
  std::string pasteList, pasteFile;  // paste: chosen vertices, 1-based (io/vertex_selection.h)
  std::string picture;      // join: inputs, placement and result as one PNG
  MeshOutputArgs mesh;      // --precision
  std::string boundary = "corner";  // loop, limit: OpenSubdiv's EDGE_AND_CORNER, or "edge"
  uint64_t batchBytes = 0;          // loop, limit on Vulkan: 0 is the device's own bound
};

// Refines on the chosen backend through the stencil tables; with `limit`, the last level's
// vertices pushed to the limit surface, with limit normals.
int runRefine(const LoopArgs& a) {
  checkMeshFormat(a.output);
  const MeshWriteOptions writeOptions = meshWriteOptions(a.mesh, a.output);
  const bool inDouble = writeOptions.precision == MeshPrecision::Double;
  if (inDouble && a.backend == "vulkan")
    throw CLI::ValidationError("--precision", "double refines in double on the CPU; Vulkan "
                                              "computes in fp32: use --backend cpu or auto");
  checkOutputs({{"input", a.input}}, {{"-o", a.output}});
  const LoopShape shape = readControlMesh(
      a.input, a.boundary == "edge" ? LoopBoundary::EdgeOnly : LoopBoundary::EdgeAndCorner);
  LoopStencilOptions options;
  options.levels = a.levels;
  options.limit = options.tangents = a.limit;
  LoopStencils stencils = buildLoopStencils(buildLoopTopology(shape.topology), options);
  // --precision double: the stencils applied in double (the reference, without the rounding
  // to fp32), so the output keeps what OpenSubdiv's PrimvarRefinerReal<double> gives.
  std::vector<double> rows(stencils.table.rowCount() * 3, 0.0);
  std::string evaluatorName = "the CPU in double";
  if (inDouble) {
    for (size_t v = 0; v < shape.positions.size(); ++v)
      for (int c = 0; c < 3; ++c) rows[3 * v + c] = shape.positions[v][c];
    applyStencils(stencils.table, rows, 3);
  } else {
    ChosenBackend chosen = chooseBackend(a.backend, a.device);
    std::vector<float> floatRows(stencils.table.rowCount() * 3, 0.0f);
    for (size_t v = 0; v < shape.positions.size(); ++v)
      for (int c = 0; c < 3; ++c) floatRows[3 * v + c] = float(shape.positions[v][c]);
    std::unique_ptr<StencilEvaluator> evaluator;
    try {
      evaluator =
          chosen.context
              ? makeVulkanStencilEvaluator(*chosen.context, toFloatStencils(stencils.table), 3,
                                           {a.batchBytes})
              : makeReferenceStencilEvaluator(stencils.table, 3);
      evaluator->apply(floatRows);  // rows past the control vertices change only on success
    } catch (const vk::VulkanError& e) {
      // As tessellate does (tessellateWithFallback): with --backend auto, a device that fails
      // mid-run hands the work to the CPU.
      if (a.backend != "auto" || !chosen.context) throw;
      std::fprintf(stderr,
                   "tessera: the Vulkan device failed (%s); falling back to the CPU backend\n",
                   e.what());
      evaluator = makeReferenceStencilEvaluator(stencils.table, 3);
      chosen.backend = makeMirrorBackend();  // its classifier holds the context: drop it first
      chosen.context.reset();
      evaluator->apply(floatRows);
    }
    rows.assign(floatRows.begin(), floatRows.end());
    evaluatorName = evaluator->name();
  }
  const LoopTopology& last = stencils.topology.back();
  auto rowsAt = [&](uint32_t first) {
    std::vector<glm::dvec3> out(last.vertexCount);
    for (uint32_t v = 0; v < last.vertexCount; ++v)
      out[v] = glm::dvec3(rows[3 * (first + v)], rows[3 * (first + v) + 1], rows[3 * (first + v) + 2]);
    return out;
  };
  std::vector<glm::dvec3> normals;
  size_t zeroNormals = 0;
  if (a.limit) {
    const auto t1 = rowsAt(stencils.tangent1Row), t2 = rowsAt(stencils.tangent2Row);
    for (uint32_t v = 0; v < last.vertexCount; ++v) {
      const glm::dvec3 n = glm::cross(t1[v], t2[v]);
      zeroNormals += !(glm::length(n) > 0);
      normals.push_back(glm::length(n) > 0 ? glm::normalize(n) : glm::dvec3(0.0));
    }
  }
  // The "zero-normals" condition of host/mesh/result_warnings.h: written, but said.
  if (zeroNormals > 0)
    std::fprintf(stderr,
                 "tessera: warning: %zu %s no limit normal (written as 0 0 0): the limit "
                 "tangents are parallel there\n",
                 zeroNormals, zeroNormals == 1 ? "vertex has" : "vertices have");
  writeMesh(a.output,
            loopMesh(rowsAt(a.limit ? stencils.limitRow : stencils.levelRow.back()),
                     last.triangles, normals),
            "", writeOptions);
  std::printf("%s: %zu triangles, level %d%s on %s: wrote %s (%u vertices, %zu triangles)\n",
              a.input.c_str(), shape.topology.triangles.size() / 3, a.levels,
              a.limit ? " limit" : "", evaluatorName.c_str(), a.output.c_str(),
              last.vertexCount, last.faceCount());
  return kExitOk;
}

// The axis-aligned bounding box diagonal of `positions`: what a relative --tolerance refers to.
double diagonalOf(const std::vector<glm::dvec3>& positions) {
  glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
  for (const glm::dvec3& p : positions) lo = glm::min(lo, p), hi = glm::max(hi, p);
  return positions.empty() ? 0.0 : glm::length(hi - lo);
}

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

}  // namespace

void addLoopCommands(CLI::App& app, int& exitCode) {
  static LoopArgs args;
  for (const bool limit : {false, true}) {
    CLI::App* cmd = app.add_subcommand(limit ? "limit" : "loop",
                                       limit ? "Loop limit surface: refine, push to the limit, with normals"
                                             : "Loop subdivision of a triangle control mesh (OBJ)");
    cmd->add_option("input", args.input, "control mesh (.obj, triangles)")->required();
    cmd->add_option("-o,--output", args.output, "output mesh (.obj, .ply or .glb)")->required();
    cmd->add_option("-l,--levels", args.levels, "refinement levels")->check(CLI::Range(0, 8));
    cmd->add_option("--backend", args.backend, "vulkan, cpu or auto")->check(CLI::IsMember({"vulkan", "cpu", "auto"}));
    cmd->add_option("--device", args.device, "Vulkan device (name substring or index)");
    addMeshOutputOptions(cmd, args.mesh);
    cmd->add_option("--boundary", args.boundary,
                    "a boundary vertex of a single triangle: corner (kept in place, OpenSubdiv's "
                    "VTX_BOUNDARY_EDGE_AND_CORNER) or edge (a crease vertex, rounded off: "
                    "VTX_BOUNDARY_EDGE_ONLY, OpenSubdiv's default)")
        ->check(CLI::IsMember({"edge", "corner"}))
        ->capture_default_str();
    cmd->add_option_function<std::string>(
           "--batch-bytes",
           [](const std::string& text) {
             try {
               args.batchBytes = parseByteSize(text);
             } catch (const std::invalid_argument& e) {
               throw CLI::ValidationError("--batch-bytes", e.what());
             }
           },
           "Vulkan: the largest array the stencils bind at once (e.g. 64K; default: the "
           "device's storage buffer range); larger tables go in batches of rows")
        ->type_name("SIZE");
    cmd->callback([&exitCode, limit] {
      args.limit = limit;
      exitCode = runReportingErrors([] { return runRefine(args); }, {args.output});
    });
  }
  CLI::App* fit = app.add_subcommand("fit", "Fit a Loop control mesh to a target mesh (Suzuki et al.)");
  fit->add_option("cage", args.input, "control mesh to move (.obj)")->required();
  fit->add_option("target", args.target, "target surface (.obj, triangles)")->required();
  fit->add_option("-o,--output", args.output, "fitted control mesh (.obj, .ply or .glb)")->required();
  fit->add_option("--lambda", args.lambda, "step weight λ in (0, 2]")
      ->check(CLI::Validator(
          [](std::string& text) {
            const double lambda = std::strtod(text.c_str(), nullptr);
            return lambda > 0.0 && lambda <= 2.0 ? std::string() : "λ must be in (0, 2], got " + text;
          },
          ""));
  fit->add_option("--threshold", args.threshold, "stop when E = Σ|p∞ − q|² is below this (≥ 0)")
      ->check(CLI::NonNegativeNumber);
  fit->add_option("--iterations", args.iterations, "at most this many steps per round")->check(CLI::Range(1, 100000));
  fit->add_option("--tolerance", args.tolerance,
                  "refine and fit again until the limit surface is within this of the target: "
                  "a distance or a percentage of the target's diagonal")
      ->capture_default_str();
  fit->add_option("--max-rounds", args.maxRounds, "fitting rounds at most (1: fit once, no subdivision)")
      ->check(CLI::Range(1, 10))
      ->capture_default_str();
  fit->add_option("--max-triangles", args.maxTriangles,
                  "no subdivision past this many control triangles")
      ->check(CLI::Range(size_t(1), size_t(100000000)))
      ->capture_default_str();
  addMeshOutputOptions(fit, args.mesh);
  fit->callback([&exitCode] { exitCode = runReportingErrors([] { return runFit(args); }, {args.output}); });
  CLI::App* join = app.add_subcommand("join", "Join two closed Loop control meshes by local refinement");
  join->add_option("first", args.input, "first control mesh (.obj)")->required();
  join->add_option("second", args.target, "second control mesh (.obj)")->required();
  join->add_option("-o,--output", args.output, "joined control mesh (.obj, .ply or .glb)")->required();
  const std::string levelRange = "0.." + std::to_string(kMaxLoopJoinLevels);
  join->add_option("--levels-first", args.levelsA,
                   "local refinement levels of the first, " + levelRange + " (default: by area)")
      ->check(CLI::Range(0, kMaxLoopJoinLevels));
  join->add_option("--levels-second", args.levelsB,
                   "local refinement levels of the second, " + levelRange + " (default: by area)")
      ->check(CLI::Range(0, kMaxLoopJoinLevels));
  CLI::Option* plane =
      join->add_option("--paste-plane", args.cut, "paste: keep the first mesh's part where n·x ≥ d (nx ny nz d)")
          ->expected(4);
  CLI::Option* listed =
      join->add_option("--paste-vertices", args.pasteList,
                       "paste: keep the first mesh's triangles whose corners are all among these "
                       "1-based OBJ vertex numbers (e.g. 12,15,40-52)")
          ->check(CLI::Validator(
              [](std::string& text) {
                try {
                  checkVertexList(text);
                  return std::string();
                } catch (const std::invalid_argument& e) {
                  return std::string(e.what());
                }
              },
              "LIST"));
  CLI::Option* listFile =
      join->add_option("--paste-vertex-file", args.pasteFile,
                       "as --paste-vertices, from a file (numbers and ranges, blanks, commas or "
                       "lines between them, # comments)");
  plane->excludes(listed)->excludes(listFile);
  join->add_option("--picture", args.picture, "also draw inputs, placement and result (.png, needs Vulkan)");
  join->add_option("--device", args.device, "Vulkan device for --picture (name substring or index)");
  addMeshOutputOptions(join, args.mesh);
  join->callback([&exitCode] {
    exitCode = runReportingErrors([] { return runJoin(args); }, {args.output, args.picture},
                                  "join --picture needs a Vulkan device that draws");
  });
}

}  // namespace tessera::cli
