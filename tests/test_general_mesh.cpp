// Meshes of rational patches (general path): closed surfaces of rational biquadratic patches
// (torus; sphere with collapsed poles) tessellate to closed, consistently oriented 2-manifolds
// with no degenerate triangles, their shared boundaries found by points and weights; the
// quarter cylinder's tessellation lies on the cylinder within the bound the flatness implies.
#include <catch2/catch.hpp>

#include <cmath>

#include "mesh/deviation.h"
#include "general_samples.h"
#include "mesh_checks.h"
#include "mesh/shared_edges.h"
#include "mesh/tessellate.h"

using namespace tessera;

namespace {

// A leaf passes only if normals across it turn by less than θ = acos(1 − flatness); a
// circular arc of chord h turning by θ deviates from its chord by (h/2)·tan(θ/4)
// (test_watertight.cpp). `chord` bounds h for the shape.
double arcBound(float flatness, double chord) {
  return 0.5 * chord * std::tan(std::acos(1.0 - flatness) / 4.0);
}

void checkClosed(const std::vector<BezierPatch>& patches, long eulerExpected, double chord,
                 const char* what) {
  Backend cpu = makeMirrorBackend();
  for (SplitRule rule : {SplitRule::Midpoint, SplitRule::SampledMax, SplitRule::TrueMax})
    for (float threshold : {0.1f, 0.03f}) {
      QuadtreeOptions o;
      o.rule = rule;
      o.linearity = o.flatness = threshold;
      Tessellation t = tessellate(patches, o, cpu);
      test::EdgeCensus c = test::censusOf(t.mesh, 1e-12);
      DeviationReport dev = measureDeviation(t, patches);
      long euler = long(c.usedVertices) - long(c.undirected.size()) + long(t.mesh.triangleCount());
      WARN(what << " rule " << splitRuleLetter(rule) << " at " << threshold << ": "
                << t.mesh.triangleCount() << " triangles, " << c.boundaryEdges << " open, "
                << c.overusedEdges << " over-used, " << c.inconsistentEdges
                << " inconsistent edges, " << c.degenerateTriangles
                << " degenerate triangles, Euler " << euler << ", max deviation "
                << dev.maxDeviation << " (bound " << arcBound(threshold, chord) << ")");
      REQUIRE(c.boundaryEdges == 0);
      REQUIRE(c.overusedEdges == 0);
      REQUIRE(c.inconsistentEdges == 0);
      REQUIRE(c.degenerateTriangles == 0);
      REQUIRE(euler == eulerExpected);
      REQUIRE(dev.maxDeviation <= arcBound(threshold, chord));
      for (const auto& n : t.mesh.normals) REQUIRE(std::fabs(glm::length(n) - 1.0f) < 1e-5f);
    }
}

}  // namespace

TEST_CASE("rational patches share boundaries by points and weights", "[watertight][general]") {
  PatchTopology torus = findSharedEdges(test::rationalTorus(2.0, 0.7));
  REQUIRE(torus.sharedSides == 64);
  REQUIRE(torus.groupCount == 32);
  PatchTopology sphere = findSharedEdges(test::rationalSphere(1.0));
  REQUIRE(sphere.collapsedSides == 8);  // every patch has one side at a pole
  REQUIRE(sphere.sharedSides == 24);
  // The same points with other weights are another curve: not shared.
  auto changed = test::rationalTorus(2.0, 0.7);
  for (double& w : changed[0].weights) w *= 2.0;
  REQUIRE(findSharedEdges(changed).sharedSides == 64 - 8);  // its 4 sides and their partners
}

TEST_CASE("a rational torus tessellates closed and consistently oriented",
          "[watertight][general]") {
  checkClosed(test::rationalTorus(2.0, 0.7), 0, (2.0 + 0.7) * std::sqrt(2.0),  // outer quarter
              "rational torus");
}

TEST_CASE("a rational sphere with collapsed poles tessellates closed", "[watertight][general]") {
  checkClosed(test::rationalSphere(1.0), 2, 2.0, "rational sphere");
}

TEST_CASE("a rational quarter cylinder's tessellation lies on the cylinder",
          "[watertight][general]") {
  Backend cpu = makeMirrorBackend();
  for (float flatness : {0.1f, 0.01f}) {
    QuadtreeOptions o;
    o.rule = SplitRule::Midpoint;
    o.linearity = o.flatness = flatness;
    Tessellation t = tessellate({test::rationalQuarterCylinder(1.0, 1.0)}, o, cpu);
    double vertexOff = 0, midOff = 0;
    for (const auto& p : t.mesh.positions)
      vertexOff = std::max(vertexOff, std::fabs(std::hypot(double(p.x), double(p.y)) - 1.0));
    // Every edge's midpoint lies inside the cylinder by at most the chord's sagitta.
    for (size_t k = 0; k < t.mesh.indices.size(); ++k) {
      const glm::dvec3 a(t.mesh.positions[t.mesh.indices[k]]);
      const glm::dvec3 b(t.mesh.positions[t.mesh.indices[k - k % 3 + (k + 1) % 3]]);
      const glm::dvec3 m = 0.5 * (a + b);
      midOff = std::max(midOff, std::fabs(std::hypot(m.x, m.y) - 1.0));
    }
    const double bound = arcBound(flatness, std::sqrt(2.0));
    WARN("quarter cylinder at " << flatness << ": " << t.mesh.triangleCount()
         << " triangles, vertices off the cylinder by " << vertexOff
         << ", edge midpoints by " << midOff << " (bound " << bound << ")");
    REQUIRE(vertexOff <= 1e-6);
    REQUIRE(midOff <= bound);
    REQUIRE(midOff > 0.0);  // the chords do cut inside: the measurement sees something
  }
}
