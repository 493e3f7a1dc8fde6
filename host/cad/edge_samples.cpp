// The once-per-edge discretisation (adaptive bisection with a measured chord deviation).
#include "cad/edge_samples.h"

#include <BRepAdaptor_Curve.hxx>
#include <BRep_Tool.hxx>
#include <TopExp.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Vertex.hxx>
#include <algorithm>
#include <cmath>

namespace tessera {
namespace {

constexpr int kChecksPerSegment = 15;
constexpr int kMaxDepth = 24;
constexpr uint32_t kUnsharedSample = UINT32_MAX;  // an interior id until shareInteriorSamples

glm::dvec3 toGlm(const gp_Pnt& p) { return {p.X(), p.Y(), p.Z()}; }

double pointSegmentDistance(glm::dvec3 p, glm::dvec3 a, glm::dvec3 b) {
  const glm::dvec3 ab = b - a;
  const double len2 = glm::dot(ab, ab);
  const double t = len2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / len2, 0.0, 1.0) : 0.0;
  return glm::length(p - (a + t * ab));
}

// Largest distance from the curve on [a, b] to the chord: for a circle (parametrised by angle)
// its sagitta R·(1 − cos((b − a)/2)), exactly; otherwise measured at kChecksPerSegment samples.
double chordDeviation(const BRepAdaptor_Curve& curve, double a, double b) {
  if (curve.GetType() == GeomAbs_Circle) {
    const double s = std::sin(0.25 * (b - a));
    return curve.Circle().Radius() * 2.0 * s * s;
  }
  const glm::dvec3 pa = toGlm(curve.Value(a)), pb = toGlm(curve.Value(b));
  double worst = 0.0;
  for (int k = 1; k <= kChecksPerSegment; ++k) {
    const double t = a + (b - a) * k / (kChecksPerSegment + 1.0);
    worst = std::max(worst, pointSegmentDistance(toGlm(curve.Value(t)), pa, pb));
  }
  return worst;
}

void refine(const BRepAdaptor_Curve& curve, double a, double b, double delta, int depth,
            std::vector<double>& params, double& worst) {
  const double deviation = chordDeviation(curve, a, b);
  if (deviation > delta && depth < kMaxDepth) {
    const double m = 0.5 * (a + b);
    refine(curve, a, m, delta, depth + 1, params, worst);
    refine(curve, m, b, delta, depth + 1, params, worst);
    return;
  }
  worst = std::max(worst, deviation);
  params.push_back(b);
}

uint32_t vertexId(const TopoDS_Vertex& v, const TopTools_IndexedMapOfShape& vertices) {
  return static_cast<uint32_t>(vertices.FindIndex(v) - 1);
}

}  // namespace

EdgeSamples discretiseEdge(const TopoDS_Shape& shape, double delta,
                           const TopTools_IndexedMapOfShape& vertices) {
  const TopoDS_Edge edge = TopoDS::Edge(shape.Oriented(TopAbs_FORWARD));
  EdgeSamples samples;
  double first, last;
  BRep_Tool::Range(edge, first, last);
  TopoDS_Vertex v0, v1;
  TopExp::Vertices(edge, v0, v1);  // FORWARD: v0 at `first`, v1 at `last`
  const uint32_t id0 = vertexId(v0, vertices), id1 = vertexId(v1, vertices);
  samples.tolerance = BRep_Tool::Tolerance(edge);

  if (BRep_Tool::Degenerated(edge)) {
    samples.degenerated = true;
    for (int k = 0; k <= 8; ++k) {
      samples.params.push_back(first + (last - first) * k / 8.0);
      samples.pointIds.push_back(id0);
    }
    return samples;
  }
  BRepAdaptor_Curve curve(edge);
  samples.params.reserve(16);  // most edges take fewer: one allocation, not five
  samples.params.push_back(first);
  if (curve.GetType() == GeomAbs_Line) {
    samples.params.push_back(last);
  } else if (curve.GetType() == GeomAbs_Circle) {
    // Parametrised by angle, so the fewest equal segments whose sagitta R·(1 − cos(Δt/2)) is
    // within δ (at least 4, as below), not a power of two of them.
    const double radius = curve.Circle().Radius();
    const double widest = radius > delta ? 2.0 * std::acos(1.0 - delta / radius) : last - first;
    int count = std::max(4, int(std::ceil((last - first) / widest)));
    while (chordDeviation(curve, first, first + (last - first) / count) > delta) ++count;  // rounding
    samples.params.reserve(size_t(count) + 1);
    for (int k = 1; k <= count; ++k) samples.params.push_back(first + (last - first) * k / count);
    samples.maxChordDeviation = chordDeviation(curve, first, first + (last - first) / count);
  } else {
    for (int k = 0; k < 4; ++k)
      refine(curve, first + (last - first) * k / 4.0, first + (last - first) * (k + 1) / 4.0,
             delta, 0, samples.params, samples.maxChordDeviation);
  }
  // The ends at the range's own ends (the last parameter can be an ulp from `last`).
  samples.curvePoints.reserve(samples.params.size());
  samples.curvePoints.push_back(toGlm(curve.Value(first)));
  for (size_t k = 1; k + 1 < samples.params.size(); ++k)
    samples.curvePoints.push_back(toGlm(curve.Value(samples.params[k])));
  samples.curvePoints.push_back(toGlm(curve.Value(last)));
  // The interior ids come with shareInteriorSamples.
  samples.pointIds.assign(samples.params.size(), kUnsharedSample);
  samples.pointIds.front() = id0;
  samples.pointIds.back() = id1;
  return samples;
}

void shareInteriorSamples(EdgeSamples& samples, SharedPoints& points) {
  if (samples.degenerated) return;
  for (size_t k = 1; k + 1 < samples.params.size(); ++k) {
    samples.pointIds[k] = static_cast<uint32_t>(points.positions.size());
    points.positions.push_back(samples.curvePoints[k]);
    points.tolerances.push_back(samples.tolerance);
  }
}

}  // namespace tessera
