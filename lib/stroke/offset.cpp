// Offsets of lines and conics: exact for lines and circular arcs, fitted
// conics with a measured (sampled Hausdorff) error otherwise.
#include <algorithm>
#include <cmath>

#include "curvetext/curves.hpp"
#include "core/tolerances.hpp"
#include "stroke/stroke_parts.hpp"

namespace curvetext::stroke {

namespace {

using tolerance::kStrokeCircleRelative;
using tolerance::kStrokeFitSamples;
using tolerance::kStrokeMaxFitDepth;

Vec2 offset_point(const Segment& s, double t, double d) {
  Vec2 tangent = unit(derivative(s, t));
  if (tangent == Vec2{}) tangent = t < 0.5 ? start_tangent(s) : end_tangent(s);
  return evaluate(s, t) + left_normal(tangent) * d;
}

// The parameter of the point of `c` nearest to x, by Newton's method on
// dot(c(t) - x, c'(t)) from `t` (a few steps: the samples start near it).
double foot(const Segment& c, Vec2 x, double t) {
  constexpr double kStep = 1e-6;
  for (int i = 0; i < 6; ++i) {
    const Vec2 r = evaluate(c, t) - x, d1 = derivative(c, t);
    const Vec2 d2 = (derivative(c, std::min(1.0, t + kStep)) - derivative(c, std::max(0.0, t - kStep))) /
                    (std::min(1.0, t + kStep) - std::max(0.0, t - kStep));
    const double g = dot(r, d1), dg = dot(d1, d1) + dot(r, d2);
    if (!(std::abs(dg) > 0.0)) break;
    const double next = std::clamp(t - g / dg, 0.0, 1.0);
    if (std::abs(next - t) < 1e-12) return next;
    t = next;
  }
  return t;
}

// Largest sampled distance between `fit` and the offset of `c` by d, both
// ways: points of the fit to the offset (their distance to c at their foot,
// less |d|), and points of the offset to their nearest point of the fit.
double fit_error(const Segment& c, double d, const Segment& fit) {
  double error = 0.0;
  for (int k = 1; k < kStrokeFitSamples; ++k) {
    const double t = static_cast<double>(k) / kStrokeFitSamples;
    // The distance from a point of the fit to c at its foot, against |d|:
    // insensitive to where Newton's method stops along c (the distance is
    // stationary there); the point must lie on d's side.
    const Vec2 x = evaluate(fit, t);
    const double f = foot(c, x, t);
    const Vec2 r = x - evaluate(c, f);
    if (cross(derivative(c, f), r) * d < 0.0) return HUGE_VAL;
    error = std::max(error, std::abs(length(r) - std::abs(d)));
    const Vec2 y = offset_point(c, t, d);
    error = std::max(error, distance(y, evaluate(fit, foot(fit, y, t))));
  }
  return error;
}

// The conic from a (tangent t0) to b (tangent t1) through the point of that
// family nearest to m, or a line when there is none (tangents that do not
// meet ahead of both ends).
Segment candidate(Vec2 a, Vec2 t0, Vec2 b, Vec2 t1, Vec2 m) {
  const double den = cross(t0, t1);
  if (std::abs(den) < 1e-12) return Segment::line(a, b);
  const double u = cross(b - a, t1) / den, v = cross(t0, b - a) / den;
  if (!(u > 0.0) || !(v > 0.0)) return Segment::line(a, b);
  const Vec2 control = a + t0 * u, mid = (a + b) * 0.5, e = control - mid;
  // Conics with these ends and control reach mid + e * w / (1 + w) at t = 1/2.
  const double k = dot(m - mid, e) / dot(e, e);
  if (!(k > 0.0 && k < 1.0)) return Segment::line(a, b);
  return Segment::conic(a, control, b, k / (1.0 - k));
}

void fit_offset(const Segment& c, double d, double tol, int depth, Budget& budget, std::vector<Segment>& out) {
  const Vec2 t0 = start_tangent(c), t1 = end_tangent(c);
  const Vec2 a = c.p[0] + left_normal(t0) * d, b = c.p[2] + left_normal(t1) * d;
  const Segment fit = candidate(a, t0, b, t1, offset_point(c, 0.5, d));
  if (depth >= kStrokeMaxFitDepth || fit_error(c, d, fit) <= tol) {
    budget.spend(1);
    out.push_back(fit);
    return;
  }
  const auto halves = split(c, 0.5);
  fit_offset(halves.first, d, tol, depth + 1, budget, out);
  fit_offset(halves.second, d, tol, depth + 1, budget, out);
}

// A conic that is an arc of a circle: legs of equal length and weight
// cos(half the arc's angle) = |chord| / (2 |leg|). Its centre in `centre`.
bool circle_arc(const Segment& c, Vec2& centre) {
  const double l0 = length(c.p[1] - c.p[0]), l2 = length(c.p[1] - c.p[2]);
  const double chord = length(c.p[2] - c.p[0]);
  if (!(l0 > 0.0) || std::abs(l0 - l2) > kStrokeCircleRelative * l0) return false;
  const double w = c.weight;
  if (!(w < 1.0) || std::abs(w - 0.5 * chord / l0) > kStrokeCircleRelative) return false;
  // The centre lies beyond the chord's midpoint seen from the control point,
  // at |leg| / sin(half angle) from it.
  const Vec2 towards = unit((c.p[0] + c.p[2]) * 0.5 - c.p[1]);
  centre = c.p[1] + towards * (l0 / std::sqrt(1.0 - w * w));
  return towards != Vec2{};
}

}  // namespace

void append_offset(const Segment& s, double d, double tol, Budget& budget, std::vector<Segment>& out) {
  if (s.kind == Segment::Kind::Line) {
    const Vec2 n = left_normal(unit(s.p[1] - s.p[0])) * d;
    budget.spend(1);
    out.push_back(Segment::line(s.p[0] + n, s.p[1] + n));
    return;
  }
  Vec2 centre;
  if (circle_arc(s, centre)) {
    // The concentric arc (through the centre to the far side when |d|
    // exceeds the radius on the centre's side: the scale is then negative).
    const double radius = length(s.p[0] - centre);
    const double toward_centre = cross(s.p[1] - s.p[0], s.p[2] - s.p[1]) > 0.0 ? 1.0 : -1.0;
    const double k = (radius - toward_centre * d) / radius;
    budget.spend(1);
    if (k == 0.0) {
      out.push_back(Segment::line(centre, centre));
      return;
    }
    out.push_back(Segment::conic(centre + (s.p[0] - centre) * k, centre + (s.p[1] - centre) * k,
                                 centre + (s.p[2] - centre) * k, s.weight));
    return;
  }
  fit_offset(s, d, tol, 0, budget, out);
}

}  // namespace curvetext::stroke
