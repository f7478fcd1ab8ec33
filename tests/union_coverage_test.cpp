// The exact nonzero-union coverage reference (support/union_coverage.hpp)
// against shapes whose coverage is known in closed form, and against the
// cases FreeType's rasterizer gets wrong (overlapping contours).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "curvetext/font.hpp"
#include "curvetext/renderer.hpp"
#include "support/coverage.hpp"
#include "support/fonts.hpp"
#include "support/union_coverage.hpp"

namespace curvetext {
namespace {

// Exact shapes are reproduced to rounding: sums of a few hundred doubles,
// stored as float (coverage units).
constexpr double kRoundingTolerance = 1e-5;

Outline rectangle(double x0, double y0, double x1, double y1, bool counter_clockwise = true) {
  Outline o;
  o.move_to({x0, y0});
  if (counter_clockwise) {
    o.line_to({x1, y0});
    o.line_to({x1, y1});
    o.line_to({x0, y1});
  } else {
    o.line_to({x0, y1});
    o.line_to({x1, y1});
    o.line_to({x1, y0});
  }
  o.close();
  return o;
}

Outline join(const Outline& a, const Outline& b) {
  Outline o = a;
  for (const Contour& c : b.contours()) o.contours().push_back(c);
  return o;
}

// Area of [x0,x1]x[y0,y1] inside pixel (px, py).
double box_in_pixel(double x0, double y0, double x1, double y1, int px, int py) {
  const double w = std::max(0.0, std::min(x1, px + 1.0) - std::max(x0, static_cast<double>(px)));
  const double h = std::max(0.0, std::min(y1, py + 1.0) - std::max(y0, static_cast<double>(py)));
  return w * h;
}

double total(const test::Coverage& c) {
  double s = 0;
  for (float v : c.value) s += v;
  return s;
}

double max_difference(const test::Coverage& a, const test::Coverage& b) {
  double m = 0;
  for (std::size_t i = 0; i < a.value.size(); ++i)
    m = std::max(m, std::abs(static_cast<double>(a.value[i]) - b.value[i]));
  return m;
}

TEST(UnionCoverage, SquareAtAFractionalPositionIsExactPerPixel) {
  const double x0 = 2.3, y0 = 3.7, x1 = 12.3, y1 = 13.7;
  const test::Coverage c = test::union_coverage(rectangle(x0, y0, x1, y1), 16, 16);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x)
      EXPECT_NEAR(c.at(x, y), box_in_pixel(x0, y0, x1, y1, x, y), kRoundingTolerance) << x << "," << y;
  EXPECT_NEAR(total(c), 100.0, 1e-4);
}

TEST(UnionCoverage, SlantedTriangleMatchesItsArea) {
  // A triangle with no axis-aligned edge: per-pixel values are checked by
  // their sum and against a 64x64 point-sampled estimate.
  Outline o;
  o.move_to({1.2, 1.7});
  o.line_to({17.9, 5.3});
  o.line_to({6.4, 18.8});
  o.close();
  const test::Coverage c = test::union_coverage(o, 20, 20);
  const double area = 0.5 * std::abs((17.9 - 1.2) * (18.8 - 1.7) - (6.4 - 1.2) * (5.3 - 1.7));
  EXPECT_NEAR(total(c), area, 1e-4);
  const test::Coverage sampled = test::sampled_reference(
      [](double x, double y) {
        auto side = [&](double ax, double ay, double bx, double by) {
          return (bx - ax) * (y - ay) - (by - ay) * (x - ax);
        };
        const double s1 = side(1.2, 1.7, 17.9, 5.3), s2 = side(17.9, 5.3, 6.4, 18.8), s3 = side(6.4, 18.8, 1.2, 1.7);
        return (s1 > 0 && s2 > 0 && s3 > 0) || (s1 < 0 && s2 < 0 && s3 < 0);
      },
      20, 20, 64);
  // Point sampling on a 64x64 grid is within about 2/64 of the area per pixel.
  EXPECT_LE(max_difference(c, sampled), 2.0 / 64);
}

TEST(UnionCoverage, CircleOfFourConicsHasAreaPiRSquared) {
  const double r = 20.0, cx = 24.4, cy = 23.9, w = std::numbers::sqrt2 / 2;
  Outline o;
  o.move_to({cx + r, cy});
  o.conic_to({cx + r, cy + r}, {cx, cy + r}, w);
  o.conic_to({cx - r, cy + r}, {cx - r, cy}, w);
  o.conic_to({cx - r, cy - r}, {cx, cy - r}, w);
  o.conic_to({cx + r, cy - r}, {cx + r, cy}, w);
  o.close();
  const test::Coverage c = test::union_coverage(o, 48, 48);
  // The polygon is inside the circle by at most the flatness: the area is
  // short by less than perimeter * flatness.
  const double exact = std::numbers::pi * r * r;
  EXPECT_LE(total(c), exact + 1e-6);
  EXPECT_GE(total(c), exact - 2 * std::numbers::pi * r * test::kUnionFlatnessPx);
  // Per pixel against a much finer flattening: within sqrt(2) * flatness.
  const test::Coverage fine = test::union_coverage(o, 48, 48, 1.0 / 65536);
  EXPECT_LE(max_difference(c, fine), std::numbers::sqrt2 * test::kUnionFlatnessPx);
  EXPECT_NEAR(total(fine), exact, 2 * std::numbers::pi * r / 65536);
}

TEST(UnionCoverage, CubicAndParabolaAreasAreExact) {
  // Parabolic segment: area between a weight-1 conic and its chord is 2/3 of
  // the control triangle; a cubic with collinear-thirds controls is the same
  // parabola.
  Outline parabola;
  parabola.move_to({2, 2});
  parabola.conic_to({10, 18}, {18, 2});
  parabola.close();
  Outline cubic;
  cubic.move_to({2, 2});
  cubic.cubic_to({2 + 2.0 / 3 * 8, 2 + 2.0 / 3 * 16}, {18 - 2.0 / 3 * 8, 2 + 2.0 / 3 * 16}, {18, 2});
  cubic.close();
  const test::Coverage a = test::union_coverage(parabola, 20, 20), b = test::union_coverage(cubic, 20, 20);
  const double area = 2.0 / 3 * 0.5 * 16 * 16;
  EXPECT_NEAR(total(a), area, 16 * 2 * test::kUnionFlatnessPx);
  EXPECT_LE(max_difference(a, b), 2 * test::kUnionFlatnessPx);
}

TEST(UnionCoverage, OverlappingSquaresGiveTheUnionNotTheSum) {
  const Outline a = rectangle(2.25, 2.5, 12.25, 12.5), b = rectangle(7.6, 6.1, 17.6, 16.1);
  const test::Coverage c = test::union_coverage(join(a, b), 20, 20);
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 20; ++x) {
      const double want = box_in_pixel(2.25, 2.5, 12.25, 12.5, x, y) + box_in_pixel(7.6, 6.1, 17.6, 16.1, x, y) -
                          box_in_pixel(7.6, 6.1, 12.25, 12.5, x, y);
      ASSERT_NEAR(c.at(x, y), want, kRoundingTolerance) << x << "," << y;
    }
  EXPECT_NEAR(total(c), 200.0 - (12.25 - 7.6) * (12.5 - 6.1), 1e-4);
}

