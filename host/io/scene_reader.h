// Reader for Tessera's JSON scene format: Bézier patches (polynomial or rational) and
// B-spline surfaces in one file. The format, with a complete example, is documented in
// docs/scene_format.md; in short:
//
//   {"tessera_scene": 1,
//    "surfaces": [
//      {"type": "bezier", "degree": [n, m], "points": [[x, y, z], ...],  "weights": [...]},
//      {"type": "bspline", "degree": [p, q], "count": [nu, nv],
//       "knots_u": [...], "knots_v": [...], "points": [[x, y, z], ...]} ]}
//
// Points are row by row, i along u (BezierPatch order, docs/conventions.md); "weights" is
// optional and makes the patch rational. The reader is as strict as the .bpt reader: unknown
// keys, wrong types, degrees outside 1..7, wrong counts, non-finite numbers, |x| > 1e15,
// negative weights, zero corner weights and invalid knot vectors are all InputErrors
// (host/io/errors.h) naming the file, the line of the offending JSON value and the reason.
#pragma once
#include <cstddef>
#include <cstdint>
#include <istream>
#include <string>
#include <string_view>
#include <vector>

#include "bspline/bspline.h"
#include "geometry/patch.h"

namespace tessera {

constexpr int kSceneFormatVersion = 1;

enum class SceneSurfaceType { Bezier, Rational, BSpline };

// Where a surface of the scene came from: its vector and index in Scene, and the lines that
// later messages (sceneToBicubicPatches) point at.
struct SceneSurfaceRef {
  SceneSurfaceType type = SceneSurfaceType::Bezier;
  size_t index = 0;     // into Scene::bezier, ::rational or ::bsplines
  int line = 0;         // the surface object's '{'
  int degreeLine = 0;   // its "degree" value
  int weightsLine = 0;  // its "weights" value (rational patches)
  std::string name;     // its optional "name", empty when none
};

struct Scene {
  std::vector<BezierPatch> bezier;             // polynomial patches
  std::vector<RationalBezierPatch> rational;   // homogeneous (w·x, w·y, w·z, w)
  std::vector<BSplineSurface> bsplines;
  // The surfaces in file order ("surface k" in messages is order[k - 1]). A scene built in
  // code may leave it empty: the order is then bezier, rational, bsplines.
  std::vector<SceneSurfaceRef> order;
  std::string source;  // the file name used in messages; empty for a scene built in code
};

// Read the file at `path`; an unreadable file is an InputError of kind Io.
Scene readScene(const std::string& path);

// The bytes parseScene holds for `text`: the text, the JSON document (whose
// values are counted from the commas and brackets, and the scene's numbers); it throws
// MemoryLimitError (common/memory_budget.h) before parsing when this exceeds the budget.
uint64_t estimatedSceneBytes(std::string_view text);

// Parse scene JSON from `in`; `nameForMessages` stands for the file in error messages.
Scene parseScene(std::istream& in, const std::string& nameForMessages);

}  // namespace tessera
