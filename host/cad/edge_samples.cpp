// The once-per-edge discretisation (adaptive bisection with a measured chord deviation).
#include "cad/edge_samples.h"

#include <BRepAdaptor_Curve.hxx>
#include <BRep_Tool.hxx>
#include <TopExp.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Vertex.hxx>
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstring>

#include "cad/detail/number_text.h"
#include "common/memory_budget.h"

namespace tessera {
namespace {

constexpr int kChecksPerSegment = 15;
constexpr int kMaxDepth = 24;
// A bisection counts its samples into the budget in steps of this many (an atomic add each).
constexpr size_t kBudgetStride = 4096;
// Below this many ulps of the chord's ends' largest coordinate a measured deviation is the
// points' rounding (OCCT's evaluation, the distance's arithmetic), not the curve: no split can
// bring it under δ.
constexpr double kRoundingUlps = 1024.0;

glm::dvec3 toGlm(const gp_Pnt& p) { return {p.X(), p.Y(), p.Z()}; }

double pointSegmentDistance(glm::dvec3 p, glm::dvec3 a, glm::dvec3 b) {
  const glm::dvec3 ab = b - a;
  const double len2 = glm::dot(ab, ab);
  const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  return glm::length(p - (a + t * ab));
}

glm::dvec3 pointAt(const BRepAdaptor_Curve& curve, double t) { return toGlm(curve.Value(t)); }

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// A circle's (parametrised by angle) largest distance to the chord of [a, b]: its sagitta
// R·(1 − cos((b − a)/2)), exactly. `radius`: curve.Circle().Radius(), read once per edge (each
// Circle() builds the located circle).
double circleSagitta(double radius, double a, double b) {
  const double s = std::sin(0.25 * (b - a));
  return radius * 2.0 * s * s;
}

// Largest distance from the curve on [a, b] to the chord pa pb (its points at a and b), measured
// at kChecksPerSegment samples; the middle sample's parameter and point go to `middle`.
double measuredDeviation(const BRepAdaptor_Curve& curve, double a, double b, glm::dvec3 pa,
                         glm::dvec3 pb, double& middleT, glm::dvec3& middle) {
  double worst = 0.0;
  for (int k = 1; k <= kChecksPerSegment; ++k) {
    const double t = a + (b - a) * k / (kChecksPerSegment + 1.0);
    const glm::dvec3 p = pointAt(curve, t);
    if (2 * k == kChecksPerSegment + 1) middleT = t, middle = p;
    worst = std::max(worst, pointSegmentDistance(p, pa, pb));
  }
  return worst;
}

double roundingFloor(glm::dvec3 pa, glm::dvec3 pb) {
  const glm::dvec3 reach = glm::max(glm::abs(pa), glm::abs(pb));
  return kRoundingUlps * DBL_EPSILON * std::max({reach.x, reach.y, reach.z});
}

// Halves [a, b] while the curve lies farther than delta from its chord (and farther than the
// points' rounding); each kept segment's end and its point are appended. Every point is
// evaluated once, at its own parameter: the ends come from the parent, the middle from the
// parent's middle check where the parameters agree.
void refine(const BRepAdaptor_Curve& curve, double a, double b, glm::dvec3 pa, glm::dvec3 pb,
            double delta, int depth, std::vector<double>& params, std::vector<glm::dvec3>& points,
            double& worst, EdgeSampleBudget& budget) {
  double middleT = 0.0;
  glm::dvec3 middle(0.0);
  const double deviation = measuredDeviation(curve, a, b, pa, pb, middleT, middle);
  if (deviation > delta && depth < kMaxDepth && deviation > roundingFloor(pa, pb)) {
    const double m = 0.5 * (a + b);
    const glm::dvec3 pm = sameBits(m, middleT) ? middle : pointAt(curve, m);
    refine(curve, a, m, pa, pm, delta, depth + 1, params, points, worst, budget);
    refine(curve, m, b, pm, pb, delta, depth + 1, params, points, worst, budget);
    return;
  }
  worst = std::max(worst, deviation);
  params.push_back(b);
  points.push_back(pb);
  if (params.size() % kBudgetStride == 0) budget.add(kBudgetStride);
}

uint32_t vertexId(const TopoDS_Vertex& v, const TopTools_IndexedMapOfShape& vertices) {
  return static_cast<uint32_t>(vertices.FindIndex(v) - 1);
}

}  // namespace

void EdgeSampleBudget::add(double samples) {
  // Saturating: a circle's count at δ → 0 is infinite.
  const uint64_t count = samples < 1e18 ? uint64_t(samples) : uint64_t(1e18);
  const uint64_t total = samples_.fetch_add(count, std::memory_order_relaxed) + count;
  requireWithinMemoryBudget(
      saturatingMultiply(total, kBytesPerSample),
      "the discretisation of the B-rep edges at δ = " + cad_detail::numberText(delta_));
}

EdgeSamples discretiseEdge(const TopoDS_Shape& shape, double delta,
                           const TopTools_IndexedMapOfShape& vertices, EdgeSampleBudget* budget) {
  TopoDS_Vertex v0, v1;  // FORWARD: v0 at `first`, v1 at `last`
  TopExp::Vertices(TopoDS::Edge(shape.Oriented(TopAbs_FORWARD)), v0, v1);
  return discretiseEdge(shape, delta, vertexId(v0, vertices), vertexId(v1, vertices), budget);
}

EdgeSamples discretiseEdge(const TopoDS_Shape& shape, double delta, uint32_t id0, uint32_t id1,
                           EdgeSampleBudget* sharedBudget) {
  EdgeSampleBudget ownBudget(delta);  // this edge alone, where the caller shares none
  EdgeSampleBudget& budget = sharedBudget ? *sharedBudget : ownBudget;
  const TopoDS_Edge edge = TopoDS::Edge(shape.Oriented(TopAbs_FORWARD));
  EdgeSamples samples;
  double first, last;
  BRep_Tool::Range(edge, first, last);
  samples.tolerance = BRep_Tool::Tolerance(edge);

  if (BRep_Tool::Degenerated(edge)) {
    samples.degenerated = true;
    samples.params.reserve(9);
    for (int k = 0; k <= 8; ++k) samples.params.push_back(first + (last - first) * k / 8.0);
    samples.firstId = samples.lastId = id0;
    return samples;
  }
  BRepAdaptor_Curve curve(edge);
  // Each vector allocated once, at its size: a free-form edge's bisection grows this thread's
  // scratch vectors instead (malloc was a third of the edges' time).
  const GeomAbs_CurveType type = curve.GetType();
  if (type == GeomAbs_Line || type == GeomAbs_Circle) {
    if (type == GeomAbs_Line) {
      samples.params = {first, last};
    } else {
      // Parametrised by angle, so the fewest equal segments whose sagitta R·(1 − cos(Δt/2)) is
      // within δ (at least 4, as below), not a power of two of them.
      const double radius = curve.Circle().Radius();
      const double widest = radius > delta ? 2.0 * std::acos(1.0 - delta / radius) : last - first;
      const double needed = std::max(4.0, std::ceil((last - first) / widest));  // inf at widest 0
      budget.add(needed + 1.0);         // before the samples are made; throws past the budget
      int64_t count = int64_t(needed);  // the budget holds it far below 2⁶³
      while (circleSagitta(radius, first, first + (last - first) / count) > delta) ++count;  // rounding
      samples.params.reserve(size_t(count) + 1);
      samples.params.push_back(first);
      for (int64_t k = 1; k <= count; ++k)
        samples.params.push_back(first + (last - first) * k / count);
      samples.maxChordDeviation = circleSagitta(radius, first, first + (last - first) / count);
    }
    // The ends at the range's own ends (the last parameter can be an ulp from `last`).
    samples.curvePoints.reserve(samples.params.size());
    samples.curvePoints.push_back(pointAt(curve, first));
    for (size_t k = 1; k + 1 < samples.params.size(); ++k)
      samples.curvePoints.push_back(pointAt(curve, samples.params[k]));
    samples.curvePoints.push_back(pointAt(curve, last));
  } else {
    // Any other curve: its points come with the bisection, each evaluated once.
    thread_local std::vector<double> params;
    thread_local std::vector<glm::dvec3> points;
    params.assign(1, first);
    glm::dvec3 previous = pointAt(curve, first + (last - first) * 0 / 4.0);
    points.assign(1, sameBits(first + (last - first) * 0 / 4.0, first) ? previous : pointAt(curve, first));
    for (int k = 0; k < 4; ++k) {
      const double a = first + (last - first) * k / 4.0, b = first + (last - first) * (k + 1) / 4.0;
      const glm::dvec3 next = pointAt(curve, b);
      refine(curve, a, b, previous, next, delta, 0, params, points, samples.maxChordDeviation,
             budget);
      previous = next;
    }
    // The end at the range's own end (the last parameter can be an ulp from `last`).
    if (!sameBits(params.back(), last)) points.back() = pointAt(curve, last);
    budget.add(double(params.size() % kBudgetStride));
    samples.params.assign(params.begin(), params.end());
    samples.curvePoints.assign(points.begin(), points.end());
  }
  samples.firstId = id0;
  samples.lastId = id1;
  return samples;
}

void shareInteriorSamples(EdgeSamples& samples, SharedPoints& points) {
  if (samples.degenerated) return;
  samples.firstInteriorId = static_cast<uint32_t>(points.positions.size());
  for (size_t k = 1; k + 1 < samples.params.size(); ++k) {
    points.positions.push_back(samples.curvePoints[k]);
    points.tolerances.push_back(samples.tolerance);
  }
}

}  // namespace tessera
