// RGBA images (8 bits per channel, row 0 at the top) and PNG files.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "curvetext/export.hpp"

namespace curvetext {

// A value type; pixel() does not check its coordinates.
struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;  // width * height * 4, not premultiplied

  Image() = default;
  Image(int w, int h) : width(w), height(h), rgba(static_cast<std::size_t>(w) * h * 4, 0) {}
  std::uint8_t* pixel(int x, int y) { return &rgba[(static_cast<std::size_t>(y) * width + x) * 4]; }
  const std::uint8_t* pixel(int x, int y) const { return &rgba[(static_cast<std::size_t>(y) * width + x) * 4]; }
};

// Writes the pixels exactly, in the fewest channels that hold them (grey,
// grey and alpha, RGB or RGBA), tagged sRGB, compressed for speed. Throws
// Error(Io) naming the path when the file cannot be written,
// Error(InvalidArgument) for an image without pixels or whose size does not
// match its data.
CURVETEXT_API void write_png(const Image& image, const std::string& path);
// write_png to memory: the same PNG file's bytes, for a caller that sends
// them on (standard output, a socket, an archive) without a file. Throws
// Error(InvalidArgument) as write_png does, Error(Io) on a libpng error.
CURVETEXT_API std::vector<std::uint8_t> encode_png(const Image& image);
// Any PNG, converted to 8-bit straight-alpha RGBA. Throws Error(Io) when
// the file cannot be read or is not a PNG.
CURVETEXT_API Image read_png(const std::string& path);
// read_png from memory: the PNG file's `size` bytes at `data`. Throws
// Error(Io) when they are not a PNG.
CURVETEXT_API Image decode_png(const std::uint8_t* data, std::size_t size);

}  // namespace curvetext
