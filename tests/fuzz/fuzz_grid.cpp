// libFuzzer target: the .grid reader (host/io/grid_reader.h) and, for small grids, the
// interpolation into bicubic patches that the CLI runs next.
#include <sstream>

#include "fuzz_checks.h"
#include "geometry/grid_interpolation.h"
#include "io/grid_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace tessera;
  fuzz::onlyInputErrors([&] {
    std::istringstream in(fuzz::asText(data, size));
    const GridData grid = parseGrid(in, "fuzz.grid");
    fuzz::expect(grid.rows >= 2 && grid.cols >= 2);
    fuzz::expect(grid.points.size() == size_t(grid.rows) * size_t(grid.cols));
    for (const glm::dvec3& p : grid.points) fuzz::expect(fuzz::finite(p));
    if (grid.points.size() <= 4096) {
      const std::vector<BezierPatch> patches = interpolateGrid(grid);
      fuzz::expect(patches.size() == size_t(grid.rows - 1) * size_t(grid.cols - 1));
      fuzz::expectWellFormed(patches);
    }
  });
  return 0;
}
