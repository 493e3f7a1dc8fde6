// Shapes the CAD import tests build with Open CASCADE itself (issue 17's list).
#pragma once
#ifdef TESSERA_HAVE_CAD
#include <TopoDS_Shape.hxx>
#include <string>
#include <vector>

namespace tessera::test {

struct NamedShape {
  std::string name;
  TopoDS_Shape shape;
};

// A box, a cylinder, a sphere, a torus, OCCT's tutorial bottle (filleted body, neck, hollowed),
// a sphere with holes cut by cylinders, a NURBS face with an inner trim loop.
std::vector<NamedShape> occtTestShapes();

// One B-spline face of degree 8 × 3 (Tessera takes degrees up to 7): a face that must fail.
TopoDS_Shape degreeEightFace();

}  // namespace tessera::test
#endif
