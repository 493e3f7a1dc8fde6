#include "mesh/triangulate.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <map>
#include <stdexcept>
#include <unordered_map>

#include "common/hash_map.h"
#include "common/parallel_for.h"
#include "geometry/bezier.h"
#include "mesh/line_index.h"
#include "mesh/near_points.h"
#include "mesh/ring_triangulation.h"
#include "mesh/shared_edges.h"
#include "mesh/side_fold.h"

namespace tessera {
namespace {

uint32_t bits(float x) {
  uint32_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

enum KeyKind : uint32_t { kPatchParam, kEdgeParam, kPosition, kFoldPosition };

struct VertexKey {
  uint32_t kind;
  uint32_t a;  // patch, edge group, position id, or folded side
  uint64_t b;  // (u bits, v bits), canonical t bits, 0, or the position along the fold's line
  bool operator==(const VertexKey& o) const { return kind == o.kind && a == o.a && b == o.b; }
};

struct VertexKeyHash {
  size_t operator()(const VertexKey& k) const {
    uint64_t h = (uint64_t(k.kind) << 32 | k.a) * 0x9E3779B97F4A7C15ull;
    return size_t(h ^ (k.b + 0x632BE59BD9B4E019ull + (h << 6) + (h >> 2)));
  }
};

struct PositionBitsHash {
  size_t operator()(const std::array<uint64_t, 3>& k) const {
    return size_t(k[0] * 0x9E3779B97F4A7C15ull ^ k[1] * 0xC2B2AE3D27D4EB4Full ^
                  (k[2] ^ k[2] >> 29) * 0x165667B19E3779F9ull);
  }
};

// The lines a node-based line index was sized for, per leaf (LineIndex::unorderedMapOrder).
constexpr size_t kLineIndexReserve = 2;

// The corners of a line merged into another point of it, sorted by t, with that point's t.
using MovedCorners = std::vector<std::pair<float, float>>;

// Where on its line the vertex of the corner at t lies.
float movedTo(const MovedCorners& moved, float t) {
  if (moved.empty()) return t;
  auto it = std::lower_bound(moved.begin(), moved.end(), std::pair<float, float>(t, -INFINITY));
  return it != moved.end() && it->first == t ? it->second : t;
}

float fromBits(uint32_t b) {
  float x;
  std::memcpy(&x, &b, sizeof x);
  return x;
}

uint64_t lineKey(uint32_t patch, float coordinate) { return (uint64_t(patch) << 32) | bits(coordinate); }

void sortUnique(std::vector<float>& values) {
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
}

// Positions strictly between lo and hi (lo < hi), ascending.
void between(const std::vector<LinePoint>* points, float lo, float hi, std::vector<float>& out) {
  out.clear();
  if (!points) return;
  // One search: a leaf edge has few points inside, most often none.
  auto first = std::upper_bound(points->begin(), points->end(), lo,
                                [](float t, const LinePoint& p) { return t < p.t; });
  for (; first != points->end() && first->t < hi; ++first) out.push_back(first->t);
}

class Triangulator {
 public:
  Triangulator(const std::vector<QuadLeaf>& leaves, const std::vector<BezierPatch>& patches,
               const TriangulationScope& scope)
      : leaves_(leaves),
        patches_(patches),
        scope_(scope),
        ownTopology_(scope.topology ? PatchTopology{} : findSharedEdges(patches)),
        topology_(scope.topology ? *scope.topology : ownTopology_),
        alongU_(leaves.size() / 4),
        alongV_(leaves.size() / 4) {
    index_.reserve(leaves.size() * 3 / 2);
    mesh_.sharedEdgeGroups = topology_.groupCount;
    sharedLines_.resize(topology_.groupCount);
    groupSide_.assign(topology_.groupCount, {0, -1});
    mesh_.vertices.reserve(leaves_.size() * 3 / 2);
    mesh_.indices.reserve(leaves_.size() * 8);
    mesh_.trianglePatch.reserve(leaves_.size() * 8 / 3);
    mesh_.cornerUv.reserve(leaves_.size() * 8);
    findFolds();
    collectLinePoints();
    for (uint32_t f = 0; f < folds_.size(); ++f) placeFoldPoints(f);
    mergeNearPoints();
    listRepresentatives();
  }


  // Leaves outside the scope are walked too, without triangles: their vertices are met in
  // the same order as in the whole mesh, so a shared vertex takes the same patch's (u, v).
  // The walk reads the line indices, merges and folds only, so runs of leaves are walked on
  // several threads (LeafRun); their vertices are then numbered in leaf order, as one walk
  // would have numbered them, so the mesh does not depend on the thread count.
  ParamMesh run() {
    registerPositions();
    walking_ = true;
    const size_t runLength = 512;
    std::vector<LeafRun> runs((leaves_.size() + runLength - 1) / runLength);
    parallelForChunks(leaves_.size(), runLength, scope_.threads, [&](size_t begin, size_t end) {
      LeafWork work;
      work.out = &runs[begin / runLength];
      // About a vertex query per leaf corner and edge point, and two triangles, per leaf.
      work.out->queries.reserve(10 * (end - begin));
      work.out->triangles.reserve(3 * (end - begin));
      for (size_t l = begin; l < end; ++l) {
        const QuadLeaf& leaf = leaves_[l];
        work.silent = leaf.patchIndex < scope_.firstPatch || leaf.patchIndex >= scope_.endPatch;
        triangulateLeaf(leaf, work);
      }
      work.out->findFirsts();
    });
    // A key's first query in leaf order is its first query in the first run that has it: the
    // runs' first queries, run by run, meet the keys in the order one walk would.
    size_t triangles = 0;
    std::vector<size_t> firstTriangle(runs.size());
    for (size_t r = 0; r < runs.size(); ++r) {
      LeafRun& run = runs[r];
      run.ids.resize(run.firsts.size());
      for (size_t k = 0; k < run.firsts.size(); ++k) {
        const VertexQuery& query = run.queries[run.firsts[k]];
        run.ids[k] = addVertex(query.key, query.patch, query.uv.x, query.uv.y);
      }
      firstTriangle[r] = triangles;
      triangles += run.triangles.size();
      mesh_.droppedTriangles += run.droppedTriangles;
      mesh_.diagonalFans += run.diagonalFans;
    }
    mesh_.indices.resize(3 * triangles);
    mesh_.cornerUv.resize(3 * triangles);
    mesh_.trianglePatch.resize(triangles);
    parallelForChunks(runs.size(), 1, scope_.threads, [&](size_t begin, size_t end) {
      for (size_t r = begin; r < end; ++r) {
        const LeafRun& run = runs[r];
        size_t t = firstTriangle[r];
        for (const std::array<uint32_t, 3>& triangle : run.triangles) {
          for (int c = 0; c < 3; ++c) {
            const uint32_t q = triangle[c];
            mesh_.indices[3 * t + c] = run.ids[run.first[q]];
            mesh_.cornerUv[3 * t + c] = run.queries[q].uv;
          }
          mesh_.trianglePatch[t++] = run.queries[triangle[0]].patch;
        }
      }
    });
    return std::move(mesh_);
  }

 private:
  static float canonical(const SideInfo& s, float t) { return s.reversed ? 1.0f - t : t; }

  // Every leaf corner with the leaf edges that end there, per line (near_points.h): lines
  // u = const and v = const of each patch, and shared sides in their canonical parameter.
  void collectLinePoints() {
    for (const QuadLeaf& leaf : leaves_) {
      const gpu::vec4& r = leaf.rect;
      const uint32_t p = leaf.patchIndex;
      // The leaf's four lines, each looked up once, in the order its corners meet them (the
      // lines' numbers follow it; a line's points are sorted before use, their order free).
      const uint32_t lineV[2] = {alongU_.number(lineKey(p, r.y)), alongU_.number(lineKey(p, r.w))};
      const uint32_t lineU[2] = {alongV_.number(lineKey(p, r.x)), alongV_.number(lineKey(p, r.z))};
      for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i) {
          const float u = i ? r.z : r.x, v = j ? r.w : r.y;
          alongU_.points(lineV[j]).push_back({u, r.z - r.x});
          alongV_.points(lineU[i]).push_back({v, r.w - r.y});
          // The sides (u, v) is on: none, one, or two at a corner of the parameter square.
          for (int side : {kSideV0, kSideV1, kSideU0, kSideU1}) {
            const bool alongU = side == kSideV0 || side == kSideV1;
            const float t = alongU ? u : v, fixed = alongU ? v : u;
            if (fixed != (side == kSideV0 || side == kSideU0 ? 0.0f : 1.0f)) continue;
            const SideInfo& s = topology_.sides[p][side];
            if (s.group >= 0) {
              sharedLines_[s.group].push_back(
                  {canonical(s, t), alongU ? r.z - r.x : r.w - r.y});
              groupSide_[s.group] = {p, side};
            }
            const int32_t f = foldOf_[p][side];
            if (f >= 0) folds_[f].corners.push_back(t);
          }
        }
    }
  }

  // Near-coincident points from the two sides of each line become one vertex (merged_).
  // Sorts every line's points.
  void mergeNearPoints() {
    for (LineIndex* line : {&alongU_, &alongV_}) {
      const bool alongU = line == &alongU_;
      // The pairs of every line first, then their merges in the walk order (LineIndex).
      // Lines apart are independent: found on all the scope's threads.
      std::vector<std::vector<std::pair<float, float>>> pairs(line->size());
      parallelForChunks(line->size(), 256, scope_.threads, [&](size_t begin, size_t end) {
        for (size_t l = begin; l < end; ++l) {
          const uint32_t patch = uint32_t(line->key(l) >> 32);
          const float fixed = fromBits(uint32_t(line->key(l)));
          const auto uvOf = [&](float t) { return alongU ? glm::vec2(t, fixed) : glm::vec2(fixed, t); };
          const auto distinct = [&](float a, float b) {
            return distinctOnModel(patch, uvOf(a), uvOf(b));
          };
          pairs[l] = nearPairs(line->points(l), distinct);
          if (lineIsSide(patch, alongU, fixed)) pairs[l].clear();  // merged by the side's own rules
        }
      });
      const bool any = std::any_of(pairs.begin(), pairs.end(), [](const auto& p) { return !p.empty(); });
      if (!any) continue;
      for (uint32_t l : line->unorderedMapOrder(kLineIndexReserve * leaves_.size())) {
        const uint32_t patch = uint32_t(line->key(l) >> 32);
        const float fixed = fromBits(uint32_t(line->key(l)));
        for (const auto& [a, b] : pairs[l])
          merge(lineKeyOf(patch, alongU, fixed, a), lineKeyOf(patch, alongU, fixed, b));
      }
    }
    for (uint32_t g = 0; g < sharedLines_.size(); ++g) {
      const auto [patch, side] = groupSide_[g];
      if (side < 0) continue;  // no leaf of this triangulation is on it (a streamed group's scope)
      const SideInfo& s = topology_.sides[patch][side];
      const bool alongU = side == kSideV0 || side == kSideV1;
      const float fixed = side == kSideV0 || side == kSideU0 ? 0.0f : 1.0f;
      // (1 − c need not give back the leaf's own t bit for bit; a distance does not mind.)
      const auto uvOf = [&](float c) {
        const float t = canonical(s, c);
        return alongU ? glm::vec2(t, fixed) : glm::vec2(fixed, t);
      };
      const auto distinct = [&, patch = patch](float a, float b) {
        return distinctOnModel(patch, uvOf(a), uvOf(b));
      };
      for (const auto& [a, b] : nearPairs(sharedLines_[g], distinct))
        merge(groupKey(g, a), groupKey(g, b));
    }
    for (auto& [key, representative] : merged_) representative = find(key);
  }

  // The line indices keep the points that stay, as the vertices they are: a point merged into
  // another is that one's vertex, and a ring over both would meet it twice. A leaf edge that
  // ends at a merged point ends where that point's vertex is on the line (MovedCorners).
  void listRepresentatives() {
    if (merged_.empty()) return;
    for (LineIndex* line : {&alongU_, &alongV_}) {
      const bool alongU = line == &alongU_;
      auto& movedOn = alongU ? movedAlongU_ : movedAlongV_;
      for (uint32_t l : line->unorderedMapOrder(kLineIndexReserve * leaves_.size())) {
        const uint64_t key = line->key(l);
        std::vector<LinePoint>& points = line->points(l);
        const uint32_t patch = uint32_t(key >> 32);
        const float fixed = fromBits(uint32_t(key));
        size_t kept = 0;
        for (const LinePoint& point : points) {
          const VertexKey own = lineKeyOf(patch, alongU, fixed, point.t);
          const VertexKey r = find(own);
          if (r == own) {
            points[kept++] = point;
            continue;
          }
          // Where r is on this line, if it is (merged along another line, it is not).
          float t = point.t;
          if (r.kind == kPatchParam && r.a == patch) {
            const float u = fromBits(uint32_t(r.b >> 32)), v = fromBits(uint32_t(r.b));
            if (alongU && v == fixed) t = u;
            if (!alongU && u == fixed) t = v;
          }
          movedOn[key].emplace_back(point.t, t);
        }
        points.resize(kept);
      }
    }
    sharedMoved_.resize(sharedLines_.size());
    for (uint32_t g = 0; g < sharedLines_.size(); ++g) {
      std::vector<LinePoint>& points = sharedLines_[g];
      size_t kept = 0;
      for (const LinePoint& point : points) {
        const VertexKey own = groupKey(g, point.t);
        const VertexKey r = find(own);
        if (r == own) {
          points[kept++] = point;
          continue;
        }
        float c = point.t;
        if (r.kind == kEdgeParam && r.a == g) c = fromBits(uint32_t(r.b));
        for (float end : {0.0f, 1.0f})
          if (r == groupKey(g, end)) c = end;
        sharedMoved_[g].emplace_back(point.t, c);
      }
      points.resize(kept);
    }
  }

  // Whether the line v = fixed (alongU) or u = fixed of `patch` is one of its sides that is
  // shared, collapsed or folded: their points are merged (or placed) by the side's own rules.
  bool lineIsSide(uint32_t patch, bool alongU, float fixed) const {
    if (fixed != 0.0f && fixed != 1.0f) return false;
    const int side = alongU ? (fixed == 0.0f ? kSideV0 : kSideV1) : (fixed == 0.0f ? kSideU0 : kSideU1);
    const SideInfo& s = topology_.sides[patch][side];
    return s.group >= 0 || s.collapsed || foldOf_[patch][side] >= 0;
  }

  // The vertex key of canonical parameter c on shared group g: its ends are patch corners.
  // (Only there is c turned back into a patch parameter: 1 − c is exact at 0 and 1 alone.)
  VertexKey groupKey(uint32_t g, float c) {
    if (c != 0.0f && c != 1.0f) return {kEdgeParam, g, bits(c)};
    const auto [patch, side] = groupSide_[g];
    const SideInfo& s = topology_.sides[patch][side];
    const float t = s.reversed ? 1.0f - c : c;
    const bool alongU = side == kSideV0 || side == kSideV1;
    const float fixed = side == kSideV0 || side == kSideU0 ? 0.0f : 1.0f;
    return alongU ? baseKey(patch, t, fixed) : baseKey(patch, fixed, t);
  }

  // Whether fp32 positions tell two points of a patch apart (near_points.h): farther apart
  // on the model, in double, than kDistinctUlps units in the last place of their coordinates.
  bool distinctOnModel(uint32_t patch, glm::vec2 a, glm::vec2 b) const {
    const glm::dvec3 pa = patchPoint(patches_[patch], a.x, a.y);
    const glm::dvec3 pb = patchPoint(patches_[patch], b.x, b.y);
    const glm::dvec3 m = glm::max(glm::abs(pa), glm::abs(pb));
    return glm::length(pa - pb) > kDistinctUlps * 0x1p-23 * std::max({m.x, m.y, m.z});
  }

  VertexKey lineKeyOf(uint32_t patch, bool alongU, float fixed, float t) {
    return alongU ? baseKey(patch, t, fixed) : baseKey(patch, fixed, t);
  }

  // Merging keeps, of two keys, the one ranked first: a patch corner, then a point of a shared
  // side, then a point inside a patch; then the smaller parameter (on a shared side, the
  // canonical one: the first of a run, as both sides see it).
  static bool ranksBefore(const VertexKey& x, const VertexKey& y) {
    static constexpr int rank[] = {3, 2, 0, 1};  // by KeyKind
    if (rank[x.kind] != rank[y.kind]) return rank[x.kind] < rank[y.kind];
    return x.a != y.a ? x.a < y.a : x.b < y.b;
  }

  VertexKey find(VertexKey key) const {
    for (auto it = merged_.find(key); it != merged_.end() && !(it->second == key);
         it = merged_.find(key))
      key = it->second;
    return key;
  }

  // The key a vertex is merged into (itself if none); notes that the leaf met a merged one.
  VertexKey resolve(const VertexKey& key, bool& touchesMerge) const {
    if (merged_.empty()) return key;
    const VertexKey r = find(key);
    if (!(r == key)) touchesMerge = true;
    return r;
  }

  void merge(const VertexKey& x, const VertexKey& y) {
    if (x.kind == kFoldPosition || y.kind == kFoldPosition) return;  // placed by the fold
    VertexKey rx = find(x), ry = find(y);
    if (rx == ry) return;
    if (ranksBefore(ry, rx)) std::swap(rx, ry);
    merged_[ry] = rx;
  }

  // Which side of the parameter square (u, v) lies on, and the parameter t along it.
  static bool onSide(float u, float v, int& side, float& t) {
    if (v == 0.0f) return side = kSideV0, t = u, true;
    if (v == 1.0f) return side = kSideV1, t = u, true;
    if (u == 0.0f) return side = kSideU0, t = v, true;
    if (u == 1.0f) return side = kSideU1, t = v, true;
    return false;
  }

  uint32_t positionId(const glm::dvec3& p) {
    std::array<uint64_t, 3> key;
    for (int c = 0; c < 3; ++c) {
      double x = p[c] == 0.0 ? 0.0 : p[c];
      std::memcpy(&key[c], &x, sizeof x);
    }
    if (walking_) {  // read only: registerPositions listed every position the walk meets
      const auto found = positions_.find(key);
      if (found == positions_.end())
        throw std::logic_error("triangulateLeaves: a position met by the walk was not listed");
      return found->second;
    }
    const auto [id, inserted] = positions_.try_emplace(key, uint32_t(positions_.size()));
    if (inserted && scope_.seamKeys) positionPoints_.push_back(p);
    return id->second;
  }

  // Gives an id to every position baseKey can meet in the leaf walk (the corners of each
  // patch with leaves, and its collapsed sides' points), so that the walk only looks ids up.
  // Ids only tell positions apart from here on: merging, where their order counts, is done.
  void registerPositions() {
    const std::vector<bool> present = patchesWithLeaves();
    for (uint32_t p = 0; p < patches_.size(); ++p) {
      if (!present[p]) continue;
      const BezierPatch& bp = patches_[p];
      for (int j : {0, bp.degreeV})
        for (int i : {0, bp.degreeU}) positionId(bp.at(i, j));
      for (int side = 0; side < 4; ++side)
        if (topology_.sides[p][side].collapsed) positionId(sideControlPoints(bp, side)[0]);
    }
  }

  // A side that folds back over itself (side_fold.h) and is no other patch's: over the part
  // it retraces, both strands are one curve, so every point on one strand is also a vertex on
  // the others, identified by its position along the fold's line (docs/watertight.md).
  struct FoldedSide {
    SideFold fold;
    uint32_t patch;
    int side;
    std::vector<float> corners;         // leaf corners on the side (t)
    std::map<float, VertexKey> points;  // t → vertex: the corners and their images
  };

  // The patches with leaves here (all of them, unless a scope passes part of them).
  std::vector<bool> patchesWithLeaves() const {
    std::vector<bool> present(patches_.size(), false);
    for (const QuadLeaf& leaf : leaves_) present[leaf.patchIndex] = true;
    return present;
  }

  void findFolds() {
    foldOf_.assign(patches_.size(), {-1, -1, -1, -1});
    const std::vector<bool> present = patchesWithLeaves();
    for (uint32_t p = 0; p < patches_.size(); ++p)
      for (int side = 0; side < 4 && present[p]; ++side) {
        const SideInfo& s = topology_.sides[p][side];
        if (s.group >= 0 || s.collapsed) continue;
        std::optional<SideFold> fold = findSideFold(sideControlPoints(patches_[p], side));
        if (!fold) continue;
        foldOf_[p][side] = int32_t(folds_.size());
        folds_.push_back({std::move(*fold), p, side, {}, {}});
      }
  }

  // Every corner's point on every strand: the side's ends are the patch corners' vertices (as
  // everywhere, welded by position), the rest keyed by their exact position along the line.
  void placeFoldPoints(uint32_t f) {
    FoldedSide& fs = folds_[f];
    // The ends are vertices of every leaf there (onSide gives a patch corner to a v side).
    fs.corners.insert(fs.corners.end(), {0.0f, 1.0f});
    sortUnique(fs.corners);
    const std::vector<glm::dvec3> ends = sideControlPoints(patches_[fs.patch], fs.side);
    const double first = foldCoordinate(fs.fold, 0), last = foldCoordinate(fs.fold, 1);
    const auto keyOf = [&](double s) -> VertexKey {
      if (s == first) return {kPosition, positionId(ends.front()), 0};
      if (s == last) return {kPosition, positionId(ends.back()), 0};
      uint64_t b;
      std::memcpy(&b, &s, sizeof b);
      return {kFoldPosition, f, b};
    };
    for (float t : fs.corners) fs.points.emplace(t, keyOf(foldCoordinate(fs.fold, t)));
    for (float t : fs.corners) {
      const double s = foldCoordinate(fs.fold, t);
      for (double image : foldImages(fs.fold, t, s)) fs.points.emplace(float(image), keyOf(s));
    }
  }

  uint32_t addVertex(const VertexKey& key, uint32_t patch, float u, float v) {
    const auto [index, inserted] = index_.try_emplace(key, uint32_t(mesh_.vertices.size()));
    if (inserted) {
      mesh_.vertices.push_back({patch, u, v});
      if (scope_.seamKeys) mesh_.seamKeys.push_back(seamKeyOf(key));
    }
    return index->second;
  }

  SeamKey seamKeyOf(const VertexKey& key) const {
    if (key.kind == kEdgeParam) return {SeamKey::kSharedSide, key.a, uint32_t(key.b), {}};
    if (key.kind == kPosition) return {SeamKey::kPosition, 0, 0, positionPoints_[key.a]};
    return {};  // a point of one patch, or of its folded side (never shared: findFolds)
  }

  // The key of the vertex at (u, v) of `patch` before merging near points: patch corners and
  // collapsed sides by position, shared sides by canonical parameter, folded sides by their
  // fold's point, anything else by (patch, u, v).
  VertexKey baseKey(uint32_t patch, float u, float v) {
    const BezierPatch& bp = patches_[patch];
    bool uEnd = u == 0.0f || u == 1.0f, vEnd = v == 0.0f || v == 1.0f;
    if (uEnd && vEnd) {
      const glm::dvec3& corner = bp.at(u == 0.0f ? 0 : bp.degreeU, v == 0.0f ? 0 : bp.degreeV);
      return {kPosition, positionId(corner), 0};
    }
    int side;
    float t;
    if (onSide(u, v, side, t)) {
      const SideInfo& s = topology_.sides[patch][side];
      if (s.collapsed) return {kPosition, positionId(sideControlPoints(bp, side)[0]), 0};
      if (s.group >= 0) return {kEdgeParam, uint32_t(s.group), bits(canonical(s, t))};
      if (const int32_t f = foldOf_[patch][side]; f >= 0) {
        auto it = folds_[f].points.find(t);
        if (it != folds_[f].points.end()) return it->second;
      }
    }
    return {kPatchParam, patch, (uint64_t(bits(u)) << 32) | bits(v)};
  }

  // A vertex the leaf walk asks for: its index is handed out after the walk (run), in the
  // order the walk asked, as if it had been looked up then.
  struct VertexQuery {
    VertexKey key;
    uint32_t patch;
    glm::vec2 uv;
  };

  // A run of consecutive leaves, walked: their vertex queries in order, and their triangles
  // as positions in `queries`.
  struct LeafRun {
    std::vector<VertexQuery> queries;
    std::vector<std::array<uint32_t, 3>> triangles;
    size_t droppedTriangles = 0, diagonalFans = 0;
    // The queries that are the first of their key in this run, in order; per query, its
    // key's place in `firsts`; per first query, its vertex index (numbered after the walk).
    std::vector<uint32_t> firsts, first, ids;

    // Numbering looks each key up once per run, not once per query (a vertex is asked for by
    // every leaf around it), here in a table small enough for the cache, on the run's thread.
    void findFirsts() {
      HashMap<VertexKey, uint32_t, VertexKeyHash> place;
      place.reserve(queries.size());
      first.resize(queries.size());
      for (size_t q = 0; q < queries.size(); ++q) {
        const auto [k, added] = place.try_emplace(queries[q].key, uint32_t(firsts.size()));
        if (added) firsts.push_back(uint32_t(q));
        first[q] = k->second;
      }
    }
  };

  struct RingVertex {
    VertexKey key;   // one vertex, one key (addVertex)
    uint32_t query;  // in LeafRun::queries
    glm::vec2 uv;    // on the leaf's own patch
    bool operator==(const RingVertex& o) const { return key == o.key; }
  };

  // One thread's walk: where it writes, and the leaf being triangulated.
  struct LeafWork {
    LeafRun* out = nullptr;
    bool silent = false;        // the leaf is outside the scope
    bool touchesFold = false;   // it has a vertex on a folded side
    bool touchesMerge = false;  // ... or a vertex merged into a near one
    std::vector<RingVertex> ring;
    std::vector<glm::vec2> ringUv;
    std::vector<VertexKey> ringKeys;
    std::vector<std::array<uint32_t, 3>> ringTriangles;
    std::vector<float> scratch;
  };

  static RingVertex query(LeafWork& work, const VertexKey& key, uint32_t patch, glm::vec2 uv) {
    work.out->queries.push_back({key, patch, uv});
    return {key, uint32_t(work.out->queries.size() - 1), uv};
  }

  // The vertex at (u, v) of `patch`, welded with every other patch's vertex at that point and
  // with the near points merged into it.
  RingVertex vertexAt(LeafWork& work, uint32_t patch, float u, float v) {
    int side;
    float t;
    if (onSide(u, v, side, t) && foldOf_[patch][side] >= 0) work.touchesFold = true;
    return query(work, resolve(baseKey(patch, u, v), work.touchesMerge), patch, glm::vec2(u, v));
  }

  // Appends the vertices strictly inside the leaf edge from t0 to t1 (in ring order) on the
  // line `fixed` (v = fixed when alongU, else u = fixed).
  void edgeInterior(LeafWork& work, uint32_t patch, bool alongU, float fixed, float t0,
                    float t1) {
    std::vector<RingVertex>& ring = work.ring;
    std::vector<float>& scratch = work.scratch;
    int side = -1;
    if (alongU && (fixed == 0.0f || fixed == 1.0f)) side = fixed == 0.0f ? kSideV0 : kSideV1;
    if (!alongU && (fixed == 0.0f || fixed == 1.0f)) side = fixed == 0.0f ? kSideU0 : kSideU1;
    // A listed point is a vertex of its own: no merge to look up.
    auto place = [&](float t) {
      const glm::vec2 uv = alongU ? glm::vec2(t, fixed) : glm::vec2(fixed, t);
      ring.push_back(query(work, baseKey(patch, uv.x, uv.y), patch, uv));
    };
    if (side >= 0) {
      const SideInfo& s = topology_.sides[patch][side];
      if (s.collapsed) return;  // every point of it is the same vertex
      if (s.group >= 0) {
        // Compare in the shared curve's own parameter, the same on both sides.
        float c0 = canonical(s, t0), c1 = canonical(s, t1);
        if (!sharedMoved_.empty())
          c0 = movedTo(sharedMoved_[s.group], c0), c1 = movedTo(sharedMoved_[s.group], c1);
        between(&sharedLines_[s.group], std::min(c0, c1), std::max(c0, c1), scratch);
        if (c0 > c1) std::reverse(scratch.begin(), scratch.end());
        for (float c : scratch) {
          float t = s.reversed ? 1.0f - c : c;
          glm::vec2 uv = alongU ? glm::vec2(t, fixed) : glm::vec2(fixed, t);
          // A listed point is a vertex of its own: no merge to look up.
          ring.push_back(query(work, {kEdgeParam, uint32_t(s.group), bits(c)}, patch, uv));
        }
        return;
      }
      if (const int32_t f = foldOf_[patch][side]; f >= 0) {
        work.touchesFold = true;
        const std::map<float, VertexKey>& points = folds_[f].points;
        auto first = points.upper_bound(std::min(t0, t1));
        auto last = points.lower_bound(std::max(t0, t1));
        std::vector<std::pair<float, VertexKey>> inside(first, last);
        if (t0 > t1) std::reverse(inside.begin(), inside.end());
        for (const auto& [t, key] : inside) {
          glm::vec2 uv = alongU ? glm::vec2(t, fixed) : glm::vec2(fixed, t);
          ring.push_back(query(work, key, patch, uv));
        }
        return;
      }
    }
    const LineIndex& lines = alongU ? alongU_ : alongV_;
    const std::vector<LinePoint>* points = lines.find(lineKey(patch, fixed));
    const auto& movedOn = alongU ? movedAlongU_ : movedAlongV_;
    if (!movedOn.empty())
      if (auto moved = movedOn.find(lineKey(patch, fixed)); moved != movedOn.end())
        t0 = movedTo(moved->second, t0), t1 = movedTo(moved->second, t1);
    between(points, std::min(t0, t1), std::max(t0, t1), scratch);
    if (t0 > t1) std::reverse(scratch.begin(), scratch.end());
    for (float t : scratch) place(t);
  }

  static void emit(LeafWork& work, const RingVertex& a, const RingVertex& b, const RingVertex& c) {
    if (work.silent) return;
    if (a == b || b == c || c == a) {
      ++work.out->droppedTriangles;
      return;
    }
    work.out->triangles.push_back({a.query, b.query, c.query});
  }

  // Along a fold the ring can meet one vertex twice: back to back (a, v, v, a at the fold's
  // turn) or as a spike (a, v, a, the leaf's own surface folded onto itself). A fan over them
  // would give zero-area and back-to-back triangles; the ring without them bounds the same
  // surface. Returns whether anything went.
  static bool dropFoldedBack(std::vector<RingVertex>& ring) {
    bool changed = false;
    for (bool again = true; again && ring.size() >= 2;) {
      again = false;
      const size_t n = ring.size();
      for (size_t i = 0; i < n && !again; ++i) {
        if (ring[i] == ring[(i + 1) % n]) {
          ring.erase(ring.begin() + long((i + 1) % n));
          again = true;
        } else if (n >= 3 && ring[i] == ring[(i + 2) % n]) {
          // Drop the spike's tip and its second base, keeping the first.
          const size_t tip = (i + 1) % n, base = (i + 2) % n;
          ring.erase(ring.begin() + long(std::max(tip, base)));
          ring.erase(ring.begin() + long(std::min(tip, base)));
          again = true;
        }
      }
      changed = changed || again;
    }
    return changed;
  }

  // Consecutive ring entries at one vertex (near points merged into it, near_points.h) are
  // one entry: the fan over them would only add triangles with two corners at one vertex.
  static void dropRepeats(std::vector<RingVertex>& ring) {
    ring.erase(std::unique(ring.begin(), ring.end()), ring.end());
    while (ring.size() > 1 && ring.back() == ring.front()) ring.pop_back();
  }

  // Rule T's leaves: its bound holds for any triangle with corners in the leaf's rectangle
  // (docs/quadtree.md, "Rule T: tolerance"), so their rings need no centre vertex. Rules A–D
  // (and rule T's MaxDepth / MinSize leaves, which share their causes) keep the fan.
  static bool provenAnyTriangulation(uint32_t cause) {
    return cause == gpu::kCauseWithinTolerance || cause == gpu::kCauseCulled ||
           cause == gpu::kCauseEyePlane;
  }

  // The ring as n − 2 triangles without a new vertex (ring_triangulation.h). Only where every
  // vertex is met once, or twice in a row (a collapsed side's two corners, whose triangle
  // collapses and is dropped as in the fan): otherwise the fan, whose triangles each hold one
  // ring edge, is kept.
  static bool triangulateRing(LeafWork& work, const gpu::vec4& r, uint32_t diagonal) {
    const std::vector<RingVertex>& ring = work.ring;
    const size_t n = ring.size();
    work.ringUv.resize(n);
    work.ringKeys.resize(n);
    for (size_t k = 0; k < n; ++k) {
      work.ringUv[k] = ring[k].uv;
      work.ringKeys[k] = ring[k].key;
    }
    std::sort(work.ringKeys.begin(), work.ringKeys.end(), keyLess);
    const size_t distinct =
        size_t(std::unique(work.ringKeys.begin(), work.ringKeys.end()) - work.ringKeys.begin());
    size_t repeats = 0;
    for (size_t k = 0; k < n; ++k) repeats += ring[k] == ring[(k + 1) % n];
    if (distinct + repeats != n) return false;
    if (!triangulateRectangleRingAlong(work.ringUv, {r.x, r.y}, {r.z, r.w}, diagonal,
                                       work.ringTriangles))
      return false;
    for (const auto& t : work.ringTriangles) emit(work, ring[t[0]], ring[t[1]], ring[t[2]]);
    return true;
  }

  // Any order of keys, for counting distinct ones.
  static bool keyLess(const VertexKey& x, const VertexKey& y) {
    return x.kind != y.kind ? x.kind < y.kind : x.a != y.a ? x.a < y.a : x.b < y.b;
  }

  void triangulateLeaf(const QuadLeaf& leaf, LeafWork& work) {
    const uint32_t p = leaf.patchIndex;
    const gpu::vec4& r = leaf.rect;
    std::vector<RingVertex>& ring = work.ring;
    ring.clear();
    work.touchesFold = work.touchesMerge = false;
    // Counter-clockwise: bottom (v0, u rising), right (u1, v rising), top (v1, u falling),
    // left (u0, v falling); each edge contributes its start corner and interior vertices.
    ring.push_back(vertexAt(work, p, r.x, r.y));
    edgeInterior(work, p, true, r.y, r.x, r.z);
    ring.push_back(vertexAt(work, p, r.z, r.y));
    edgeInterior(work, p, false, r.z, r.y, r.w);
    ring.push_back(vertexAt(work, p, r.z, r.w));
    edgeInterior(work, p, true, r.w, r.z, r.x);
    ring.push_back(vertexAt(work, p, r.x, r.w));
    edgeInterior(work, p, false, r.x, r.w, r.y);

    const bool folded = work.touchesFold && dropFoldedBack(ring);
    if (work.touchesMerge) dropRepeats(ring);
    if (ring.size() < 3) return;
    // Four entries are the four corners unless a merge took one: a leaf kept to a diagonal then
    // goes through triangulateRing, which finds that diagonal's corners or keeps the fan.
    const bool cornerDiagonal = leaf.diagonal == gpu::kToleranceAnyDiagonal ||
                                (leaf.diagonal == gpu::kToleranceMainDiagonal && !work.touchesMerge);
    if (ring.size() == 4 && !folded && cornerDiagonal) {
      emit(work, ring[0], ring[1], ring[2]);
      emit(work, ring[0], ring[2], ring[3]);
      return;
    }
    if (!folded && provenAnyTriangulation(leaf.cause) && triangulateRing(work, r, leaf.diagonal))
      return;
    // The fan's triangles need not keep to one diagonal: such a leaf's bound is then only
    // the any-triangle one (counted, docs/quadtree.md, "One diagonal").
    if (leaf.diagonal != gpu::kToleranceAnyDiagonal) ++work.out->diagonalFans;
    float us = leaf.split.x, vs = leaf.split.y;
    if (!(us > r.x && us < r.z && vs > r.y && vs < r.w)) {
      us = 0.5f * (r.x + r.z);
      vs = 0.5f * (r.y + r.w);
    }
    const RingVertex center = vertexAt(work, p, us, vs);
    for (size_t k = 0; k < ring.size(); ++k) emit(work, center, ring[k], ring[(k + 1) % ring.size()]);
  }

  const std::vector<QuadLeaf>& leaves_;
  const std::vector<BezierPatch>& patches_;
  const TriangulationScope scope_;
  const PatchTopology ownTopology_;
  const PatchTopology& topology_;
  LineIndex alongU_, alongV_;
  std::vector<std::vector<LinePoint>> sharedLines_;  // per group, in canonical parameters
  std::unordered_map<uint64_t, MovedCorners> movedAlongU_, movedAlongV_;  // lines with merges
  std::vector<MovedCorners> sharedMoved_;  // per group (empty when nothing merged)
  std::vector<std::pair<uint32_t, int>> groupSide_;  // per group, one (patch, side) on it
  // Near-coincident points (near_points.h): key → the key of the vertex it is merged into.
  std::unordered_map<VertexKey, VertexKey, VertexKeyHash> merged_;
  std::vector<std::array<int32_t, 4>> foldOf_;    // per patch side, index in folds_ or -1
  std::vector<FoldedSide> folds_;
  bool walking_ = false;  // the leaves are being walked (run): positions are only looked up
  // Ids in the order positions are first met (ranksBefore compares them).
  HashMap<std::array<uint64_t, 3>, uint32_t, PositionBitsHash> positions_;
  std::vector<glm::dvec3> positionPoints_;  // by position id, for seam keys
  HashMap<VertexKey, uint32_t, VertexKeyHash> index_;
  ParamMesh mesh_;
};

}  // namespace

ParamMesh triangulateLeaves(const std::vector<QuadLeaf>& leaves,
                            const std::vector<BezierPatch>& patches,
                            const TriangulationScope& scope) {
  return Triangulator(leaves, patches, scope).run();
}

}  // namespace tessera
