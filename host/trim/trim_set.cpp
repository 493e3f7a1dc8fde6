// Packing trim loops and piece rectangles for the trim classifiers (trim_classifier.h).
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "common/glsl_builtins.h"
#include "trim/trim_classifier.h"

namespace tessera::mirror::glsl {
#include "shaders/lib/shared_glsl_cpp.h"
#include "shaders/lib/trim_bin.h"
}  // namespace tessera::mirror::glsl

namespace tessera {
namespace {

std::string pointText(glm::dvec2 p) {
  return "(" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")";
}

// Finite and representable in fp32 with room for the margin.
bool fitsFloat(double x) { return std::isfinite(x) && std::abs(x) < 0.5 * double(FLT_MAX); }

// Faces with fewer segments are scanned whole; the others get about one bin per
// kSegmentsPerBin segments, at most kMaxBins, and fewer while the entries (a segment is one in
// every bin it spans) would pass kMaxEntriesPerSegment per segment.
constexpr uint32_t kBinnedSegments = 32;
constexpr uint32_t kSegmentsPerBin = 4;
constexpr uint32_t kMaxBins = 256;
constexpr size_t kMaxEntriesPerSegment = 8;

// Face `face`'s v bins appended to binWords: its bin table (binCount + 1 offsets into binWords),
// then each bin's entries (segment index, first bin of the segment), segments in index order.
void binFace(gpu::TrimFace& face, const std::vector<gpu::vec4>& segments,
             std::vector<uint32_t>& binWords) {
  const float range = face.box.w - face.box.y;
  if (face.segmentCount < kBinnedSegments || !(range > 0.0f) || !std::isfinite(range)) return;
  std::vector<std::pair<uint32_t, uint32_t>> spans(face.segmentCount);  // first, last bin
  uint32_t bins = std::min(kMaxBins, face.segmentCount / kSegmentsPerBin);
  float scale = 0.0f;
  for (;; bins /= 2) {
    scale = float(bins) / range;
    if (bins <= 1 || !std::isfinite(scale)) return;  // one bin reads every segment anyway
    size_t entries = 0;
    for (uint32_t k = 0; k < face.segmentCount; ++k) {
      const gpu::vec4 s = segments[face.firstSegment + k];
      spans[k] = {mirror::glsl::trimBin(std::min(s.y, s.w), face.box.y, scale, bins),
                  mirror::glsl::trimBin(std::max(s.y, s.w), face.box.y, scale, bins)};
      entries += spans[k].second - spans[k].first + 1;
    }
    if (entries <= kMaxEntriesPerSegment * face.segmentCount) break;
  }
  std::vector<uint32_t> counts(bins, 0);
  for (const auto& [first, last] : spans)
    for (uint32_t b = first; b <= last; ++b) ++counts[b];
  const size_t table = binWords.size();
  size_t next = table + bins + 1;
  binWords.resize(next);
  for (uint32_t b = 0; b < bins; ++b) {
    binWords[table + b] = uint32_t(next);
    next += 2 * size_t(counts[b]);
  }
  binWords[table + bins] = uint32_t(next);
  if (next > UINT32_MAX) throw std::length_error("trim: more than 2³² − 1 bin words");
  binWords.resize(next);
  std::vector<uint32_t> fill(binWords.begin() + table, binWords.begin() + table + bins);
  for (uint32_t k = 0; k < face.segmentCount; ++k)
    for (uint32_t b = spans[k].first; b <= spans[k].second; ++b) {
      binWords[fill[b]++] = face.firstSegment + k;
      binWords[fill[b]++] = spans[k].first;
    }
  face.firstBin = uint32_t(table);
  face.binCount = bins;
  face.binScale = scale;
}

}  // namespace

float trimMargin(double scale) {
  const double margin = std::ldexp(scale, -18);
  float rounded = float(margin);
  if (double(rounded) < margin) rounded = std::nextafter(rounded, std::numeric_limits<float>::infinity());
  return rounded;
}

TrimSet packTrimSet(const std::vector<std::vector<std::vector<glm::dvec2>>>& faceLoops,
                    const std::vector<TrimPieceRect>& pieces) {
  TrimSet set;
  // Room for every piece, face and segment up front: grown by doubling, the segment arrays
  // were copied a few times per tree.
  size_t segmentCount = 0;
  for (const auto& loops : faceLoops)
    for (const std::vector<glm::dvec2>& loop : loops) segmentCount += loop.size();
  set.pieces.reserve(pieces.size()), set.pieceRectsDouble.reserve(pieces.size());
  set.faces.reserve(faceLoops.size());
  set.segments.reserve(segmentCount), set.segmentsDouble.reserve(segmentCount);
  std::vector<double> scale(faceLoops.size(), 0.0);
  for (size_t k = 0; k < pieces.size(); ++k) {
    const TrimPieceRect& p = pieces[k];
    const glm::dvec4& r = p.rect;
    if (p.face >= faceLoops.size())
      throw std::invalid_argument("trim: piece " + std::to_string(k) + " names face " +
                                  std::to_string(p.face) + " of " +
                                  std::to_string(faceLoops.size()));
    if (!fitsFloat(r.x) || !fitsFloat(r.y) || !fitsFloat(r.z) || !fitsFloat(r.w) ||
        !(r.x < r.z) || !(r.y < r.w))
      throw std::invalid_argument("trim: piece " + std::to_string(k) + " of face " +
                                  std::to_string(p.face) +
                                  ": its rectangle must be finite with u0 < u1 and v0 < v1 (got " +
                                  pointText({r.x, r.y}) + " to " + pointText({r.z, r.w}) + ")");
    scale[p.face] = std::max({scale[p.face], std::abs(r.x), std::abs(r.y), std::abs(r.z),
                              std::abs(r.w)});
    set.pieces.push_back({gpu::vec4(r), p.face, 0u, 0u, 0u});
    set.pieceRectsDouble.push_back(r);
  }
  for (size_t f = 0; f < faceLoops.size(); ++f) {
    gpu::TrimFace face{};
    face.firstSegment = uint32_t(set.segments.size());
    face.box = gpu::vec4(FLT_MAX, FLT_MAX, -FLT_MAX, -FLT_MAX);
    for (size_t l = 0; l < faceLoops[f].size(); ++l) {
      const std::vector<glm::dvec2>& loop = faceLoops[f][l];
      for (size_t i = 0; i < loop.size(); ++i) {
        if (!fitsFloat(loop[i].x) || !fitsFloat(loop[i].y))
          throw std::invalid_argument("trim: face " + std::to_string(f) + ", loop " +
                                      std::to_string(l) + ", point " + std::to_string(i) +
                                      ": coordinates must be finite and within fp32 (got " +
                                      pointText(loop[i]) + ")");
        const glm::dvec2 a = loop[i], b = loop[(i + 1) % loop.size()];
        scale[f] = std::max({scale[f], std::abs(a.x), std::abs(a.y)});
        const gpu::vec4 s(float(a.x), float(a.y), float(b.x), float(b.y));
        set.segments.push_back(s);
        set.segmentsDouble.push_back({a.x, a.y, b.x, b.y});
        face.box = gpu::vec4(std::min(face.box.x, s.x), std::min(face.box.y, s.y),
                             std::max(face.box.z, s.x), std::max(face.box.w, s.y));
      }
    }
    face.segmentCount = uint32_t(set.segments.size()) - face.firstSegment;
    if (face.segmentCount == 0) face.box = gpu::vec4(0.0f);
    set.faces.push_back(face);
  }
  for (size_t f = 0; f < set.faces.size(); ++f) {
    set.faces[f].margin = trimMargin(scale[f]);
    binFace(set.faces[f], set.segments, set.binWords);
  }
  return set;
}

TrimSet packTrimSet(const TrimmedModel& model) {
  std::vector<std::vector<std::vector<glm::dvec2>>> loops(model.faces.size());
  std::vector<TrimPieceRect> pieces;
  for (size_t f = 0; f < model.faces.size(); ++f) {
    for (const TrimLoop& loop : model.faces[f].loops) loops[f].push_back(loop.uv);
    for (const BezierPatchPiece& piece : model.faces[f].pieces)
      pieces.push_back({uint32_t(f), {piece.u0, piece.v0, piece.u1, piece.v1}});
  }
  try {
    return packTrimSet(loops, pieces);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string(e.what()) + " (faces numbered in model order)");
  }
}

void validateTrimQueries(const TrimSet& set, const std::vector<gpu::TrimQuery>& queries) {
  for (size_t i = 0; i < queries.size(); ++i)
    if (queries[i].piece >= set.pieces.size())
      throw std::out_of_range("trim: query " + std::to_string(i) + " names piece " +
                              std::to_string(queries[i].piece) + " of " +
                              std::to_string(set.pieces.size()));
}

}  // namespace tessera
