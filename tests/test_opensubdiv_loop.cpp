// Our Loop subdivision against OpenSubdiv itself (Far, scheme LOOP, PrimvarRefinerReal<double>):
// refined positions at levels 1–4 and limit points (PrimvarRefiner::Limit on level 4) agree
// within 1e-6 relative to the mesh size on closed meshes, an open grid with single-triangle
// corners, and meshes with creases, darts and a marked corner. OpenSubdiv's options that match
// docs/loop.md are in host/osd/osd_loop.h.
#include <catch2/catch.hpp>

#include <opensubdiv/far/primvarRefiner.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>

#include "io/obj_reader.h"
#include "scratch_dir.h"

#include "loop/limit.h"
#include "loop/shapes.h"
#include "osd/osd_loop.h"

using namespace tessera;

namespace {

constexpr int kLevels = 4;

double extent(const std::vector<glm::dvec3>& p) {
  glm::dvec3 lo(1e300), hi(-1e300);
  for (const auto& q : p) lo = glm::min(lo, q), hi = glm::max(hi, q);
  return glm::length(hi - lo);
}

struct OsdResult {
  std::vector<std::vector<osd::Point>> levels;  // OpenSubdiv's numbering
  std::vector<osd::Point> limit, tangent1, tangent2;  // of the last level's vertices
  std::vector<std::vector<uint32_t>> ours;      // our index of each of its vertices
};

OsdResult refineWithOpenSubdiv(const LoopShape& s, const LoopLevels& ours,
                               osd::BoundaryRule boundary) {
  auto refiner = osd::makeLoopRefiner(s.topology, boundary);
  osd::TopologyRefiner::UniformOptions uniform(kLevels);
  uniform.fullTopologyInLastLevel = true;  // Limit() needs the last level's rings
  refiner->RefineUniform(uniform);
  OsdResult r;
  r.levels.resize(kLevels + 1);
  for (const auto& p : s.positions) r.levels[0].push_back({p.x, p.y, p.z});
  OpenSubdiv::Far::PrimvarRefinerReal<double> primvar(*refiner);
  for (int l = 1; l <= kLevels; ++l) {
    r.levels[l].resize(refiner->GetLevel(l).GetNumVertices());
    const osd::Point* src = r.levels[l - 1].data();
    osd::Point* dst = r.levels[l].data();
    primvar.Interpolate(l, src, dst);
  }
  const size_t last = r.levels[kLevels].size();
  r.limit.resize(last);
  r.tangent1.resize(last);
  r.tangent2.resize(last);
  const osd::Point* src = r.levels[kLevels].data();
  osd::Point *limit = r.limit.data(), *tangent1 = r.tangent1.data(), *tangent2 = r.tangent2.data();
  primvar.Limit(src, limit, tangent1, tangent2);
  r.ours = osd::matchVertices(*refiner, ours.topology);
  return r;
}

double worstDifference(const std::vector<osd::Point>& theirs, const std::vector<uint32_t>& map,
                       const std::vector<glm::dvec3>& ours) {
  double worst = 0;
  for (size_t i = 0; i < theirs.size(); ++i)
    worst = std::max(worst, glm::length(glm::dvec3(theirs[i].x, theirs[i].y, theirs[i].z) -
                                        ours[map[i]]));
  return worst;
}

}  // namespace

TEST_CASE("Loop refinement and limit points agree with OpenSubdiv", "[loop][opensubdiv]") {
  for (const LoopShape& s : {loopIcosphere(3), loopTorus(12, 8, 0.08, 5), loopBunny(3, 11),
                             loopGrid(7, 6, 2), loopCreasedSphere(2, 4), loopCreasedCube()}) {
    INFO(s.name);
    LoopLevels ours = refineLoop(buildLoopTopology(s.topology), s.positions, kLevels);
    OsdResult theirs =
        refineWithOpenSubdiv(s, ours, OpenSubdiv::Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER);
    const double size = extent(s.positions);
    double worstLevel = 0;
    for (int l = 1; l <= kLevels; ++l) {
      REQUIRE(theirs.levels[l].size() == ours.positions[l].size());
      worstLevel = std::max(worstLevel, worstDifference(theirs.levels[l], theirs.ours[l],
                                                        ours.positions[l]) / size);
    }
    const LoopTopology& last = ours.topology.back();
    const auto limit = loopLimitPositions(last, ours.positions.back());
    const double worstLimit = worstDifference(theirs.limit, theirs.ours[kLevels], limit) / size;
    // Normals from the tangents (OpenSubdiv's tangent masks, which ours copy). An interior
    // crease or corner vertex has one normal per side, and each of us picks the side by its own
    // ring order: those are left out (and counted).
    const auto normals = loopLimitNormals(last, ours.positions.back());
    double worstNormal = 0;
    size_t twoSided = 0;
    for (size_t i = 0; i < theirs.limit.size(); ++i) {
      const uint32_t v = theirs.ours[kLevels][i];
      const LoopVertexRule rule = last.vertexRule[v];
      if (!last.vertexBoundary[v] && (rule == LoopVertexRule::Crease || rule == LoopVertexRule::Corner)) {
        ++twoSided;
        continue;
      }
      const glm::dvec3 t1(theirs.tangent1[i].x, theirs.tangent1[i].y, theirs.tangent1[i].z);
      const glm::dvec3 t2(theirs.tangent2[i].x, theirs.tangent2[i].y, theirs.tangent2[i].z);
      const glm::dvec3 n = glm::normalize(glm::cross(t1, t2));
      REQUIRE(std::isfinite(n.x + n.y + n.z));
      worstNormal = std::max(worstNormal, glm::length(n - normals[v]));
    }
    WARN(s.name << " vs OpenSubdiv: refined levels 1-" << kLevels << " differ by at most "
                << worstLevel << " × size, limit points by " << worstLimit
                << ", limit normals by " << worstNormal << " (" << twoSided
                << " two-sided crease/corner vertices left out)");
    REQUIRE(worstLevel < 1e-6);
    REQUIRE(worstLimit < 1e-6);
    REQUIRE(worstNormal < 1e-6);
  }
}