TEST(UnionCoverage, FreeTypeOverCoversWhereContoursOverlapAndThisDoesNot) {
  // Two squares sharing an edge pixel column with fractional coverage: the
  // union there is the larger of the two, not their sum.
  const Outline a = rectangle(2.0, 2.0, 10.5, 10.0), b = rectangle(2.0, 2.0, 10.3, 10.0);
  const test::Coverage c = test::union_coverage(join(a, b), 14, 14);
  EXPECT_NEAR(c.at(10, 5), 0.5, kRoundingTolerance);
  // FreeType places outline units (y up) with a placement; y_px = 14 - y.
  Outline up = join(a, b);
  for (Contour& k : up.contours())
    for (Segment& s : k.segments)
      for (Vec2& p : s.p) p.y = 14.0 - p.y;
  const test::Coverage ft = test::freetype_reference(up, Placement{1.0, 0.0, 14.0}, 14, 14, 1);
  EXPECT_GT(ft.at(10, 5), 0.75)
      << "FreeType no longer sums overlapping contours; the note in docs/design.md section 6 is stale";
}

TEST(UnionCoverage, SelfIntersectingStarFillsItsCentre) {
  // A pentagram drawn as one self-intersecting contour: nonzero winding fills
  // the inner pentagon (winding 2) too, so it equals the simple decagon.
  const double cx = 20.3, cy = 19.8, R = 16.0;
  const double r = R * std::cos(2 * std::numbers::pi / 5) / std::cos(std::numbers::pi / 5);
  Outline star, decagon;
  for (int k = 0; k < 5; ++k) {
    const double t = std::numbers::pi / 2 + k * 4 * std::numbers::pi / 5;
    const Vec2 p{cx + R * std::cos(t), cy + R * std::sin(t)};
    if (k == 0)
      star.move_to(p);
    else
      star.line_to(p);
  }
  star.close();
  for (int k = 0; k < 10; ++k) {
    const double t = std::numbers::pi / 2 + k * std::numbers::pi / 5;
    const double rr = k % 2 ? r : R;
    const Vec2 p{cx + rr * std::cos(t), cy + rr * std::sin(t)};
    if (k == 0)
      decagon.move_to(p);
    else
      decagon.line_to(p);
  }
  decagon.close();
  const test::Coverage a = test::union_coverage(star, 40, 40), b = test::union_coverage(decagon, 40, 40);
  EXPECT_LE(max_difference(a, b), kRoundingTolerance);
  EXPECT_NEAR(total(a), 5 * R * r * std::sin(std::numbers::pi / 5), 1e-3);
  EXPECT_NEAR(a.at(20, 19), 1.0, kRoundingTolerance) << "the centre (winding 2) is filled";
}

