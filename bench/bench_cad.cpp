// Case 7, CAD models (issue 17): every STEP and IGES model of FreeCAD's IDF library
// (/usr/share/freecad/Mod/Idf/Idflibs/, Debian's freecad-common), meshed at two tolerances
// relative to each model's bounding-box diagonal by Open CASCADE's BRepMesh_IncrementalMesh
// (linear deflection δ, angular 0.5 rad, serial and parallel) and by Tessera's trimmed-face
// path (host/cad/ + host/trim/: faces to rational Bézier pieces, edges discretised once to δ,
// rule T per face, the cut along the trim loops), on the CPU mirror and on Vulkan.
// Reading the file is left out of every time (both use OCCT's reader); Tessera's time is the
// conversion to its trimmed faces plus the meshing, OCCT's is BRepMesh on a cleaned shape.
// Both meshes are measured by the same code: the distance from sample points of every
// triangle ((i, j, k)/3 barycentric, corners included) to the face's own surface
// (GeomAPI_ProjectPointOnSurf within the face's uv bounds grown by 10⁻⁶ of their range: a
// boundary point's foot just outside by rounding was missed, or worse, replaced by the far
// side of a cylinder, 2R away; a point still without a foot there, a vertex rounded to fp32
// off a thin face, is projected onto the whole surface and kept if its foot lies within the
// box grown by 1%), the largest over the corpus, as a
// multiple of δ. A point the projection cannot place is counted, not guessed.
// Then, at equal measured deviation (the comparison): each model meshed again by Tessera
// at a scale s ≤ 1 of δ at which its measured distance is no larger than OCCT's on that model
// (matchOcctDistance), timed on every backend; the rows "at OCCT's measured distance".
// Usage: bench_cad [relative tolerances = 0.001,0.0001] [--dir folder] [--json file] [--cpu]
//        [--model name-part] [--detail] [--tessera-only] [--tessera-scale s] [--threads n]
//        [--no-match]
// --cpu leaves Vulkan out; --model keeps the models whose file name contains the text;
// --detail prints each model's worst faces (distance, unprojected samples) for both meshers;
// --tessera-only runs Tessera alone, unmeasured (for profiling its stages).
// --tessera-scale s meshes Tessera at s·δ while OCCT keeps δ, distances still over δ: set s to
// OCCT's measured distance / Tessera's to compare the corpus at one scale (no matched rows then).
// --no-match leaves out the rows at OCCT's measured distance.
// --threads n gives Tessera's import and per-face stages n threads (TrimmedMeshOptions::threads,
// default 0: all cores; 1: serial); the CPU backend's tree keeps all cores.
// Each tolerance's load average at its start and end is printed and noted in the JSON
// (loadAverage IDF <δ>): the Vulkan tree and trim times are the most sensitive to load.
#include <BRepAdaptor_Surface.hxx>
#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_Copy.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <Bnd_Box.hxx>
#include <GeomAPI_ProjectPointOnSurf.hxx>
#include <Geom_Surface.hxx>
#include <Poly_Triangulation.hxx>
#include <Standard_Version.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <string>
#include <vector>

#include "bench_args.h"
#include "bench_report.h"
#include "cad/cad_file.h"
#include "cad/to_trimmed.h"
#include "common/stopwatch.h"
#include "mesh/tessellate.h"
#include "trim/mesher.h"
#include "vk/context.h"

using namespace tessera;
namespace fs = std::filesystem;

