// RGBA images (8 bits per channel, row 0 at the top) and PNG files.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace curvetext {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;  // width * height * 4, not premultiplied

  Image() = default;
  Image(int w, int h) : width(w), height(h), rgba(static_cast<std::size_t>(w) * h * 4, 0) {}
  std::uint8_t* pixel(int x, int y) { return &rgba[(static_cast<std::size_t>(y) * width + x) * 4]; }
  const std::uint8_t* pixel(int x, int y) const { return &rgba[(static_cast<std::size_t>(y) * width + x) * 4]; }
};

// Throws Error(Io) naming the path when the file cannot be written.
void write_png(const Image& image, const std::string& path);
// Throws Error(Io) when the file cannot be read or is not a PNG.
Image read_png(const std::string& path);

}  // namespace curvetext
