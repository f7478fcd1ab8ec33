// The stroker's geometry (lib/stroke) without a GPU: the nonzero union of a
// stroke's outline (exact area coverage, support/union_coverage.hpp)
// against closed-form areas, meshing by build_mesh, the invariants of
// docs/strokes.md and the bounded-input cases.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
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
      if (s.kind == Segment::Kind::Conic) {
        EXPECT_NEAR(s.weight, w, 1e-12);
      }
  EXPECT_NEAR(union_area(o, {-13, -13}, {13, 13}), kPi * (144.0 - 64.0), kPi * 80.0 * kAreaRelative);
}

ShapeContour reversed_contour(const ShapeContour& c) {
  ShapeContour r;
  r.closed = c.closed;
  for (auto it = c.pieces.rbegin(); it != c.pieces.rend(); ++it) {
    RationalBezier b = *it;
    std::reverse(b.points.begin(), b.points.end());
    std::reverse(b.weights.begin(), b.weights.end());
    r.pieces.push_back(b);
  }
  return r;
}

TEST(StrokeInvariant, ReversedOpenPathGivesTheSameStroke) {
  ShapeContour c = polyline({{2, 3}, {20, 18}, {9, 30}}, false);
  c.pieces.push_back(RationalBezier::cubic({9, 30}, {30, 40}, {-5, 44}, {28, 52}));
  c.pieces.push_back(RationalBezier::conic({28, 52}, {40, 60}, {30, 34}, 0.6));
  for (LineJoin j : {LineJoin::Miter, LineJoin::Round, LineJoin::Bevel, LineJoin::MiterClip, LineJoin::Arcs})
    for (LineCap cap : {LineCap::Butt, LineCap::Round, LineCap::Square}) {
      const StrokeStyle st = style(5, j, cap);
      const double a = stroke_area({c}, st, {-10, -10}, {50, 70});
      const double b = stroke_area({reversed_contour(c)}, st, {-10, -10}, {50, 70});
      EXPECT_NEAR(a, b, a * 1e-4) << static_cast<int>(j) << " " << static_cast<int>(cap);
    }
}

TEST(StrokeInvariant, ArcsJoinOfLinesIsTheMiterJoin) {
  // SVG 2: arcs between two straight segments is a miter, with its limit
  // clipping as miter-clip does.
  const std::vector<ShapeContour> path{polyline({{0, 0}, {10, 0}, {10, 10}}, false)};
  const Vec2 lo{-3, -3}, hi{13, 13};
  StrokeStyle a = style(2, LineJoin::Arcs, LineCap::Butt), m = style(2, LineJoin::MiterClip, LineCap::Butt);
  EXPECT_NEAR(stroke_area(path, a, lo, hi), stroke_area(path, m, lo, hi), 1e-6);
  a.miter_limit = m.miter_limit = 1.2;
  EXPECT_NEAR(stroke_area(path, a, lo, hi), stroke_area(path, m, lo, hi), 1e-6);
}

TEST(StrokeInvariant, ArcsJoinBetweenCurvesFollowsTheirCurvature) {
  // A quarter circle turning left (centre (0, 10), radius 10) then one
  // turning right (centre (10, 20)), meeting at (10, 10) with a left turn of
  // 90 degrees; width 2. The outer (right) edges continue as circles of
  // radius 11 about (0, 10) from a = (11, 10) and 9 about (10, 20) back
  // from b = (10, 11): they meet at X, x + y = 22, x^2 - 12x + 11.5 = 0.
  ShapeContour c;
  c.closed = false;
  const double w = std::sqrt(0.5);
  c.pieces = {RationalBezier::conic({0, 0}, {10, 0}, {10, 10}, w),
              RationalBezier::conic({10, 10}, {0, 10}, {0, 20}, w)};
  const auto area = [&](LineJoin j) { return stroke_area({c}, style(2, j, LineCap::Butt), {-3, -3}, {14, 23}); };
  const Vec2 p{10, 10}, a{11, 10}, b{10, 11}, ca{0, 10}, cb{10, 20};
  const double xx = (12.0 + std::sqrt(144.0 - 46.0)) / 2.0;
  const Vec2 x{xx, 22.0 - xx};
  // The join region p, a, arc to X, arc to b, by the shoelace formula over
  // finely sampled arcs.
  std::vector<Vec2> ring{p};
  const auto arc = [&](Vec2 centre, Vec2 from, Vec2 to) {
    const double r = distance(from, centre), t0 = std::atan2(from.y - centre.y, from.x - centre.x);
    double t1 = std::atan2(to.y - centre.y, to.x - centre.x);
    if (std::abs(t1 - t0) > kPi) t1 += t1 < t0 ? 2 * kPi : -2 * kPi;
    for (int i = 0; i <= 4000; ++i) {
      const double t = t0 + (t1 - t0) * i / 4000.0;
      ring.push_back({centre.x + r * std::cos(t), centre.y + r * std::sin(t)});
    }
  };
  arc(ca, a, x);
  arc(cb, x, b);
  double join = 0.0;
  for (std::size_t i = 0; i < ring.size(); ++i) join += cross(ring[i], ring[(i + 1) % ring.size()]) * 0.5;
  const double bevel = area(LineJoin::Bevel);
  EXPECT_NEAR(area(LineJoin::Arcs), bevel + std::abs(join) - 0.5, 2e-3);  // 0.5: the bevel's triangle p, a, b
  EXPECT_GT(std::abs(join) - 0.5, 0.5);                                   // beyond the miter's square corner here
}

