// Case 3, accuracy per triangle against Open CASCADE, on the tea set (teapot, teacup, teaspoon):
// every Bézier patch becomes a Geom_BezierSurface face, the faces are sewn into shells
// (BRepBuilderAPI_Sewing: an unsewn compound leaves T-junctions between faces) and meshed by
// BRepMesh_IncrementalMesh at linear deflections 0.01 and 0.001 (angular 0.5 rad), serial and
// parallel. Tessera (rule B by default) then runs at the largest threshold whose mesh has the same
// or a smaller measured maximum deviation. Both meshes are measured by the same code with both
// metrics: distance to the true surface (host/mesh/deviation.h geometric metric, what OCCT's deflection
// promises; the metric the settings are matched on) and parametric (host/mesh/deviation.h).
// The threshold pair is searched along linearity = ratio · flatness for each ratio asked for
// (1: the two equal; inf: flatness only, linearity 2 so that it never splits).
// Rule A means grids per patch from Filip's bound (countedGrids below), in two rows: at
// TOL = δ (the deflection; Filip's bound proves it, the peer the issue means) and at the TOL
// matched on OCCT's measured distance (searched after the fact, unproven: the stronger peer).
// Per model, the asymptotic lower bound N_min(δ) on an interpolating mesh's triangles at the
// deflection δ (host/mesh/lower_bound.h) and each mesh's triangles over it.
// Rule T (tolerance, issue 15) runs at δ = the deflection, unmatched: its bound is the promise.
// With rule T asked for, a last table has the teaspoon alone at a tenth of the smallest
// deflection (the 0.0001): OCCT, rule A (if asked for; its matched row matched on the
// deflection) and rule T.
// Usage: bench_occt [deflections=0.01,0.001] [rules=B] [ratios=1] [--json file]
//   (rules e.g. ABCDT, ratios e.g. 1,4,inf)
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_Sewing.hxx>
#include <BRepMesh_IncrementalMesh.hxx>
#include <BRepTools.hxx>
#include <BRep_Tool.hxx>
#include <Geom_BezierSurface.hxx>
#include <Poly_Triangulation.hxx>
#include <Precision.hxx>
#include <Standard_Version.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Face.hxx>
#include <TopoDS_Shape.hxx>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <sstream>
#include <stdexcept>

#include "bench_args.h"
#include "bench_report.h"
#include "common/stopwatch.h"
#include "mesh/deviation.h"
#include "mesh/lower_bound.h"
#include "division/count.h"
#include "eval/evaluator.h"
#include "geometry/rational.h"
#include "io/bpt_reader.h"
#include "mesh/tessellate.h"
#include "vk/context.h"

using namespace tessera;

namespace {

struct OcctModel {
  TopoDS_Shape shape;
  std::map<const Geom_Surface*, uint32_t> patchOf;  // surface → index into the patches
};

OcctModel buildShells(const std::vector<BezierPatch>& patches, const std::vector<size_t>& parts) {
  OcctModel model;
  BRepBuilderAPI_Sewing sewing(1e-6);
  for (size_t p = 0; p < patches.size(); ++p) {
    TColgp_Array2OfPnt poles(1, 4, 1, 4);
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) {
        const glm::dvec3& c = patches[p].at(i, j);
        poles.SetValue(i + 1, j + 1, gp_Pnt(c.x, c.y, c.z));
      }
    Handle(Geom_BezierSurface) surface = new Geom_BezierSurface(poles);
    model.patchOf[surface.get()] = uint32_t(p);
    sewing.Add(BRepBuilderAPI_MakeFace(surface, Precision::Confusion()).Face());
  }
  (void)parts;  // the three models are far apart: one sewing pass keeps them separate shells
  sewing.Perform();
  model.shape = sewing.SewedShape();
  return model;
}