namespace {

constexpr const char* kIdfLibrary = "/usr/share/freecad/Mod/Idf/Idflibs";

// A triangle soup with each triangle's face: what the deviation measure takes from either mesher.
struct FaceTriangles {
  std::vector<gp_Pnt> corners;   // 3 per triangle
  std::vector<TopoDS_Face> face;  // 1 per triangle
};

// Largest distance of the triangles' sample points to their faces' surfaces.
struct Deviation {
  double max = 0;
  size_t samples = 0, unprojected = 0;
};

// --detail: per face, the largest distance and the unprojected samples, the worst few printed.
struct FaceDetail {
  int face = 0;
  double max = 0;
  size_t samples = 0, unprojected = 0, triangles = 0;
};
bool gDetail = false;
// The face's uv bounds are grown by this share of their range before projecting (see below).
constexpr double kBoundsGrowth = 1e-6;

// The face's surface kind (GeomAbs_SurfaceType, OtherSurface last) and its name.
constexpr int kSurfaceKinds = 11;
int surfaceKind(const TopoDS_Face& face) {
  return std::min(int(BRepAdaptor_Surface(face, Standard_False).GetType()), kSurfaceKinds - 1);
}
const char* const kSurfaceKindNames[kSurfaceKinds] = {
    "plane", "cylinder", "cone", "sphere", "torus", "Bézier", "B-spline", "revolution",
    "extrusion", "offset", "other"};

// --detail: triangles per surface kind (plane, cylinder, …), the faces' count beside them.
void printKinds(const char* who, const FaceTriangles& mesh) {
  size_t triangles[kSurfaceKinds] = {}, faces[kSurfaceKinds] = {};
  TopoDS_Face current;
  int kind = 0;
  for (const TopoDS_Face& face : mesh.face) {
    if (!face.IsEqual(current)) {
      current = face;
      kind = surfaceKind(face);
      ++faces[kind];
    }
    ++triangles[kind];
  }
  std::fprintf(stderr, "  %s triangles by surface kind:", who);
  for (int k = 0; k < kSurfaceKinds; ++k)
    if (faces[k])
      std::fprintf(stderr, " %s %zu (%zu faces)", kSurfaceKindNames[k], triangles[k], faces[k]);
  std::fprintf(stderr, "\n");
}

// --detail: the faces where Tessera makes the most triangles beyond OCCT's (face indices of
// TopExp::MapShapes on each mesher's shape, a copy and its original: the same numbering).
void printExcess(const FaceTriangles& occt, const TopTools_IndexedMapOfShape& occtFaces,
                 const FaceTriangles& tessera, const TopTools_IndexedMapOfShape& faces) {
  std::vector<long> counts[2] = {std::vector<long>(size_t(faces.Extent()) + 1, 0),
                                 std::vector<long>(size_t(faces.Extent()) + 1, 0)};
  for (const TopoDS_Face& face : occt.face) ++counts[0][size_t(occtFaces.FindIndex(face))];
  for (const TopoDS_Face& face : tessera.face) ++counts[1][size_t(faces.FindIndex(face))];
  std::vector<int> order;
  for (int f = 1; f <= faces.Extent(); ++f) order.push_back(f);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    return counts[1][size_t(a)] - counts[0][size_t(a)] > counts[1][size_t(b)] - counts[0][size_t(b)];
  });
  for (size_t k = 0; k < order.size() && k < 8; ++k) {
    const int f = order[k];
    const TopoDS_Face& face = TopoDS::Face(faces(f));
    std::fprintf(stderr, "  face %d (%s): Tessera %ld, OCCT %ld triangles\n", f - 1,
                 kSurfaceKindNames[surfaceKind(face)],
                 counts[1][size_t(f)], counts[0][size_t(f)]);
  }
}

void printDetail(const char* who, std::vector<FaceDetail> faces, double delta) {
  std::sort(faces.begin(), faces.end(), [](const FaceDetail& a, const FaceDetail& b) {
    return a.max != b.max ? a.max > b.max : a.unprojected > b.unprojected;
  });
  for (size_t k = 0; k < faces.size() && k < 8; ++k)
    std::fprintf(stderr, "  %s face %d: %zu triangles, distance/δ %.3f, %zu of %zu unprojected\n",
                 who, faces[k].face, faces[k].triangles, faces[k].max / delta,
                 faces[k].unprojected, faces[k].samples);
}