TEST(StrokeDashes, DashEndsFallAtTheirArcLength) {
  // A half circle of radius 50 (length 50 pi) dashed 10 on, 10 off, butt
  // caps: each dash's outline has its ends at multiples of 10 along the arc,
  // so its area is exactly 10 * width wherever it lies on the arc.
  ShapeContour c;
  c.closed = false;
  const double w = std::sqrt(0.5);
  c.pieces = {RationalBezier::conic({50, 0}, {50, 50}, {0, 50}, w),
              RationalBezier::conic({0, 50}, {-50, 50}, {-50, 0}, w)};
  StrokeStyle st = style(2, LineJoin::Miter, LineCap::Butt);
  st.dashes = {10, 10};
  const Outline o = stroke_outline({c}, st, 1e-3);
  // 50 pi / 20 = 7.85 periods: 8 dashes, the last 0.85 * 20 - 10 = 7.08 long.
  ASSERT_EQ(o.contours().size(), 8u);
  const double annulus_per_length = 2.0 * 50.0 / 50.0;  // area per unit of centre-line length: width * R / R
  for (std::size_t i = 0; i + 1 < o.contours().size(); ++i) {
    Outline one;
    one.contours().push_back(o.contours()[i]);
    EXPECT_NEAR(std::abs(one.signed_area()), 10.0 * annulus_per_length, 10.0 * annulus_per_length * 1e-5) << i;
  }
}

TEST(StrokeDashes, InvalidPatternsDrawSolidPerSvg) {
  const std::vector<ShapeContour> line{polyline({{0, 0}, {10, 0}}, false)};
  const Vec2 lo{-3, -3}, hi{13, 3};
  for (std::vector<double> dashes : {std::vector<double>{}, {2, -1}, {0, 0}, {0}}) {
    StrokeStyle st = style(2, LineJoin::Miter, LineCap::Butt);
    st.dashes = dashes;
    EXPECT_NEAR(stroke_area(line, st, lo, hi), 20.0, 20.0 * kAreaRelative) << dashes.size();
  }
  StrokeStyle odd = style(2, LineJoin::Miter, LineCap::Butt);
  odd.dashes = {3};  // repeated: 3 on, 3 off: dashes at 0-3, 6-9
  EXPECT_NEAR(stroke_area(line, odd, lo, hi), 12.0, 12.0 * kAreaRelative);
  odd.path_length = 20.0;  // lengths times 10 / 20: on 0-1.5, 3-4.5, 6-7.5, 9-10
  EXPECT_NEAR(stroke_area(line, odd, lo, hi), 11.0, 11.0 * kAreaRelative);
  odd.dash_offset = 4.0;  // 2 (scaled) into the pattern: on 1-2.5, 4-5.5, 7-8.5
  EXPECT_NEAR(stroke_area(line, odd, lo, hi), 9.0, 9.0 * kAreaRelative);
}