// OCCT's triangulation of every face as a Tessellation (per-triangle patch and corner uvs), so
// that both metrics of measureDeviation see it exactly as they see Tessera's.
Tessellation readTriangulation(const OcctModel& model) {
  Tessellation t;
  for (TopExp_Explorer e(model.shape, TopAbs_FACE); e.More(); e.Next()) {
    const TopoDS_Face& face = TopoDS::Face(e.Current());
    TopLoc_Location loc;
    Handle(Poly_Triangulation) tri = BRep_Tool::Triangulation(face, loc);
    if (tri.IsNull() || !tri->HasUVNodes()) throw std::runtime_error("OCCT: face without mesh");
    auto found = model.patchOf.find(BRep_Tool::Surface(face).get());
    if (found == model.patchOf.end()) throw std::runtime_error("OCCT: face of unknown surface");
    const uint32_t base = uint32_t(t.mesh.positions.size());
    const gp_Trsf trsf = loc.Transformation();
    for (int i = 1; i <= tri->NbNodes(); ++i) {
      gp_Pnt p = tri->Node(i).Transformed(trsf);
      t.mesh.positions.emplace_back(float(p.X()), float(p.Y()), float(p.Z()));
    }
    for (int k = 1; k <= tri->NbTriangles(); ++k) {
      int n[3];
      tri->Triangle(k).Get(n[0], n[1], n[2]);
      for (int c = 0; c < 3; ++c) {
        t.mesh.indices.push_back(base + uint32_t(n[c] - 1));
        gp_Pnt2d uv = tri->UVNode(n[c]);
        t.cornerUv.emplace_back(float(uv.X()), float(uv.Y()));
      }
      t.trianglePatch.push_back(found->second);
    }
  }
  return t;
}

struct Measured {
  size_t triangles = 0;
  double surfaceMax = 0, parametricMax = 0;
  std::vector<size_t> perModel;  // triangles on each model's patches
};

// parts: patch counts of the models, in the order their patches were appended.
Measured measure(const Tessellation& t, const std::vector<BezierPatch>& patches,
                 const std::vector<size_t>& parts) {
  Measured m{t.mesh.triangleCount(),
             measureDeviation(t, patches, 4, DeviationMetric::Geometric).maxDeviation,
             measureDeviation(t, patches).maxDeviation, std::vector<size_t>(parts.size(), 0)};
  for (uint32_t patch : t.trianglePatch) {
    size_t model = 0;
    for (size_t first = parts[0]; patch >= first; first += parts[++model]) {}
    ++m.perModel[model];
  }
  return m;
}

nlohmann::json toJson(const Measured& m) {
  return {{"triangles", m.triangles},
          {"trianglesPerModel", m.perModel},
          {"maxDistanceToSurface", m.surfaceMax},
          {"maxParametricDeviation", m.parametricMax}};
}

// One line per model: N_min at `deflection` and every case's triangles over it (also put in
// each case's JSON as lowerBoundPerModel and lowerBoundRatioPerModel).
void printLowerBounds(bench::Table& table, const std::vector<const char*>& names,
                      const std::vector<CurvatureRootIntegral>& integrals, double deflection) {
  std::printf("\n| model | N_min(%g) |", deflection);
  for (const bench::Case& c : table.cases) std::printf(" %s |", c.path.c_str());
  std::printf("\n|---|---|");
  for (size_t i = 0; i < table.cases.size(); ++i) std::printf("---|");
  std::printf("\n");
  for (size_t model = 0; model < names.size(); ++model) {
    const double bound = lowerBoundTriangles(integrals[model], deflection);
    std::printf("| %s | %.0f |", names[model], bound);
    for (bench::Case& c : table.cases) {
      const double triangles = c.extra["trianglesPerModel"][model].get<double>();
      std::printf(" %.0f (%.2fx) |", triangles, triangles / bound);
      c.extra["lowerBoundPerModel"].push_back(bound);
      c.extra["lowerBoundRatioPerModel"].push_back(triangles / bound);
    }
    std::printf("\n");
  }
}

// The rows issue 15's time goal compares (OCCT serial and parallel, rule T) run this many
// timed runs each, the same count on both sides: on this 2-core VM a minimum of 5 runs moved by
// ±15% from one bench run to the next (bench/HISTORY.md, session 44), more than the margin the
// goal is decided on. Rules A–D keep bench::kMinRuns.
constexpr int kGoalRuns = 15;

// Rule A's triangles, for rule T's goals (0: rule A not asked for).
struct RuleATriangles {
  size_t atTolerance = 0;  // Filip counts at TOL = δ: proven, the peer
  size_t matched = 0;      // TOL searched until the distance matches OCCT's (or δ): unproven
};

const char* verdict(bool met) { return met ? "met" : "missed"; }