Deviation measureDistance(const FaceTriangles& mesh, const TopTools_IndexedMapOfShape* map = nullptr,
                          const char* who = nullptr, double delta = 1) {
  Deviation d;
  std::vector<FaceDetail> details;
  // Triangles of one face are consecutive in both meshers' output, so the projector is set up
  // once per run of triangles on one face.
  GeomAPI_ProjectPointOnSurf projector;
  TopoDS_Face current;  // instances of one face differ by location: IsEqual compares both
  double box[4] = {0, 0, 0, 0};  // the current face's uv bounds: u0, u1, v0, v1
  for (size_t t = 0; t < mesh.face.size(); ++t) {
    const TopoDS_Face& face = mesh.face[t];
    if (!face.IsEqual(current)) {
      current = face;
      double u0, u1, v0, v1;
      BRepTools::UVBounds(face, u0, u1, v0, v1);
      box[0] = u0, box[1] = u1, box[2] = v0, box[3] = v1;
      // Grown by a share of the range: a point on the face's boundary (both meshers put their
      // boundary vertices there) has its foot on the edge of the box, and rounding can put it
      // just outside; Extrema then finds no foot, or only a farther one (a cylinder's far side).
      const double du = kBoundsGrowth * (u1 - u0), dv = kBoundsGrowth * (v1 - v0);
      projector.Init(BRep_Tool::Surface(face), u0 - du, u1 + du, v0 - dv, v1 + dv);
      if (gDetail && map) details.push_back({map->FindIndex(face) - 1});
    }
    if (gDetail && map) ++details.back().triangles;
    const gp_Pnt* c = &mesh.corners[3 * t];
    for (int i = 0; i <= 3; ++i)
      for (int j = 0; i + j <= 3; ++j) {
        const int k = 3 - i - j;
        const gp_Pnt p((i * c[0].XYZ() + j * c[1].XYZ() + k * c[2].XYZ()) / 3.0);
        projector.Perform(p);
        ++d.samples;
        if (gDetail && map) ++details.back().samples;
        double distance = projector.NbPoints() > 0 ? projector.LowerDistance() : -1;
        if (distance < 0) {
          // No foot inside the box: a vertex's fp32 rounding (1e-7 of the model's size) can
          // still put it outside a thin face's box. Project onto the whole surface and keep
          // the foot when it lies within the box grown by 1% of its range.
          GeomAPI_ProjectPointOnSurf free(p, BRep_Tool::Surface(face));
          if (free.NbPoints() > 0) {
            double u, v;
            free.LowerDistanceParameters(u, v);
            if (u >= box[0] - 0.01 * (box[1] - box[0]) && u <= box[1] + 0.01 * (box[1] - box[0]) &&
                v >= box[2] - 0.01 * (box[3] - box[2]) && v <= box[3] + 0.01 * (box[3] - box[2]))
              distance = free.LowerDistance();
          }
        }
        if (distance < 0) {
          ++d.unprojected;
          if (gDetail && map) ++details.back().unprojected;
          continue;
        }
        d.max = std::max(d.max, distance);
        if (gDetail && map) details.back().max = std::max(details.back().max, distance);
      }
  }
  if (gDetail && map) {
    printKinds(who, mesh);
    printDetail(who, details, delta);
  }
  return d;
}

FaceTriangles occtTriangles(const TopoDS_Shape& shape) {
  FaceTriangles out;
  for (TopExp_Explorer e(shape, TopAbs_FACE); e.More(); e.Next()) {
    const TopoDS_Face& face = TopoDS::Face(e.Current());
    TopLoc_Location location;
    Handle(Poly_Triangulation) tri = BRep_Tool::Triangulation(face, location);
    if (tri.IsNull()) continue;
    for (int t = 1; t <= tri->NbTriangles(); ++t) {
      int n[3];
      tri->Triangle(t).Get(n[0], n[1], n[2]);
      for (int corner : n) out.corners.push_back(tri->Node(corner).Transformed(location));
      out.face.push_back(face);
    }
  }
  return out;
}

FaceTriangles tesseraTriangles(const TrimmedMesh& mesh, const CadImport& import) {
  FaceTriangles out;
  for (size_t t = 0; t < mesh.triangleFace.size(); ++t) {
    for (int corner = 0; corner < 3; ++corner) {
      const glm::vec3& p = mesh.mesh.positions[mesh.mesh.indices[3 * t + corner]];
      out.corners.emplace_back(p.x, p.y, p.z);
    }
    const uint32_t faceIndex = import.model.faces[mesh.triangleFace[t]].faceIndex;
    out.face.push_back(TopoDS::Face(import.faces.FindKey(int(faceIndex) + 1)));
  }
  return out;
}

double diagonalOf(const TopoDS_Shape& shape) {
  Bnd_Box box;
  BRepBndLib::Add(shape, box);
  return box.IsVoid() ? 1.0 : std::sqrt(box.SquareExtent());
}

// The sum over the corpus of each model's min and median: the corpus meshed once, file by file.
struct Totals {
  double minSeconds = 0, medianSeconds = 0;
  size_t triangles = 0;
  double worstRatio = 0;  // largest measured distance / δ over the models
  std::string worstModel;
  size_t samples = 0, unprojected = 0;
  nlohmann::json perModel = nlohmann::json::array();

