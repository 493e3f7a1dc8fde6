// CadSurface::mapUvs's Newton solves (host/cad/face_surface.cpp) stop early once an iterate
// repeats: they must still give the bits of the full 40 iterations, here run as the import ran
// them before, on Geom_BSplineSurface::D1, over the IDF library's reparametrised faces.
#ifdef TESSERA_HAVE_CAD
#include <catch2/catch.hpp>
#include <TopoDS.hxx>
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "cad/cad_file.h"
#include "cad/face_surface.h"
#include "cad/to_trimmed.h"

namespace {

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// The solve as it was: every one of the 40 iterations evaluated unless the step is tiny.
// `cycled` tells whether an iterate repeated an earlier one (the case the import cuts short).
double fullSolve(const tessera::CadSurface& s, double t, bool alongU, bool& cycled) {
  const gp_Pnt target = alongU ? s.original->Value(t, s.vRef) : s.original->Value(s.uRef, t);
  double lo, hi, c0, c1;
  if (alongU) s.nurbs->Bounds(lo, hi, c0, c1); else s.nurbs->Bounds(c0, c1, lo, hi);
  const double width = hi - lo;
  std::vector<double> iterates;
  double x = t;
  for (int iteration = 0; iteration < 40; ++iteration) {
    for (const double earlier : iterates) cycled = cycled || sameBits(earlier, x);
    iterates.push_back(x);
    gp_Pnt p;
    gp_Vec du, dv;
    if (alongU) s.nurbs->D1(x, s.vRef, p, du, dv); else s.nurbs->D1(s.uRef, x, p, du, dv);
    const gp_Vec d = alongU ? du : dv;
    const double dd = d.SquareMagnitude();
    if (dd == 0.0) break;
    const double step = gp_Vec(p, target).Dot(d) / dd;
    x = std::clamp(x + step, lo - width, hi + width);
    if (std::abs(step) <= 1e-15 * std::max(1.0, std::abs(x))) break;
  }
  return x;
}

}  // namespace

TEST_CASE("cad: the uv map's solves cut short at a repeated iterate give the full solves' bits",
          "[cad]") {
  const std::string dir = "/usr/share/freecad/Mod/Idf/Idflibs";
  REQUIRE(std::filesystem::exists(dir + "/CAP_50SGV_8_10.stp"));  // freecad-common
  size_t solves = 0, cycled = 0, differing = 0;
  for (const char* name : {"CAP_50SGV_8_10.stp", "0805_SMD.stp", "RLF_12545.stp", "EPL22_6_16.stp"}) {
    const tessera::CadFile file = tessera::readCadFile(dir + "/" + name);
    const tessera::CadImport in = tessera::toTrimmedModel(file, 1e-3, 1);
    for (size_t f = 0; f < in.model.faces.size(); ++f) {
      const TopoDS_Face face = TopoDS::Face(
          in.faces(int(in.model.faces[f].faceIndex) + 1).Oriented(TopAbs_FORWARD));
      const std::array<double, 4>& b = in.uvBounds[f];
      const tessera::CadSurface surface =
          tessera::convertFaceSurface(tessera::faceBasisSurface(face), b[0], b[1], b[2], b[3]);
      if (!surface.reparametrised) continue;
      // A 41 × 41 grid over the face's bounds and a little beyond: 41 distinct u and v each.
      std::vector<gp_Pnt2d> grid;
      for (int i = 0; i <= 40; ++i) {
        const double s = -0.05 + 1.1 * i / 40.0;
        grid.emplace_back(b[0] + (b[1] - b[0]) * s, b[2] + (b[3] - b[2]) * s);
      }
      const std::vector<glm::dvec2> mapped = surface.mapUvs(grid);
      for (size_t k = 0; k < grid.size(); ++k) {
        bool cycledU = false, cycledV = false;
        const double u = fullSolve(surface, grid[k].X(), true, cycledU);
        const double v = fullSolve(surface, grid[k].Y(), false, cycledV);
        solves += 2;
        cycled += size_t(cycledU) + size_t(cycledV);
        if (!sameBits(u, mapped[k].x) || !sameBits(v, mapped[k].y)) ++differing;
      }
    }
  }
  std::printf("map solves: %zu, %zu of them cycling, %zu points differing\n", solves, cycled, differing);
  CHECK(solves > 1000);
  CHECK(cycled > 0);  // the shortcut was taken
  CHECK(differing == 0);
}

#endif  // TESSERA_HAVE_CAD
