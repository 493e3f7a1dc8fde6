// The lines of `tessera tessellate`'s summary that the held and the streamed runs share
// (cmd_tessellate.cpp, streamed_tessellate.cpp).
#pragma once
#include <cstdio>
#include <string>

#include "mesh/lower_bound.h"
#include "mesh/tessellate.h"

namespace tessera::cli {

// "<input>: N patches, method X, <thresholds>, backend B[ on <device>]"
void printRunLine(FILE* to, const std::string& input, const TessellationStats& s, SplitRule rule,
                  const std::string& thresholds, const std::string& backend,
                  const std::string& device);
// "depth …, leaves …, triangles …, vertices … (… zero-area dropped)"
void printCountsLine(FILE* to, const TessellationStats& s);
// Rule T in model units: "proven within <bound> of the surface (…)", and the leaves that are
// not (TessellationStats::diagonalFans).
void printProvenLine(FILE* to, double bound, double tolerance, size_t fannedLeaves);
// "lower bound at δ …: … triangles (…); this mesh has …x that (… ms)"
void printLowerBoundLine(FILE* to, const TriangleLowerBound& bound, size_t triangles);
// "time: tree …, triangulation …, vertices …, total … ms"
void printTimesLine(FILE* to, const TessellationStats& s);

}  // namespace tessera::cli