// Rule T (issue 15) at δ = the deflection itself: no matching, the bound is the promise. Each
// backend's run is checked against the goals (within δ by both metrics; ≤ 0.5× OCCT's
// and ≤ 0.7× rule A's triangles at TOL = δ; ≤ 4× N_min per model; ≤ 1/20 of OCCT's parallel
// time), with rule A's matched row beside them, and the Vulkan run's levels are printed split
// into GPU time, the rest of the classify call (transfers, submission) and frontier time.
void addToleranceCases(bench::Table& table, const std::vector<BezierPatch>& patches,
                       const std::vector<size_t>& parts,
                       const std::vector<CurvatureRootIntegral>& integrals, double tolerance,
                       const Measured& occt, const bench::Timing& occtParallel,
                       RuleATriangles ruleA, const std::vector<Backend*>& backends) {
  const QuadtreeOptions o = toleranceOptions(tolerance);
  for (Backend* backend : backends) {
    const bool onVulkan = backend == backends.front();
    Tessellation t;
    bench::Case c{std::string("Tessera rule T, ") + (onVulkan ? "Vulkan" : "CPU all cores"), 0};
    // Warm runs, each after the previous mesh is released outside the timer (as OCCT's runs
    // clean the shape outside theirs): assigning over a live mesh timed its release and the
    // heap growth of holding two (~100-200 page faults in the first timed run). The first
    // call on this backend (the process's first at the first deflection: pipelines are
    // compiled then) is reported beside them, not in them. The warm runs are a reused
    // backend's steady state: they start once 0.25 s of untimed runs have let rule T's fused
    // pipeline, which the Vulkan backend builds on a worker from its second tree on, get ready
    // (docs/quadtree.md; the level table below counts its nodes).
    constexpr double kSteadyAfterSeconds = 0.25;
    c.timing = bench::timeRepeated(
        kGoalRuns, [&] { t = tessellate(patches, o, *backend); }, [&] { t = {}; },
        kSteadyAfterSeconds);
    Measured m = measure(t, patches, parts);
    c.workSize = double(m.triangles);
    c.throughput = 1.0 / c.timing.minSeconds;
    c.extra = toJson(m);
    c.extra["firstCallSeconds"] = c.timing.firstSeconds;
    c.extra["tolerance"] = tolerance;
    const bool within = m.surfaceMax <= tolerance && m.parametricMax <= tolerance;
    const double overOcct = double(m.triangles) / double(occt.triangles);
    const double speedup = occtParallel.minSeconds / c.timing.minSeconds;
    const double speedupOfMedians = occtParallel.medianSeconds / c.timing.medianSeconds;
    c.extra["withinToleranceBothMetrics"] = within;
    c.extra["trianglesOverOcct"] = overOcct;
    c.extra["speedupVsOcctParallel"] = speedup;
    c.extra["speedupVsOcctParallelOfMedians"] = speedupOfMedians;
    std::fprintf(stderr,
                 "  rule T δ %g (%s): %zu triangles; distance %.3g, parametric %.3g (goal <= δ: "
                 "%s)\n    %.3gx OCCT (goal <= 0.5: %s)\n",
                 tolerance, onVulkan ? "Vulkan" : "CPU", m.triangles, m.surfaceMax, m.parametricMax,
                 verdict(within), overOcct, verdict(overOcct <= 0.5));
    if (ruleA.atTolerance) {
      const double overA = double(m.triangles) / double(ruleA.atTolerance);
      const double overMatched = double(m.triangles) / double(ruleA.matched);
      c.extra["trianglesOverRuleA"] = overA;
      c.extra["trianglesOverRuleAMatched"] = overMatched;
      std::fprintf(stderr,
                   "    %.3gx rule A at TOL = δ, %zu (goal <= 0.7: %s); %.3gx rule A matched "
                   "after the fact, %zu (unproven peer)\n",
                   overA, ruleA.atTolerance, verdict(overA <= 0.7), overMatched, ruleA.matched);
    }
    double worstOverBound = 0;
    std::fprintf(stderr, "    N_min ratio per model:");
    for (size_t model = 0; model < parts.size(); ++model) {
      const double ratio =
          double(m.perModel[model]) / lowerBoundTriangles(integrals[model], tolerance);
      worstOverBound = std::max(worstOverBound, ratio);
      std::fprintf(stderr, " %.3g", ratio);
    }
    std::fprintf(stderr,
                 " (goal <= 4: %s)\n    %.1fx faster than OCCT parallel (goal >= 20: %s; by "
                 "medians %.1fx): warm min %.3f ms, median %.3f ms of %d runs; first call on this "
                 "backend %.3f ms\n",
                 verdict(worstOverBound <= 4), speedup, verdict(speedup >= 20), speedupOfMedians,
                 c.timing.minSeconds * 1e3, c.timing.medianSeconds * 1e3, c.timing.runs,
                 c.timing.firstSeconds * 1e3);
    if (onVulkan) {
      // One more run for the levels' GPU time: timestamps cost lavapipe ~0.4 ms of the run at
      // δ 0.01 (QuadtreeOptions::timeGpu), so the timed runs take none.
      QuadtreeOptions timed = o;
      timed.timeGpu = true;
      t = tessellate(patches, timed, *backend);
      std::printf(
          "\nrule T δ %g on Vulkan, per level (one more run, with GPU timestamps):\n\n"
          "| level | nodes | splits | host nodes | fused nodes | GPU ms | transfers + submission "
          "ms (or the host mirror's) | frontier ms |\n"
          "|---|---|---|---|---|---|---|---|\n",
          tolerance);
      for (const LevelStats& level : t.stats.levels)
        std::printf("| %u | %zu | %zu | %zu | %zu | %.3f | %.3f | %.3f |\n", level.level,
                    level.nodes, level.splits, level.hostNodes, level.fusedNodes, level.gpuMs,
                    level.classifyMs - level.gpuMs, level.frontierMs);
    }
    table.cases.push_back(c);
  }
}

