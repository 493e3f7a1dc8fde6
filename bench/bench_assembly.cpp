// An assembly of one part placed many times (issue 17, docs/cad.md "Assemblies"): the bench
// places `copies` instances of an IDF part on a grid, each turned about z, writes them as one
// STEP assembly (Open CASCADE's writer: one product, many placements) and reads it back as
// `tessera tessellate` would. Then, at δ = 10⁻³ of one part's diagonal: Open CASCADE's
// BRepMesh (serial and parallel; it meshes a part's faces once for all placements), Tessera as
// the CLI runs it (each part converted and meshed once, the other instances moved:
// cad/instances.h; its copies in the mesh, and only listed as an engine draws them instanced
// and the CLI's .glb writes them), and Tessera converting and meshing every instance (how it
// ran before).
// Usage: bench_assembly [copies=64] [--model file] [--cpu] [--json file]
//        bench_assembly copies --write-step file   (only writes the assembly, for the CLI)
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Poly_Triangulation.hxx>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_PrinterOStream.hxx>
#include <STEPControl_Writer.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <gp_Ax1.hxx>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <unistd.h>

#include "bench_args.h"
#include "bench_report.h"
#include "cad/cad_file.h"
#include "cad/mesh_cad_file.h"
#include "cad/to_trimmed.h"
#include "mesh/tessellate.h"
#include "trim/mesher.h"
#include "vk/context.h"

using namespace tessera;
namespace fs = std::filesystem;

namespace {

const char* kDefaultModel = "/usr/share/freecad/Mod/Idf/Idflibs/CAP_50SGV_8_10.stp";

// `copies` placements of `part` on a square grid `spacing` apart, the k-th turned k·0.3 rad
// about z, as one compound (OCCT's STEP writer makes it an assembly of one product).
TopoDS_Compound placedCopies(const TopoDS_Shape& part, int copies, double spacing) {
  BRep_Builder builder;
  TopoDS_Compound compound;
  builder.MakeCompound(compound);
  const int side = int(std::ceil(std::sqrt(double(copies))));
  for (int k = 0; k < copies; ++k) {
    gp_Trsf turn, move;
    turn.SetRotation(gp_Ax1(gp_Pnt(0, 0, 0), gp_Dir(0, 0, 1)), 0.3 * k);
    move.SetTranslation(gp_Vec(spacing * (k % side), spacing * (k / side), 0));
    builder.Add(compound, part.Moved(TopLoc_Location(move * turn)));
  }
  return compound;
}

size_t occtTriangleCount(const TopoDS_Shape& shape) {
  size_t count = 0;
  for (TopExp_Explorer e(shape, TopAbs_FACE); e.More(); e.Next()) {
    TopLoc_Location location;
    const Handle(Poly_Triangulation) t =
        BRep_Tool::Triangulation(TopoDS::Face(e.Current()), location);
    if (!t.IsNull()) count += size_t(t->NbTriangles());
  }
  return count;
}

}  // namespace