  void add(const std::string& model, const bench::Timing& time, size_t count, const Deviation& d,
           double delta) {
    minSeconds += time.minSeconds;
    medianSeconds += time.medianSeconds;
    triangles += count;
    samples += d.samples;
    unprojected += d.unprojected;
    if (d.max / delta > worstRatio) {
      worstRatio = d.max / delta;
      worstModel = model;
    }
    perModel.push_back({{"model", model},
                        {"triangles", count},
                        {"minSeconds", time.minSeconds},
                        {"distanceOverDelta", d.max / delta}});
  }
};

struct Models {
  std::vector<std::string> paths;
  std::vector<CadFile> files;
};

Models readCorpus(const std::string& folder, const std::string& filter) {
  Models m;
  for (const auto& entry : fs::directory_iterator(folder)) {
    std::string ext = entry.path().extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
    if ((ext == ".stp" || ext == ".step" || ext == ".igs" || ext == ".iges") &&
        entry.path().filename().string().find(filter) != std::string::npos)
      m.paths.push_back(entry.path().string());
  }
  std::sort(m.paths.begin(), m.paths.end());
  for (const std::string& path : m.paths) m.files.push_back(readCadFile(path));
  return m;
}

// The CPU time of every thread of the process so far: a stage's thread time, which a loaded
// machine moves much less than its wall time.
double processCpuMs() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return 1e3 * double(t.tv_sec) + 1e-6 * double(t.tv_nsec);
}

// The machine's load average (1, 5 and 15 minutes), as /proc/loadavg gives it; "" elsewhere.
// Printed at each tolerance's start and end: on the shared 2-core VM the Vulkan tree and its
// trim classification, a few hundred small dispatches each waited for, take several times
// longer while another process competes for the cores (bench/HISTORY.md, session 40).
std::string loadAverage() {
  std::FILE* file = std::fopen("/proc/loadavg", "r");
  if (!file) return "";
  double one = 0, five = 0, fifteen = 0;
  const int read = std::fscanf(file, "%lf %lf %lf", &one, &five, &fifteen);
  std::fclose(file);
  if (read != 3) return "";
  char text[64];
  std::snprintf(text, sizeof text, "%.2f %.2f %.2f", one, five, fifteen);
  return text;
}

// Tessera's time split by stage, summed over the corpus (each model's fastest run).
struct Stages {
  double convertMs = 0;     // toTrimmedModel: faces to Bézier pieces, edges discretised
  double convertCpuMs = 0;  // the same, the process's CPU time (all its threads)
  TrimmedMeshTimings mesh;

  void add(double convert, double convertCpu, const TrimmedMeshTimings& t) {
    convertMs += convert;
    convertCpuMs += convertCpu;
    mesh.treeMs += t.treeMs, mesh.trimMs += t.trimMs, mesh.triangulateMs += t.triangulateMs;
    mesh.evaluateMs += t.evaluateMs, mesh.assembleMs += t.assembleMs, mesh.cutMs += t.cutMs;
    mesh.emitMs += t.emitMs, mesh.totalMs += t.totalMs;
    mesh.classifyCpuMs += t.classifyCpuMs, mesh.gapCpuMs += t.gapCpuMs;
    mesh.refineCpuMs += t.refineCpuMs, mesh.measureCpuMs += t.measureCpuMs;
    mesh.trees += t.trees, mesh.leaves += t.leaves, mesh.trimmedAwayLeaves += t.trimmedAwayLeaves;
  }
  nlohmann::json json() const {
    return {{"convertMs", convertMs},         {"convertCpuMs", convertCpuMs},
            {"treeMs", mesh.treeMs},
            {"trimMs", mesh.trimMs},          {"triangulateMs", mesh.triangulateMs},
            {"evaluateMs", mesh.evaluateMs},  {"assembleMs", mesh.assembleMs},
            {"cutMs", mesh.cutMs},            {"emitMs", mesh.emitMs},
            {"classifyCpuMs", mesh.classifyCpuMs}, {"gapCpuMs", mesh.gapCpuMs},
            {"refineCpuMs", mesh.refineCpuMs}, {"measureCpuMs", mesh.measureCpuMs},
            {"meshMs", mesh.totalMs},         {"trees", mesh.trees},
            {"leaves", mesh.leaves},          {"trimmedAwayLeaves", mesh.trimmedAwayLeaves}};
  }
};

