#ifdef TESSERA_HAVE_CAD
#include "cad_test_shapes.h"

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepBuilderAPI_MakeEdge.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeWire.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <BRepFilletAPI_MakeFillet.hxx>
#include <BRepLib.hxx>
#include <BRepOffsetAPI_MakeThickSolid.hxx>
#include <BRepPrimAPI_MakeBox.hxx>
#include <BRepPrimAPI_MakeCylinder.hxx>
#include <BRepPrimAPI_MakePrism.hxx>
#include <BRepPrimAPI_MakeSphere.hxx>
#include <BRepPrimAPI_MakeTorus.hxx>
#include <BRep_Tool.hxx>
#include <GC_MakeArcOfCircle.hxx>
#include <GC_MakeSegment.hxx>
#include <Geom2d_Circle.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_Plane.hxx>
#include <Geom_Surface.hxx>
#include <TColStd_Array1OfInteger.hxx>
#include <TColStd_Array1OfReal.hxx>
#include <TColgp_Array2OfPnt.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <cmath>

namespace tessera::test {
namespace {

// OCCT's tutorial bottle (MakeBottle), without the thread: a profile of two segments and an
// arc, mirrored, extruded, every edge filleted, a cylindrical neck fused on, hollowed from the
// neck's top face.
TopoDS_Shape bottle(double width, double height, double thickness) {
  gp_Pnt p1(-width / 2, 0, 0), p2(-width / 2, -thickness / 4, 0), p3(0, -thickness / 2, 0);
  gp_Pnt p4(width / 2, -thickness / 4, 0), p5(width / 2, 0, 0);
  TopoDS_Edge e1 = BRepBuilderAPI_MakeEdge(GC_MakeSegment(p1, p2).Value());
  TopoDS_Edge e2 = BRepBuilderAPI_MakeEdge(GC_MakeArcOfCircle(p2, p3, p4).Value());
  TopoDS_Edge e3 = BRepBuilderAPI_MakeEdge(GC_MakeSegment(p4, p5).Value());
  TopoDS_Wire half = BRepBuilderAPI_MakeWire(e1, e2, e3);
  gp_Trsf mirror;
  mirror.SetMirror(gp::OX());
  BRepBuilderAPI_MakeWire profile;
  profile.Add(half);
  profile.Add(TopoDS::Wire(BRepBuilderAPI_Transform(half, mirror).Shape()));
  TopoDS_Face base = BRepBuilderAPI_MakeFace(profile.Wire());
  TopoDS_Shape body = BRepPrimAPI_MakePrism(base, gp_Vec(0, 0, height));
  BRepFilletAPI_MakeFillet fillet(body);
  for (TopExp_Explorer e(body, TopAbs_EDGE); e.More(); e.Next())
    fillet.Add(thickness / 12, TopoDS::Edge(e.Current()));
  body = fillet.Shape();
  gp_Ax2 neckAxis(gp_Pnt(0, 0, height), gp::DZ());
  body = BRepAlgoAPI_Fuse(body, BRepPrimAPI_MakeCylinder(neckAxis, thickness / 4, height / 10).Shape());
  TopoDS_Face top;
  double topZ = -1e300;
  for (TopExp_Explorer f(body, TopAbs_FACE); f.More(); f.Next()) {
    auto plane = Handle(Geom_Plane)::DownCast(BRep_Tool::Surface(TopoDS::Face(f.Current())));
    if (!plane.IsNull() && plane->Location().Z() > topZ) topZ = plane->Location().Z(), top = TopoDS::Face(f.Current());
  }
  TopTools_ListOfShape removed;
  removed.Append(top);
  BRepOffsetAPI_MakeThickSolid hollow;
  hollow.MakeThickSolidByJoin(body, removed, -thickness / 50, 1e-3);
  return hollow.Shape();
}

TopoDS_Shape sphereWithHoles() {
  TopoDS_Shape shape = BRepPrimAPI_MakeSphere(1.0).Shape();
  const gp_Dir axes[3] = {gp::DX(), gp::DY(), gp_Dir(1, 1, 1)};
  for (const gp_Dir& axis : axes) {
    gp_Ax2 frame(gp_Pnt(0, 0, 0).Translated(gp_Vec(axis) * -2.0), axis);
    shape = BRepAlgoAPI_Cut(shape, BRepPrimAPI_MakeCylinder(frame, 0.3, 4.0).Shape());
  }
  return shape;
}

Handle(Geom_BSplineSurface) bumpySurface(int degreeU, int polesU) {
  TColgp_Array2OfPnt poles(1, polesU, 1, 4);
  for (int i = 1; i <= polesU; ++i)
    for (int j = 1; j <= 4; ++j)
      poles(i, j) = gp_Pnt(i - 1.0, j - 1.0, 0.4 * std::sin(1.3 * i) * std::cos(0.9 * j));
  const int spansU = polesU - degreeU;
  TColStd_Array1OfReal knotsU(1, spansU + 1), knotsV(1, 2);
  TColStd_Array1OfInteger multsU(1, spansU + 1), multsV(1, 2);
  for (int k = 1; k <= spansU + 1; ++k) {
    knotsU(k) = k - 1.0;
    multsU(k) = (k == 1 || k == spansU + 1) ? degreeU + 1 : 1;
  }
  knotsV(1) = 0.0, knotsV(2) = 1.0, multsV(1) = multsV(2) = 4;
  return new Geom_BSplineSurface(poles, knotsU, knotsV, multsU, multsV, degreeU, 3);
}

// A bicubic B-spline face (two spans in u) with a circular hole: the inner wire's edge is a
// pcurve circle on the surface, its 3D curve built from it (BRepLib::BuildCurves3d).
TopoDS_Shape nurbsFaceWithHole() {
  Handle(Geom_BSplineSurface) surface = bumpySurface(3, 5);
  Handle(Geom2d_Circle) circle = new Geom2d_Circle(gp_Ax2d(gp_Pnt2d(1.0, 0.5), gp_Dir2d(1, 0)), 0.3);
  TopoDS_Edge rim = BRepBuilderAPI_MakeEdge(circle, surface);
  BRepLib::BuildCurves3d(rim);
  TopoDS_Wire hole = BRepBuilderAPI_MakeWire(rim);
  hole.Reverse();  // clockwise in uv: a hole
  BRepBuilderAPI_MakeFace face(surface, 1e-7);
  face.Add(hole);
  TopoDS_Shape result = face.Shape();
  BRepLib::BuildCurves3d(result);
  return result;
}

}  // namespace

std::vector<NamedShape> occtTestShapes() {
  return {
      {"box", BRepPrimAPI_MakeBox(2.0, 1.0, 0.5).Shape()},
      {"cylinder", BRepPrimAPI_MakeCylinder(0.5, 2.0).Shape()},
      {"sphere", BRepPrimAPI_MakeSphere(1.0).Shape()},
      {"torus", BRepPrimAPI_MakeTorus(2.0, 0.5).Shape()},
      {"bottle", bottle(50.0, 70.0, 30.0)},
      {"sphere with holes", sphereWithHoles()},
      {"NURBS face with a hole", nurbsFaceWithHole()},
  };
}

TopoDS_Shape degreeEightFace() {
  return BRepBuilderAPI_MakeFace(bumpySurface(8, 9), 1e-7).Shape();
}

}  // namespace tessera::test
#endif
