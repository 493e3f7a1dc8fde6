// The tolerance δ of rule T as a user gives it: in model units ("0.01") or relative to the size
// of the model ("0.1%" of the diagonal of the bounding box of all control points; for rational
// patches the points of weight > 0, whose affine position is defined). Shared by the CLI and the
// public API so that "0.1%" means the same model-unit δ everywhere.
#pragma once
#include <string>
#include <vector>

#include "geometry/patch.h"
#include "quadtree/quadtree.h"

namespace tessera {

// The default δ when rule T runs without one: 0.1% of the diagonal. Open CASCADE's importers
// mesh at about 1/1000 of the model's size; the teapot (control-point diagonal 8.28) gets
// δ = 0.0083, under a pixel on a 1000-pixel-wide view of the whole model.
constexpr double kDefaultRelativeTolerance = 0.001;

struct ToleranceSpec {
  double value = kDefaultRelativeTolerance;  // model units, or a fraction (0.001 for "0.1%")
  bool relative = true;                      // value is a fraction of the diagonal
  bool pixels = false;                       // value is in pixels: needs a camera (rule T in
                                             // screen space, mesh/screen_tolerance.h)
  std::string text = "0.1%";                 // as the user gave it
};

// "0.01" (model units, finite and > 0), "0.1%" (a percentage in (0, 100]) or "1px" (pixels,
// finite and > 0). Throws std::invalid_argument naming the text for anything else (0,
// negative, NaN, inf, "abc%", "150%", "0px", trailing garbage).
ToleranceSpec parseTolerance(const std::string& text);

// The diagonal of the axis-aligned bounding box of every control point of every patch
// (weight-0 points left out). Throws std::invalid_argument when there is no patch or the
// diagonal is 0 (every point the same), since a relative tolerance would then be 0.
double controlPointDiagonal(const std::vector<BezierPatch>& patches);

// δ in model units: spec.value, or spec.value × controlPointDiagonal(patches). A pixel
// tolerance has no model-unit value: std::invalid_argument saying it needs a camera.
double resolveTolerance(const ToleranceSpec& spec, const std::vector<BezierPatch>& patches);

// "0.007 (0.1% of the diagonal 7.2)", "0.01" or "1 px": for summaries and messages.
std::string describeTolerance(const ToleranceSpec& spec, double resolved);

// Rule T: the largest proven deviation bound over the tree's leaves, in model units (each
// rule-T leaf keeps its bound in QuadLeaf::flatness, in units of tree.boundScale); 0 for a tree
// without leaves.
double largestLeafBound(const QuadtreeResult& tree);

}  // namespace tessera