TEST_CASE("OpenSubdiv's VTX_BOUNDARY_EDGE_ONLY differs from our rules exactly at the corners",
          "[loop][opensubdiv]") {
  // With EDGE_ONLY a boundary vertex of one triangle is a crease vertex, not a corner: the grid's
  // two single-triangle corners move, and everything else matches.
  LoopShape s = loopGrid(7, 6, 2);
  LoopLevels ours = refineLoop(buildLoopTopology(s.topology), s.positions, kLevels);
  OsdResult theirs =
      refineWithOpenSubdiv(s, ours, OpenSubdiv::Sdc::Options::VTX_BOUNDARY_EDGE_ONLY);
  const auto& level1 = theirs.levels[1];
  int moved = 0;
  for (size_t i = 0; i < level1.size(); ++i) {
    const uint32_t v = theirs.ours[1][i];
    const double d = glm::length(glm::dvec3(level1[i].x, level1[i].y, level1[i].z) -
                                 ours.positions[1][v]);
    if (d > 1e-12) {
      ++moved;
      REQUIRE(v < s.topology.vertexCount);
      REQUIRE(ours.topology[0].vertexRule[v] == LoopVertexRule::Corner);
    }
  }
  REQUIRE(moved == 2);
}

TEST_CASE("LoopBoundary::EdgeOnly agrees with OpenSubdiv's VTX_BOUNDARY_EDGE_ONLY",
          "[loop][opensubdiv]") {
  // The grid has two boundary vertices of a single triangle; with EdgeOnly they are crease
  // vertices on both sides, and every level and the limit points and normals must agree.
  LoopShape s = loopGrid(7, 6, 2);
  s.topology.boundary = LoopBoundary::EdgeOnly;
  const LoopTopology base = buildLoopTopology(s.topology);
  size_t singleTriangleCorners = 0;
  for (uint32_t v = 0; v < base.vertexCount; ++v)
    if (base.vertexBoundary[v] && base.faceValence(v) == 1) {
      ++singleTriangleCorners;
      REQUIRE(base.vertexRule[v] == LoopVertexRule::Crease);
    }
  REQUIRE(singleTriangleCorners == 2);
  LoopLevels ours = refineLoop(base, s.positions, kLevels);
  REQUIRE(ours.topology.back().boundary == LoopBoundary::EdgeOnly);
  OsdResult theirs = refineWithOpenSubdiv(s, ours, osd::osdBoundaryRule(s.topology.boundary));
  const double size = extent(s.positions);
  double worstLevel = 0;
  for (int l = 1; l <= kLevels; ++l)
    worstLevel = std::max(worstLevel, worstDifference(theirs.levels[l], theirs.ours[l],
                                                      ours.positions[l]) / size);
  const LoopTopology& last = ours.topology.back();
  const auto limit = loopLimitPositions(last, ours.positions.back());
  const double worstLimit = worstDifference(theirs.limit, theirs.ours[kLevels], limit) / size;
  const auto normals = loopLimitNormals(last, ours.positions.back());
  double worstNormal = 0;
  for (size_t i = 0; i < theirs.limit.size(); ++i) {
    const glm::dvec3 t1(theirs.tangent1[i].x, theirs.tangent1[i].y, theirs.tangent1[i].z);
    const glm::dvec3 t2(theirs.tangent2[i].x, theirs.tangent2[i].y, theirs.tangent2[i].z);
    worstNormal = std::max(worstNormal, glm::length(glm::normalize(glm::cross(t1, t2)) -
                                                    normals[theirs.ours[kLevels][i]]));
  }
  // The rule matters: under EdgeAndCorner the two corners stay where they are.
  LoopShape cornered = s;
  cornered.topology.boundary = LoopBoundary::EdgeAndCorner;
  const LoopLevels kept = refineLoop(buildLoopTopology(cornered.topology), s.positions, 1);
  double cornerMoved = 0;
  for (uint32_t v = 0; v < base.vertexCount; ++v)
    cornerMoved = std::max(cornerMoved, glm::length(kept.positions[1][v] - ours.positions[1][v]));
  WARN("EdgeOnly vs OpenSubdiv EDGE_ONLY on " << s.name << ": levels 1-" << kLevels << " "
                                              << worstLevel << " × size, limit points "
                                              << worstLimit << ", normals " << worstNormal
                                              << "; EdgeAndCorner moves level 1 by up to "
                                              << cornerMoved);
  REQUIRE(worstLevel < 1e-12);
  REQUIRE(worstLimit < 1e-12);
  REQUIRE(worstNormal < 1e-9);
  REQUIRE(cornerMoved > 1e-3 * size);
}

