#include "io/png_writer.h"

#include <limits>
#include <stdexcept>

#include "io/atomic_file.h"

// The one translation unit holding stb_image_write's implementation; static, so the symbols
// cannot clash with another copy linked into the same program, and without stdio, because
// every byte goes through writeFileAtomically's stream.
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#define STBI_WRITE_NO_STDIO
#include <stb_image_write.h>

namespace tessera {
namespace {

void appendToStream(void* context, void* data, int size) {
  static_cast<std::ostream*>(context)->write(static_cast<const char*>(data), size);
}

}  // namespace

void writePng(std::ostream& out, const std::vector<uint8_t>& rgba, int width, int height) {
  // stb computes the row stride and the filtered image size in int.
  if (width <= 0 || height <= 0 ||
      int64_t(width) * height > std::numeric_limits<int>::max() / 5)
    throw std::invalid_argument("writePng: unsupported extent " + std::to_string(width) + "x" +
                                std::to_string(height));
  if (rgba.size() != size_t(width) * size_t(height) * 4)
    throw std::invalid_argument("writePng: " + std::to_string(rgba.size()) + " bytes for " +
                                std::to_string(width) + "x" + std::to_string(height) +
                                " RGBA pixels");
  if (!stbi_write_png_to_func(appendToStream, &out, width, height, 4, rgba.data(), width * 4))
    throw std::runtime_error("writePng: the PNG encoder failed");
}

void writePngFile(const std::string& path, const std::vector<uint8_t>& rgba, int width,
                  int height) {
  writeFileAtomically(path, [&](std::ostream& out) { writePng(out, rgba, width, height); });
}

}  // namespace tessera
