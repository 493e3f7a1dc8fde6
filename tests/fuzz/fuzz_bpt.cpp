// libFuzzer target: the .bpt reader (host/io/bpt_reader.h).
#include <sstream>

#include "fuzz_checks.h"
#include "io/bpt_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  using namespace tessera;
  fuzz::onlyInputErrors([&] {
    std::istringstream in(fuzz::asText(data, size));
    const std::vector<BezierPatch> patches = parseBpt(in, "fuzz.bpt");
    fuzz::expect(!patches.empty());
    fuzz::expectWellFormed(patches);
  });
  return 0;
}
