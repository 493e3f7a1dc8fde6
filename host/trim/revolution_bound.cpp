#include "trim/revolution_bound.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "common/parallel_for.h"
#include "quadtree/detail/classify_mirror.h"

namespace tessera {
namespace {

// Spans are measured as the angle between their end directions, which is the span only while
// it is under π; nodes whose half spans reach π/4 split instead (a piece of a rational circle
// spans at most 2π/3, so only the first levels meet this).
constexpr double kLargestHalfSpan = 0.78539816339744830962;  // π/4
// The pieces are the analytic surface up to the conversion's rounding (docs/cad.md: pieces
// against OCCT's surface within 3·10⁻¹⁴ of the model's size); the bound adds 10⁻¹² of the
// surface's radii for it.
constexpr double kConversionGuard = 1e-12;
// lib/tolerance_bound.h's kToleranceUnbounded: a bound no δ accepts, so the node splits both ways.
constexpr float kUnbounded = 1.0e30f;
// Nodes a thread takes at a time: a node's bound is a few surface points and arc tangents
// (about a microsecond), so fewer would be all hand-out.
constexpr size_t kNodesPerTurn = 64;

double angleBetween(glm::dvec2 a, glm::dvec2 b) {
  return std::atan2(std::abs(a.x * b.y - a.y * b.x), glm::dot(a, b));
}
double angleBetween(const glm::dvec3& a, const glm::dvec3& b) {
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}
// 1 − cos x without the cancellation: 2·sin²(x/2).
double oneMinusCos(double x) {
  const double s = std::sin(0.5 * x);
  return 2.0 * s * s;
}

// A point in meridian coordinates: its direction away from the axis, its distance ρ from the
// axis and its height h above the form's origin.
struct Meridian {
  glm::dvec3 radial;
  double rho = 0.0, h = 0.0;
};
Meridian meridianOf(const RevolutionForm& form, const glm::dvec3& p) {
  const glm::dvec3 x = p - form.origin;
  Meridian m;
  m.h = glm::dot(x, form.axis);
  m.radial = x - m.h * form.axis;
  m.rho = glm::length(m.radial);
  return m;
}

// Half the span from a to b, with the middle m checked to lie between them (so the span is the
// short way round): a negative value when it does not, or when the half span is too wide.
template <typename V>
double halfSpan(const V& a, const V& b, const V& m) {
  const double whole = angleBetween(a, b);
  const double viaMiddle = angleBetween(a, m) + angleBetween(m, b);
  if (!(viaMiddle <= whole * (1.0 + 1e-9) + 1e-12) || !(0.5 * whole < kLargestHalfSpan)) return -1.0;
  return 0.5 * whole;
}

}  // namespace

RevolutionBound revolutionNodeBound(const RevolutionForm& form, const FaceSurface& surface,
                                    size_t piece, glm::dvec4 rect) {
  RevolutionBound out;
  if (form.profile == RevolutionForm::Profile::None) return out;
  const auto at = [&](double s, double t) {
    return meridianOf(form, surface.point(surface.faceUv(piece, {s, t})));
  };
  const double um = 0.5 * (rect.x + rect.z), vm = 0.5 * (rect.y + rect.w);
  // ρ and h depend on v alone (u turns about the axis), the azimuth on u alone.
  const Meridian low = at(rect.x, rect.y), high = at(rect.x, rect.w);

  // Along the profile: its half span β, and the largest ρ over the node (ρ_max). A line's ρ is
  // affine along it: largest at an end. A circle's ρ = c + r·cos ψ: largest at ψ = 0 when the
  // arc passes it.
  double rhoMax = std::max(low.rho, high.rho);
  // A node across a cone's apex has points on both nappes, azimuths half a turn apart.
  if (form.profile == RevolutionForm::Profile::Line && glm::dot(low.radial, high.radial) < 0.0)
    return out;
  if (form.profile == RevolutionForm::Profile::Circle) {
    const Meridian middle = at(rect.x, vm);
    const auto profileVector = [&](const Meridian& m) {
      return glm::dvec2(m.rho - form.circleCentre, m.h);
    };
    const glm::dvec2 d0 = profileVector(low), d1 = profileVector(high);
    const double beta = halfSpan(d0, d1, profileVector(middle));
    if (beta < 0.0) return out;
    out.profile = form.circleRadius * oneMinusCos(beta);
    if (angleBetween(d0, {1.0, 0.0}) + angleBetween(glm::dvec2(1.0, 0.0), d1) <=
        2.0 * beta * (1.0 + 1e-9) + 1e-12)
      rhoMax = form.circleCentre + form.circleRadius;
  }

  // Around the axis: the half span α of the azimuth, on the row farther from it (a cone's apex
  // or a sphere's pole has none; ρ is the same along a row).
  if (rhoMax > 0.0) {
    // The row's first point is low or high itself: evaluated once (the same doubles).
    const bool lowRow = low.rho >= high.rho;
    const double t = lowRow ? rect.y : rect.w;
    const glm::dvec3& first = lowRow ? low.radial : high.radial;
    const double alpha = halfSpan(first, at(rect.z, t).radial, at(um, t).radial);
    if (alpha < 0.0) return out;
    out.azimuth = rhoMax * oneMinusCos(alpha);
  }
  out.guard = kConversionGuard * (rhoMax + form.circleRadius + std::max(std::abs(low.h), std::abs(high.h)));
  out.valid = true;
  return out;
}

RevolutionBoundClassifier::RevolutionBoundClassifier(NodeClassifier& inner,
                                                     std::vector<Patch> patches, double scale,
                                                     unsigned threads)
    : RevisingClassifier(inner, patches.size()),
      patches_(std::move(patches)),
      scale_(scale),
      threads_(threads) {}

std::string RevolutionBoundClassifier::name() const {
  return inner().name() + " (surfaces of revolution by their distance bound)";
}

bool RevolutionBoundClassifier::rewritesWhole(size_t patch, const QuadtreeOptions& options) const {
  const Patch& p = patches_[patch];
  return options.rule == SplitRule::Tolerance && p.form &&
         p.form->profile != RevolutionForm::Profile::None;
}

void RevolutionBoundClassifier::revise(const std::vector<gpu::QuadNode>& nodes,
                                       const QuadtreeOptions& options,
                                       std::vector<gpu::NodeDecision>& decisions, LevelStats&) {
  if (options.rule != SplitRule::Tolerance) return;
  const gpu::ClassifyPush params = classifyParams(options, uint32_t(nodes.size()));
  const float up = std::numeric_limits<float>::infinity();
  revised_.clear();
  for (size_t i = 0; i < nodes.size(); ++i)
    if (rewritesWhole(groupFirst() + nodes[i].patchIndex, options)) revised_.push_back(i);
  // Each node's decision is its own: on all threads where there are enough of them (on one,
  // the IDF library's cylinders, cones and spheres were a quarter to 40% of the CPU tree's time).
  const auto decide = [&](size_t i) {
    const Patch& patch = patches_[groupFirst() + nodes[i].patchIndex];
    const gpu::vec4& r = nodes[i].rect;
    const RevolutionBound bound =
        revolutionNodeBound(*patch.form, *patch.surface, patch.piece, glm::dvec4(r));
    // Rule T's decision reads (M_ss + 2·M_st + M_tt)/8 + guard: the azimuth term as the u part
    // and the profile term as the v part, each ×8, in the tree's local units, rounded up to fp32.
    gpu::vec4 terms(kUnbounded, 0.0f, kUnbounded, 0.0f);
    if (bound.valid)
      terms = {std::nextafter(float(8.0 * bound.azimuth / scale_), up), 0.0f,
               std::nextafter(float(8.0 * bound.profile / scale_), up),
               std::nextafter(float(bound.guard / scale_), up)};
    decisions[i] = mirror::toleranceDecisionOf(terms, nodes[i], params);
  };
  parallelForChunks(revised_.size(), kNodesPerTurn,
                    threadsForChunks(revised_.size(), kNodesPerTurn, threads_),
                    [&](size_t begin, size_t end) {
                      for (size_t k = begin; k < end; ++k) decide(revised_[k]);
                    });
  decided_ += revised_.size();
}

}  // namespace tessera
