// Points that two quad-trees put on one line independently and that are one point. Both sides
// of a line inside a patch are different subtrees, and both patches on a shared side are
// different trees; each places its leaf corners on the line by its own arithmetic, so the
// "same" split can land an fp32 ulp (teapot, rule C at 0.1: u = 0.41666672 and 0.4166667) or a
// few millionths (mirror-image patches, rule D's Newton steps) from its twin. Left apart, such a
// pair makes a sliver triangle a million times longer than wide, or of zero area in fp32.
//
// Merging is relative to the local spacing, never a fixed parameter distance: two adjacent
// points are one when their gap is at most kMergeFraction of the shortest leaf edge on the
// line that ends at either, or when fp32 could not tell them apart on the model. Why a
// real model cannot straddle it into a defect: one tree's own corners on a line are a leaf
// edge apart (ratio ≥ 1, never merged); a merged point moves by at most kMergeFraction of a
// leaf edge, far inside any flatness or tolerance bound, and two points fp32 cannot separate
// would be welded after evaluation anyway; a pair left apart is more than kMergeFraction of
// the leaf edge apart and more than kDistinctUlps apart on the model, so the fan triangle over
// it is at most about 4 / kMergeFraction times longer than wide and fp32 keeps its corners
// apart. Either side of the threshold is thus a correct mesh. On the tea set the ratios of
// near pairs run continuously from 2⁻²⁴ to 1 (rule D's Newton steps on mirror-image patches
// scatter their twins): with 2⁻⁸ the edges shorter than 2⁻¹⁰ of their neighbours went from
// 687 to 8, none of them a near pair (docs/watertight.md).
#pragma once
#include <functional>
#include <utility>
#include <vector>

namespace tessera {

struct LinePoint {
  float t;        // position on the line: a patch parameter, or a shared side's canonical one
  float spacing;  // the shortest leaf edge on the line that ends at t
};

constexpr float kMergeFraction = 1.0f / 256.0f;

// Two points fewer than this many fp32 units in the last place of their coordinates apart on
// the model are one point too, whatever the spacing: fp32 positions could not tell them apart
// (or only by a triangle rounding can flatten), so they would be welded after evaluation
// anyway, where merging them here keeps the mesh's topology an edge collapse.
constexpr double kDistinctUlps = 4.0;

// Sorts `points` by t, folds equal t into one (the shortest spacing), and returns the adjacent
// pairs (a, b), a < b, that are one point: b − a ≤ kMergeFraction × the smaller spacing, or
// closer than either spacing and not `distinct` (asked only then: it evaluates the surface).
// Runs of more than two come as consecutive pairs.
std::vector<std::pair<float, float>> nearPairs(std::vector<LinePoint>& points,
                                               const std::function<bool(float, float)>& distinct);
// The same on points[0, count), which keeps the folded points first: count becomes theirs.
std::vector<std::pair<float, float>> nearPairs(LinePoint* points, size_t& count,
                                               const std::function<bool(float, float)>& distinct);

}  // namespace tessera