TEST(StrokeBadInput, NegativeOrZeroWidthStrokesNothing) {
  const std::vector<ShapeContour> line{polyline({{0, 0}, {10, 0}}, false)};
  EXPECT_TRUE(stroke_outline(line, style(-2, LineJoin::Miter, LineCap::Round), 1e-3).empty());
  EXPECT_TRUE(stroke_outline(line, style(0, LineJoin::Miter, LineCap::Round), 1e-3).empty());
  StrokeStyle hair = style(-2, LineJoin::Miter, LineCap::Butt);
  hair.width_unit = StrokeWidthUnit::Hairline;  // one device pixel whatever the width
  EXPECT_NEAR(union_area(stroke_outline(line, hair, 1e-3, 4.0), {-3, -3}, {13, 3}), 10.0 * 0.25, 1e-3);
}

TEST(StrokeBadInput, NonFiniteValuesAreRefusedByName) {
  const std::vector<ShapeContour> line{polyline({{0, 0}, {10, 0}}, false)};
  StrokeStyle st;
  st.width = std::nan("");
  testing::expect_error([&] { (void)stroke_outline(line, st, 1e-3); }, ErrorCode::InvalidArgument, "stroke width");
  st = StrokeStyle{};
  st.dashes = {1, HUGE_VAL};
  testing::expect_error([&] { (void)stroke_outline(line, st, 1e-3); }, ErrorCode::InvalidArgument, "dash length");
  st = StrokeStyle{};
  st.miter_limit = std::nan("");
  testing::expect_error([&] { (void)stroke_outline(line, st, 1e-3); }, ErrorCode::InvalidArgument, "miter limit");
  testing::expect_error([&] { (void)stroke_outline(line, StrokeStyle{}, 0.0); }, ErrorCode::InvalidArgument,
                        "tolerance");
  testing::expect_error([&] { (void)stroke_outline(line, StrokeStyle{}, 1e-3, -1.0); }, ErrorCode::InvalidArgument,
                        "px_per_unit");
}

// Strokes that stress the mesher: a valid mesh (checked by build_mesh
// itself) or Error(Geometry), in bounded time.
void expect_mesh_or_error(const std::vector<ShapeContour>& path, const StrokeStyle& st, double tolerance,
                          double seconds, const char* what) {
  const auto t0 = std::chrono::steady_clock::now();
  try {
    const Mesh m = build_mesh(stroke_outline(path, st, tolerance));
    EXPECT_FALSE(m.empty()) << what;
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::Geometry) << what << ": " << e.what();
  }
  const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf("%-44s %.3f s\n", what, s);
  EXPECT_LT(s, seconds) << what;
}

TEST(StrokeBadInput, LongPathsManyDashesCuspsAndExtremeWidths) {
  // 65,536 segments: a closed wavy ring (a zigzag band of that length takes
  // build_mesh about 20 s: docs/strokes.md, limits).
  ShapeContour ring;
  const int n = 65536;
  for (int i = 0; i < n; ++i) {
    const auto at = [&](int k) {
      const double t = 2 * kPi * k / n, r = 1000.0 + 0.02 * (k % 2);
      return Vec2{r * std::cos(t), r * std::sin(t)};
    };
    ring.pieces.push_back(RationalBezier::line(at(i), at((i + 1) % n)));
  }
  expect_mesh_or_error({ring}, style(0.5, LineJoin::Miter, LineCap::Butt), 1e-2, 10.0, "65,536 segments, miter");
  ShapeContour zigzag;
  zigzag.closed = false;
  for (int i = 0; i < 2048; ++i)
    zigzag.pieces.push_back(RationalBezier::line({i * 1.0, (i % 2) * 3.0}, {i + 1.0, ((i + 1) % 2) * 3.0}));
  StrokeStyle dashes = style(1, LineJoin::Miter, LineCap::Butt);
  dashes.dashes = {0.001, 0.001};  // 10^6 dashes along the zigzag's 6,500 units
  expect_mesh_or_error({zigzag}, dashes, 1e-2, 5.0, "10^6 dashes");
  StrokeStyle long_pattern = style(1, LineJoin::Miter, LineCap::Butt);
  long_pattern.dashes.assign(1000000, 0.5);  // a pattern of 10^6 entries on a short path
  expect_mesh_or_error({polyline({{0, 0}, {40, 0}}, false)}, long_pattern, 1e-2, 5.0, "10^6-entry pattern");
  ShapeContour cusp;
  cusp.closed = false;
  cusp.pieces.push_back(RationalBezier::cubic({0, 0}, {100, 100}, {0, 100}, {100, 0}));
  for (LineJoin j : {LineJoin::Round, LineJoin::Miter})
    expect_mesh_or_error({cusp}, style(30, j, LineCap::Round), 1e-2, 5.0, "cusp, width 30");
  ShapeContour turns = polyline({{0, 0}, {10, 0}, {0, 0}, {10, 0}, {0, 0}, {10, 1e-9}}, false);
  expect_mesh_or_error({turns}, style(3, LineJoin::Round, LineCap::Square), 1e-3, 5.0, "180-degree turns");
  expect_mesh_or_error({cusp}, style(1e7, LineJoin::Round, LineCap::Round), 1.0, 5.0, "width 1e7");
  expect_mesh_or_error({cusp}, style(1e-7, LineJoin::Round, LineCap::Round), 1e-9, 5.0, "width 1e-7");
}