struct TesseraBackend {
  std::string name;
  Backend* backend;
  TrimClassifier* trim;  // the trim pass of the quad-tree on the same device
};

bool tesseraOnly = false;
double tesseraScale = 1.0;
unsigned tesseraThreads = 0;
bool matchOcct = true;

// One backend's Tessera mesh of one model at `tolerance`: conversion plus meshing, timed over
// kMinRuns runs (after a warm-up) or run once; the fastest run's stage split.
struct TesseraRun {
  bench::Timing time;
  CadImport import;
  TrimmedMesh mesh;
  double convertMs = 0, convertCpuMs = 0;
  TrimmedMeshTimings timings;
};

TesseraRun runTessera(const CadFile& file, double tolerance, const TesseraBackend& backend,
                      bool timed) {
  TrimmedMeshOptions options;
  options.tolerance = tolerance;
  options.threads = tesseraThreads;
  options.measureGeometric = false;  // measured by the bench's own code
  // Rule T proves the kept quad-tree triangles; the gap ones are measured (refinement).
  options.measureKeptTriangles = false;
  TesseraRun run;
  double fastest = 1e300;
  // Each run's result is kept until the timing ends, so that no run times the freeing of the
  // run before it (OCCT's runs leave out BRepTools::Clean, the removal of theirs, alike).
  std::vector<CadImport> earlierImports;
  std::vector<TrimmedMesh> earlierMeshes;
  const auto once = [&] {
    earlierImports.push_back(std::move(run.import));
    earlierMeshes.push_back(std::move(run.mesh));
    const Stopwatch clock;
    const double cpuBefore = processCpuMs();
    run.import = toTrimmedModel(file, options.tolerance, options.threads);
    const double convertMs = clock.elapsedMs(), convertCpuMs = processCpuMs() - cpuBefore;
    run.mesh = meshTrimmedModel(run.import.model, options, *backend.backend, backend.trim);
    if (clock.elapsedMs() < fastest)
      fastest = clock.elapsedMs(), run.convertMs = convertMs, run.convertCpuMs = convertCpuMs,
      run.timings = run.mesh.timings;
  };
  if (timed)
    run.time = bench::timeRepeated(bench::kMinRuns, once);
  else
    once();
  return run;
}

// Measured distances up to this share of δ count as equal when matching: both meshes are then
// far inside δ (planes and cylinders' straight sides give fp32 rounding, 10⁻⁴ δ and less).
constexpr double kMatchFloor = 0.05;

// A scale s ≤ 1 of δ at which Tessera's measured distance on a model is no larger than OCCT's
// there (the "at equal measured deviation"), searched on the first backend: from 1, s
// shrinks by the ratio of the distances and 2% more, and by at least 10% a step (a tree's
// leaves can stay the same over a small change of δ), until Tessera's distance is within
// OCCT's. A model still above it at s = 1/16 is not matched and keeps s = 1: its distance is
// not set by δ (e.g. edges whose 3D curves and pcurves part by more than δ, docs/cad.md).
struct MatchedScale {
  double scale = 1;
  Deviation deviation;  // Tessera's at that scale
  bool matched = true;
};

constexpr double kSmallestMatchScale = 1.0 / 16;

MatchedScale matchOcctDistance(const CadFile& file, double delta, double occtDistance,
                               const Deviation& atDelta, const TesseraBackend& backend) {
  MatchedScale m;
  m.deviation = atDelta;
  const double target = std::max(occtDistance, kMatchFloor * delta);
  while (m.deviation.max > target && m.scale > kSmallestMatchScale) {
    m.scale = std::max(kSmallestMatchScale,
                       m.scale * std::min(0.9, 0.98 * target / m.deviation.max));
    const TesseraRun run = runTessera(file, m.scale * delta, backend, false);
    m.deviation = measureDistance(tesseraTriangles(run.mesh, run.import));
  }
  if (gDetail)
    std::fprintf(stderr, "  matched: OCCT %.3f δ, Tessera %.3f δ at δ, %.3f δ at %.4g δ%s\n",
                 occtDistance / delta, atDelta.max / delta, m.deviation.max / delta, m.scale,
                 m.deviation.max > target ? " (not matched: kept at δ)" : "");
  if (m.deviation.max > target) m = {1, atDelta, false};
  return m;
}

