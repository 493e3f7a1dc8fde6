#include "mesh/streamed_tessellation.h"

#include <algorithm>
#include <array>
#include <cstring>
#include <string>
#include <unordered_map>

#include "common/memory_budget.h"
#include "common/stopwatch.h"
#include "mesh/mesh_cleanup.h"
#include "mesh/shared_edges.h"
#include "mesh/triangulate.h"
#include "mesh/zero_area.h"

namespace tessera {
namespace {

using PointBits = std::array<uint64_t, 3>;

PointBits pointBits(const glm::dvec3& p) {
  PointBits key;
  for (int c = 0; c < 3; ++c) {
    const double x = p[c] == 0.0 ? 0.0 : p[c];
    std::memcpy(&key[c], &x, sizeof x);
  }
  return key;
}

// Every patch corner (exact control point) with its patch, sorted: the patches that meet at
// a point. Those sharing a side share its end corners, so this finds side neighbours too.
class CornerIndex {
 public:
  explicit CornerIndex(const std::vector<BezierPatch>& patches) {
    corners_.reserve(4 * patches.size());
    for (uint32_t p = 0; p < patches.size(); ++p)
      for (const PointBits& key : cornersOf(patches[p])) corners_.push_back({key, p});
    std::sort(corners_.begin(), corners_.end());
  }

  // The last patch with a corner at `point` (0 if none).
  uint32_t lastPatchAt(const glm::dvec3& point) const {
    const PointBits key = pointBits(point);
    auto it = std::upper_bound(corners_.begin(), corners_.end(), std::make_pair(key, UINT32_MAX));
    return it != corners_.begin() && std::prev(it)->first == key ? std::prev(it)->second : 0;
  }

  // Patches [first, end) and every patch meeting one of them at a corner, ascending.
  std::vector<uint32_t> withNeighbours(const std::vector<BezierPatch>& patches, uint32_t first,
                                       uint32_t end) const {
    // Each distinct corner once: many patches can meet at one point (a pole, copies in place).
    std::vector<PointBits> keys;
    for (uint32_t p = first; p < end; ++p)
      for (const PointBits& key : cornersOf(patches[p])) keys.push_back(key);
    std::sort(keys.begin(), keys.end());
    keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
    std::vector<uint32_t> result;
    for (const PointBits& key : keys) {
      auto it = std::lower_bound(corners_.begin(), corners_.end(), std::make_pair(key, 0u));
      for (; it != corners_.end() && it->first == key; ++it) result.push_back(it->second);
    }
    std::sort(result.begin(), result.end());
    result.erase(std::unique(result.begin(), result.end()), result.end());
    return result;
  }

 private:
  static std::array<PointBits, 4> cornersOf(const BezierPatch& bp) {
    return {pointBits(bp.at(0, 0)), pointBits(bp.at(bp.degreeU, 0)),
            pointBits(bp.at(0, bp.degreeV)), pointBits(bp.at(bp.degreeU, bp.degreeV))};
  }
  std::vector<std::pair<PointBits, uint32_t>> corners_;
};

// The patches `indices` of `all` as a set of the same kind as `all` (the kind picks the
// classifier's shaders, so a group's leaves are those of the whole set).
PatchSet subsetOf(const PatchSet& all, const std::vector<BezierPatch>& local,
                  const std::vector<uint32_t>& indices) {
  if (all.isBicubic()) {
    std::vector<gpu::BicubicPatch> bicubic;
    bicubic.reserve(indices.size());
    for (uint32_t p : indices) bicubic.push_back(all.bicubic()[p]);
    return PatchSet(std::move(bicubic));
  }
  std::vector<BezierPatch> chosen;
  chosen.reserve(indices.size());
  for (uint32_t p : indices) chosen.push_back(local[p]);
  return PatchSet(toGeneralPatchSet(chosen));
}

using PositionBits = std::array<uint32_t, 3>;

PositionBits bitsOf(const glm::vec3& p) {
  PositionBits key;
  for (int c = 0; c < 3; ++c) {
    const float x = p[c] == 0.0f ? 0.0f : p[c];  // -0 and +0 weld, as weldIdenticalPositions
    std::memcpy(&key[c], &x, sizeof x);
  }
  return key;
}

struct PositionBitsHash {
  size_t operator()(const PositionBits& k) const {
    return (size_t(k[0]) * 73856093u) ^ (size_t(k[1]) * 19349663u) ^ (size_t(k[2]) * 83492791u);
  }
};

// A vertex already written, as later groups find it.
struct WrittenVertex {
  uint32_t index;
  glm::vec3 position;  // in the local frame, for the cap removal of later groups
  uint32_t lastPatch;  // the last patch that can meet it: kept until that patch's group
};

// The welding map that persists across groups: boundary vertices by shared-side key and by
// position (a held mesh welds every equal position; only boundary vertices meet other groups).
class SeamMap {
 public:
  const WrittenVertex* find(const SeamKey& key, const glm::vec3& position) const {
    if (key.kind == SeamKey::kSharedSide) {
      auto it = bySide_.find(sideKey(key));
      if (it != bySide_.end()) return &it->second;
    }
    if (key.kind == SeamKey::kPosition) {
      auto it = byPoint_.find(pointKey(key.point));
      if (it != byPoint_.end()) return &it->second;
    }
    auto it = byPosition_.find(bitsOf(position));
    return it == byPosition_.end() ? nullptr : &it->second;
  }
  void add(const SeamKey& key, const WrittenVertex& v) {
    if (key.kind == SeamKey::kOwnPatch) return;
    if (key.kind == SeamKey::kSharedSide) bySide_.emplace(sideKey(key), v);
    if (key.kind == SeamKey::kPosition) byPoint_.emplace(pointKey(key.point), v);
    byPosition_.emplace(bitsOf(v.position), v);
  }
  size_t size() const { return bySide_.size() + byPoint_.size() + byPosition_.size(); }