namespace {

void writeControlObj(const std::string& path, const LoopShape& s) {
  std::ofstream out(path);
  out << std::setprecision(17);
  for (const auto& p : s.positions) out << "v " << p.x << ' ' << p.y << ' ' << p.z << '\n';
  for (size_t t = 0; t < s.topology.triangles.size(); t += 3)
    out << "f " << s.topology.triangles[t] + 1 << ' ' << s.topology.triangles[t + 1] + 1 << ' '
        << s.topology.triangles[t + 2] + 1 << '\n';
}

// `tessera limit` on `s` at kLevels, the output read back: the limit positions in our numbering.
std::vector<glm::dvec3> limitThroughCli(const LoopShape& s, const std::string& extraOptions) {
  test::ScratchDir dir("osd_cli");
  const std::string in = (dir.path / "control.obj").string();
  const std::string out = (dir.path / "limit.obj").string();
  writeControlObj(in, s);
  const std::string command = std::string(TESSERA_BINARY_DIR) + "/tessera limit " + in + " -l " +
                              std::to_string(kLevels) + " --backend cpu " + extraOptions + " -o " +
                              out + " > /dev/null";
  REQUIRE(std::system(command.c_str()) == 0);
  return readObj(out).positions;
}

}  // namespace

TEST_CASE("tessera limit --precision double matches OpenSubdiv as the library does",
          "[loop][opensubdiv][cli]") {
  // The CLI's fp32 output holds about 7 digits; with --precision double it carries the
  // double stencils' result, which agrees with PrimvarRefinerReal<double> to rounding.
  const LoopShape s = loopBunny(2, 5);
  LoopLevels ours = refineLoop(buildLoopTopology(s.topology), s.positions, kLevels);
  OsdResult theirs =
      refineWithOpenSubdiv(s, ours, OpenSubdiv::Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER);
  const double size = extent(s.positions);
  const auto inFloat = limitThroughCli(s, "");
  const auto inDouble = limitThroughCli(s, "--precision double");
  REQUIRE(inFloat.size() == theirs.limit.size());
  REQUIRE(inDouble.size() == theirs.limit.size());
  const double worstFloat = worstDifference(theirs.limit, theirs.ours[kLevels], inFloat) / size;
  const double worstDouble = worstDifference(theirs.limit, theirs.ours[kLevels], inDouble) / size;
  WARN("tessera limit -l " << kLevels << " vs OpenSubdiv's limit points, × size: fp32 output "
                           << worstFloat << ", --precision double " << worstDouble);
  REQUIRE(worstDouble < 1e-14);
  REQUIRE(worstFloat > 1e-9);  // the fp32 output really is rounded: the option matters
}

TEST_CASE("tessera limit --boundary edge matches OpenSubdiv's VTX_BOUNDARY_EDGE_ONLY",
          "[loop][opensubdiv][cli]") {
  LoopShape s = loopGrid(7, 6, 2);
  s.topology.boundary = LoopBoundary::EdgeOnly;
  LoopLevels ours = refineLoop(buildLoopTopology(s.topology), s.positions, kLevels);
  OsdResult theirs = refineWithOpenSubdiv(s, ours, OpenSubdiv::Sdc::Options::VTX_BOUNDARY_EDGE_ONLY);
  const double size = extent(s.positions);
  const auto edge = limitThroughCli(s, "--precision double --boundary edge");
  const auto corner = limitThroughCli(s, "--precision double");
  const double worstEdge = worstDifference(theirs.limit, theirs.ours[kLevels], edge) / size;
  const double worstCorner = worstDifference(theirs.limit, theirs.ours[kLevels], corner) / size;
  WARN("tessera limit on " << s.name << " vs OpenSubdiv EDGE_ONLY, × size: --boundary edge "
                           << worstEdge << ", the default (corner) " << worstCorner);
  REQUIRE(worstEdge < 1e-14);
  REQUIRE(worstCorner > 1e-3);
}