void runTolerance(bench::Report& report, const Models& models, double relative,
                  std::vector<TesseraBackend>& backends) {
  const std::string loadAtStart = loadAverage();
  Totals occt[2];
  std::vector<Totals> tessera(backends.size());
  std::vector<Stages> stages(backends.size());
  // At equal measured deviation (matchOcctDistance): each model at its own scale of δ.
  std::vector<Totals> matched(backends.size());
  std::vector<std::string> unmatched;
  double matchedWorst = 0;  // the largest distance / δ over the models that were matched
  const bool matching = matchOcct && !tesseraOnly && tesseraScale == 1.0;
  size_t failedFaces = 0, emptyFaces = 0, faces = 0;
  for (size_t f = 0; f < models.files.size(); ++f) {
    const CadFile& file = models.files[f];
    const std::string name = fs::path(file.path).filename().string();
    const double delta = relative * diagonalOf(file.shape);
    // BRepMesh leaves its work in the shape it meshes (triangulations, which Clean removes, but
    // also pcurves on planes and updated tolerances), so a later mesher would see another
    // shape: OCCT meshes a copy made for this tolerance, Tessera the file's shape as read.
    const TopoDS_Shape occtShape = BRepBuilderAPI_Copy(file.shape).Shape();
    double occtDistance = 0;  // OCCT's largest measured distance on this model
    for (int parallel = 0; parallel < (tesseraOnly ? 0 : 2); ++parallel) {
      size_t count = 0;
      std::vector<double> seconds;
      for (int run = 0; run <= bench::kMinRuns; ++run) {  // run 0 warms up
        BRepTools::Clean(occtShape);
        const Stopwatch clock;
        BRepMesh_IncrementalMesh mesher(occtShape, delta, Standard_False, 0.5,
                                        parallel ? Standard_True : Standard_False);
        if (run > 0) seconds.push_back(clock.elapsedSeconds());
      }
      std::sort(seconds.begin(), seconds.end());
      const FaceTriangles soup = occtTriangles(occtShape);
      count = soup.face.size();
      TopTools_IndexedMapOfShape faceMap;
      TopExp::MapShapes(occtShape, TopAbs_FACE, faceMap);
      const Deviation d = parallel ? Deviation{} : measureDistance(soup, &faceMap, "OCCT", delta);
      if (!parallel) occtDistance = d.max;
      occt[parallel].add(name, {seconds.front(), seconds[seconds.size() / 2], int(seconds.size())},
                         count, parallel ? Deviation{} : d, delta);
    }
    FaceTriangles lastTessera;  // the first backend's, for --detail
    Deviation tesseraDeviation;   // the first backend's (the mirror's: the backends agree bit for bit)
    std::vector<std::pair<bench::Timing, size_t>> atDelta;  // per backend: time, triangles
    for (size_t b = 0; b < backends.size(); ++b) {
      const TesseraRun run = runTessera(file, tesseraScale * delta, backends[b], true);
      stages[b].add(run.convertMs, run.convertCpuMs, run.timings);
      if (b == 0) {
        faces += size_t(run.import.faces.Extent());
        failedFaces += run.import.failures.size();
        emptyFaces += run.import.emptyFaces.size();
      }
      if (b == 0) lastTessera = tesseraTriangles(run.mesh, run.import);
      const Deviation d =
          tesseraOnly ? Deviation{}
                      : measureDistance(b == 0 ? lastTessera : tesseraTriangles(run.mesh, run.import),
                                        &run.import.faces, "Tessera", delta);
      if (b == 0) tesseraDeviation = d;
      tessera[b].add(name, run.time, run.mesh.mesh.triangleCount(), d, delta);
      atDelta.emplace_back(run.time, run.mesh.mesh.triangleCount());
    }
    if (matching) {
      const MatchedScale m = matchOcctDistance(file, delta, occtDistance, tesseraDeviation,
                                               backends.front());
      if (!m.matched) unmatched.push_back(name);
      if (m.matched) matchedWorst = std::max(matchedWorst, m.deviation.max / delta);
      for (size_t b = 0; b < backends.size(); ++b) {
        if (m.scale == 1.0) {  // the mesh at δ already is
          matched[b].add(name, atDelta[b].first, atDelta[b].second, m.deviation, delta);
        } else {
          const TesseraRun run = runTessera(file, m.scale * delta, backends[b], true);
          matched[b].add(name, run.time, run.mesh.mesh.triangleCount(), m.deviation, delta);
        }
        matched[b].perModel.back()["scale"] = m.scale;
      }
    }
    if (gDetail && !tesseraOnly) {
      TopTools_IndexedMapOfShape faceMap;
      TopExp::MapShapes(occtShape, TopAbs_FACE, faceMap);
      TopTools_IndexedMapOfShape tesseraFaces;
      TopExp::MapShapes(file.shape, TopAbs_FACE, tesseraFaces);
      printExcess(occtTriangles(occtShape), faceMap, lastTessera, tesseraFaces);
    }
    if (!tesseraOnly)
      std::fprintf(stderr, "%s at %g of its diagonal: OCCT %zu triangles, Tessera %zu\n",
                   name.c_str(), relative, occt[0].perModel.back()["triangles"].get<size_t>(),
                   tessera[0].perModel.back()["triangles"].get<size_t>());
  }

  char title[384];
  std::snprintf(title, sizeof title,
                "FreeCAD IDF library, %zu models (%zu faces, %zu of zero area, %zu failed to "
                "convert), δ = %g of each model's diagonal; times are sums over the models of "
                "each one's min (median) of %d runs; distance = largest measured distance to the "
                "face's surface / δ",
                models.files.size(), faces, emptyFaces, failedFaces, relative, bench::kMinRuns);
  char tableName[64];
  std::snprintf(tableName, sizeof tableName, "IDF %g", relative);
  bench::Table& table = report.table(tableName, "triangles", title);
  table.rateUnit = "corpora/s";  // the ratio is then the speed-up over OCCT serial
  auto addCase = [&](const std::string& path, const Totals& totals, const Totals* measured) {
    bench::Case c{path, double(totals.triangles),
                  {totals.minSeconds, totals.medianSeconds, bench::kMinRuns}};
    c.throughput = 1.0 / totals.minSeconds;
    const Totals& m = measured ? *measured : totals;
    c.extra = {{"distanceOverDelta", m.worstRatio},
               {"worstModel", m.worstModel},
               {"samples", m.samples},
               {"unprojectedSamples", m.unprojected},
               {"perModel", totals.perModel}};
    c.extra["speedupVsOcctParallel"] = occt[1].minSeconds / totals.minSeconds;
    c.extra["trianglesVsOcct"] = double(totals.triangles) / double(occt[0].triangles);
    table.cases.push_back(c);
    std::fprintf(stderr,
                 "%-40s %8zu triangles (%.2fx OCCT), %.4f s (%.1fx faster than OCCT parallel), "
                 "distance/δ %.3f (%s), %zu of %zu samples unprojected\n",
                 path.c_str(), totals.triangles, double(totals.triangles) / double(occt[0].triangles),
                 totals.minSeconds, occt[1].minSeconds / totals.minSeconds, m.worstRatio,
                 m.worstModel.c_str(), m.unprojected, m.samples);
  };
  if (!tesseraOnly) {
    addCase("OCCT BRepMesh, serial", occt[0], nullptr);
    addCase("OCCT BRepMesh, parallel (all cores)", occt[1], &occt[0]);  // the same mesh
  }
  for (size_t b = 0; b < backends.size(); ++b) {
    char scaled[48] = "";
    if (tesseraScale != 1.0) std::snprintf(scaled, sizeof scaled, " at %g δ", tesseraScale);
    addCase("Tessera trimmed faces, " + backends[b].name + scaled, tessera[b], nullptr);
    table.cases.back().extra["stages"] = stages[b].json();
    const TrimmedMeshTimings& t = stages[b].mesh;
    std::fprintf(stderr,
                 "  %s stages (ms, fastest run of each model, summed): convert %.1f (thread time "
                 "%.1f), tree %.1f "
                 "(trim %.1f), triangulate %.1f, evaluate %.1f, assemble %.1f, cut %.1f (thread "
                 "time: classify %.1f, gap %.1f, refine %.1f, measure %.1f), emit %.1f, mesh "
                 "total %.1f; %zu trees, %zu leaves, %zu trimmed away\n",
                 backends[b].name.c_str(), stages[b].convertMs, stages[b].convertCpuMs, t.treeMs,
                 t.trimMs,
                 t.triangulateMs, t.evaluateMs, t.assembleMs, t.cutMs, t.classifyCpuMs,
                 t.gapCpuMs, t.refineCpuMs, t.measureCpuMs, t.emitMs, t.totalMs,
                 t.trees, t.leaves, t.trimmedAwayLeaves);
  }
  const std::string loadAtEnd = loadAverage();
  std::fprintf(stderr, "  load average (1, 5, 15 min): %s at this tolerance's start, %s at its end\n",
               loadAtStart.c_str(), loadAtEnd.c_str());
  report.note("loadAverage " + std::string(tableName), {{"start", loadAtStart}, {"end", loadAtEnd}});
  if (matching) {
    for (size_t b = 0; b < backends.size(); ++b) {
      addCase("Tessera trimmed faces, " + backends[b].name + ", at OCCT's measured distance",
              matched[b], nullptr);
      table.cases.back().extra["unmatchedModels"] = unmatched;
      table.cases.back().extra["distanceOverDeltaMatchedModels"] = matchedWorst;
    }
    std::fprintf(stderr,
                 "  at OCCT's measured distance: each model at a scale of δ (at most 1) at which "
                 "its measured distance is no larger than OCCT's on it (or than %g δ), largest "
                 "over those models %.3f δ; %zu model(s) not matched even at %g δ, kept at δ "
                 "(their distance is not set by δ):",
                 kMatchFloor, matchedWorst, unmatched.size(), kSmallestMatchScale);
    for (const std::string& name : unmatched) std::fprintf(stderr, " %s", name.c_str());
    std::fprintf(stderr, "\n");
  }
  report.print(table);
}

}  // namespace

