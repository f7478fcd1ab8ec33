// PNG files: write_png keeps every pixel exactly while storing the fewest
// channels that hold them, and reports I/O errors as Error(Io).
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <string>

#include "curvetext/error.hpp"
#include "curvetext/image.hpp"

namespace curvetext {
namespace {

std::string temp_path(const std::string& name) {
  return (std::filesystem::temp_directory_path() / ("curvetext_png_test_" + name)).string();
}

// The IHDR colour type: 0 grey, 2 RGB, 4 grey + alpha, 6 RGBA.
int png_colour_type(const std::string& path) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (f == nullptr) return -1;
  unsigned char header[26] = {};
  const std::size_t n = std::fread(header, 1, sizeof header, f);
  std::fclose(f);
  return n == sizeof header ? header[25] : -1;
}

// Text-like pixels: a background with a gradient band of "ink", then `edit`
// applied to every pixel.
template <typename Edit>
Image sample(Edit edit) {
  Image image(37, 11);
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      std::uint8_t* p = image.pixel(x, y);
      const auto v = static_cast<std::uint8_t>(x > 10 && x < 20 ? 255 - 23 * (x - 10) : 255);
      p[0] = p[1] = p[2] = v;
      p[3] = 255;
      edit(p, x, y);
    }
  }
  return image;
}

void expect_round_trip(const Image& image, int colour_type, const std::string& name) {
  const std::string path = temp_path(name + ".png");
  write_png(image, path);
  EXPECT_EQ(png_colour_type(path), colour_type) << name;
  const Image back = read_png(path);
  EXPECT_EQ(back.width, image.width) << name;
  EXPECT_EQ(back.height, image.height) << name;
  EXPECT_TRUE(back.rgba == image.rgba) << name << ": pixels changed";
  std::filesystem::remove(path);
}

TEST(Png, GreyOpaqueIsWrittenAsGrey) {
  expect_round_trip(sample([](std::uint8_t*, int, int) {}), 0, "grey");
}

TEST(Png, GreyWithAlphaKeepsAlpha) {
  expect_round_trip(sample([](std::uint8_t* p, int x, int) { p[3] = static_cast<std::uint8_t>(7 * x); }), 4,
                    "grey_alpha");
}

TEST(Png, ColourOpaqueIsWrittenAsRgb) {
  // One pixel off grey is enough to need colour.
  expect_round_trip(sample([](std::uint8_t* p, int x, int y) {
                      if (x == 36 && y == 10) p[2] = 1;
                    }),
                    2, "rgb");
}

TEST(Png, ColourWithAlphaIsWrittenAsRgba) {
  expect_round_trip(sample([](std::uint8_t* p, int x, int y) {
                      p[0] = static_cast<std::uint8_t>(x * 5);
                      p[3] = static_cast<std::uint8_t>(y == 0 ? 0 : 255);
                    }),
                    6, "rgba");
}

TEST(Png, UnwritablePathIsIoError) {
  const Image image = sample([](std::uint8_t*, int, int) {});
  try {
    write_png(image, "/nonexistent-dir/out.png");
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::Io);
    EXPECT_NE(std::string(e.what()).find("/nonexistent-dir/out.png"), std::string::npos) << e.what();
  }
}

TEST(Png, WriteErrorIsIoError) {
  // /dev/full accepts the open and fails the writes.
  if (!std::filesystem::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  Image big(512, 512);
  for (std::size_t i = 0; i < big.rgba.size(); ++i) big.rgba[i] = static_cast<std::uint8_t>(i * 2654435761u >> 24);
  try {
    write_png(big, "/dev/full");
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::Io) << e.what();
  }
}

TEST(Png, EmptyImageIsInvalidArgument) {
  try {
    write_png(Image{}, temp_path("empty.png"));
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::InvalidArgument);
  }
}

}  // namespace
}  // namespace curvetext
