// A trimmed face's surface as one function of the face's (u, v): the Bézier piece whose
// rectangle holds (u, v), evaluated in double (the reference kernel). Points outside every
// piece go to the nearest piece, clamped to its rectangle (trim loops may overhang the
// surface's domain by the CAD model's tolerance).
#pragma once
#include <array>
#include <glm/glm.hpp>
#include <optional>
#include <vector>

#include "geometry/rational.h"
#include "trim/trimmed_face.h"

namespace tessera {

class FaceSurface {
 public:
  explicit FaceSurface(const TrimmedFace& face);
  // The piece for (u, v) and (u, v) in its local [0,1]² (clamped).
  size_t pieceAt(glm::dvec2 uv) const;
  glm::dvec2 localUv(size_t piece, glm::dvec2 uv) const;
  glm::dvec2 faceUv(size_t piece, glm::dvec2 local) const;
  glm::dvec3 point(glm::dvec2 uv) const;
  // point() at three uvs of one v (uvs[k].y all equal; otherwise, or across pieces, three
  // point() calls): the same doubles, the v direction's sums taken once.
  std::array<glm::dvec3, 3> pointsAlongU(const std::array<glm::dvec2, 3>& uvs) const;
  // point() of each of `count` uvs into `out`: the same doubles, the piece's form and degrees
  // looked up once when every uv falls in one piece, and the points' divisions overlapping in
  // the loop.
  void points(const glm::dvec2* uvs, size_t count, glm::dvec3* out) const;
  // Distance from `target` to the surface, by the closest-point search on the piece of
  // `guess` started there (closest_point.h): an upper bound of the true distance. With
  // `enough` > 0 the search ends once within it (closestPointOnPatch's `enough`).
  double distance(const glm::dvec3& target, glm::dvec2 guess, double enough = 0.0) const;
  // The largest |coordinate| of the pieces' control points: every evaluation is a convex mix
  // of them (weights ≥ 0), so its rounding is a few ulps of this.
  double netReach() const { return netReach_; }
  // Means over a 6 × 6 grid of [lo, hi], by central differences (one set of five points per
  // grid point).
  struct Scales {
    // |∂S/∂u| and |∂S/∂v|: (u·su, v·sv) makes (u, v) distances about 3D distances. Never
    // below 10⁻¹² of the larger, so a pole does not collapse a direction.
    glm::dvec2 speeds;
    // |n·∂²S/∂u²| and |n·∂²S/∂v²| (n the unit normal): how fast the surface leaves its tangent
    // plane along u and along v. A chord of parameter length d along u is off the surface by
    // about ⅛·b_u·d² (a cylinder, flat along its rulings, has b_v = 0).
    glm::dvec2 bending;
  };
  Scales meanScales(glm::dvec2 lo, glm::dvec2 hi) const;
  // The same doubles, each point by pointsAlongU and points() (the plain version, for tests:
  // meanScales takes a one-piece face's grid with its shared rows once).
  Scales meanScalesPointwise(glm::dvec2 lo, glm::dvec2 hi) const;

 private:
  // meanScales' sums from its 6 × 6 grid's points, 5 a grid point (u − h, u, u + h, v − h, v + h).
  static Scales scalesOf(const std::array<glm::dvec3, 5 * 36>& stencil, glm::dvec2 h);
  static constexpr size_t kNoPiece = ~size_t(0);
  // The cell of the pieces' grid along one axis holding x (clamped to the grid).
  static size_t cellOf(const std::vector<double>& sides, double x);
  // point() on a known piece (pieceAt's answer for uv).
  glm::dvec3 pointOnPiece(size_t piece, glm::dvec2 uv) const;
  // pieceAt of each uv into `pieces`, from the cells of the uvs' box (no search per uv); false
  // where that box holds a hole of the pieces' grid or a uv is NaN (then pieceAt decides).
  bool piecesInBox(const glm::dvec2* uvs, size_t count, std::vector<size_t>& pieces) const;
  // pieceAt of every uv when they all agree, kNoPiece otherwise.
  size_t commonPiece(const glm::dvec2* uvs, size_t count) const;
  const TrimmedFace* face_;
  std::vector<double> us_, vs_;       // the pieces' sorted distinct sides
  std::vector<int> cellPiece_;        // (us_.size()−1)·(vs_.size()−1) cells → piece or −1
  std::vector<std::optional<RationalBezierPatch>> rational_;  // per rational piece, its form
  double netReach_ = 0;
  bool checked_ = false;  // every piece passes validateTessellationPatch: the fast point()
};

}  // namespace tessera