TEST(UnionCoverage, OppositeOrientationMakesAHoleSameOrientationDoesNot) {
  const Outline outer = rectangle(2.5, 2.5, 17.5, 17.5);
  const test::Coverage hole = test::union_coverage(join(outer, rectangle(6.25, 6.25, 13.75, 13.75, false)), 20, 20);
  const test::Coverage same = test::union_coverage(join(outer, rectangle(6.25, 6.25, 13.75, 13.75, true)), 20, 20);
  EXPECT_NEAR(total(hole), 15.0 * 15.0 - 7.5 * 7.5, 1e-4);
  EXPECT_NEAR(total(same), 15.0 * 15.0, 1e-4);
  EXPECT_NEAR(hole.at(10, 10), 0.0, kRoundingTolerance);
  EXPECT_NEAR(hole.at(6, 10), 0.25, kRoundingTolerance);  // [6, 6.25] of it is outside the hole
  EXPECT_NEAR(same.at(10, 10), 1.0, kRoundingTolerance);
}

TEST(UnionCoverage, HorizontalStepPastAnotherContourInsideARow) {
  // An L whose right side steps from x = 10 back to x = 4 at y = 5.5 (inside
  // pixel row 5), with a second contour between the two x: the step changes
  // the order of the boundaries inside the row without any crossing (a bug
  // found on Inter wght 900 glyph 1052, whose counter then read as filled).
  Outline l;
  l.move_to({0, 0});
  l.line_to({10, 0});
  l.line_to({10, 5.5});
  l.line_to({4, 5.5});
  l.line_to({4, 10});
  l.line_to({0, 10});
  l.close();
  const test::Coverage c = test::union_coverage(join(l, rectangle(6, 3.2, 8, 8.7)), 12, 12);
  EXPECT_NEAR(total(c), 73.0 + 11.0 - 4.6, 1e-4);
  EXPECT_NEAR(c.at(7, 5), 1.0, kRoundingTolerance);  // L above 5.5, the square below
  EXPECT_NEAR(c.at(9, 5), 0.5, kRoundingTolerance);  // only the L, above 5.5
  EXPECT_NEAR(c.at(5, 5), 0.5, kRoundingTolerance);
  EXPECT_NEAR(c.at(5, 7), 0.0, kRoundingTolerance);
  EXPECT_NEAR(c.at(3, 7), 1.0, kRoundingTolerance);
}

