// Text under rotation, non-uniform scale, skew and perspective, rendered
// through the whole pipeline and compared with the exact area coverage of
// the transformed outline (a projective map takes a rational quadratic to a
// rational quadratic: control points mapped, weights times the homogeneous w).
// Failing cases write result, reference and diff images to build/test-output.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <numbers>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include "curvetext/error.hpp"
#include "curvetext/font.hpp"
#include "curvetext/headless.hpp"
#include "curvetext/renderer.hpp"
#include "curvetext/shaping.hpp"
#include "curvetext/text_image.hpp"
#include "curvetext/transform.hpp"
#include "support/camera.hpp"
#include "support/coverage.hpp"
#include "support/fonts.hpp"
#include "support/union_coverage.hpp"
#include "support/gpu.hpp"

namespace curvetext {
namespace {

using test::Gpu;
using test::gpu;

using test::camera_mvp;
using test::transform_outline;

struct Result {
  test::Coverage result, reference;
  test::CoverageStats stats;
};

Result render(const char* font_path, const char* text, double size, const Transform& transform, AntiAliasing aa) {
  const Font font = Font::open(font_path);
  TextImageOptions options;
  options.size_px = size;
  options.antialiasing = aa;
  options.transform = transform;
  const TextImageLayout layout = layout_text_image(font, text, options);
  const Image image = render_text_image(gpu().renderer, gpu().cache, font, layout, options);
  Result r;
  r.result = test::coverage_from_black_on_white(image);
  Placement untransformed = layout.placement;
  untransformed.transform = Transform{};
  const Outline pixels = test::place_outline(test::line_outline(font, layout.line), untransformed);
  r.reference =
      test::union_coverage(transform_outline(pixels, layout.placement.transform), layout.width, layout.height);
  r.stats = test::compare(r.result, r.reference);
  return r;
}

void expect_close(const std::string& name, const Result& r, double edge_limit, double ink_limit) {
  test::expect_coverage(name, r.result, r.reference, r.stats, edge_limit, ink_limit);
}

// Limits: the unrotated text measures edge 0.0039 at 16 px and 0.0015 at
// 48 px (bench/quality_bench); full AA's areas are exact at any angle (the
// triangles' edges clip the pixel box), so rotation should not change the
// order of the error.
// Placement::on_plane puts outline points where the model-view-projection
// and the viewport put the plane's points (the GL pipeline's arithmetic,
// written out), upright; and text drawn so matches the exact coverage of its
// outline under that map.
TEST(Plane, OnPlaneFollowsTheModelViewProjection) {
  const int w = 320, h = 200;
  const std::array<float, 16> mvp = camera_mvp(static_cast<double>(w) / h);
  const double units = 0.002;  // plane units per outline unit
  const Placement placement = Placement::on_plane(mvp.data(), w, h, units, 0.25, 0.4);
  double worst = 0.0, worst_z = 0.0;
  for (const Vec2 o : {Vec2{0, 0}, Vec2{500, 0}, Vec2{0, 700}, Vec2{1200, -300}}) {
    const double X = 0.25 + units * o.x, Y = 0.4 + units * o.y;  // on the plane, y up
    double clip[4];
    for (int row = 0; row < 4; ++row)
      clip[row] = mvp[static_cast<std::size_t>(row)] * X + mvp[static_cast<std::size_t>(4 + row)] * Y +
                  mvp[static_cast<std::size_t>(12 + row)];
    const Vec2 want{(clip[0] / clip[3] + 1.0) / 2.0 * w, (1.0 - clip[1] / clip[3]) / 2.0 * h};
    const Vec2 pre{placement.scale * o.x + placement.origin_x, placement.origin_y - placement.scale * o.y};
    const Vec2 got = placement.transform.apply(pre);
    worst = std::max({worst, std::abs(got.x - want.x), std::abs(got.y - want.y)});
    // Its depth: the pipeline's normalized device z at that pixel.
    const auto& d = placement.depth;
    worst_z = std::max(worst_z, std::abs(d[0] * want.x + d[1] * want.y + d[2] - clip[2] / clip[3]));
  }
  EXPECT_LT(worst, 1e-3) << "pixels from the pipeline's projection";
  EXPECT_LT(worst_z, 1e-6) << "device z from the pipeline's projection";
  const float bad[16] = {std::nanf(""), 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  EXPECT_THROW(Transform::plane_to_viewport(bad, w, h), Error);
  EXPECT_THROW(Transform::plane_to_viewport(mvp.data(), 0, h), Error);

  // Drawn: "Plane" on the plane, against the exact coverage of its outline.
  const Font font = Font::open(test::kDejaVuSans);
  const ShapedLine line = shape_line(font, "Plane");
  DrawBatch batch = DrawBatch::from_text(gpu().cache, font, line, 48.0);
  gpu().target.begin(w, h, Color{1, 1, 1, 1});
  gpu().renderer.draw(batch, placement, DrawOptions(Color{0, 0, 0, 1}, AntiAliasing::Full));
  const test::Coverage got = test::coverage_from_black_on_white(gpu().target.read_pixels());
  Placement untransformed = placement;
  untransformed.transform = Transform{};
  const test::Coverage want = test::union_coverage(
      transform_outline(test::place_outline(test::line_outline(font, line), untransformed), placement.transform), w, h);
  const test::CoverageStats st = test::compare(got, want);
  std::printf("text on a plane: edge %.4f, max %.3f, ink %.4f (%zu edge pixels)\n", st.edge_mean_abs, st.max_abs,
              st.ink_ratio, st.edge_pixels);
  EXPECT_GT(st.edge_pixels, 200u);
  test::expect_coverage("text-on-plane", got, want, st, 0.01, 0.02);
}

TEST(Rotation, ThirtyDegreesMatchesExactCoverage) {
  for (double size : {16.0, 48.0}) {
    for (const char* path : {test::kDejaVuSans, test::kNimbusRoman}) {
      const Result r = render(path, "Hamburgefontsiv", size, Transform::rotation(30.0), AntiAliasing::Full);
      expect_close(std::string("rotate30_") + (path == test::kDejaVuSans ? "DejaVu_" : "Nimbus_") +
                       std::to_string(static_cast<int>(size)) + "px",
                   r, size < 24 ? 0.02 : 0.008, size < 24 ? 0.02 : 0.01);
    }
  }
}

TEST(Perspective, TiltedPlaneMatchesExactCoverage) {
  // The line turned 50 degrees about its horizontal centre line, seen from
  // 400 px: the top half comes nearer and grows, the bottom half shrinks.
  for (double size : {24.0, 64.0}) {
    const Result r =
        render(test::kDejaVuSans, "Hamburgefontsiv", size, Transform::perspective(50.0, 400.0), AntiAliasing::Full);
    expect_close("perspective50_DejaVu_" + std::to_string(static_cast<int>(size)) + "px", r, size < 48 ? 0.02 : 0.008,
                 size < 48 ? 0.02 : 0.01);
  }
}

// Steeper: turned 80 degrees and seen from 120 px, the far half shrinks to a
// sliver and a pixel's footprint changes across the pixel itself; full's one
// pass takes the local affine map at each pixel (first order), measured here
// against the exact coverage.
TEST(Perspective, SteepTiltStaysCloseToExactCoverage) {
  for (double size : {32.0, 96.0}) {
    const Result r =
        render(test::kDejaVuSans, "Hamburgefontsiv", size, Transform::perspective(80.0, 120.0), AntiAliasing::Full);
    expect_close("perspective80_DejaVu_" + std::to_string(static_cast<int>(size)) + "px", r, 0.01, 0.02);
  }
}

TEST(AffineMaps, NonUniformScaleAndSkew) {
  const Result scaled =
      render(test::kNotoSans, "Hamburgefontsiv", 24.0, Transform::scale(2.0, 0.75), AntiAliasing::Full);
  expect_close("scale2x0.75_Noto_24px", scaled, 0.015, 0.02);
  const Result skewed =
      render(test::kNotoSans, "Hamburgefontsiv", 24.0, Transform::skew(-15.0, 5.0), AntiAliasing::Full);
  expect_close("skew-15,5_Noto_24px", skewed, 0.015, 0.02);
}

// The aliased modes under rotation: none is a binary in/out test with the
// right ink on average.
TEST(Rotation, NoAntialiasingKeepsInk) {
  const Result r = render(test::kDejaVuSans, "Hamburgefontsiv", 48.0, Transform::rotation(30.0), AntiAliasing::None);
  std::printf("rotate30_none_48px edge %.4f ink %.4f\n", r.stats.edge_mean_abs, r.stats.ink_ratio);
  EXPECT_NEAR(r.stats.ink_ratio, 1.0, 0.03);
}

// vbaa (paper section 5): issue 4's target is edge error <= 0.02 at 8-16 px;
// it also holds under rotation, and the offscreen pass is reused while the
// block and its transform stay the same.
TEST(Vbaa, SmallTextMatchesExactCoverage) {
  for (double size : {8.0, 12.0, 16.0}) {
    for (const char* path : {test::kDejaVuSans, test::kNimbusRoman}) {
      const Result r = render(path, "Hamburgefontsiv", size, Transform{}, AntiAliasing::Vbaa);
      expect_close("vbaa_" + std::to_string(static_cast<int>(size)) + "px", r, 0.02, 0.03);
    }
  }
  const Result rotated =
      render(test::kDejaVuSans, "Hamburgefontsiv", 12.0, Transform::rotation(30.0), AntiAliasing::Vbaa);
  expect_close("vbaa_rotate30_12px", rotated, 0.02, 0.03);
}

TEST(Vbaa, OffscreenPassIsReusedWhileNothingChanges) {
  Gpu& g = gpu();
  const Font font = Font::open(test::kDejaVuSans);
  const ShapedLine line = shape_line(font, "Reuse");
  DrawBatch batch = DrawBatch::from_text(g.cache, font, line, 20.0);
  const double s = 20.0 / font.metrics().units_per_em;
  DrawOptions options;
  options.antialiasing = AntiAliasing::Vbaa;
  g.target.begin(100, 40, Color{1, 1, 1, 1});
  const std::size_t before = g.renderer.offscreen_passes();
  g.renderer.draw(batch, Placement{s, 5.0, 30.0}, options);
  const Image first = g.target.read_pixels();
  g.target.begin(100, 40, Color{1, 1, 1, 1});
  g.renderer.draw(batch, Placement{s, 5.0, 30.0}, options);
  EXPECT_EQ(g.renderer.offscreen_passes(), before + 1);
  EXPECT_EQ(g.target.read_pixels().rgba, first.rgba);
  g.renderer.draw(batch, Placement{s, 6.0, 30.0}, options);  // moved: a new pass
  EXPECT_EQ(g.renderer.offscreen_passes(), before + 2);
}

// Regression: the filter pass found its pixel from gl_FragCoord, which GLSL
// ES 1.00 declares mediump; llvmpipe lowers that to 16-bit floats, whose
// spacing is 1 px from 1024 to 2048, so x + 0.5 rounded to even and every odd
// column there read its neighbour (at 96 px and up, the right end of a
// block lost a column: largest error 0.94-1.0). Text placed past x = 1024
// must match exact coverage pixel by pixel in both offscreen modes.
TEST(Vbaa, ColumnsPast1024PxAreKept) {
  const Font font = Font::open(test::kDejaVuSans);
  for (AntiAliasing aa : {AntiAliasing::Vbaa, AntiAliasing::Msaa}) {
    if (aa == AntiAliasing::Msaa && gpu().renderer.msaa_samples() < 2) continue;
    TextImageOptions options;
    options.size_px = 24.0;
    options.margin_px = 1100.0;  // the text lies between x = 1100 and 1300
    options.antialiasing = aa;
    const TextImageLayout layout = layout_text_image(font, "Hamburgefontsiv", options);
    const Image image = render_text_image(gpu().renderer, gpu().cache, font, layout, options);
    const test::Coverage result = test::coverage_from_black_on_white(image);
    const test::Coverage reference = test::union_coverage(
        test::place_outline(test::line_outline(font, layout.line), layout.placement), layout.width, layout.height);
    const test::CoverageStats st = test::compare(result, reference);
    const std::string name = aa == AntiAliasing::Vbaa ? "vbaa_past1024" : "msaa_past1024";
    std::printf("%s edge %.4f max %.3f\n", name.c_str(), st.edge_mean_abs, st.max_abs);
    // vbaa measures max 0.04-0.08 at every size, msaa (4 samples) 0.5-0.54;
    // a lost column is 1.0 and doubles the edge error.
    const double max_limit = aa == AntiAliasing::Vbaa ? 0.15 : 0.6;
    if (st.max_abs > max_limit) test::write_comparison(name, result, reference);
    EXPECT_LE(st.max_abs, max_limit) << name;
    EXPECT_LE(st.edge_mean_abs, aa == AntiAliasing::Vbaa ? 0.01 : 0.08) << name;
  }
}

// msaa where the context has multisampled renderbuffers (llvmpipe: GLES 3.2).
TEST(Msaa, SamplesGiveRightInk) {
  if (gpu().renderer.msaa_samples() < 2) GTEST_SKIP() << "no multisampled renderbuffers";
  const Result r = render(test::kDejaVuSans, "Hamburgefontsiv", 24.0, Transform{}, AntiAliasing::Msaa);
  std::printf("msaa x%d 24px edge %.4f ink %.4f\n", gpu().renderer.msaa_samples(), r.stats.edge_mean_abs,
              r.stats.ink_ratio);
  EXPECT_LE(r.stats.edge_mean_abs, 0.08);
  EXPECT_NEAR(r.stats.ink_ratio, 1.0, 0.03);
}

TEST(TransformInput, BadMatricesAreRejected) {
  const Font font = Font::open(test::kDejaVuSans);
  TextImageOptions options;
  options.size_px = 16;
  options.transform.m[0] = std::nan("");
  EXPECT_THROW(layout_text_image(font, "x", options), Error);
  options.transform = Transform{{1e12, 0, 0, 0, 1, 0, 0, 0, 1}};
  EXPECT_THROW(layout_text_image(font, "x", options), Error);
  options.transform = Transform{{1, 2, 0, 2, 4, 0, 0, 0, 1}};  // singular
  EXPECT_THROW(layout_text_image(font, "x", options), Error);
  options.transform = Transform::perspective(89.0, 10.0);  // behind the viewer
  EXPECT_THROW(layout_text_image(font, "Hamburgefontsiv", options), Error);
  options.transform = Transform::scale(5000.0, 5000.0);  // image too large
  EXPECT_THROW(layout_text_image(font, "Hamburgefontsiv", options), Error);
}

}  // namespace
}  // namespace curvetext
