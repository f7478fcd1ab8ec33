// The debug view (paper Figure 1), linear-light blending and coverage gamma,
// checked on pixels whose expected value is known exactly.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <memory>
#include <string>

#include "curvetext/error.hpp"
#include "curvetext/headless.hpp"
#include "curvetext/image_style.hpp"
#include "curvetext/renderer.hpp"
#include "curvetext/shape_image.hpp"
#include "curvetext/shapes.hpp"
#include "support/gpu.hpp"

namespace curvetext {
namespace {

using test::gpu;

struct Rgba {
  int r, g, b, a;
};
Rgba at(const Image& image, int x, int y) {
  const std::size_t i = (static_cast<std::size_t>(y) * image.width + x) * 4;
  return {image.rgba[i], image.rgba[i + 1], image.rgba[i + 2], image.rgba[i + 3]};
}

struct Rendered {
  Image image;
  ShapeImageLayout layout;
  // Pixel under document point (x, y).
  Rgba doc(double x, double y) const {
    const Placement& p = layout.placement;
    return at(image, static_cast<int>(std::floor(p.scale * x + p.origin_x)),
              static_cast<int>(std::floor(p.origin_y - p.scale * y)));
  }
};

Rendered render(const std::string& json, const ShapeImageOptions& options) {
  const ShapeDocument doc = parse_shape_json(json);
  Rendered r;
  r.layout = layout_shape_image(doc, options);
  r.image = render_shape_image(gpu().renderer, doc, r.layout, options);
  return r;
}

// One convex rational quadratic (w = 0.5, apex (50, 33.3)) closed by its
// chord. The mesh splits its hull at the apex: curved triangles
// (0,0) (16.7,33.3) (50,33.3) and its mirror, and an interior triangle on
// the chord. (20, 30), (24, 31) and (80, 30) lie inside a curved triangle
// and outside the curve (which passes x = 32 at y = 30): the pixels the
// paper's Figure 1 shows discarded.
const char* kArc = R"({"size": [120, 120], "view": [-10, -10, 110, 110], "shapes": [{"color": "#000000",
  "contours": [[{"bezier": {"points": [[0, 0], [50, 100], [100, 0]], "weights": [1, 0.5, 1]}},
                {"line": [[100, 0], [0, 0]]}]]}]})";

bool is_debug_orange(Rgba c) { return c.r > 240 && c.g > 90 && c.g < 140 && c.b < 20; }
bool is_debug_blue(Rgba c) { return c.b > 220 && c.r < 40 && c.g > 60 && c.g < 120; }

TEST(Debug, DiscardedCurvePixelsAreColouredAndOthersAreNot) {
  for (AntiAliasing aa : {AntiAliasing::None, AntiAliasing::Full}) {
    ShapeImageOptions options;
    options.scale = 1.0;
    options.antialiasing = aa;
    const Rendered plain = render(kArc, options);
    options.debug = true;
    const Rendered debug = render(kArc, options);
    // Inside the triangle, outside the curve: background normally, orange in debug.
    for (auto [x, y] : {std::pair{20.0, 30.0}, std::pair{24.0, 31.0}, std::pair{80.0, 30.0}}) {
      EXPECT_EQ(plain.doc(x, y).r, 255) << x << "," << y;
      const Rgba c = debug.doc(x, y);
      EXPECT_TRUE(is_debug_orange(c)) << x << "," << y << ": " << c.r << " " << c.g << " " << c.b;
    }
    // Above the hulls, inside the control triangle: nothing is drawn there.
    EXPECT_EQ(debug.doc(50, 60).r, 255);
    // Inside the curve, and outside the hull: the same in both views.
    for (auto [x, y] : {std::pair{50.0, 15.0}, std::pair{30.0, 8.0}, std::pair{105.0, 80.0}, std::pair{-5.0, 50.0}}) {
      const Rgba a = plain.doc(x, y), b = debug.doc(x, y);
      EXPECT_EQ(a.r, b.r) << x << "," << y;
      EXPECT_EQ(a.g, b.g) << x << "," << y;
      EXPECT_EQ(a.b, b.b) << x << "," << y;
    }
    // The triangles' edges: the chord (an edge of the interior triangle) is
    // drawn blue (a pixel next to its midpoint); nowhere blue without debug.
    bool blue = false;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) blue = blue || is_debug_blue(debug.doc(50.0 + dx, 0.5 + dy));
    EXPECT_TRUE(blue);
    int plain_blue = 0, plain_orange = 0;
    for (int y = 0; y < plain.image.height; ++y)
      for (int x = 0; x < plain.image.width; ++x) {
        plain_blue += is_debug_blue(at(plain.image, x, y));
        plain_orange += is_debug_orange(at(plain.image, x, y));
      }
    EXPECT_EQ(plain_blue, 0);
    EXPECT_EQ(plain_orange, 0);
  }
}