  // Drops the vertices no patch from `next` on can meet.
  void forgetBefore(uint32_t next) {
    const auto prune = [next](auto& map) {
      for (auto it = map.begin(); it != map.end();)
        it = it->second.lastPatch < next ? map.erase(it) : std::next(it);
    };
    prune(byPoint_);
    prune(bySide_);
    prune(byPosition_);
  }

 private:
  struct PointBitsHash {
    size_t operator()(const PointBits& k) const {
      return size_t((k[0] * 0x9E3779B97F4A7C15ull) ^ (k[1] * 0xC2B2AE3D27D4EB4Full) ^ k[2]);
    }
  };
  static uint64_t sideKey(const SeamKey& k) { return uint64_t(k.group) << 32 | k.parameter; }
  static PointBits pointKey(const glm::dvec3& p) { return pointBits(p); }
  std::unordered_map<PointBits, WrittenVertex, PointBitsHash> byPoint_;
  std::unordered_map<uint64_t, WrittenVertex> bySide_;
  std::unordered_map<PositionBits, WrittenVertex, PositionBitsHash> byPosition_;
};

// Keeps the triangles not marked in `drop` (with their patch and corner uvs).
size_t keepTriangles(const std::vector<bool>& drop, std::vector<uint32_t>& indices,
                     std::vector<uint32_t>& trianglePatch, std::vector<glm::vec2>& cornerUv) {
  size_t kept = 0;
  for (size_t t = 0; t < drop.size(); ++t) {
    if (drop[t]) continue;
    for (size_t c = 0; c < 3; ++c) {
      indices[3 * kept + c] = indices[3 * t + c];
      cornerUv[3 * kept + c] = cornerUv[3 * t + c];
    }
    trianglePatch[kept++] = trianglePatch[t];
  }
  const size_t dropped = drop.size() - kept;
  indices.resize(3 * kept);
  cornerUv.resize(3 * kept);
  trianglePatch.resize(kept);
  return dropped;
}

class GroupStreamer {
 public:
  GroupStreamer(const std::vector<BezierPatch>& patches, const QuadtreeOptions& options,
                Backend& backend, const MeshChunkSink& sink)
      : frame_(modelFrame(patches)),
        local_(toLocalFrame(patches, frame_)),
        options_(options),
        backend_(backend),
        sink_(sink),
        topology_(findSharedEdges(local_)),
        corners_(local_) {
    lastPatchOfSideGroup_.assign(topology_.groupCount, 0);
    for (uint32_t p = 0; p < topology_.sides.size(); ++p)
      for (const SideInfo& side : topology_.sides[p])
        if (side.group >= 0) lastPatchOfSideGroup_[size_t(side.group)] = p;
    if (options.rule == SplitRule::Tolerance) options_.tolerance = options.tolerance / frame_.scale;
    gpuPatches_ = toPatchSet(local_);
    backend_.evaluator->prepareVertices(gpuPatches_);
  }