int main(int argc, char** argv) {
  bench::Report report("cad",
                       "[relative tolerances=0.001,0.0001] [--dir folder] [--cpu] [--model text] "
                       "[--detail] [--tessera-only] [--tessera-scale s] [--threads n] "
                       "[--no-match] [--json file]",
                       argc, argv);
  std::vector<double> relatives = {1e-3, 1e-4};
  std::string folder = kIdfLibrary, filter;
  bool cpuOnly = false;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--dir" && i + 1 < argc)
      folder = argv[++i];
    else if (arg == "--model" && i + 1 < argc)
      filter = argv[++i];
    else if (arg == "--cpu")
      cpuOnly = true;
    else if (arg == "--detail")
      gDetail = true;
    else if (arg == "--tessera-only")
      tesseraOnly = true;
    else if (arg == "--tessera-scale" && i + 1 < argc)
      tesseraScale = bench::numberArg(report, argv[++i], "--tessera-scale", 1e-6);
    else if (arg == "--no-match")
      matchOcct = false;
    else if (arg == "--threads" && i + 1 < argc)
      tesseraThreads = unsigned(bench::integerArg(report, argv[++i], "--threads", 0, 1024));
    else if (arg.rfind("--", 0) == 0)
      report.usageError("unknown option or missing value: '" + arg + "'");
    else
      relatives = bench::numberListArg(report, arg, "relative tolerances", 1e-9);
  }
  if (!fs::is_directory(folder)) {
    std::fprintf(stderr, "bench_cad: %s is not a folder (install freecad-common: scripts/deps.sh)\n",
                 folder.c_str());
    return 2;
  }
  const Models models = readCorpus(folder, filter);
  report.note("corpus", folder);
  report.note("models", models.paths.size());
  report.note("occtVersion", OCC_VERSION_COMPLETE);
  report.note("tesseraScale", tesseraScale);
  report.note("tesseraThreads", tesseraThreads);
  report.note("matchedOnOcctDistance", matchOcct && !tesseraOnly && tesseraScale == 1.0);

  Backend cpu = makeMirrorBackend();
  const std::unique_ptr<TrimClassifier> cpuTrim = makeMirrorTrimClassifier();
  std::vector<TesseraBackend> backends = {{"CPU (fp32 mirror)", &cpu, cpuTrim.get()}};
  std::unique_ptr<vk::Context> context;
  Backend vulkan;
  std::unique_ptr<TrimClassifier> vulkanTrim;
  try {
    if (cpuOnly) throw std::runtime_error("--cpu");
    context = std::make_unique<vk::Context>();
    vulkan = makeVulkanBackend(*context);
    vulkanTrim = makeVulkanTrimClassifier(*context);
    report.setDevice(*context);
    backends.push_back({"Vulkan", &vulkan, vulkanTrim.get()});
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_cad: no Vulkan device (%s): CPU only\n", e.what());
  }
  for (double relative : relatives) runTolerance(report, models, relative, backends);
  report.finish();
  return 0;
}
