// PNG files through libpng. Reading uses the simplified API (png_image): it
// handles every input colour type and bit depth and converts to RGBA8, and
// reports errors through a message instead of longjmp. Writing uses the full
// API for its compression settings; its longjmp error path is confined to one
// function that owns no C++ objects.
#include <png.h>
#include <zlib.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <memory>
#include <new>
#include <string>
#include <vector>

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

// The fewest channels that hold every pixel exactly: 1 grey, 2 grey and
// alpha, 3 RGB, 4 RGBA. Text on a plain background is mostly grey and opaque,
// and a quarter of the bytes is a quarter of the compression time.
int channels_needed(const Image& image) {
  bool grey = true, opaque = true;
  const std::uint8_t* p = image.rgba.data();
  const std::uint8_t* end = p + image.rgba.size();
  for (; p != end && (grey || opaque); p += 4) {
    grey = grey && p[0] == p[1] && p[1] == p[2];
    opaque = opaque && p[3] == 255;
  }
  return grey ? (opaque ? 1 : 2) : (opaque ? 3 : 4);
}

// Each pixel's first `channels` of R, G, B, A, with grey + alpha taking R and A.
std::vector<std::uint8_t> pack_channels(const Image& image, int channels) {
  const std::size_t pixels = image.rgba.size() / 4;
  std::vector<std::uint8_t> out(pixels * static_cast<std::size_t>(channels));
  const std::uint8_t* src = image.rgba.data();
  std::uint8_t* dst = out.data();
  for (std::size_t i = 0; i < pixels; ++i, src += 4) {
    *dst++ = src[0];
    if (channels == 2) *dst++ = src[3];
    if (channels >= 3) {
      *dst++ = src[1];
      *dst++ = src[2];
    }
    if (channels == 4) *dst++ = src[3];
  }
  return out;
}

int color_type(int channels) {
  switch (channels) {
    case 1:
      return PNG_COLOR_TYPE_GRAY;
    case 2:
      return PNG_COLOR_TYPE_GRAY_ALPHA;
    case 3:
      return PNG_COLOR_TYPE_RGB;
    default:
      return PNG_COLOR_TYPE_RGBA;
  }
}

struct WriteErrors {
  char message[256] = "unknown libpng error";
};

void on_png_error(png_structp png, png_const_charp message) {
  auto* errors = static_cast<WriteErrors*>(png_get_error_ptr(png));
  std::snprintf(errors->message, sizeof errors->message, "%s", message);
  png_longjmp(png, 1);
}

void on_png_warning(png_structp, png_const_charp) {}

// Where the encoder's bytes go: a file, or else a byte vector.
struct PngSink {
  std::FILE* file = nullptr;
  std::vector<std::uint8_t>* bytes = nullptr;
};

void append_bytes(png_structp png, png_bytep data, png_size_t size) {
  auto* bytes = static_cast<std::vector<std::uint8_t>*>(png_get_io_ptr(png));
  bool grown = true;
  try {
    bytes->insert(bytes->end(), data, data + size);
  } catch (const std::bad_alloc&) {
    grown = false;
  }
  // png_error longjmps: outside the handler, so no exception is left live.
  if (!grown) png_error(png, "out of memory");
}

void flush_nothing(png_structp) {}

