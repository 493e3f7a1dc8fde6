// What every Tessera fuzz target asserts, besides "no crash, no sanitizer report": a reader
// either returns well-formed data or throws InputError, or LimitError where the input asks
// for more than the memory budget (its documented refusal, exit 4) — any other exception escapes
// LLVMFuzzerTestOneInput, which libFuzzer reports as a crash — and what it returns is what
// its documentation promises (finite numbers, consistent sizes). A broken promise traps.
#pragma once
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "io/errors.h"
#include "geometry/patch.h"

namespace tessera::fuzz {

inline std::string asText(const uint8_t* data, size_t size) {
  return std::string(reinterpret_cast<const char*>(data), size);
}

// Stops the run with a crash report (libFuzzer saves the input) when `ok` is false.
inline void expect(bool ok) {
  if (!ok) __builtin_trap();
}

inline bool finite(const glm::dvec3& p) { return std::isfinite(p.x + p.y + p.z); }

inline void expectWellFormed(const std::vector<BezierPatch>& patches) {
  for (const BezierPatch& p : patches) {
    expect(p.degreeU >= 1 && p.degreeU <= kMaxDegree && p.degreeV >= 1 && p.degreeV <= kMaxDegree);
    expect(p.cp.size() == size_t(p.degreeU + 1) * size_t(p.degreeV + 1));
    for (const glm::dvec3& c : p.cp) expect(finite(c));
  }
}

// Runs `read`; an InputError, or a LimitError (a grid header of 9999999×3 points asks for
// 15 GiB: refused before allocating), is a fine answer; anything else escapes as a crash.
template <typename Read>
void onlyInputErrors(Read read) {
  try {
    read();
  } catch (const InputError&) {
  } catch (const LimitError&) {
  }
}

}  // namespace tessera::fuzz