int main(int argc, char** argv) {
  bench::Report report("bench_assembly", "[copies=64] [--model file] [--cpu] [--write-step file]",
                       argc, argv);
  std::string model = kDefaultModel, writeStep;
  bool cpuOnly = false;
  long copies = 64;
  int positional = 0;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--model" && i + 1 < argc)
      model = argv[++i];
    else if (arg == "--cpu")
      cpuOnly = true;
    else if (arg == "--write-step" && i + 1 < argc)
      writeStep = argv[++i];
    else if (positional++ == 0)
      copies = bench::integerArg(report, arg, "copies", 2, 100000);
    else
      report.usageError("unexpected argument '" + arg + "'");
  }
  if (!fs::is_regular_file(model)) {
    std::fprintf(stderr, "bench_assembly: no %s (install freecad-common: scripts/deps.sh)\n",
                 model.c_str());
    return 2;
  }

  const CadFile single = readCadFile(model);
  const double diagonal = cadModelDiagonal(single);
  const fs::path folder =
      fs::temp_directory_path() / ("bench_assembly_" + std::to_string(getpid()));
  fs::create_directories(folder);
  const std::string path = writeStep.empty() ? (folder / "assembly.step").string() : writeStep;
  {
    // Open CASCADE's writer reports its steps on standard output: not in the bench's.
    Message::DefaultMessenger()->RemovePrinters(STANDARD_TYPE(Message_PrinterOStream));
    STEPControl_Writer writer;
    writer.Transfer(placedCopies(single.shape, int(copies), 1.5 * diagonal), STEPControl_AsIs);
    if (writer.Write(path.c_str()) != IFSelect_RetDone) {
      std::fprintf(stderr, "bench_assembly: Open CASCADE could not write %s\n", path.c_str());
      return 1;
    }
  }
  if (!writeStep.empty()) {
    fs::remove_all(folder);
    std::printf("wrote %s: %ld placements of %s\n", path.c_str(), copies, model.c_str());
    return 0;
  }
  const CadFile file = readCadFile(path);

  ToleranceSpec tolerance;
  tolerance.value = 1e-3 * diagonal;  // one part's δ, so each instance meshes as alone
  tolerance.relative = false;
  TrimmedMeshOptions options;  // measured by the stats as bench_cad's runs are not: off
  options.measureGeometric = false;
  options.measureKeptTriangles = false;

  report.note("model", fs::path(model).filename().string());
  report.note("copies", copies);
  report.note("delta", tolerance.value);
  bench::Table& table =
      report.table("assembly", "instances",
                   std::to_string(copies) + " placed copies of " +
                       fs::path(model).filename().string() + " in one STEP file, δ " +
                       std::to_string(tolerance.value) + " (10⁻³ of one part's diagonal)");

  // Open CASCADE meshes a shape of its own, read from the file again: BRepMesh leaves its
  // triangulations in the shape, and BRepBuilderAPI_Copy (bench_cad's way) would make every
  // placement a part of its own (2,400 faces' TShapes of 48), which BRepMesh then meshes
  // one by one (1.1 s against 63 ms for 50 copies).
  const TopoDS_Shape occtShape = readCadFile(path).shape;
  for (const bool parallel : {true, false}) {
    bench::Case c;
    c.path = std::string("OCCT BRepMesh, ") + (parallel ? "parallel" : "serial");
    c.workSize = double(copies);
    c.timing = bench::timeRepeated(
        bench::kMinRuns,
        [&] {
          BRepMesh_IncrementalMesh(occtShape, tolerance.value, Standard_False, 0.5, parallel);
        },
        [&] { BRepTools::Clean(occtShape); });
    c.extra["triangles"] = occtTriangleCount(occtShape);
    table.cases.push_back(c);
  }

  Backend cpu = makeMirrorBackend();
  std::unique_ptr<vk::Context> context;
  Backend vulkan;
  std::unique_ptr<TrimClassifier> vulkanTrim;
  if (!cpuOnly) {
    context = std::make_unique<vk::Context>();
    vulkan = makeVulkanBackend(*context);
    vulkanTrim = makeVulkanTrimClassifier(*context);
    report.setDevice(*context);
  }
  CadMeshRun last;
  const auto tessera = [&](const std::string& name, Backend& backend, TrimClassifier* trim,
                           CopyPlacement placement) {
    bench::Case c;
    c.path = name;
    c.workSize = double(copies);
    c.timing = bench::timeRepeated(bench::kMinRuns, [&] {
      last = meshCadModel(file, tolerance, false, "", backend, trim, options, placement);
    });
    c.extra["triangles"] = last.modelTriangles();  // every placement's, listed or not
    c.extra["trianglesInMesh"] = last.mesh.mesh.triangleCount();
    c.extra["instancedParts"] = last.instancedParts();
    c.extra["instanceCopies"] = last.instanceCopies();
    table.cases.push_back(c);
  };
  tessera("Tessera CPU, each part meshed once", cpu, nullptr, CopyPlacement::InMesh);
  const CadMeshRun once = last;
  if (context)
    tessera("Tessera Vulkan, each part meshed once", vulkan, vulkanTrim.get(),
            CopyPlacement::InMesh);
  // The copies listed, not made (an engine's instanced drawing, the CLI's .glb).
  tessera("Tessera CPU, each part meshed once, copies listed", cpu, nullptr,
          CopyPlacement::Listed);

  // Before instances: every instance converted and meshed (toTrimmedModel on the whole shape).
  bench::Case every;
  every.path = "Tessera CPU, every instance meshed";
  every.workSize = double(copies);
  TrimmedMesh everyMesh;
  every.timing = bench::timeRepeated(bench::kMinRuns, [&] {
    options.tolerance = tolerance.value;
    const CadImport import = toTrimmedModel(file, tolerance.value, options.threads);
    everyMesh = meshTrimmedModel(import.model, options, cpu, nullptr);
  });
  every.extra["triangles"] = everyMesh.mesh.triangleCount();
  every.extra["trianglesInMesh"] = everyMesh.mesh.triangleCount();
  table.cases.push_back(every);
  report.print(table);
  fs::remove_all(folder);

  for (const bench::Case& c : table.cases)
    std::printf("%s: %zu triangles, %.1f ms min (%.1f median), %.2fx OCCT parallel's time\n",
                c.path.c_str(), c.extra["triangles"].get<size_t>(), 1e3 * c.timing.minSeconds,
                1e3 * c.timing.medianSeconds,
                c.timing.minSeconds / table.cases.front().timing.minSeconds);
  std::printf("each part once: %zu parts placed more than once, %zu copies moved\n",
              once.instancedParts(), once.instanceCopies());
  report.finish();
  return 0;
}
