// One quad-tree node against its face's trim loops, in fp32: outside, inside or crossing
// (docs/trimmed_faces.md, "Classifying nodes against trim loops (GPU)", derives the margin).
// Compiled twice from this one text: as GLSL in shaders/trim_classify.comp.glsl, where faces,
// pieces and segments are storage buffers, and as C++ inside the struct of
// host/trim/trim_classify_mirror.cpp, where they are members of the same names. PRECISE on
// every local: no fused multiply-add, so lavapipe and the mirror round identically.
// Include shared_glsl_cpp.h and lib/trim_bin.h first.
#ifndef TESSERA_TRIM_CLASSIFY_H
#define TESSERA_TRIM_CLASSIFY_H

// (b − a) × (p − a) for the segment s = (a, b): > 0 when p lies left of a → b. `bound` gets
// the bound on its rounding: every input is an fp32 value, four differences, two products and
// one difference, Shewchuk's orient2d (1997, §4.2), whose bound (3 + 16u)·u·(|l| + |r|) is
// below kTrimOrientErrorFactor·(|l| + |r|).
float trimOrient(IN(vec4) s, float px, float py, OUT(float) bound) {
  PRECISE float left = (s.z - s.x) * (py - s.y);
  PRECISE float right = (s.w - s.y) * (px - s.x);
  PRECISE float value = left - right;
  PRECISE float magnitude = abs(left) + abs(right);
  PRECISE float scaled = kTrimOrientErrorFactor * magnitude;
  bound = scaled;
  return value;
}

// Whether segment s meets the closed box (u0, v0, u1, v1): by separating axes, its bounding
// box overlaps the box (exact comparisons) and the box's corners are not all on one side of
// its line. A corner whose side rounding cannot certify counts as on the line: conservative.
bool trimSegmentMeetsBox(IN(vec4) s, IN(vec4) box) {
  if (max(s.x, s.z) < box.x || min(s.x, s.z) > box.z || max(s.y, s.w) < box.y ||
      min(s.y, s.w) > box.w)
    return false;
  int positive = 0;
  int negative = 0;
  for (int k = 0; k < 4; ++k) {
    float px = (k & 1) == 0 ? box.x : box.z;
    float py = (k & 2) == 0 ? box.y : box.w;
    float bound = 0.0f;
    PRECISE float side = trimOrient(s, px, py, bound);
    if (side > bound)
      ++positive;
    else if (side < -bound)
      ++negative;
    else
      return true;
  }
  return positive > 0 && negative > 0;
}

// The node's rectangle in face (u, v): the piece's rectangle at the node's fractions,
// u = a + s·(b − a), as the double reference maps it (within 8u·U per side, U the face scale).
vec4 trimFaceRect(IN(vec4) piece, IN(vec4) node) {
  PRECISE float du = piece.z - piece.x;
  PRECISE float dv = piece.w - piece.y;
  PRECISE float su0 = node.x * du;
  PRECISE float sv0 = node.y * dv;
  PRECISE float su1 = node.z * du;
  PRECISE float sv1 = node.w * dv;
  PRECISE float u0 = piece.x + su0;
  PRECISE float v0 = piece.y + sv0;
  PRECISE float u1 = piece.x + su1;
  PRECISE float v1 = piece.y + sv1;
  return vec4(u0, v0, u1, v1);
}

// One segment's part in a node's answer: true when it meets the grown rectangle (the node is
// crossing); else `inside` flips when it crosses the ray from the centre (cu, cv) towards +u
// (half-open in v: its ends on opposite sides of v = cv, one strictly above).
bool trimSegmentStep(IN(vec4) s, IN(vec4) grown, float cu, float cv, INOUT(bool) inside) {
  if (trimSegmentMeetsBox(s, grown)) return true;
  if ((s.y > cv) != (s.w > cv)) {
    // The segment crosses v = cv outside the grown box, at least the margin away from the
    // centre: the side's sign is certain (docs/trimmed_faces.md).
    float bound = 0.0f;
    PRECISE float side = trimOrient(s, cu, cv, bound);
    if ((side > 0.0f) == (s.w > s.y)) inside = !inside;
  }
  return false;
}

// kTrimCrossing if a segment of the face meets the node's rectangle grown by the face's margin;
// else kTrimInside or kTrimOutside by the parity of the segments a ray from the rectangle's
// centre towards +u crosses. A face without loops is all inside. With bins, the node reads
// only the bins its v range [min(g_v0, cv), max(g_v1, cv)] reaches, each segment once (in the
// first of those bins that holds it): the others fail trimSegmentMeetsBox's first comparisons
// and the ray's v test, and the answer does not depend on the segments' order (any one meeting
// the box makes it crossing; else the parity), so it is the whole face's bit for bit.
uint classifyTrimNode(IN(TrimQuery) query) {
  TrimPiece piece = pieces[query.piece];
  TrimFace face = faces[piece.face];
  if (face.segmentCount == 0u) return kTrimInside;
  PRECISE vec4 rect = trimFaceRect(piece.rect, query.rect);
  PRECISE float g0 = rect.x - face.margin;
  PRECISE float g1 = rect.y - face.margin;
  PRECISE float g2 = rect.z + face.margin;
  PRECISE float g3 = rect.w + face.margin;
  vec4 grown = vec4(g0, g1, g2, g3);
  // Beyond the loops' box: no segment is near, and a ray from there crosses none.
  if (grown.z < face.box.x || grown.x > face.box.z || grown.w < face.box.y ||
      grown.y > face.box.w)
    return kTrimOutside;
  PRECISE float sumU = rect.x + rect.z;
  PRECISE float sumV = rect.y + rect.w;
  PRECISE float cu = sumU * 0.5f;
  PRECISE float cv = sumV * 0.5f;
  bool inside = false;
  if (face.binCount == 0u || isnan(g1) || isnan(g3) || isnan(cv)) {
    for (uint k = 0u; k < face.segmentCount; ++k)
      if (trimSegmentStep(segments[face.firstSegment + k], grown, cu, cv, inside))
        return kTrimCrossing;
    return inside ? kTrimInside : kTrimOutside;
  }
  uint firstBin = trimBin(min(g1, cv), face.box.y, face.binScale, face.binCount);
  uint lastBin = trimBin(max(g3, cv), face.box.y, face.binScale, face.binCount);
  for (uint b = firstBin; b <= lastBin; ++b) {
    uint end = binWords[face.firstBin + b + 1u];
    for (uint e = binWords[face.firstBin + b]; e < end; e += 2u) {
      // Read already in an earlier bin of this node's.
      if (b > firstBin && binWords[e + 1u] < b) continue;
      if (trimSegmentStep(segments[binWords[e]], grown, cu, cv, inside)) return kTrimCrossing;
    }
  }
  return inside ? kTrimInside : kTrimOutside;
}

#endif
