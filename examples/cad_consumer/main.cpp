// A program that meshes a CAD model with an installed Tessera (tessera/cad.h, tessera::cad).
//   cad_consumer <model.step|.stp|.iges|.igs|.brep> [tolerance in model units]
#include <tessera/cad.h>

#include <cstdio>
#include <cstdlib>

int main(int argc, char** argv) {
  if (argc != 2 && argc != 3) {
    std::fprintf(stderr, "usage: %s <model.step> [tolerance]\n", argv[0]);
    return 2;
  }
  try {
    tessera::Tessellator tessellator;  // Vulkan if usable, else the CPU
    tessera::CadOptions options;       // 0.1% of the model's size unless a tolerance is given
    if (argc == 3) options.tolerance = std::strtod(argv[2], nullptr);
    const tessera::CadMesh cad = tessera::tessellateCadFile(tessellator, argv[1], options);
    std::printf("tessera %s on %s: %zu triangles, %zu of %zu faces, tolerance %g, measured %g\n",
                tessera::version(), tessellator.deviceName().c_str(), cad.mesh.triangleCount(),
                cad.facesMeshed, cad.faces, cad.tolerance, cad.maxDeviation);
    for (const std::string& warning : cad.warnings) std::printf("warning: %s\n", warning.c_str());
  } catch (const tessera::Error& e) {
    std::fprintf(stderr, "cad_consumer: %s\n", e.what());
    return 1;
  }
}
