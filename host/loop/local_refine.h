// Local Loop refinement with T-node splits (the paper's §3.1 (1), figure 6): chosen triangles are
// split 1 → 4 with new vertices by Loop's edge mask; a neighbour with one split edge becomes 2
// triangles, with two split edges 3, with three the regular 1 → 4 split. Existing vertices keep
// their positions bit for bit (the fitting step moves the ones near the seam afterwards).
#pragma once
#include <cstdint>
#include <vector>

#include "loop/shapes.h"

namespace tessera {

struct LocalRefinement {
  LoopShape mesh;
  // Per vertex of `mesh`: 1 when it belongs to a split triangle (the new vertices and the corners
  // of split triangles), the paper's "locally subdivided triangles' vertices" (figure 8).
  std::vector<uint8_t> refined;
};

// Splits the faces with split[f] != 0 (and neighbours as above). `refined` flags carry over
// from `previous` (may be empty) for the vertices that already existed.
LocalRefinement refineLocally(const LoopShape& mesh, const std::vector<uint8_t>& split,
                              const std::vector<uint8_t>& previous = {});

}  // namespace tessera