// Linearity = ratio · flatness, capped at 2 (1 − cos never exceeds 2: that test never splits).
void setThresholds(QuadtreeOptions& o, double flatness, double ratio) {
  o.flatness = float(flatness);
  o.linearity = float(std::min(2.0, ratio * flatness));
}

// The largest flatness threshold (linearity = ratio · flatness) whose mesh is within `target`
// by distance to the surface: bisection in log space between thresholds that pass and fail.
QuadtreeOptions matchDeviation(const std::vector<BezierPatch>& patches, SplitRule rule,
                               double ratio, double target, Backend& backend) {
  QuadtreeOptions o;
  o.rule = rule;
  auto within = [&](double threshold) {
    setThresholds(o, threshold, ratio);
    Tessellation t = tessellate(patches, o, backend);
    double d = measureDeviation(t, patches, 4, DeviationMetric::Geometric).maxDeviation;
    std::fprintf(stderr,
                 "  rule %c flatness %.3g linearity %.3g: %zu triangles, distance %.3g (target "
                 "%.3g)\n",
                 splitRuleLetter(rule), threshold, o.linearity, t.mesh.triangleCount(), d, target);
    return d <= target;
  };
  // Thresholds are 1 − cos of angles; the deviation is not monotone in them (a level more or
  // less on some patch), so the best threshold that passed is kept, not the bracket's end.
  double pass = 1e-3, fail = 0.3, best = 0;
  for (int step = 0; step < 8; ++step) {
    double mid = std::sqrt(pass * fail);
    if (within(mid)) {
      pass = best = mid;
    } else {
      fail = mid;
    }
  }
  if (best == 0) best = pass;  // none passed: the lower end, reported with what it measures
  setThresholds(o, best, ratio);
  return o;
}

// Rule A with each patch's grid from Filip's bound at TOL in model units
// (host/division/count.h): the size-aware setting. Rules B–D stop on angles (1 − cos), which
// do not see a patch's size, so at one absolute deviation they over-refine small patches.
// The grids come from buildQuadtree's rule A, one patch at a time (as uniformGridMesh does),
// and meshFromTree makes them watertight.
Tessellation countedGrids(const std::vector<BezierPatch>& patches,
                          const std::vector<gpu::BicubicPatch>& gpuPatches, double tolerance,
                          PatchEvaluator& evaluator) {
  DivisionOptions counting;
  counting.tolerance = tolerance;
  QuadtreeOptions grid;
  grid.rule = SplitRule::UniformGrid;
  const std::unique_ptr<NodeClassifier> unused = makeReferenceClassifier();
  QuadtreeResult tree;
  for (size_t p = 0; p < patches.size(); ++p) {
    const Divisions d = patchDivisions(toRationalPatch(patches[p]), counting);
    grid.gridU = d.nu;
    grid.gridV = d.nv;
    const PatchSet one(std::vector<gpu::BicubicPatch>{gpuPatches[p]});
    for (QuadLeaf leaf : buildQuadtree(one, grid, *unused).leaves) {
      leaf.patchIndex = uint32_t(p);
      tree.leaves.push_back(leaf);
    }
  }
  return meshFromTree(patches, gpuPatches, std::move(tree), evaluator);
}