TEST(StrokeJson, EveryPropertyIsRead) {
  const ShapeDocument doc = parse_shape_json(R"({"shapes": [
    {"fill": false, "paint_order": "stroke fill",
     "stroke": {"width": 3, "units": "px", "color": "#ff0000", "opacity": 0.5, "join": "miter-clip",
                "miter_limit": 2.5, "cap": "square", "dashes": [4, 2, 1], "dash_offset": -3, "path_length": 100},
     "contours": [{"items": [{"line": [[0, 0], [10, 0], [10, 10]]}], "closed": false}, [{"line": [[0, 0], [5, 5]]}]]},
    {"stroke": {"units": "hairline", "join": "arcs"}, "contours": [[{"line": [[0, 0], [1, 1]]}]]}]})");
  ASSERT_EQ(doc.shapes.size(), 2u);
  const Shape& a = doc.shapes[0];
  EXPECT_FALSE(a.filled);
  EXPECT_EQ(a.paint_order, PaintOrder::StrokeFill);
  ASSERT_TRUE(a.stroke.has_value());
  const StrokeStyle& st = a.stroke->style;
  EXPECT_EQ(st.width, 3.0);
  EXPECT_EQ(st.width_unit, StrokeWidthUnit::Device);
  EXPECT_FLOAT_EQ(a.stroke->color.r, 1.0f);
  EXPECT_FLOAT_EQ(a.stroke->color.a, 0.5f);
  EXPECT_EQ(st.join, LineJoin::MiterClip);
  EXPECT_EQ(st.miter_limit, 2.5);
  EXPECT_EQ(st.cap, LineCap::Square);
  EXPECT_EQ(st.dashes, (std::vector<double>{4, 2, 1}));
  EXPECT_EQ(st.dash_offset, -3.0);
  EXPECT_EQ(st.path_length, 100.0);
  ASSERT_EQ(a.contours.size(), 2u);
  EXPECT_FALSE(a.contours[0].closed);
  EXPECT_TRUE(a.contours[1].closed);
  EXPECT_TRUE(doc.shapes[1].filled);
  EXPECT_EQ(doc.shapes[1].stroke->style.width_unit, StrokeWidthUnit::Hairline);
  EXPECT_EQ(doc.shapes[1].stroke->style.join, LineJoin::Arcs);
  EXPECT_EQ(doc.shapes[1].paint_order, PaintOrder::FillStroke);
}

TEST(StrokeJson, BadValuesAreRefusedByName) {
  const std::string head = R"({"shapes": [{"contours": [[{"line": [[0, 0], [1, 0]]}]], "stroke": )";
  const struct {
    const char* stroke;
    const char* part;
  } cases[] = {
      {R"({"width": -1})", "shapes[0].stroke.width"},
      {R"({"join": "mitre"})", "unknown value \"mitre\""},
      {R"({"cap": 1})", "cap: expected a string"},
      {R"({"units": "mm"})", "known: user, px, hairline"},
      {R"({"dashes": [1, -2]})", "stroke.dashes[1]"},
      {R"({"miter_limit": 0.5})", "miter_limit"},
      {R"({"opacity": 2})", "opacity"},
      {R"({"colour": "red"})", "unknown key \"colour\""},
  };
  for (const auto& c : cases)
    testing::expect_error([&] { (void)parse_shape_json(head + c.stroke + "}]}"); }, ErrorCode::InvalidArgument, c.part);
  testing::expect_error([] { (void)parse_shape_json(R"({"shapes": [{"contours": [{"items": [], "open": true}]}]})"); },
                        ErrorCode::InvalidArgument, "unknown key \"open\"");
}

}  // namespace
}  // namespace curvetext
