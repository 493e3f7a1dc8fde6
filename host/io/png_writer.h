// PNG output of RGBA8 pixels (what host/render/offscreen.h produces), through stb_image_write.
// Rows run top to bottom, 4 bytes per pixel, no padding between rows.
#pragma once
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace tessera {

// Encode `rgba` (width·height·4 bytes) as PNG into `out`. Throws std::invalid_argument when
// the extent is not positive or does not match the pixel count, std::runtime_error when the
// encoder fails (out of memory).
void writePng(std::ostream& out, const std::vector<uint8_t>& rgba, int width, int height);

// Same, into the file at `path` via writeFileAtomically: the whole file or, on any error,
// nothing (InputError of kind Io for I/O failures).
void writePngFile(const std::string& path, const std::vector<uint8_t>& rgba, int width,
                  int height);

}  // namespace tessera
