// Tangents, curvature and arc length of lines and conics, for the stroker.
#include <algorithm>
#include <cmath>
#include <string>

#include "curvetext/curves.hpp"
#include "curvetext/error.hpp"
#include "curvetext/tolerances.hpp"
#include "core/format.hpp"
#include "stroke/stroke_parts.hpp"

namespace curvetext::stroke {

Vec2 derivative(const Segment& s, double t) {
  if (s.kind == Segment::Kind::Line) return s.p[1] - s.p[0];
  // P = N / D in homogeneous form; P' = (N' - P D') / D.
  const double u = 1.0 - t, w = s.weight;
  const double d = u * u + 2.0 * w * u * t + t * t;
  const Vec2 n = s.p[0] * (u * u) + s.p[1] * (2.0 * w * u * t) + s.p[2] * (t * t);
  const Vec2 dn = s.p[0] * (-2.0 * u) + s.p[1] * (2.0 * w * (u - t)) + s.p[2] * (2.0 * t);
  const double dd = -2.0 * u + 2.0 * w * (u - t) + 2.0 * t;
  return (dn - n / d * dd) / d;
}

Vec2 start_tangent(const Segment& s) {
  if (s.kind == Segment::Kind::Line) return unit(s.p[1] - s.p[0]);
  const Vec2 t = unit(s.p[1] - s.p[0]);
  return t == Vec2{} ? unit(s.p[2] - s.p[0]) : t;
}

Vec2 end_tangent(const Segment& s) {
  if (s.kind == Segment::Kind::Line) return unit(s.p[1] - s.p[0]);
  const Vec2 t = unit(s.p[2] - s.p[1]);
  return t == Vec2{} ? unit(s.p[2] - s.p[0]) : t;
}

Segment reversed(const Segment& s) {
  if (s.kind == Segment::Kind::Line) return Segment::line(s.p[1], s.p[0]);
  return Segment::conic(s.p[2], s.p[1], s.p[0], s.weight);
}

double end_curvature(const Segment& s, bool at_end) {
  if (s.kind == Segment::Kind::Line) return 0.0;
  // A rational quadratic's curvature at its start is
  // cross(p1 - p0, p2 - p0) / (2 w^2 |p1 - p0|^3) (symmetrically at its end).
  const Vec2 leg = at_end ? s.p[2] - s.p[1] : s.p[1] - s.p[0];
  const double l = length(leg);
  if (!(l > 0.0) || !(s.weight > 0.0)) return 0.0;
  return cross(s.p[1] - s.p[0], s.p[2] - s.p[0]) / (2.0 * s.weight * s.weight * l * l * l);
}

void Budget::spend(std::size_t n) {
  used_ += n;
  if (used_ > tolerance::kMaxStrokeSegments)
    throw Error(ErrorCode::Geometry, "the stroke would need more than " +
                                         std::to_string(tolerance::kMaxStrokeSegments) +
                                         " segments (a dash pattern too fine for the path, or a width or "
                                         "tolerance far from the path's size)");
}

namespace {

// Five-point Gauss-Legendre nodes and weights on [-1, 1].
constexpr double kNodes[5] = {0.0, -0.5384693101056831, 0.5384693101056831, -0.9061798459386640, 0.9061798459386640};
constexpr double kWeights[5] = {0.5688888888888889, 0.4786286704993665, 0.4786286704993665, 0.2369268850561891,
                                0.2369268850561891};
// Deepest bisection of the integration interval (2^-30 of a segment).
constexpr int kMaxLengthDepth = 30;

double gauss(const Segment& s, double a, double b) {
  const double half = 0.5 * (b - a), mid = 0.5 * (a + b);
  double sum = 0.0;
  for (int i = 0; i < 5; ++i) sum += kWeights[i] * length(derivative(s, mid + half * kNodes[i]));
  return sum * half;
}

double adaptive_length(const Segment& s, double a, double b, double whole, double tolerance, int depth) {
  const double m = 0.5 * (a + b);
  const double left = gauss(s, a, m), right = gauss(s, m, b);
  if (depth >= kMaxLengthDepth || std::abs(left + right - whole) <= tolerance) return left + right;
  return adaptive_length(s, a, m, left, 0.5 * tolerance, depth + 1) +
         adaptive_length(s, m, b, right, 0.5 * tolerance, depth + 1);
}

}  // namespace

double arc_length(const Segment& s, double t, double tolerance) {
  if (s.kind == Segment::Kind::Line) return length(s.p[1] - s.p[0]) * t;
  if (t <= 0.0) return 0.0;
  return adaptive_length(s, 0.0, t, gauss(s, 0.0, t), tolerance, 0);
}

double parameter_at_length(const Segment& s, double target, double total, double tolerance) {
  if (total <= 0.0) return 0.0;
  if (s.kind == Segment::Kind::Line) return std::clamp(target / total, 0.0, 1.0);
  // Newton on L(t) - target, kept inside a shrinking bracket (bisection
  // where Newton leaves it or the speed vanishes).
  double lo = 0.0, hi = 1.0, t = target / total;
  for (int i = 0; i < 100; ++i) {
    const double f = arc_length(s, t, 0.25 * tolerance) - target;
    if (std::abs(f) <= 0.5 * tolerance) return t;
    (f > 0.0 ? hi : lo) = t;
    const double speed = length(derivative(s, t));
    double next = speed > 0.0 ? t - f / speed : 0.5 * (lo + hi);
    if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
    t = next;
    if (hi - lo < 1e-15) break;
  }
  return t;
}

}  // namespace curvetext::stroke
