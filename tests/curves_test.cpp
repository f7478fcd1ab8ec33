// Curves: exact conic areas and subdivision, and the cubic -> quadratic bound
// checked by measuring the true distance between the curves.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <random>

#include "curvetext/curves.hpp"
#include "curvetext/outline.hpp"

namespace curvetext {
namespace {

// Area between a conic and its chord by a fine polyline (independent of the
// closed form under test).
double polyline_chord_area(const Segment& conic, int steps) {
  double area = 0.0;
  Vec2 prev = conic.p[0];
  for (int i = 1; i <= steps; ++i) {
    const Vec2 p = evaluate(conic, static_cast<double>(i) / steps);
    area += cross(prev, p);
    prev = p;
  }
  area += cross(prev, conic.p[0]);
  return -0.5 * area;  // the arc's loop turns opposite to this polyline's orientation
}

TEST(Conic, AreaRatioMatchesIntegration) {
  for (double w : {0.05, 0.3, 0.5, std::numbers::sqrt2 / 2, 0.999, 1.0, 1.0000001, 1.5, 3.0, 10.0}) {
    const Segment s = Segment::conic({0, 0}, {3, -2}, {5, 1}, w);
    const double expected = polyline_chord_area(s, 200000);
    EXPECT_NEAR(conic_chord_area(s), expected, 1e-8 * std::abs(expected) + 1e-9) << "w=" << w;
  }
  EXPECT_NEAR(conic_area_ratio(1.0), 2.0 / 3.0, 1e-15);
  EXPECT_NEAR(conic_area_ratio(std::numbers::sqrt2 / 2), std::numbers::pi / 2 - 1, 1e-14);
}

// Huge weights: the ratio tends to 1 (the curve hugs its legs), also where
// w * w overflows (it read 0 from w = 1.3e154 on, dropping a conic's cap).
TEST(Conic, AreaRatioOfHugeWeights) {
  double previous = conic_area_ratio(1e3);
  for (double w : {1e6, 1e7 * (1 - 1e-12), 1e7, 1e7 * (1 + 1e-12), 1e100, 1e154, 1e160, 1e300, 1.7e308}) {
    const double r = conic_area_ratio(w);
    EXPECT_GE(r, previous) << "w=" << w;
    EXPECT_LE(r, 1.0) << "w=" << w;
    EXPECT_GT(r, 1.0 - 1e-10) << "w=" << w;
    previous = r;
  }
}

Outline circle(Vec2 c, double r) {
  const double w = std::numbers::sqrt2 / 2;
  Outline o;
  o.move_to({c.x + r, c.y});
  o.conic_to({c.x + r, c.y + r}, {c.x, c.y + r}, w);
  o.conic_to({c.x - r, c.y + r}, {c.x - r, c.y}, w);
  o.conic_to({c.x - r, c.y - r}, {c.x, c.y - r}, w);
  o.conic_to({c.x + r, c.y - r}, {c.x + r, c.y}, w);
  o.close();
  return o;
}

TEST(Outline, CircleAreaIsExact) {
  const Outline o = circle({3, -7}, 400);
  EXPECT_NEAR(o.signed_area(), std::numbers::pi * 400 * 400, 1e-9 * 400 * 400);
  EXPECT_EQ(o.contours().size(), 1u);
  EXPECT_EQ(o.contours()[0].segments.size(), 4u);
}

TEST(Outline, BuilderClosesContoursAndSkipsEmptyOnes) {
  Outline o;
  o.move_to({0, 0});
  o.line_to({10, 0});
  o.line_to({10, 10});  // not closed by hand
  o.move_to({50, 50});  // closes the first, opens an empty one
  o.move_to({20, 20});  // the empty one is dropped
  o.line_to({20, 20});  // zero-length: nothing
  o.close();
  ASSERT_EQ(o.contours().size(), 1u);
  EXPECT_EQ(o.contours()[0].segments.size(), 3u);
  EXPECT_EQ(o.contours()[0].segments.back().end(), (Vec2{0, 0}));
  EXPECT_NEAR(o.signed_area(), 50.0, 1e-12);  // counter-clockwise triangle
}

TEST(Outline, ClearKeepsNoContours) {
  Outline o;
  o.move_to({0, 0});
  o.conic_to({5, 10}, {10, 0});
  o.move_to({20, 0});
  o.line_to({30, 0});
  o.line_to({30, 10});
  o.close();
  ASSERT_EQ(o.contours().size(), 2u);
  o.clear();
  EXPECT_TRUE(o.contours().empty());
  EXPECT_TRUE(o.empty());
  // Built again after clear(): the same as built in a new outline, with no
  // segment left over from before.
  Outline fresh;
  for (Outline* out : {&o, &fresh}) {
    out->move_to({1, 1});
    out->line_to({4, 1});
    out->line_to({1, 5});
    out->close();
  }
  ASSERT_EQ(o.contours().size(), 1u);
  ASSERT_EQ(o.contours()[0].segments.size(), fresh.contours()[0].segments.size());
  EXPECT_EQ(o.contours()[0].segments.size(), 3u);
  EXPECT_EQ(o.signed_area(), fresh.signed_area());
  // An open contour is dropped by clear(), not closed into the next one.
  o.clear();
  o.move_to({0, 0});
  o.line_to({9, 9});
  o.clear();
  o.close();
  EXPECT_TRUE(o.contours().empty());
}

TEST(Outline, CubicAreaMatchesPolyline) {
  Outline o;
  o.move_to({0, 0});
  o.cubic_to({100, 300}, {400, -200}, {500, 0});
  o.close();
  const Segment& s = o.contours()[0].segments[0];
  double area = 0.0;
  Vec2 prev = s.p[0];
  const int steps = 200000;
  for (int i = 1; i <= steps; ++i) {
    const Vec2 p = evaluate(s, static_cast<double>(i) / steps);
    area += 0.5 * cross(prev, p);
    prev = p;
  }
  area += 0.5 * cross(prev, s.p[0]);
  EXPECT_NEAR(o.signed_area(), area, 1e-6 * std::abs(area) + 1e-6);
}

TEST(Outline, FiniteCheck) {
  Outline o = circle({0, 0}, 1);
  EXPECT_TRUE(o.is_finite());
  o.contours()[0].segments[1].p[1].x = std::nan("");
  EXPECT_FALSE(o.is_finite());
  Outline z = circle({0, 0}, 1);
  z.contours()[0].segments[0].weight = 0.0;
  EXPECT_FALSE(z.is_finite());
  Outline inf = circle({0, 0}, 1);
  inf.contours()[0].segments[2].p[0].y = -std::numeric_limits<double>::infinity();
  EXPECT_FALSE(inf.is_finite());
  Outline huge = circle({0, 0}, 1e300);  // large but finite
  EXPECT_TRUE(huge.is_finite());
}

// Barycentric implicit form of docs/design.md section 3: zero on the conic.
double implicit(const Segment& s, Vec2 p) {
  const Vec2 a = s.p[0], b = s.p[1], c = s.p[2];
  const double det = cross(b - a, c - a);
  const double t1 = cross(p - a, c - a) / det;  // weight of the control point
  const double t2 = cross(b - a, p - a) / det;
  const double t0 = 1.0 - t1 - t2;
  return t1 * t1 - 4.0 * s.weight * s.weight * t0 * t2;
}

TEST(Conic, SplitIsExact) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coord(-100, 100), weight(0.05, 6.0), param(0.05, 0.95);
  for (int iter = 0; iter < 200; ++iter) {
    const Segment s =
        Segment::conic({coord(rng), coord(rng)}, {coord(rng), coord(rng)}, {coord(rng), coord(rng)}, weight(rng));
    if (std::abs(cross(s.p[1] - s.p[0], s.p[2] - s.p[0])) < 100) continue;  // near-degenerate
    const double t = param(rng);
    const auto [left, right] = split(s, t);
    EXPECT_LT(distance(left.p[2], evaluate(s, t)), 1e-9);
    EXPECT_EQ(left.p[0], s.p[0]);
    EXPECT_EQ(right.p[2], s.p[2]);
    for (double u : {0.1, 0.37, 0.5, 0.81}) {
      EXPECT_NEAR(implicit(s, evaluate(left, u)), 0.0, 1e-9);
      EXPECT_NEAR(implicit(s, evaluate(right, u)), 0.0, 1e-9);
    }
    // Areas add up: the two halves' chord areas plus the triangle between
    // the three split points equal the whole.
    const double whole = conic_chord_area(s);
    const double parts =
        conic_chord_area(left) + conic_chord_area(right) - 0.5 * cross(left.p[2] - s.p[0], s.p[2] - s.p[0]);
    EXPECT_NEAR(parts, whole, 1e-9 * (std::abs(whole) + 1));
  }
}

// Distance from p to a weight-1 conic: coarse sampling, then Newton on the
// squared distance from the best samples.
double distance_to_quadratic(const Segment& q, Vec2 p) {
  auto pos = [&](double t) { return evaluate(q, t); };
  auto d1 = [&](double t) { return (q.p[1] - q.p[0]) * (2 * (1 - t)) + (q.p[2] - q.p[1]) * (2 * t); };
  const Vec2 d2 = (q.p[2] - q.p[1] * 2.0 + q.p[0]) * 2.0;
  double best = std::min(distance(pos(0), p), distance(pos(1), p));
  const int samples = 48;
  for (int i = 0; i <= samples; ++i) {
    double t = static_cast<double>(i) / samples;
    for (int it = 0; it < 20; ++it) {
      const Vec2 diff = pos(t) - p, der = d1(t);
      const double g = dot(diff, der), h = dot(der, der) + dot(diff, d2);
      if (h <= 0) break;
      t = std::clamp(t - g / h, 0.0, 1.0);
    }
    best = std::min(best, distance(pos(t), p));
  }
  return best;
}

double distance_to_cubic(const Segment& c, Vec2 p) {
  double best = 1e300;
  const int samples = 64;
  for (int i = 0; i <= samples; ++i) {
    double t = static_cast<double>(i) / samples;
    for (int it = 0; it < 30; ++it) {
      const double u = 1 - t;
      const Vec2 diff = evaluate(c, t) - p;
      const Vec2 der =
          (c.p[1] - c.p[0]) * (3 * u * u) + (c.p[2] - c.p[1]) * (6 * u * t) + (c.p[3] - c.p[2]) * (3 * t * t);
      const Vec2 der2 = (c.p[2] - c.p[1] * 2.0 + c.p[0]) * (6 * u) + (c.p[3] - c.p[2] * 2.0 + c.p[1]) * (6 * t);
      const double g = dot(diff, der), h = dot(der, der) + dot(diff, der2);
      if (h <= 0) break;
      t = std::clamp(t - g / h, 0.0, 1.0);
    }
    best = std::min(best, distance(evaluate(c, t), p));
  }
  return best;
}

TEST(CubicToQuadratics, BoundHoldsOnRandomCubics) {
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> coord(-1000, 1000);
  std::uniform_real_distribution<double> log_tol(-1.0, 1.5);  // 0.1 .. 30 units: 1..35 pieces
  double worst_ratio = 0.0, best_ratio = 1.0;
  for (int iter = 0; iter < 300; ++iter) {
    const Segment cubic = Segment::cubic({coord(rng), coord(rng)}, {coord(rng), coord(rng)}, {coord(rng), coord(rng)},
                                         {coord(rng), coord(rng)});
    const double tol = std::pow(10.0, log_tol(rng));
    std::vector<Segment> quads;
    const int n = cubic_to_quadratics(cubic, tol, quads);
    ASSERT_EQ(static_cast<int>(quads.size()), n);
    ASSERT_GE(n, 1);
    // A chain: joins are exact and the ends are the cubic's.
    EXPECT_EQ(quads.front().p[0], cubic.p[0]);
    EXPECT_EQ(quads.back().p[2], cubic.p[3]);
    for (std::size_t i = 1; i < quads.size(); ++i) EXPECT_EQ(quads[i].p[0], quads[i - 1].p[2]);

    // True maximum distance, both ways (a Hausdorff distance).
    double measured = 0.0;
    const int per_piece = 40;
    for (int i = 0; i < n; ++i) {
      for (int k = 0; k <= per_piece; ++k) {
        const double u = static_cast<double>(k) / per_piece;
        // Cubic point -> nearest of the neighbouring quadratics.
        const Vec2 cp = evaluate(cubic, (i + u) / n);
        double d = 1e300;
        for (int j = std::max(0, i - 1); j <= std::min(n - 1, i + 1); ++j)
          d = std::min(d, distance_to_quadratic(quads[static_cast<std::size_t>(j)], cp));
        measured = std::max(measured, d);
        // Quadratic point -> cubic.
        measured = std::max(measured, distance_to_cubic(cubic, evaluate(quads[static_cast<std::size_t>(i)], u)));
      }
    }
    EXPECT_LE(measured, tol * (1 + 1e-9)) << "iteration " << iter << " pieces " << n;
    worst_ratio = std::max(worst_ratio, measured / tol);
    best_ratio = std::min(best_ratio, measured / tol);
  }
  // The bound is not vacuous: some cubics come close to it.
  EXPECT_GT(worst_ratio, 0.3);
  std::printf("cubic->quadratic: measured/tolerance from %.3f to %.3f over 300 cubics\n", best_ratio, worst_ratio);
}

TEST(CubicToQuadratics, FewestPiecesForTheBound) {
  const Segment cubic = Segment::cubic({0, 0}, {0, 100}, {100, -100}, {100, 0});
  const double third = length(cubic.p[3] - cubic.p[2] * 3.0 + cubic.p[1] * 3.0 - cubic.p[0]);
  for (double tol : {0.01, 0.1, 1.0, 5.0}) {
    std::vector<Segment> quads;
    const int n = cubic_to_quadratics(cubic, tol, quads);
    const double bound = std::sqrt(3.0) / 36.0 * third;
    EXPECT_LE(bound / (n * n * n), tol);
    if (n > 1) {
      EXPECT_GT(bound / ((n - 1) * (n - 1) * (n - 1)), tol);
    }
  }
}

TEST(CubicToQuadratics, OutlineKeepsLinesAndConics) {
  Outline o;
  o.move_to({0, 0});
  o.line_to({100, 0});
  o.cubic_to({150, 50}, {150, 100}, {100, 150});
  o.conic_to({50, 200}, {0, 150}, 0.8);
  o.close();
  const Outline q = to_quadratic_outline(o, 0.01);
  EXPECT_FALSE(q.has_cubics());
  EXPECT_TRUE(o.has_cubics());
  EXPECT_NEAR(q.signed_area(), o.signed_area(), 1e-3);
}

}  // namespace
}  // namespace curvetext
