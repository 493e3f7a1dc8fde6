// tessera loop | limit: Loop subdivision of OBJ control meshes on the chosen backend, and the
// registration of every Loop command (fit and join run in cmd_fit_join.cpp; docs/loop.md).
// Output by extension: .obj, .ply or .glb.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <stdexcept>

#include "cli/cli_support.h"
#include "cli/commands.h"
#include "cli/loop_args.h"
#include "common/memory_budget.h"
#include "io/errors.h"
#include "io/obj_reader.h"
#include "io/vertex_selection.h"
#include "loop/evaluator.h"
#include "loop/join.h"
#include "loop/stencils.h"
#include "vk/context.h"

namespace tessera::cli {

LoopShape readControlMesh(const std::string& path, LoopBoundary boundary) {
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

namespace {

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
