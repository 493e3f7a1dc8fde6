// Where rule T's triangles go (docs/quadtree.md, "Where the triangles are"): a leaf whose ring
// has n vertices gives n − 2 triangles, so a mesh is 2 per leaf plus one per extra ring vertex
// (a corner of a neighbour split otherwise in the same patch, or a point a shared side inherits
// from the other patch), less one a leaf at a pole (its two corners there are one vertex).
// Counted per patch from the tree alone and checked against the triangulator: the issue's
// 0.5× OCCT at δ = 0.001 needs the extras gone, so where they sit is printed too.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <tuple>
#include <vector>

#include "io/bpt_reader.h"
#include "mesh/shared_edges.h"
#include "mesh/side_fold.h"
#include "mesh/tessellate.h"
#include "quadtree/quadtree.h"

using namespace tessera;

namespace {

constexpr float kSamePoint = 0x1p-20f;

struct ExtraVertices {
  size_t inPatch = 0;   // corners of the same patch's leaves strictly inside a leaf's side
  size_t fromSeam = 0;  // points of the other patch's leaves on a shared side
  size_t atPoles = 0;   // leaves with a side collapsed to a point
  std::map<int, size_t> at;  // in-patch extras by their position along the side, in %
  std::vector<size_t> expected;  // per patch: 2 a leaf + its extras − its leaves at poles
};

// Whether one of the patch's unshared sides folds back over itself (side_fold.h): its leaf
// corners get images on the other strand, vertices this count does not follow.
bool hasFoldedSide(const BezierPatch& patch, const PatchTopology& topology, uint32_t p) {
  for (int side : {kSideV0, kSideU1, kSideV1, kSideU0}) {
    const SideInfo& s = topology.sides[p][side];
    if (s.group < 0 && !s.collapsed && findSideFold(sideControlPoints(patch, side))) return true;
  }
  return false;
}

// The extra ring vertices of every leaf, found from the leaves' rectangles as the
// triangulator's line indices find them; of its near-point merges (near_points.h) only those
// of a shared side's two parametrisations, the only ones on the tea set.
ExtraVertices extraVertices(const std::vector<QuadLeaf>& leaves, const PatchTopology& topology,
                            size_t patchCount) {
  // (patch, line) → sorted corners on it; a line v = c keyed with u = 0, a line u = c with 1.
  std::map<std::tuple<uint32_t, int, float>, std::vector<float>> lines;
  std::map<std::pair<uint32_t, int>, std::set<float>> ownOnSide;  // canonical t, per side
  std::map<int32_t, std::set<float>> onGroup;                       // canonical t, per group
  for (const QuadLeaf& leaf : leaves)
    for (float v : {leaf.rect.y, leaf.rect.w})
      for (float u : {leaf.rect.x, leaf.rect.z}) {
        lines[{leaf.patchIndex, 0, v}].push_back(u);
        lines[{leaf.patchIndex, 1, u}].push_back(v);
        for (int side : {kSideV0, kSideU1, kSideV1, kSideU0}) {
          const bool alongU = side == kSideV0 || side == kSideV1;
          const float fixed = alongU ? v : u, t = alongU ? u : v;
          if (fixed != (side == kSideV0 || side == kSideU0 ? 0.0f : 1.0f)) continue;
          const SideInfo& s = topology.sides[leaf.patchIndex][side];
          if (s.group < 0) continue;
          const float c = s.reversed ? 1.0f - t : t;
          ownOnSide[{leaf.patchIndex, side}].insert(c);
          onGroup[s.group].insert(c);
        }
      }
  for (auto& [key, points] : lines) {
    std::sort(points.begin(), points.end());
    points.erase(std::unique(points.begin(), points.end()), points.end());
  }
  ExtraVertices extras;
  extras.expected.assign(patchCount, 0);
  for (const QuadLeaf& leaf : leaves) {
    const size_t before = extras.inPatch + extras.fromSeam;
    bool atPole = false;
    const gpu::vec4& r = leaf.rect;
    struct Side {
      int direction;  // 0: along u on the line v = fixed; 1: along v on u = fixed
      float fixed, lo, hi;
      int patchSide;  // the patch's side it lies on, or -1
    };
    const Side sides[4] = {{0, r.y, r.x, r.z, r.y == 0.0f ? int(kSideV0) : -1},
                           {0, r.w, r.x, r.z, r.w == 1.0f ? int(kSideV1) : -1},
                           {1, r.x, r.y, r.w, r.x == 0.0f ? int(kSideU0) : -1},
                           {1, r.z, r.y, r.w, r.z == 1.0f ? int(kSideU1) : -1}};
    for (const Side& side : sides) {
      const SideInfo* shared = side.patchSide >= 0 ? &topology.sides[leaf.patchIndex][side.patchSide] : nullptr;
      if (shared && shared->collapsed) {  // one vertex: nothing inside it
        atPole = true;
        continue;
      }
      const std::vector<float>& line = lines.at({leaf.patchIndex, side.direction, side.fixed});
      for (auto it = std::upper_bound(line.begin(), line.end(), side.lo);
           it != line.end() && *it < side.hi; ++it) {
        ++extras.inPatch;
        ++extras.at[int(std::lround(100.0 * (*it - side.lo) / (side.hi - side.lo)))];
      }
      if (!shared || shared->group < 0) continue;
      float c0 = shared->reversed ? 1.0f - side.lo : side.lo;
      float c1 = shared->reversed ? 1.0f - side.hi : side.hi;
      if (c0 > c1) std::swap(c0, c1);
      const std::set<float>& own = ownOnSide.at({leaf.patchIndex, side.patchSide});
      const std::set<float>& all = onGroup.at(shared->group);
      // 1 − t need not give back the other side's t bit for bit: points closer than
      // kSamePoint are one vertex (the triangulator merges them, near_points.h).
      const auto near = [&own](float c) {
        auto it = own.lower_bound(c - kSamePoint);
        return it != own.end() && *it <= c + kSamePoint;
      };
      float previous = c0;
      for (auto it = all.upper_bound(c0 + kSamePoint); it != all.end() && *it < c1 - kSamePoint; ++it) {
        extras.fromSeam += !near(*it) && *it - previous > kSamePoint;
        previous = *it;
      }
    }
    extras.atPoles += atPole;
    extras.expected[leaf.patchIndex] += 2 + (extras.inPatch + extras.fromSeam - before) - atPole;
  }
  return extras;
}

}  // namespace