// Rows unfiltered, deflated for speed: on rendered text (long runs of
// background, short antialiased edges) zlib's level 1 is smaller than its
// default with adaptive filters and 3-5 times faster; for grey, run-length
// matches alone are as small and faster still (colour repeats every 3 or 4
// bytes, which they miss). False on a libpng error (the message is in the
// error pointer's WriteErrors).
bool encode_rows(png_structp png, png_infop info, PngSink sink, int width, int height, int channels,
                 const std::uint8_t* pixels) {
  if (setjmp(png_jmpbuf(png))) return false;
  if (sink.file != nullptr)
    png_init_io(png, sink.file);
  else
    png_set_write_fn(png, sink.bytes, append_bytes, flush_nothing);
  png_set_IHDR(png, info, static_cast<png_uint_32>(width), static_cast<png_uint_32>(height), 8, color_type(channels),
               PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
  png_set_sRGB(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
  png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_NONE);
  if (channels == 1) {
    png_set_compression_strategy(png, Z_RLE);
  } else {
    png_set_compression_strategy(png, Z_DEFAULT_STRATEGY);
    png_set_compression_level(png, 1);
  }
  png_write_info(png, info);
  const std::size_t stride = static_cast<std::size_t>(width) * static_cast<std::size_t>(channels);
  for (int y = 0; y < height; ++y) png_write_row(png, pixels + static_cast<std::size_t>(y) * stride);
  png_write_end(png, nullptr);
  return true;
}

// Owns the write structures.
struct PngWriter {
  WriteErrors errors;
  png_structp png = nullptr;
  png_infop info = nullptr;
  PngWriter() {
    png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &errors, on_png_error, on_png_warning);
    if (png != nullptr) info = png_create_info_struct(png);
  }
  PngWriter(const PngWriter&) = delete;
  PngWriter& operator=(const PngWriter&) = delete;
  ~PngWriter() { png_destroy_write_struct(&png, &info); }
};

// Encodes `image` into `sink`; `name` (the path, or "a PNG in memory") heads
// the errors.
void encode(const Image& image, PngSink sink, const std::string& name) {
  const int channels = channels_needed(image);
  const std::vector<std::uint8_t> packed = channels == 4 ? std::vector<std::uint8_t>() : pack_channels(image, channels);
  PngWriter writer;
  if (writer.info == nullptr) throw Error(ErrorCode::Io, "cannot write " + name + ": out of memory");
  if (!encode_rows(writer.png, writer.info, sink, image.width, image.height, channels,
                   channels == 4 ? image.rgba.data() : packed.data())) {
    throw Error(ErrorCode::Io, "cannot write " + name + ": " + writer.errors.message);
  }
}

void check_size(const Image& image, const std::string& name) {
  if (image.width <= 0 || image.height <= 0 ||
      image.rgba.size() != static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 4) {
    throw Error(ErrorCode::InvalidArgument, "cannot write " + name + ": image has no pixels or a bad size");
  }
}

// Finishes a read begun on `png` into RGBA8; `name` heads the errors.
Image finish_read(PngImage& png, const std::string& name) {
  png.image.format = PNG_FORMAT_RGBA;
  if (png.image.width > 1u << 16 || png.image.height > 1u << 16) {
    throw Error(ErrorCode::Io, "cannot read " + name + ": image too large");
  }
  Image out(static_cast<int>(png.image.width), static_cast<int>(png.image.height));
  if (!png_image_finish_read(&png.image, nullptr, out.rgba.data(), static_cast<png_int_32>(out.width) * 4, nullptr)) {
    throw Error(ErrorCode::Io, "cannot read " + name + ": " + png.image.message);
  }
  return out;
}

}  // namespace

void write_png(const Image& image, const std::string& path) {
  check_size(image, path);
  // Open the file ourselves so the error names the system's reason.
  FilePtr file(std::fopen(path.c_str(), "wb"));
  if (!file) throw Error(ErrorCode::Io, "cannot write " + path + ": " + std::strerror(errno));
  encode(image, PngSink{file.get(), nullptr}, path);
  std::FILE* f = file.release();
  if (std::fclose(f) != 0) throw Error(ErrorCode::Io, "cannot write " + path + ": close failed (disk full?)");
}

std::vector<std::uint8_t> encode_png(const Image& image) {
  const std::string name = "a PNG in memory";
  check_size(image, name);
  std::vector<std::uint8_t> bytes;
  encode(image, PngSink{nullptr, &bytes}, name);
  return bytes;
}

Image read_png(const std::string& path) {
  PngImage png;
  if (!png_image_begin_read_from_file(&png.image, path.c_str())) {
    throw Error(ErrorCode::Io, "cannot read " + path + ": " + png.image.message);
  }
  return finish_read(png, path);
}

Image decode_png(const std::uint8_t* data, std::size_t size) {
  PngImage png;
  if (data == nullptr || !png_image_begin_read_from_memory(&png.image, data, size)) {
    throw Error(ErrorCode::Io,
                std::string("cannot read a PNG in memory: ") + (data == nullptr ? "no data" : png.image.message));
  }
  return finish_read(png, "a PNG in memory");
}

}  // namespace curvetext