  // Streams patches [first, end); throws MemoryLimitError when the group does not fit.
  void streamGroup(uint32_t first, uint32_t end, StreamedTessellationStats& stats) {
    const std::vector<uint32_t> members = corners_.withNeighbours(local_, first, end);
    Stopwatch step;
    QuadtreeResult tree =
        buildQuadtree(subsetOf(gpuPatches_, local_, members), options_, *backend_.classifier);
    for (QuadLeaf& leaf : tree.leaves) leaf.patchIndex = members[leaf.patchIndex];
    // The whole tree's order (level by level, patches ascending within a level), so the
    // triangulation meets shared vertices as the held one does (TriangulationScope).
    std::stable_sort(tree.leaves.begin(), tree.leaves.end(),
                     [](const QuadLeaf& x, const QuadLeaf& y) {
                       return x.level != y.level ? x.level < y.level : x.patchIndex < y.patchIndex;
                     });
    const uint64_t bytes =
        saturatingAdd(saturatingMultiply(tree.leaves.size(), kTessellationBytesPerNode),
                      saturatingMultiply(seams_.size(), kSeamVertexBytes));
    requireWithinMemoryBudget(
        bytes, "patches " + std::to_string(first) + "–" + std::to_string(end - 1) + " (" +
                   std::to_string(members.size() - (end - first)) + " neighbours), their " +
                   std::to_string(tree.leaves.size()) + " leaves and mesh, and the welding map of " +
                   std::to_string(seams_.size()) + " seam vertices");
    stats.largestGroupBytes = std::max(stats.largestGroupBytes, bytes);
    TessellationStats& s = stats.totals;
    s.treeMs += step.elapsedMs();
    for (const QuadLeaf& leaf : tree.leaves)
      if (leaf.patchIndex >= first && leaf.patchIndex < end) {
        ++s.leaves;
        s.depth = std::max(s.depth, leaf.level);
        stats.largestLeafBound =
            std::max(stats.largestLeafBound, double(leaf.flatness) * frame_.scale);
      }

    step.restart();
    const TriangulationScope scope{&topology_, first, end, true};
    ParamMesh param = triangulateLeaves(tree.leaves, local_, scope);
    tree = {};
    s.triangulateMs += step.elapsedMs();

    step.restart();
    std::vector<gpu::EvalQuery> queries(param.vertices.size());
    for (size_t i = 0; i < queries.size(); ++i)
      queries[i] = {param.vertices[i].patchIndex, param.vertices[i].u, param.vertices[i].v, 0};
    const std::vector<gpu::VertexSample> samples =
        backend_.evaluator->evaluateVertices(gpuPatches_, queries);
    s.evaluateMs += step.elapsedMs();
    requireFiniteSamples(param, samples);
    s.degenerateTrianglesDropped += param.droppedTriangles;
    s.diagonalFans += param.diagonalFans;
    emitChunk(param, samples, end, s);
    stats.seamVertices = std::max(stats.seamVertices, seams_.size());
    seams_.forgetBefore(end);
  }

 private:
  // The last patch that has the vertex of `key` (on a side group's sides, or at a corner).
  uint32_t lastPatchMeeting(const SeamKey& key) const {
    if (key.kind == SeamKey::kSharedSide) return lastPatchOfSideGroup_[key.group];
    if (key.kind == SeamKey::kPosition) return corners_.lastPatchAt(key.point);
    return 0;
  }