// The largest TOL whose counted grids are within `target` by distance to the surface.
double matchCountedGrids(const std::vector<BezierPatch>& patches,
                         const std::vector<gpu::BicubicPatch>& gpuPatches, double target,
                         PatchEvaluator& evaluator) {
  double pass = target / 64, fail = 16 * target, best = 0;
  for (int step = 0; step < 10; ++step) {
    double mid = std::sqrt(pass * fail);
    Tessellation t = countedGrids(patches, gpuPatches, mid, evaluator);
    double d = measureDeviation(t, patches, 4, DeviationMetric::Geometric).maxDeviation;
    std::fprintf(stderr, "  rule A counted TOL %.3g: %zu triangles, distance %.3g (target %.3g)\n",
                 mid, t.mesh.triangleCount(), d, target);
    if (d <= target) {
      pass = best = mid;
    } else {
      fail = mid;
    }
  }
  return best == 0 ? pass : best;
}

// The models one OCCT table covers: their patches side by side, the patch count of each, names
// and ∫√|K| dA (for N_min at every δ).
struct BenchSet {
  std::string label, tablePrefix;  // "tea set", ""; "teaspoon alone", "teaspoon "
  std::vector<BezierPatch> patches;
  std::vector<size_t> parts;
  std::vector<const char*> names;
  std::vector<CurvatureRootIntegral> integrals;
  // Rule A's matched row is matched on OCCT's measured distance, or on the deflection itself
  // where OCCT's mesh misses it (the teaspoon at 0.0001: 5× δ at its tips), so that rule T,
  // held to δ, is compared with grids of the same accuracy.
  bool ruleAOnDeflection = false;
};

