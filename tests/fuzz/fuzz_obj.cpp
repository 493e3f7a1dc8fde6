// libFuzzer target: the OBJ reader and its topology checks (host/io/obj_reader.h).
#include <sstream>

#include "fuzz_checks.h"
#include "io/obj_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace tessera;
  fuzz::onlyInputErrors([&] {
    std::istringstream in(fuzz::asText(data, size));
    const PolygonMesh mesh = parseObj(in, "fuzz.obj");
    fuzz::expect(!mesh.positions.empty() && !mesh.faces.empty());
    fuzz::expect(mesh.faceLines.size() == mesh.faces.size());
    for (const glm::dvec3& p : mesh.positions) fuzz::expect(fuzz::finite(p));
    for (const auto& face : mesh.faces) {
      fuzz::expect(face.size() >= 3);
      for (uint32_t v : face) fuzz::expect(v < mesh.positions.size());
    }
    validateManifold(mesh, "fuzz.obj");
    validateTriangles(mesh, "fuzz.obj");
  });
  return 0;
}
