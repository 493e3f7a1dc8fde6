// A program that uses an installed Tessera: tessellates a surface file and prints its triangles.
//   consumer <file.bpt|.grid|.json>
#include <tessera/tessera.h>

#include <cstdio>

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s <surface file>\n", argv[0]);
    return 2;
  }
  try {
    tessera::Tessellator tessellator;  // Vulkan if usable, else the CPU
    tessera::Mesh mesh = tessellator.tessellate(tessera::loadPatches(argv[1]));
    std::printf("tessera %s on %s: %zu triangles, %zu vertices\n", tessera::version(),
                tessellator.deviceName().c_str(), mesh.triangleCount(), mesh.vertexCount());
    const float* p = &mesh.positions[3 * mesh.indices[0]];
    std::printf("first triangle's first corner: %g %g %g\n", p[0], p[1], p[2]);
  } catch (const tessera::Error& e) {
    std::fprintf(stderr, "consumer: %s\n", e.what());
    return 1;
  }
}
