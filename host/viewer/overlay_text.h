// The on-screen status line: stb_easy_font's quads as triangles in pixel coordinates, white
// on a dark band, drawn with kColourFlat after the mesh.
#pragma once
#include <string>
#include <vector>

#include "shaders/layout.h"
#include "viewer/draw_vertex.h"

namespace tessera::viewer {

// Triangles for `text` at the top left, `scale` pixels per font unit, in pixels (z = 0: in
// front of everything the depth test keeps). The text comes before its band: with the depth
// test LESS the band, at the same depth, leaves the letters alone.
std::vector<DrawVertex> overlayTriangles(const std::string& text, int scale);

// Push constants that map pixels (x right, y down) of a width×height window to clip space.
gpu::MeshDrawPush overlayPush(int width, int height);

}  // namespace tessera::viewer
