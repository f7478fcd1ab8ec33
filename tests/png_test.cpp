// PNG files: write_png keeps every pixel exactly while storing the fewest
// channels that hold them, and reports I/O errors as Error(Io); encode_png
// and decode_png do the same in memory.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "curvetext/error.hpp"
#include "curvetext/image.hpp"
#include "support/expect_error.hpp"

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

std::vector<std::uint8_t> file_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void expect_same_pixels(const Image& back, const Image& image, const std::string& name) {
  EXPECT_EQ(back.width, image.width) << name;
  EXPECT_EQ(back.height, image.height) << name;
  EXPECT_TRUE(back.rgba == image.rgba) << name << ": pixels changed";
}

// Through a file and through memory: the same bytes, the same pixels back.
void expect_round_trip(const Image& image, int colour_type, const std::string& name) {
  const std::string path = temp_path(name + ".png");
  write_png(image, path);
  EXPECT_EQ(png_colour_type(path), colour_type) << name;
  expect_same_pixels(read_png(path), image, name);
  const std::vector<std::uint8_t> bytes = encode_png(image);
  EXPECT_TRUE(bytes == file_bytes(path)) << name << ": encode_png differs from the file write_png wrote";
  ASSERT_GT(bytes.size(), 26u);
  EXPECT_EQ(bytes[25], colour_type) << name;
  expect_same_pixels(decode_png(bytes.data(), bytes.size()), image, name);
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

TEST(Png, EncodeEmptyImageIsInvalidArgument) {
  testing::expect_error([] { encode_png(Image{}); }, ErrorCode::InvalidArgument, "in memory");
  Image bad(4, 4);
  bad.rgba.pop_back();
  testing::expect_error([&] { encode_png(bad); }, ErrorCode::InvalidArgument, "bad size");
}

TEST(Png, DecodeOfOtherBytesIsIoError) {
  const std::vector<std::uint8_t> text = {'n', 'o', 't', ' ', 'a', ' ', 'p', 'n', 'g'};
  testing::expect_error([&] { decode_png(text.data(), text.size()); }, ErrorCode::Io, "in memory");
  testing::expect_error([] { decode_png(nullptr, 0); }, ErrorCode::Io, "in memory");
  // A PNG cut short: its header reads, its pixels do not.
  std::vector<std::uint8_t> bytes =
      encode_png(sample([](std::uint8_t* p, int x, int) { p[1] = static_cast<std::uint8_t>(3 * x); }));
  bytes.resize(bytes.size() / 2);
  testing::expect_error([&] { decode_png(bytes.data(), bytes.size()); }, ErrorCode::Io, "in memory");
}

}  // namespace
}  // namespace curvetext