// One table: OCCT serial and parallel at `deflection`, then the Tessera rules asked for.
void runDeflection(bench::Report& report, const BenchSet& set, double deflection,
                   const std::vector<SplitRule>& rules, const std::vector<double>& ratios,
                   bool countedGridsAsked, Backend& vulkan, Backend& cpu) {
  const std::vector<BezierPatch>& patches = set.patches;
  const std::vector<size_t>& parts = set.parts;
  OcctModel model = buildShells(patches, parts);
  Tessellation occtMesh;
  bench::Timing occtTime[2];
  for (int parallel = 0; parallel < 2; ++parallel) {
    std::vector<double> seconds;
    double first = 0;
    for (int run = 0; run <= kGoalRuns; ++run) {  // run 0 warms up
      BRepTools::Clean(model.shape);
      const Stopwatch stopwatch;
      BRepMesh_IncrementalMesh mesher(model.shape, deflection, Standard_False, 0.5,
                                      parallel ? Standard_True : Standard_False);
      (run > 0 ? seconds.push_back(stopwatch.elapsedSeconds())
               : void(first = stopwatch.elapsedSeconds()));
    }
    std::sort(seconds.begin(), seconds.end());
    occtTime[parallel] = {seconds.front(), seconds[seconds.size() / 2], int(seconds.size()),
                          first};
  }
  occtMesh = readTriangulation(model);
  Measured occt = measure(occtMesh, patches, parts);
  std::fprintf(stderr,
               "OCCT %g: %.3f s serial, %.3f s parallel (warm minima; first runs %.3f, %.3f), %zu "
               "triangles, distance %.3g\n",
               deflection, occtTime[0].minSeconds, occtTime[1].minSeconds, occtTime[0].firstSeconds,
               occtTime[1].firstSeconds, occt.triangles, occt.surfaceMax);

  char title[400];
  std::snprintf(title, sizeof title,
                "%s (%zu patches), OCCT deflection %g (angular 0.5): %zu triangles, max "
                "distance to surface %.3g, parametric %.3g; Tessera rules B-D and rule A's "
                "matched row matched on distance to surface%s; rule A also at TOL = δ, rule T "
                "at δ",
                set.label.c_str(), patches.size(), deflection, occt.triangles, occt.surfaceMax,
                occt.parametricMax, set.ruleAOnDeflection ? " (rule A: on the deflection)" : "");
  char name[64];
  std::snprintf(name, sizeof name, "%sOCCT %g", set.tablePrefix.c_str(), deflection);
  bench::Table& table = report.table(name, "triangles", title);
  table.rateUnit = "meshes/s";  // the ratio is then the speed-up over OCCT serial
  const char* modes[2] = {"OCCT BRepMesh, serial", "OCCT BRepMesh, parallel (all cores)"};
  for (int parallel = 0; parallel < 2; ++parallel) {
    bench::Case c{modes[parallel], double(occt.triangles), occtTime[parallel]};
    c.throughput = 1.0 / occtTime[parallel].minSeconds;  // meshes per second
    c.extra = toJson(occt);
    c.extra["firstCallSeconds"] = occtTime[parallel].firstSeconds;
    table.cases.push_back(c);
  }
  const std::vector<gpu::BicubicPatch> gpuPatches = toGpuPatches(patches);
  RuleATriangles ruleA;
  // Rule A's grids at one TOL, on both evaluators; returns the triangles.
  const auto addCountedGrids = [&](const char* label, double tolerance) {
    size_t triangles = 0;
    for (Backend* backend : {&vulkan, &cpu}) {
      Tessellation t;
      bench::Case c{std::string("Tessera rule A, Filip counts per patch ") + label + ", " +
                        (backend == &vulkan ? "Vulkan evaluation" : "CPU evaluation"),
                    0};
      c.timing = bench::timeRepeated(bench::kMinRuns, [&] {
        t = countedGrids(patches, gpuPatches, tolerance, *backend->evaluator);
      });
      Measured m = measure(t, patches, parts);
      c.workSize = double(m.triangles);
      c.throughput = 1.0 / c.timing.minSeconds;
      c.extra = toJson(m);
      c.extra["divisionTolerance"] = tolerance;
      c.extra["fewerTrianglesThanOcct"] = m.triangles < occt.triangles;
      c.extra["speedupVsOcctParallel"] = occtTime[1].minSeconds / c.timing.minSeconds;
      table.cases.push_back(c);
      triangles = m.triangles;
    }
    return triangles;
  };
  if (countedGridsAsked) {
    ruleA.atTolerance = addCountedGrids("at TOL = δ (proven)", deflection);
    const double matched =
        matchCountedGrids(patches, gpuPatches, set.ruleAOnDeflection ? deflection : occt.surfaceMax,
                          *vulkan.evaluator);
    ruleA.matched =
        addCountedGrids(set.ruleAOnDeflection ? "at TOL matched on δ (unproven)"
                                              : "at TOL matched on OCCT's distance (unproven)",
                        matched);
  }
  for (SplitRule rule : rules) {
    if (rule == SplitRule::Tolerance) {
      addToleranceCases(table, patches, parts, set.integrals, deflection, occt, occtTime[1], ruleA,
                        {&vulkan, &cpu});
      continue;
    }
    for (double ratio : ratios) {
      QuadtreeOptions o = matchDeviation(patches, rule, ratio, occt.surfaceMax, vulkan);
      char setting[64] = "";
      if (ratios.size() > 1 || ratio != 1.0)
        std::snprintf(setting, sizeof setting,
                      ratio >= 1e29 ? " flatness only" : " linearity %g x flatness", ratio);
      for (Backend* backend : {&vulkan, &cpu}) {
        Tessellation t;
        bench::Case c{std::string("Tessera rule ") + splitRuleLetter(rule) + setting + ", " +
                          (backend == &vulkan ? "Vulkan" : "CPU all cores"),
                      0};
        c.timing = bench::timeRepeated(bench::kMinRuns,
                                       [&] { t = tessellate(patches, o, *backend); });
        Measured m = measure(t, patches, parts);
        c.workSize = double(m.triangles);
        c.throughput = 1.0 / c.timing.minSeconds;
        c.extra = toJson(m);
        c.extra["threshold"] = o.flatness;
        c.extra["linearity"] = o.linearity;
        c.extra["fewerTrianglesThanOcct"] = m.triangles < occt.triangles;
        c.extra["speedupVsOcctParallel"] = occtTime[1].minSeconds / c.timing.minSeconds;
        table.cases.push_back(c);
      }
    }
  }
  report.print(table);
  std::printf("\n| mesh | triangles | max distance to surface | max parametric deviation |\n"
              "|---|---|---|---|\n");
  for (const bench::Case& c : table.cases)
    std::printf("| %s | %.0f | %.3g | %.3g |\n", c.path.c_str(), c.workSize,
                c.extra["maxDistanceToSurface"].get<double>(),
                c.extra["maxParametricDeviation"].get<double>());
  printLowerBounds(table, set.names, set.integrals, deflection);
}

}  // namespace

