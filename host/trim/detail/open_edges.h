// The open edges of the triangles the cut keeps: the gap's boundary besides the trim loops
// (mesher.cpp). An open edge is a directed edge (a, b) of some triangle whose reverse (b, a) no
// triangle has.
#pragma once
#include <cstdint>
#include <utility>
#include <vector>

#include "trim/detail/gap_refine.h"

namespace tessera::trim_detail {

// Appends each open edge (a, b) reversed, as (b, a), once, in increasing (a, b) order: the
// order of a sorted list of the distinct directed edges, which the gap's triangulation is fed
// in. Every corner must be below vertexCount. Each vertex's outgoing edges are listed by
// counting (a handful each) instead of sorting all 3n directed edges and searching the list
// for each reverse: that sort and those searches were ~8% of the cut's time.
void appendReversedOpenEdges(const std::vector<FaceTriangle>& triangles, size_t vertexCount,
                             std::vector<std::pair<uint32_t, uint32_t>>& out);

}  // namespace tessera::trim_detail
