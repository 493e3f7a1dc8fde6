// The edges' memory bound (host/cad/edge_samples.h, docs/hardening.md): a tolerance far below a
// model's size stops with MemoryLimitError before its samples fill memory, on a circle before
// the samples are made and in a bisection within a few thousand of the budget; and a bisection
// stops where the measured deviation is the points' own rounding.
#include <catch2/catch.hpp>

#include <BRepBuilderAPI_MakeEdge.hxx>
#include <Geom_BSplineCurve.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array1OfPnt.hxx>
#include <TopoDS_Edge.hxx>
#include <gp_Ax2.hxx>
#include <gp_Circ.hxx>
#include <gp_Elips.hxx>
#include <string>

#include "cad/edge_samples.h"
#include "common/memory_budget.h"

using namespace tessera;

namespace {

// Sets the process's memory budget for one test, restores it after.
struct BudgetFor {
  uint64_t saved = memoryBudget();
  explicit BudgetFor(uint64_t bytes) { setMemoryBudget(bytes); }
  ~BudgetFor() { setMemoryBudget(saved); }
};

void requireStopsAtBudget(const TopoDS_Edge& edge, double delta) {
  const BudgetFor budget(1ull << 20);  // 1 MiB: 5,461 samples at 192 bytes
  EdgeSampleBudget samples(delta);
  try {
    discretiseEdge(edge, delta, 0, 1, &samples);
    FAIL("the edge was discretised at δ = " << delta << " within 1 MiB");
  } catch (const MemoryLimitError& e) {
    const std::string text = e.what();
    INFO(text);
    CHECK(text.find("the discretisation of the B-rep edges at δ = ") == 0);
    CHECK(text.find("more than the memory budget of 1.00 MiB") != std::string::npos);
    CHECK(text.find("--memory-budget") != std::string::npos);
  }
}

}  // namespace

TEST_CASE("cad edges: a circle past the memory budget stops before its samples are made",
          "[cad][memory]") {
  const TopoDS_Edge circle = BRepBuilderAPI_MakeEdge(gp_Circ(gp_Ax2(), 1.0));
  requireStopsAtBudget(circle, 1e-14);   // ~2·10⁷ samples
  requireStopsAtBudget(circle, 1e-300);  // infinitely many: the count saturates, no overflow
  // Within the budget the same edge discretises as before: the fewest equal sagittas ≤ δ.
  const BudgetFor budget(1ull << 20);
  const EdgeSamples coarse = discretiseEdge(circle, 1e-3, 0, 1);
  CHECK(coarse.params.size() == 71 + 1);  // 2π / (2 acos(1 − 10⁻³)) = 70.2 → 71 segments
  CHECK(coarse.maxChordDeviation <= 1e-3);
}

TEST_CASE("cad edges: a bisection past the memory budget stops", "[cad][memory]") {
  const TopoDS_Edge ellipse = BRepBuilderAPI_MakeEdge(gp_Elips(gp_Ax2(), 2.0, 1.0));
  requireStopsAtBudget(ellipse, 1e-12);
}

// A straight cubic B-spline (collinear poles, uneven speed): in exact arithmetic it never leaves
// its chords, so the measured deviation is rounding alone. At δ = 10⁻³⁰⁰ the bisection used to
// halve every segment to its depth limit (4 · 2²⁴ samples); now it keeps the first four.
TEST_CASE("cad edges: a bisection stops at the points' rounding", "[cad][memory]") {
  TColgp_Array1OfPnt poles(1, 4);
  poles(1) = gp_Pnt(0.1, 0.2, 0.3);
  poles(2) = gp_Pnt(0.1 + 0.7, 0.2 + 1.4, 0.3 + 2.1);
  poles(3) = gp_Pnt(0.1 + 0.9, 0.2 + 1.8, 0.3 + 2.7);
  poles(4) = gp_Pnt(0.1 + 3.0, 0.2 + 6.0, 0.3 + 9.0);
  TColStd_Array1OfReal knots(1, 2);
  knots(1) = 0.0, knots(2) = 1.0;
  TColStd_Array1OfInteger multiplicities(1, 2);
  multiplicities(1) = multiplicities(2) = 4;
  const Handle(Geom_BSplineCurve) line = new Geom_BSplineCurve(poles, knots, multiplicities, 3);
  const TopoDS_Edge edge = BRepBuilderAPI_MakeEdge(line);
  const BudgetFor budget(64ull << 20);
  const EdgeSamples samples = discretiseEdge(edge, 1e-300, 0, 1);
  INFO("largest measured deviation " << samples.maxChordDeviation);
  CHECK(samples.params.size() == 5);
  CHECK(samples.maxChordDeviation < 1e-12);
}