TEST(UnionCoverage, CollinearSharedEdgesAndClippingAtTheImageBorder) {
  // Two squares sharing an edge exactly (as variable fonts' contours do):
  // the shared column is covered once.
  const test::Coverage c =
      test::union_coverage(join(rectangle(2.5, 2.0, 8.5, 10.0), rectangle(8.5, 2.0, 14.5, 10.0)), 16, 12);
  EXPECT_NEAR(c.at(8, 5), 1.0, kRoundingTolerance);
  EXPECT_NEAR(total(c), 12.0 * 8.0, 1e-4);
  // A shape hanging over every border: pixels inside the image are exact.
  const test::Coverage clipped = test::union_coverage(rectangle(-5.5, -3.25, 7.5, 6.75), 6, 5);
  for (int y = 0; y < 5; ++y)
    for (int x = 0; x < 6; ++x) EXPECT_NEAR(clipped.at(x, y), 1.0, kRoundingTolerance);
  const test::Coverage partly = test::union_coverage(rectangle(-5.5, -3.25, 3.5, 2.75), 6, 5);
  EXPECT_NEAR(partly.at(3, 2), 0.5 * 0.75, kRoundingTolerance);
  EXPECT_NEAR(partly.at(0, 0), 1.0, kRoundingTolerance);
}

TEST(UnionCoverage, AgreesWithSupersampledFreeTypeOnAGlyphWithoutOverlaps) {
  // DejaVu Sans "g" at 32 px/em: FreeType at 16x (chords within 1/256 px,
  // positions to 1/1024 px after the box filter) must agree closely.
  const Font font = Font::open(test::kDejaVuSans);
  const Outline glyph = font.glyph_outline(font.glyph_for_codepoint(U'g'));
  const Placement p{32.0 / font.metrics().units_per_em, 4.37, 30.21};
  const test::Coverage mine = test::union_coverage(test::place_outline(glyph, p), 32, 40);
  const test::Coverage ft = test::freetype_reference(glyph, p, 32, 40, 16);
  const test::CoverageStats s = test::compare(mine, ft);
  EXPECT_LE(s.max_abs, 0.01);
  EXPECT_NEAR(s.ink_ratio, 1.0, 1e-3);
  EXPECT_GT(s.edge_pixels, 50u);
}

TEST(UnionCoverage, NeverAboveSupersampledFreeTypeOnRealGlyphs) {
  // FreeType's nonzero rasterizer is exact for one contour and can only
  // over-cover where contours overlap (it sums them per cell), so the exact
  // union must never be above it by more than FreeType's own error at 16x
  // (chords within 1/256 px, points rounded to 1/1024 px). Glyphs with
  // overlaps (Inter), cubics (Nimbus Roman) and plain TrueType (DejaVu).
  constexpr double kFreeTypeError = 0.02;  // coverage units, per pixel
  const struct {
    const char* path;
    float wght;
    std::uint32_t stride;
  } fonts[] = {{test::kDejaVuSans, 0.0f, 23}, {test::kInterVariable, 900.0f, 7}, {test::kNimbusRoman, 0.0f, 5}};
  for (const auto& spec : fonts) {
    Font font = Font::open(spec.path);
    if (spec.wght > 0) font.set_variations({{"wght", spec.wght}});
    const double scale = 32.0 / font.metrics().units_per_em;
    for (std::uint32_t g = 0; g < font.glyph_count(); g += spec.stride) {
      const Outline outline = font.glyph_outline(g);
      if (outline.empty()) continue;
      const Box box = outline.control_box();
      const int w = static_cast<int>(scale * (box.max.x - box.min.x)) + 4;
      const int h = static_cast<int>(scale * (box.max.y - box.min.y)) + 4;
      if (w > 200 || h > 200) continue;
      const Placement p{scale, 1.37 - scale * box.min.x, 1.21 + scale * box.max.y};
      const test::Coverage mine = test::union_coverage(test::place_outline(outline, p), w, h);
      const test::Coverage ft = test::freetype_reference(outline, p, w, h, 16);
      double above = 0;
      for (std::size_t i = 0; i < mine.value.size(); ++i)
        above = std::max(above, static_cast<double>(mine.value[i]) - ft.value[i]);
      ASSERT_LE(above, kFreeTypeError) << spec.path << " glyph " << g;
    }
  }
}

}  // namespace
}  // namespace curvetext
