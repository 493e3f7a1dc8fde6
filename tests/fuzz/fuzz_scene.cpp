// libFuzzer target: the JSON scene reader (host/io/scene_reader.h) and, for small scenes, the
// conversion to bicubic patches that the CLI runs next (InputError is its only refusal too).
#include <sstream>

#include "fuzz_checks.h"
#include "io/scene_reader.h"
#include "io/scene_convert.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace tessera;
  fuzz::onlyInputErrors([&] {
    std::istringstream in(fuzz::asText(data, size));
    const Scene scene = parseScene(in, "fuzz.json");
    fuzz::expect(scene.order.size() ==
                 scene.bezier.size() + scene.rational.size() + scene.bsplines.size());
    fuzz::expectWellFormed(scene.bezier);
    size_t controlPoints = 0;
    for (const BSplineSurface& s : scene.bsplines) controlPoints += s.cp.size();
    if (controlPoints <= 4096) fuzz::expectWellFormed(sceneToBicubicPatches(scene));
  });
  return 0;
}
