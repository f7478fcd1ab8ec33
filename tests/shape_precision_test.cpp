// Shapes drawn where float32 and the area shader are pushed: high-weight
// conics, and geometry far from the document's origin.
//
// High-weight conics (w = 16, 40, 1000) hug their control polygon: most of
// the arc's length runs close along its legs, and its parameter crowds at
// the apex. Drawn at 1x and through a 20x zoom window on a flank, every
// antialiasing mode that computes area (full, vbaa) matches the exact
// coverage of the region between the chord and the arc, by the conic's
// implicit form tau1^2 < 4 w^2 tau0 tau2 (docs/design.md section 3) sampled
// 32 x 32 per pixel.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "curvetext/error.hpp"
#include "curvetext/renderer.hpp"
#include "curvetext/shape_image.hpp"
#include "curvetext/shapes.hpp"
#include "support/coverage.hpp"
#include "support/gpu.hpp"

namespace curvetext {
namespace {

constexpr Vec2 kP0{0.0, 0.0}, kC{50.0, 80.0}, kP2{100.0, 0.0};

ShapeDocument conic_shape(double w) {
  ShapeDocument doc;
  Shape s;
  s.contours.push_back(ShapeContour{{RationalBezier::conic(kP0, kC, kP2, w), RationalBezier::line(kP2, kP0)}});
  doc.shapes.push_back(s);
  return doc;
}

// Inside the region between the chord and the arc, at document point (x, y).
bool inside(double w, double x, double y) {
  // Barycentrics in the control triangle (p0, c, p2).
  const double d = (kC.x - kP0.x) * (kP2.y - kP0.y) - (kP2.x - kP0.x) * (kC.y - kP0.y);
  const double t1 = ((x - kP0.x) * (kP2.y - kP0.y) - (kP2.x - kP0.x) * (y - kP0.y)) / d;
  const double t2 = ((kC.x - kP0.x) * (y - kP0.y) - (x - kP0.x) * (kC.y - kP0.y)) / d;
  const double t0 = 1.0 - t1 - t2;
  if (t0 < 0.0 || t1 < 0.0 || t2 < 0.0) return false;
  return t1 * t1 < 4.0 * w * w * t0 * t2;
}

struct View {
  const char* name;
  double scale;   // pixels per document unit
  double x0, y0;  // document point at the image's top-left
  int width, height;
};

TEST(ConicWeight, HighWeightsMatchExactCoverageAtOneAndTwentyTimes) {
  // The whole shape; a window on the left flank near the apex at 20x, where
  // the arc runs within a few pixels of the leg; and one at the apex.
  const View views[] = {{"1x", 1.0, -10.0, 90.0, 120, 100},
                        {"20x flank", 20.0, 40.0, 74.0, 200, 160},
                        {"20x apex", 20.0, 45.0, 82.0, 200, 160}};
  struct Mode {
    AntiAliasing aa;
    double edge, max;
  };
  for (double w : {16.0, 40.0, 1000.0}) {
    const ShapeDocument doc = conic_shape(w);
    for (const View& v : views) {
      ShapeImageLayout layout;
      layout.width = v.width;
      layout.height = v.height;
      layout.placement = Placement(v.scale, -v.x0 * v.scale, v.y0 * v.scale);
      const test::Coverage ref = test::sampled_reference(
          [&](double px, double py) { return inside(w, v.x0 + px / v.scale, v.y0 - py / v.scale); }, v.width, v.height,
          32);
      for (const Mode& m : {Mode{AntiAliasing::Full, 0.01, 0.06}, Mode{AntiAliasing::Vbaa, 0.01, 0.06}}) {
        ShapeImageOptions o;
        o.antialiasing = m.aa;
        const test::Coverage got =
            test::coverage_from_black_on_white(render_shape_image(test::gpu().renderer, doc, layout, o));
        const test::CoverageStats st = test::compare(got, ref);
        const std::string name = "conic-w" + std::to_string(static_cast<int>(w)) + "-" + v.name + "-mode" +
                                 std::to_string(static_cast<int>(m.aa));
        std::printf("%-32s edge %.4f  max %.3f  ink %.4f  (%zu edge px)\n", name.c_str(), st.edge_mean_abs, st.max_abs,
                    st.ink_ratio, st.edge_pixels);
        if (st.edge_mean_abs > m.edge || st.max_abs > m.max) test::write_comparison(name, got, ref);
        EXPECT_GT(st.edge_pixels, 50u) << name;
        EXPECT_LE(st.edge_mean_abs, m.edge) << name;
        EXPECT_LE(st.max_abs, m.max) << name;
      }
    }
  }
}

// A circle of radius 50 centred at (1e8, -3e7), drawn at 1 px per unit:
// float32 holds 1e8 to within 8 units, so the mesh is drawn relative to the
// view's centre (moved there in double) and matches the exact coverage.
TEST(FarGeometry, SmallShapeFarFromTheOriginIsDrawnExactly) {
  const double cx = 1e8, cy = -3e7, r = 50.0, k = 0.70710678118654757;
  ShapeDocument doc;
  Shape s;
  ShapeContour c;
  const Vec2 pts[9] = {{cx + r, cy},     {cx + r, cy + r}, {cx, cy + r},     {cx - r, cy + r}, {cx - r, cy},
                       {cx - r, cy - r}, {cx, cy - r},     {cx + r, cy - r}, {cx + r, cy}};
  for (int i = 0; i < 8; i += 2) c.pieces.push_back(RationalBezier::conic(pts[i], pts[i + 1], pts[i + 2], k));
  s.contours.push_back(c);
  doc.shapes.push_back(s);
  doc.view = Box{{cx - 64.3, cy - 60.1}, {cx + 63.7, cy + 67.9}};
  ShapeImageOptions o;
  o.scale = 1.0;
  const ShapeImageLayout layout = layout_shape_image(doc, o);
  const test::Coverage got =
      test::coverage_from_black_on_white(render_shape_image(test::gpu().renderer, doc, layout, o));
  const Placement& p = layout.placement;
  const test::Coverage ref = test::sampled_reference(
      [&](double px, double py) {
        const double x = (px - p.origin_x) / p.scale - cx, y = (p.origin_y - py) / p.scale - cy;
        return x * x + y * y < r * r;
      },
      layout.width, layout.height, 32);
  const test::CoverageStats st = test::compare(got, ref);
  std::printf("circle r=50 at (1e8, -3e7): edge %.4f, max %.3f, ink %.4f\n", st.edge_mean_abs, st.max_abs,
              st.ink_ratio);
  if (st.edge_mean_abs > 0.01) test::write_comparison("far-circle", got, ref);
  EXPECT_GT(st.edge_pixels, 200u);
  EXPECT_LE(st.edge_mean_abs, 0.01);
  EXPECT_NEAR(st.ink_ratio, 1.0, 0.005);
}

// A circle of radius 1e7 px seen through a 512 px window on its edge: its
// curve pieces reach 1e7 px from the view, where float32 cannot place them
// within 1/16 px: refused with an error saying so, not drawn with stripes.
TEST(FarGeometry, GeometryBeyondFloatPrecisionIsRefused) {
  const double r = 1e7, k = 0.70710678118654757;
  ShapeDocument doc;
  Shape s;
  ShapeContour c;
  const Vec2 pts[9] = {{r, 0}, {r, r}, {0, r}, {-r, r}, {-r, 0}, {-r, -r}, {0, -r}, {r, -r}, {r, 0}};
  for (int i = 0; i < 8; i += 2) c.pieces.push_back(RationalBezier::conic(pts[i], pts[i + 1], pts[i + 2], k));
  s.contours.push_back(c);
  doc.shapes.push_back(s);
  doc.view = Box{{r - 256.0, -256.0}, {r + 256.0, 256.0}};
  ShapeImageOptions o;
  o.scale = 1.0;
  const ShapeImageLayout layout = layout_shape_image(doc, o);
  try {
    (void)render_shape_image(test::gpu().renderer, doc, layout, o);
    ADD_FAILURE() << "a circle of radius 1e7 px was drawn through float32";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::Geometry);
    EXPECT_NE(std::string(e.what()).find("float32"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace curvetext