int main(int argc, char** argv) {
  bench::Report report("bench_occt", "[deflections=0.01,0.001] [rules=B] [ratios=1] [--json file]",
                       argc, argv);
  bench::atMostArguments(report, argc, argv, 3);
  std::vector<double> deflections = {0.01, 0.001};
  if (argc > 1) deflections = bench::numberListArg(report, argv[1], "deflections", 1e-9);
  std::vector<SplitRule> rules = {SplitRule::Midpoint};
  bool countedGridsAsked = false;  // "A": rule A with per-patch Filip counts
  if (argc > 2) {
    rules.clear();
    for (const char* r = argv[2]; *r; ++r) {
      if (*r == ',') continue;
      if (!std::strchr("ABCDT", *r))
        report.usageError(std::string("rules '") + argv[2] +
                          "': expected letters of A, B, C, D, T");
      SplitRule rule = parseSplitRule(std::string(1, *r));
      if (rule == SplitRule::UniformGrid)
        countedGridsAsked = true;
      else
        rules.push_back(rule);
    }
  }
  std::vector<double> ratios = {1.0};
  if (argc > 3) {
    ratios.clear();
    std::stringstream list(argv[3]);
    for (std::string item; std::getline(list, item, ',');)
      ratios.push_back(item == "inf" ? 1e30 : bench::numberArg(report, item, "ratios", 1e-9));
    if (ratios.empty()) report.usageError("ratios: expected at least one number");
  }
  BenchSet teaSet;
  teaSet.label = "tea set";
  teaSet.names = {"teapot", "teacup", "teaspoon"};
  std::vector<BezierPatch>& patches = teaSet.patches;
  std::vector<size_t>& parts = teaSet.parts;
  for (const char* name : teaSet.names) {
    auto model = readBpt(std::string(TESSERA_BENCH_DATA "/") + name + ".bpt");
    const TriangleLowerBound bound = asymptoticTriangleLowerBound(model, 1.0);
    std::fprintf(stderr, "%s: N_min = %.4g/δ (k = %d, %.1f ms)\n", name, bound.triangles,
                 bound.cells, bound.ms);
    teaSet.integrals.push_back(bound.integral);
    // Side by side, 10 units apart, so no face of one touches another's.
    for (auto& p : model) {
      for (auto& c : p.cp) c.x += 10.0 * double(parts.size());
      patches.push_back(p);
    }
    parts.push_back(model.size());
  }
  vk::ContextOptions options;
  vk::Context context(options);
  report.setDevice(context);
  report.note("occtVersion", OCC_VERSION_COMPLETE);
  report.note("patches", patches.size());
  Backend vulkan = makeVulkanBackend(context);
  Backend cpu = makeMirrorBackend();

  for (double deflection : deflections)
    runDeflection(report, teaSet, deflection, rules, ratios, countedGridsAsked, vulkan, cpu);
  // The teaspoon case (issue 15): the teaspoon alone at a tenth of the smallest
  // deflection (0.0001 for 0.01,0.001), OCCT, rule A and rule T only (matching rules B–D
  // there would take minutes).
  const bool toleranceAsked =
      std::find(rules.begin(), rules.end(), SplitRule::Tolerance) != rules.end();
  if (toleranceAsked && !deflections.empty()) {
    BenchSet teaspoon;
    teaspoon.label = "teaspoon alone";
    teaspoon.tablePrefix = "teaspoon ";
    teaspoon.patches = readBpt(std::string(TESSERA_BENCH_DATA "/teaspoon.bpt"));
    teaspoon.parts = {teaspoon.patches.size()};
    teaspoon.names = {"teaspoon"};
    teaspoon.integrals = {teaSet.integrals.back()};
    teaspoon.ruleAOnDeflection = true;
    const double smallest = *std::min_element(deflections.begin(), deflections.end());
    runDeflection(report, teaspoon, smallest / 10, {SplitRule::Tolerance}, ratios,
                  countedGridsAsked, vulkan, cpu);
  }
  report.finish();
  return 0;
}
