// The stroker's geometry (lib/stroke) without a GPU: the nonzero union of a
// stroke's outline (exact area coverage, support/union_coverage.hpp)
// against closed-form areas, meshing by build_mesh, the invariants of
// docs/strokes.md and the bounded-input cases.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <vector>

#include "curvetext/error.hpp"
#include "curvetext/mesh.hpp"
#include "curvetext/stroke.hpp"
#include "support/expect_error.hpp"
#include "support/union_coverage.hpp"

namespace curvetext {
namespace {

constexpr double kPi = 3.14159265358979323846;

ShapeContour polyline(std::initializer_list<Vec2> points, bool closed) {
  ShapeContour c;
  c.closed = closed;
  const Vec2* prev = nullptr;
  for (const Vec2& p : points) {
    if (prev) c.pieces.push_back(RationalBezier::line(*prev, p));
    prev = &p;
  }
  return c;
}

StrokeStyle style(double width, LineJoin join, LineCap cap) {
  StrokeStyle s;
  s.width = width;
  s.join = join;
  s.cap = cap;
  return s;
}

// Area of the nonzero union of `o` (path units), measured as exact pixel
// coverage at `scale` px per unit over the box [lo, hi].
double union_area(const Outline& o, Vec2 lo, Vec2 hi, double scale = 8.0) {
  Outline px;
  for (const Contour& c : o.contours()) {
    bool first = true;
    for (const Segment& s : c.segments) {
      auto map = [&](Vec2 p) { return Vec2{(p.x - lo.x) * scale, (hi.y - p.y) * scale}; };
      if (first) px.move_to(map(s.p[0]));
      first = false;
      if (s.kind == Segment::Kind::Line)
        px.line_to(map(s.p[1]));
      else
        px.conic_to(map(s.p[1]), map(s.p[2]), s.weight);
    }
    px.close();
  }
  const int w = static_cast<int>(std::ceil((hi.x - lo.x) * scale)),
            h = static_cast<int>(std::ceil((hi.y - lo.y) * scale));
  const test::Coverage c = test::union_coverage(px, w, h);
  double sum = 0.0;
  for (float v : c.value) sum += v;
  return sum / (scale * scale);
}

double stroke_area(const std::vector<ShapeContour>& path, const StrokeStyle& s, Vec2 lo, Vec2 hi) {
  return union_area(stroke_outline(path, s, 1e-3), lo, hi);
}

// The union's flattening and float32 coverage sum: relative area error.
constexpr double kAreaRelative = 2e-4;

TEST(StrokeArea, StraightLineWithEachCap) {
  const std::vector<ShapeContour> line{polyline({{0, 0}, {10, 0}}, false)};
  const Vec2 lo{-3, -3}, hi{13, 3};
  EXPECT_NEAR(stroke_area(line, style(2, LineJoin::Miter, LineCap::Butt), lo, hi), 20.0, 20.0 * kAreaRelative);
  EXPECT_NEAR(stroke_area(line, style(2, LineJoin::Miter, LineCap::Square), lo, hi), 24.0, 24.0 * kAreaRelative);
  EXPECT_NEAR(stroke_area(line, style(2, LineJoin::Miter, LineCap::Round), lo, hi), 20.0 + kPi,
              (20.0 + kPi) * kAreaRelative);
}

TEST(StrokeArea, RightAngleJoins) {
  // Two legs of 10 at a right angle, width 2: 2 * 20 less the shared
  // 1 x 1 inner square, plus the outer corner piece of each join.
  const std::vector<ShapeContour> path{polyline({{0, 0}, {10, 0}, {10, 10}}, false)};
  const Vec2 lo{-3, -3}, hi{13, 13};
  const double base = 40.0 - 1.0;
  EXPECT_NEAR(stroke_area(path, style(2, LineJoin::Bevel, LineCap::Butt), lo, hi), base + 0.5, 1e-2);
  EXPECT_NEAR(stroke_area(path, style(2, LineJoin::Miter, LineCap::Butt), lo, hi), base + 1.0, 1e-2);
  EXPECT_NEAR(stroke_area(path, style(2, LineJoin::Round, LineCap::Butt), lo, hi), base + kPi / 4.0, 1e-2);
  // Miter ratio sqrt(2) > 1.2: bevel; miter-clip cuts at 1.2 * 1 from the corner.
  StrokeStyle m = style(2, LineJoin::Miter, LineCap::Butt);
  m.miter_limit = 1.2;
  EXPECT_NEAR(stroke_area(path, m, lo, hi), base + 0.5, 1e-2);
  m.join = LineJoin::MiterClip;
  // The clipped miter: the square corner less the triangle beyond the clip
  // line at distance 1.2 from the corner along the diagonal (tip at sqrt(2)).
  const double cut = std::sqrt(2.0) - 1.2;
  EXPECT_NEAR(stroke_area(path, m, lo, hi), base + 1.0 - cut * cut, 1e-2);
}

TEST(StrokeArea, CircleIsAnExactAnnulus) {
  // A circle of radius 10 as four exact quarter conics, width 4.
  ShapeContour c;
  const double w = std::sqrt(0.5);
  c.pieces = {
      RationalBezier::conic({10, 0}, {10, 10}, {0, 10}, w), RationalBezier::conic({0, 10}, {-10, 10}, {-10, 0}, w),
      RationalBezier::conic({-10, 0}, {-10, -10}, {0, -10}, w), RationalBezier::conic({0, -10}, {10, -10}, {10, 0}, w)};
  const Outline o = stroke_outline({c}, style(4, LineJoin::Miter, LineCap::Butt), 1e-3);
  // Exact offsets: every piece is a conic with the circle's weight.
  for (const Contour& k : o.contours())
    for (const Segment& s : k.segments)
      if (s.kind == Segment::Kind::Conic) EXPECT_NEAR(s.weight, w, 1e-12);
  EXPECT_NEAR(union_area(o, {-13, -13}, {13, 13}), kPi * (144.0 - 64.0), kPi * 80.0 * kAreaRelative);
}

}  // namespace
}  // namespace curvetext
