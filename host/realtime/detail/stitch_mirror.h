// The fp32 mirror of shaders/stitch_pattern.comp.glsl: the same pattern functions
// (shaders/lib/stitch_pattern.h) compiled as C++ with -ffp-contract=off, bit-identical to the
// shader on lavapipe; and the pattern's counts for the host, which lays out each frame.
#pragma once
#include <cstdint>
#include <vector>

#include "shaders/layout.h"

namespace tessera::mirror {

// One work item (record << kStitchSlotBits | band) into the frame's vertex and index arrays,
// as one shader invocation does.
void stitchItem(const gpu::BicubicPatch* patches, const gpu::StitchPatch* records,
                const gpu::vec4* edgePoints, uint32_t item, float eps, gpu::GridVertex* vertices,
                uint32_t* indices);

uint32_t stitchVertexCount(const gpu::StitchPatch& record);
uint32_t stitchTriangleCount(const gpu::StitchPatch& record);
uint32_t stitchItemCount(const gpu::StitchPatch& record);  // bands of inner rows
// Local index of edge point k (0 ≤ k ≤ sideSegments[side]) of side `side`, in the side's t.
uint32_t stitchSideVertex(const gpu::StitchPatch& record, uint32_t side, uint32_t k);

// (u, v) of each of the record's vertices, in its local order (the shader's fp32 parameters).
std::vector<gpu::vec2> stitchVertexParams(const gpu::StitchPatch& record);

}  // namespace tessera::mirror
