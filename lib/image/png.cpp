// PNG files through libpng's simplified API (png_image): it handles every
// input colour type and bit depth and converts to RGBA8 for us, and reports
// errors through a message instead of longjmp, which keeps C++ unwinding safe.
#include <png.h>

#include <cstdio>
#include <memory>
#include <string>

#include "curvetext/error.hpp"
#include "curvetext/image.hpp"

namespace curvetext {
namespace {

struct FileCloser {
  void operator()(std::FILE* f) const { std::fclose(f); }
};
using FilePtr = std::unique_ptr<std::FILE, FileCloser>;

// png_image owns internal state once a begin_read call succeeded.
struct PngImage {
  png_image image{};
  PngImage() { image.version = PNG_IMAGE_VERSION; }
  PngImage(const PngImage&) = delete;
  PngImage& operator=(const PngImage&) = delete;
  ~PngImage() { png_image_free(&image); }
};

}  // namespace

void write_png(const Image& image, const std::string& path) {
  if (image.width <= 0 || image.height <= 0 ||
      image.rgba.size() != static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 4) {
    throw Error(ErrorCode::InvalidArgument, "cannot write " + path + ": image has no pixels or a bad size");
  }
  // Open the file ourselves so the error names the system's reason.
  FilePtr file(std::fopen(path.c_str(), "wb"));
  if (!file) throw Error(ErrorCode::Io, "cannot write " + path + ": cannot open for writing");
  PngImage png;
  png.image.width = static_cast<png_uint_32>(image.width);
  png.image.height = static_cast<png_uint_32>(image.height);
  png.image.format = PNG_FORMAT_RGBA;
  const int ok = png_image_write_to_stdio(&png.image, file.get(), 0, image.rgba.data(),
                                          static_cast<png_int_32>(image.width) * 4, nullptr);
  if (!ok) throw Error(ErrorCode::Io, "cannot write " + path + ": " + png.image.message);
  std::FILE* f = file.release();
  if (std::fclose(f) != 0) throw Error(ErrorCode::Io, "cannot write " + path + ": close failed (disk full?)");
}

Image read_png(const std::string& path) {
  PngImage png;
  if (!png_image_begin_read_from_file(&png.image, path.c_str())) {
    throw Error(ErrorCode::Io, "cannot read " + path + ": " + png.image.message);
  }
  png.image.format = PNG_FORMAT_RGBA;
  if (png.image.width > 1u << 16 || png.image.height > 1u << 16) {
    throw Error(ErrorCode::Io, "cannot read " + path + ": image too large");
  }
  Image out(static_cast<int>(png.image.width), static_cast<int>(png.image.height));
  if (!png_image_finish_read(&png.image, nullptr, out.rgba.data(), static_cast<png_int_32>(out.width) * 4, nullptr)) {
    throw Error(ErrorCode::Io, "cannot read " + path + ": " + png.image.message);
  }
  return out;
}

}  // namespace curvetext