  // Welds the group's vertices with each other and with the seams written before, cleans the
  // triangles as assembleTessellation does, and hands the chunk to the sink.
  void emitChunk(const ParamMesh& param, const std::vector<gpu::VertexSample>& samples,
                 uint32_t end, TessellationStats& s) {
    const size_t n = samples.size();
    std::vector<glm::vec3> positions(n);
    for (size_t i = 0; i < n; ++i) positions[i] = glm::vec3(samples[i].position);
    // The vertices the group's triangles use (the neighbours' leaves made others).
    std::vector<bool> isUsed(n, false);
    for (uint32_t i : param.indices) isUsed[i] = true;
    std::vector<uint32_t> used;
    std::vector<glm::vec3> usedPositions;
    for (uint32_t i = 0; i < n; ++i)
      if (isUsed[i]) used.push_back(i), usedPositions.push_back(positions[i]);
    const std::vector<uint32_t> firstEqual = weldIdenticalPositions(usedPositions);
    // Per local vertex: its output index and the local vertex that stands for it.
    std::vector<uint32_t> output(n), standsFor(n);
    std::unordered_map<uint32_t, uint32_t> localOf;  // output index of an earlier group → local
    MeshChunk chunk;
    for (uint32_t k = 0; k < used.size(); ++k) {
      const uint32_t i = used[k];
      const SeamKey& key = param.seamKeys[i];
      if (firstEqual[k] != k) {
        output[i] = output[used[firstEqual[k]]];
        standsFor[i] = standsFor[used[firstEqual[k]]];
      } else if (const WrittenVertex* seen = seams_.find(key, positions[i])) {
        output[i] = seen->index;
        positions[i] = seen->position;
        standsFor[i] = localOf.emplace(seen->index, i).first->second;
      } else {
        output[i] = nextIndex_++;
        standsFor[i] = i;
        chunk.positions.push_back(glm::vec3(frame_.toModel(glm::dvec3(positions[i]))));
        chunk.normals.push_back(glm::vec3(samples[i].normal));
        chunk.uvs.push_back({param.vertices[i].u, param.vertices[i].v});
        chunk.patchIds.push_back(param.vertices[i].patchIndex);
      }
      const uint32_t last = lastPatchMeeting(key);
      if (last >= end) seams_.add(key, {output[i], positions[i], last});
    }
    std::vector<uint32_t> indices;
    std::vector<uint32_t> trianglePatch;
    std::vector<glm::vec2> cornerUv;
    indices.reserve(param.indices.size());
    for (size_t k = 0; k < param.indices.size(); k += 3) {
      const uint32_t a = standsFor[param.indices[k]], b = standsFor[param.indices[k + 1]],
                     c = standsFor[param.indices[k + 2]];
      if (a == b || b == c || c == a) {
        ++s.degenerateTrianglesDropped;
        continue;
      }
      indices.insert(indices.end(), {a, b, c});
      trianglePatch.push_back(param.trianglePatch[k / 3]);
      cornerUv.insert(cornerUv.end(), param.cornerUv.begin() + long(k),
                      param.cornerUv.begin() + long(k) + 3);
    }
    s.degenerateTrianglesDropped +=
        keepTriangles(backToBackPairs(indices), indices, trianglePatch, cornerUv);
    s.degenerateTrianglesDropped +=
        keepTriangles(removeCaps(positions, indices, trianglePatch, cornerUv), indices,
                      trianglePatch, cornerUv);
    chunk.indices.resize(indices.size());
    for (size_t k = 0; k < indices.size(); ++k) chunk.indices[k] = output[indices[k]];
    chunk.trianglePatch = std::move(trianglePatch);
    s.triangles += chunk.trianglePatch.size();
    s.vertices += chunk.positions.size();
    sink_(chunk);
  }

  ModelFrame frame_;
  std::vector<BezierPatch> local_;
  QuadtreeOptions options_;
  Backend& backend_;
  const MeshChunkSink& sink_;
  PatchTopology topology_;
  CornerIndex corners_;
  std::vector<uint32_t> lastPatchOfSideGroup_;
  PatchSet gpuPatches_;
  SeamMap seams_;
  uint32_t nextIndex_ = 0;
};

}  // namespace

StreamedTessellationStats tessellateStreamed(const std::vector<BezierPatch>& patches,
                                             const QuadtreeOptions& options, Backend& backend,
                                             size_t patchesPerGroup, const MeshChunkSink& sink) {
  const Stopwatch total;
  for (size_t i = 0; i < patches.size(); ++i)
    validateTessellationPatch(patches[i], "patch " + std::to_string(i));
  StreamedTessellationStats stats;
  stats.totals.patches = patches.size();
  GroupStreamer streamer(patches, options, backend, sink);
  const bool adapt = patchesPerGroup == 0;
  size_t size = adapt ? std::max<size_t>(1, patches.size() / 8) : patchesPerGroup;
  for (size_t first = 0; first < patches.size();) {
    const size_t end = std::min(patches.size(), first + size);
    try {
      streamer.streamGroup(uint32_t(first), uint32_t(end), stats);
    } catch (const MemoryLimitError& e) {
      // Nothing of the group reached the sink (the estimate comes before the triangles).
      if (!adapt || size == 1)
        throw MemoryLimitError("streamed patches " + std::to_string(first) + "–" +
                               std::to_string(end - 1) + " with their neighbours: " + e.what());
      size /= 2;
      continue;
    }
    ++stats.groups;
    first = end;
  }
  stats.patchesPerGroup = size;
  stats.totals.totalMs = total.elapsedMs();
  return stats;
}

}  // namespace tessera