// White over black covering exactly half of pixel column 20 (x from 0 to 20.5).
const char* kHalf = R"({"size": [40, 20], "view": [0, 0, 40, 20], "shapes": [{"color": "#ffffff",
  "contours": [[{"line": [[0, 0], [20.5, 0]]}, {"line": [[20.5, 0], [20.5, 20]]},
                {"line": [[20.5, 20], [0, 20]]}, {"line": [[0, 20], [0, 0]]}]]}]})";

int half_pixel(Blending blending, float gamma, AntiAliasing aa, Color background = {0, 0, 0, 1}, int* alpha = nullptr) {
  ShapeImageOptions options;
  options.scale = 1.0;
  options.background = background;
  options.blending = blending;
  options.gamma = gamma;
  options.antialiasing = aa;
  const ShapeDocument doc = parse_shape_json(kHalf);
  const ShapeImageLayout layout = layout_shape_image(doc, options);
  const Image image = render_shape_image(gpu().renderer, doc, layout, options);
  EXPECT_EQ(at(image, 19, 10).r, 255);
  EXPECT_EQ(at(image, 21, 10).a == 0 ? 0 : at(image, 21, 10).r, 0);
  if (alpha != nullptr) *alpha = at(image, 20, 10).a;
  return at(image, 20, 10).r;
}

TEST(Blending, LinearLightEncodesHalfCoverageAsSrgbOfHalf) {
  // sRGB encoding of 0.5 linear: 1.055 * 0.5^(1/2.4) - 0.055 = 0.7354 -> 187.5.
  for (AntiAliasing aa : {AntiAliasing::Full, AntiAliasing::Vbaa}) {
    EXPECT_NEAR(half_pixel(Blending::Linear, 1.0f, aa), 187.5, 1.0);
    // Blending on the stored values: 0.5 -> 127.5.
    EXPECT_NEAR(half_pixel(Blending::Srgb, 1.0f, aa), 127.5, 1.0);
  }
}

TEST(Blending, LinearOverTransparentGivesStraightAlpha) {
  int alpha = 0;
  const int v = half_pixel(Blending::Linear, 1.0f, AntiAliasing::Full, Color{0, 0, 0, 0}, &alpha);
  EXPECT_NEAR(alpha, 127.5, 1.0);
  EXPECT_GE(v, 253);  // white, un-premultiplied in linear light
}

TEST(Gamma, RaisesCoverageToOneOverGamma) {
  // 0.5^(1/2) = 0.7071 -> 180.3; 0.5^(1/0.5) = 0.25 -> 63.75.
  for (AntiAliasing aa : {AntiAliasing::Full, AntiAliasing::Vbaa}) {
    EXPECT_NEAR(half_pixel(Blending::Srgb, 2.0f, aa), 180.3, 1.5);
    EXPECT_NEAR(half_pixel(Blending::Srgb, 0.5f, aa), 63.75, 1.5);
  }
}

// The image paths refuse a gamma out of range before drawing (the renderer
// itself clamps it).
TEST(Gamma, OutOfRangeIsRefused) {
  ImageStyle style;
  style.gamma = 1.8f;
  EXPECT_NO_THROW(draw_options(style, Color{}, 16.0));
  for (float bad : {std::nanf(""), 0.0f, 100.0f}) {
    style.gamma = bad;
    try {
      draw_options(style, Color{}, 16.0);
      FAIL() << bad;
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), ErrorCode::InvalidArgument);
      EXPECT_NE(std::string(e.what()).find("gamma must be a number"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace curvetext