TEST_CASE("rule T: triangles are 2 a leaf plus one a neighbour's extra vertex", "[tolerance][extras]") {
  Backend backend = makeMirrorBackend();
  for (const char* name : {"teapot", "teacup", "teaspoon"}) {
    const auto patches = readBpt(std::string(TESSERA_SOURCE_DIR "/data/") + name + ".bpt");
    const PatchTopology topology = findSharedEdges(patches);
    for (double delta : {1e-2, 1e-3}) {
      const Tessellation t = tessellate(patches, toleranceOptions(delta), backend);
      const std::vector<QuadLeaf>& leaves = t.tree.leaves;
      const ExtraVertices extras = extraVertices(leaves, topology, patches.size());
      std::ostringstream positions;
      for (const auto& [percent, count] : extras.at) positions << " " << percent << "%:" << count;
      WARN(name << " at δ = " << delta << ": " << leaves.size() << " leaves, "
                << t.stats.triangles << " triangles: 2 a leaf + " << extras.inPatch
                << " corners of neighbours + " << extras.fromSeam << " seam points − "
                << extras.atPoles << " leaves at poles; neighbours' corners at"
                << positions.str() << " of the side");
      CHECK(t.stats.diagonalFans == 0);
      for (const QuadLeaf& leaf : leaves) REQUIRE(leaf.cause == gpu::kCauseWithinTolerance);
      // Every leaf's ring triangulated without a new vertex: n − 2 triangles a ring.
      std::vector<size_t> triangles(patches.size(), 0);
      for (uint32_t p : t.trianglePatch) ++triangles[p];
      size_t folded = 0, counted = 0;
      for (uint32_t p = 0; p < patches.size(); ++p) {
        if (hasFoldedSide(patches[p], topology, p)) {
          ++folded;
          continue;
        }
        INFO("patch " << p);
        CHECK(triangles[p] == extras.expected[p]);
        counted += triangles[p];
      }
      CHECK(folded <= 1);  // the teaspoon's handle tip (docs/watertight.md)
      CHECK(counted * 10 >= t.stats.triangles * 9);  // all but that one patch
    }
  }
}
