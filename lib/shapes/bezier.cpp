// Rational Bezier pieces, NURBS -> Bezier (exact), and pieces -> lines and
// conics (exact for degree <= 2, within a tolerance above).
#include <algorithm>
#include <cmath>
#include <string>

#include "check.hpp"
#include "curvetext/curves.hpp"
#include "curvetext/error.hpp"
#include "curvetext/shapes.hpp"
#include "curvetext/tolerances.hpp"

namespace curvetext {

using shapes_detail::check_point;
using shapes_detail::check_weight;
using shapes_detail::number_text;

namespace {

// Homogeneous point (w x, w y, w).
struct H {
  double x = 0, y = 0, w = 0;
};
H hlerp(H a, H b, double t) {
  const double u = 1.0 - t;
  return {u * a.x + t * b.x, u * a.y + t * b.y, u * a.w + t * b.w};
}
H to_h(Vec2 p, double w) { return {p.x * w, p.y * w, w}; }
Vec2 from_h(H h) { return {h.x / h.w, h.y / h.w}; }

std::vector<H> homogeneous(const RationalBezier& c) {
  std::vector<H> h(c.points.size());
  for (std::size_t i = 0; i < h.size(); ++i) h[i] = to_h(c.points[i], c.weights[i]);
  return h;
}

RationalBezier from_homogeneous(const std::vector<H>& h) {
  RationalBezier c;
  c.points.resize(h.size());
  c.weights.resize(h.size());
  for (std::size_t i = 0; i < h.size(); ++i) {
    c.points[i] = from_h(h[i]);
    c.weights[i] = h[i].w;
  }
  return c;
}

}  // namespace

FillRule parse_fill_rule(std::string_view text) {
  if (text == "nonzero") return FillRule::NonZero;
  if (text == "evenodd" || text == "even-odd") return FillRule::EvenOdd;
  throw Error(ErrorCode::InvalidArgument,
              "unknown fill rule '" + std::string(text) + "' (expected nonzero or evenodd)");
}

bool RationalBezier::is_polynomial() const {
  for (double w : weights)
    if (w != weights.front()) return false;
  return true;
}

RationalBezier RationalBezier::line(Vec2 a, Vec2 b) { return {{a, b}, {1.0, 1.0}}; }
RationalBezier RationalBezier::conic(Vec2 a, Vec2 control, Vec2 b, double weight) {
  return {{a, control, b}, {1.0, weight, 1.0}};
}
RationalBezier RationalBezier::cubic(Vec2 a, Vec2 c1, Vec2 c2, Vec2 b) { return {{a, c1, c2, b}, {1, 1, 1, 1}}; }

Vec2 evaluate(const RationalBezier& curve, double t) {
  std::vector<H> h = homogeneous(curve);
  for (std::size_t level = 1; level < h.size(); ++level)
    for (std::size_t i = 0; i + level < h.size(); ++i) h[i] = hlerp(h[i], h[i + 1], t);
  return from_h(h[0]);
}

std::pair<RationalBezier, RationalBezier> split(const RationalBezier& curve, double t) {
  std::vector<H> h = homogeneous(curve);
  const std::size_t n = h.size();
  std::vector<H> left(n), right(n);
  left[0] = h[0];
  right[n - 1] = h[n - 1];
  for (std::size_t level = 1; level < n; ++level) {
    for (std::size_t i = 0; i + level < n; ++i) h[i] = hlerp(h[i], h[i + 1], t);
    left[level] = h[0];
    right[n - 1 - level] = h[n - 1 - level];
  }
  return {from_homogeneous(left), from_homogeneous(right)};
}

// --- NURBS ----------------------------------------------------------------------

void validate_nurbs(const Nurbs& c) {
  const auto fail = [](const std::string& m) { throw Error(ErrorCode::InvalidArgument, "NURBS: " + m); };
  if (c.degree < 1 || c.degree > kMaxNurbsDegree)
    fail("degree " + std::to_string(c.degree) + " is outside 1.." + std::to_string(kMaxNurbsDegree));
  const std::size_t p = static_cast<std::size_t>(c.degree);
  const std::size_t count = c.points.size();
  if (count < p + 1)
    fail("degree " + std::to_string(p) + " needs at least " + std::to_string(p + 1) + " control points, got " +
         std::to_string(count));
  for (std::size_t i = 0; i < count; ++i) check_point(c.points[i], "NURBS control point " + std::to_string(i));
  if (!c.weights.empty()) {
    if (c.weights.size() != count)
      fail(std::to_string(count) + " control points but " + std::to_string(c.weights.size()) + " weights");
    for (std::size_t i = 0; i < count; ++i)
      if (!shapes_detail::is_zero_middle_weight(p, i, count, c.weights[i]))
        check_weight(c.weights[i], "NURBS weight " + std::to_string(i));
  }
  const std::size_t want = count + p + 1;
  if (c.knots.size() != want)
    fail("knot vector has " + std::to_string(c.knots.size()) + " values; " + std::to_string(count) +
         " control points of degree " + std::to_string(p) + " need " + std::to_string(want));
  for (std::size_t i = 0; i < c.knots.size(); ++i) {
    if (!std::isfinite(c.knots[i])) fail("knot " + std::to_string(i) + " is not a finite number");
    if (std::abs(c.knots[i]) > kMaxShapeCoordinate) fail("knot " + std::to_string(i) + " is too large");
    if (i > 0 && c.knots[i] < c.knots[i - 1])
      fail("knot vector must be non-decreasing, but knot " + std::to_string(i) + " (" + number_text(c.knots[i]) +
           ") < knot " + std::to_string(i - 1) + " (" + number_text(c.knots[i - 1]) + ")");
  }
  const double lo = c.knots[p], hi = c.knots[count];
  if (!(lo < hi)) fail("the domain [knot p, knot n+1] is empty (all knots of the domain are equal)");
  // Inside the domain a knot of multiplicity > p breaks the curve into
  // disconnected pieces; a contour must be one connected path.
  for (std::size_t i = 0; i < c.knots.size();) {
    std::size_t j = i;
    while (j < c.knots.size() && c.knots[j] == c.knots[i]) ++j;
    if (c.knots[i] > lo && c.knots[i] < hi && j - i > p)
      fail("interior knot " + number_text(c.knots[i]) + " has multiplicity " + std::to_string(j - i) + " > degree " +
           std::to_string(p) + " (the curve would be disconnected)");
    i = j;
  }
}

std::vector<RationalBezier> nurbs_to_beziers(const Nurbs& c) {
  validate_nurbs(c);
  const std::size_t p = static_cast<std::size_t>(c.degree);
  const std::size_t count = c.points.size();
  const std::vector<double>& u = c.knots;
  std::vector<H> q(count);
  for (std::size_t i = 0; i < count; ++i) q[i] = to_h(c.points[i], c.weights.empty() ? 1.0 : c.weights[i]);

  // Blossom of span [u_i, u_{i+1}] at (t_1..t_p): de Boor's recurrence with a
  // different argument per level. For arguments inside the span every alpha
  // is in [0,1], so homogeneous weights stay positive.
  std::vector<H> d(p + 1);
  std::vector<double> args(p);
  auto blossom = [&](std::size_t span) {
    for (std::size_t k = 0; k <= p; ++k) d[k] = q[span - p + k];
    for (std::size_t r = 1; r <= p; ++r) {
      for (std::size_t k = p; k >= r; --k) {
        const std::size_t j = span - p + k;  // index of the control point d[k] stands for
        const double a = (args[r - 1] - u[j]) / (u[j + p + 1 - r] - u[j]);
        d[k] = hlerp(d[k - 1], d[k], a);
      }
    }
    return d[p];
  };

  std::vector<RationalBezier> out;
  for (std::size_t span = p; span < count; ++span) {
    if (!(u[span] < u[span + 1])) continue;
    std::vector<H> bez(p + 1);
    for (std::size_t k = 0; k <= p; ++k) {
      for (std::size_t r = 0; r < p; ++r) args[r] = r < p - k ? u[span] : u[span + 1];
      bez[k] = blossom(span);
    }
    if (p == 2) {
      // Weight 0 (degree 2 only) is well defined where it lands on a Bezier
      // middle point (the piece is its chord); at a piece's end it would put
      // that end at infinity. Weights from [kMinWeight, kMaxWeight] blend to
      // at least kMinWeight, so only a zero weight gets below it.
      if (bez[0].w < shapes_detail::kMinWeight || bez[2].w < shapes_detail::kMinWeight)
        throw Error(
            ErrorCode::InvalidArgument,
            "NURBS: a weight of 0 gives the piece over knots [" + number_text(u[span]) + ", " +
                number_text(u[span + 1]) +
                "] an end at infinity; 0 is allowed only where a control point is a piece's middle point (its knots "
                "doubled)");
      if (bez[1].w < shapes_detail::kMinWeight) {
        out.push_back(RationalBezier::line(from_h(bez[0]), from_h(bez[2])));
        continue;
      }
    }
    out.push_back(from_homogeneous(bez));
  }
  return out;
}

// --- Lines and conics -----------------------------------------------------------

namespace {

double distance_to_segment(Vec2 q, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double len2 = dot(ab, ab);
  double t = len2 > 0.0 ? dot(q - a, ab) / len2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return distance(q, a + ab * t);
}

// The conic (p0, c, p2, w) tangent to the piece at both ends and through its
// point at t = 1/2; false where none exists (inflection, tangents parallel or
// pointing away from each other).
bool fit_conic(const RationalBezier& piece, Segment& conic) {
  const Vec2 p0 = piece.points.front(), p2 = piece.points.back();
  const double size = distance(p0, p2);
  if (!(size > 0.0)) return false;
  const double tiny = 1e-12 * size;
  Vec2 t0{}, t1{};
  for (std::size_t i = 1; i < piece.points.size(); ++i)
    if (distance(piece.points[i], p0) > tiny) {
      t0 = piece.points[i] - p0;
      break;
    }
  for (std::size_t i = piece.points.size() - 1; i-- > 0;)
    if (distance(piece.points[i], p2) > tiny) {
      t1 = p2 - piece.points[i];
      break;
    }
  // p0 + s t0 = p2 - v t1
  const double det = cross(t0, t1);
  if (std::abs(det) <= 1e-12 * length(t0) * length(t1)) return false;
  const Vec2 d = p2 - p0;
  const double s = cross(d, t1) / det;
  const double v = cross(t0, d) / det;
  if (!(s > 0.0 && v > 0.0)) return false;
  const Vec2 c = p0 + t0 * s;
  const Vec2 m = evaluate(piece, 0.5);
  const double area = cross(c - p0, p2 - p0);
  const double tau1 = cross(m - p0, p2 - p0) / area;
  const double tau2 = cross(c - p0, m - p0) / area;
  const double tau0 = 1.0 - tau1 - tau2;
  if (!(tau0 > 0.0 && tau1 > 0.0 && tau2 > 0.0)) return false;
  // The conic through m: tau1^2 = 4 w^2 tau0 tau2 (docs/design.md section 3).
  conic = Segment::conic(p0, c, p2, tau1 / (2.0 * std::sqrt(tau0 * tau2)));
  return std::isfinite(conic.weight) && conic.weight > 0.0;
}

// First-order distance from q to the conic: |F| / |grad F| with
// F = tau1^2 - 4 w^2 tau0 tau2. Accurate to O(d^2 * curvature) for small d,
// which is where it is used (d around the tolerance).
double implicit_distance(const Segment& conic, Vec2 q) {
  const Vec2 p0 = conic.p[0], c = conic.p[1], p2 = conic.p[2];
  const double area = cross(c - p0, p2 - p0);
  const Vec2 e = p2 - p0, f = c - p0;
  const double tau1 = cross(q - p0, e) / area;
  const double tau2 = cross(f, q - p0) / area;
  const double tau0 = 1.0 - tau1 - tau2;
  const Vec2 g1{e.y / area, -e.x / area};
  const Vec2 g2{-f.y / area, f.x / area};
  const Vec2 g0 = (g1 + g2) * -1.0;
  const double w2 = conic.weight * conic.weight;
  const double value = tau1 * tau1 - 4.0 * w2 * tau0 * tau2;
  const Vec2 grad = g1 * (2.0 * tau1) - (g0 * tau2 + g2 * tau0) * (4.0 * w2);
  const double g = length(grad);
  return g > 0.0 ? std::abs(value) / g : INFINITY;
}

// Samples per piece for the error estimate, and the factor by which the
// sampled estimate must undercut the tolerance (covers the error between
// samples and the first-order distance; tests measure the true distance).
constexpr int kErrorSamples = 32;
constexpr double kSafety = 1.5;
constexpr int kMaxDepth = 30;

void approximate(const RationalBezier& piece, double tolerance, int depth, std::vector<Segment>& out, int& budget) {
  const Vec2 p0 = piece.points.front(), p2 = piece.points.back();
  // Convex hull property (weights > 0): the piece lies in the hull of its
  // control points, so when they are all within `tolerance` of the chord,
  // so is the piece, and the chord is within tolerance of the piece.
  double hull = 0.0;
  for (Vec2 q : piece.points) hull = std::max(hull, distance_to_segment(q, p0, p2));
  if (hull <= tolerance) {
    if (--budget < 0) throw Error(ErrorCode::Geometry, "curve needs more than the allowed number of pieces");
    out.push_back(Segment::line(p0, p2));
    return;
  }
  Segment conic;
  if (depth > 0 && fit_conic(piece, conic)) {
    double worst = 0.0;
    for (int i = 1; i < kErrorSamples && worst * kSafety <= tolerance; ++i)
      worst = std::max(worst, implicit_distance(conic, evaluate(piece, i / static_cast<double>(kErrorSamples))));
    if (worst * kSafety <= tolerance) {
      if (--budget < 0) throw Error(ErrorCode::Geometry, "curve needs more than the allowed number of pieces");
      out.push_back(conic);
      return;
    }
  }
  if (depth >= kMaxDepth)
    throw Error(ErrorCode::Geometry, "a curve could not be approximated within tolerance " + number_text(tolerance));
  const auto [a, b] = split(piece, 0.5);
  approximate(a, tolerance, depth + 1, out, budget);
  approximate(b, tolerance, depth + 1, out, budget);
}

// Polynomial cubics: cubic_to_quadratics honours the bound only up to
// tolerance::kMaxQuadraticsPerCubic pieces; halve first until it fits (each
// halving divides the third difference by 8).
void cubic_pieces(const Segment& cubic, double tolerance, int depth, std::vector<Segment>& out) {
  const Vec2 d3 = cubic.p[3] - cubic.p[2] * 3.0 + cubic.p[1] * 3.0 - cubic.p[0];
  const double n = std::cbrt((std::sqrt(3.0) / 36.0) * length(d3) / tolerance);
  if (n > tolerance::kMaxQuadraticsPerCubic && depth < kMaxDepth) {
    const auto [a, b] = split(cubic, 0.5);
    cubic_pieces(a, tolerance, depth + 1, out);
    cubic_pieces(b, tolerance, depth + 1, out);
    return;
  }
  cubic_to_quadratics(cubic, tolerance, out);
}

}  // namespace

void append_quadratics(const RationalBezier& curve, double tolerance, std::vector<Segment>& out) {
  if (curve.points.size() < 2 || curve.weights.size() != curve.points.size())
    throw Error(ErrorCode::InvalidArgument, "a curve piece needs at least 2 points and one weight per point");
  if (!(tolerance > 0.0) || !std::isfinite(tolerance))
    throw Error(ErrorCode::InvalidArgument, "tolerance must be positive, got " + number_text(tolerance));
  for (Vec2 p : curve.points) check_point(p, "curve piece");
  for (std::size_t i = 0; i < curve.weights.size(); ++i)
    if (!shapes_detail::is_zero_middle_weight(static_cast<std::size_t>(curve.degree()), i, curve.weights.size(),
                                              curve.weights[i]))
      check_weight(curve.weights[i], "curve piece");
  const Vec2 p0 = curve.points.front(), p2 = curve.points.back();
  switch (curve.degree()) {
    case 1:
      out.push_back(Segment::line(p0, p2));
      return;
    case 2:
      if (curve.weights[1] == 0.0) {  // docs/design.md section 3: weight 0 is the chord
        out.push_back(Segment::line(p0, p2));
        return;
      }
      // Reparametrising t -> t / (t + k (1 - t)) moves the end weights to 1
      // and leaves the middle weight w1 / sqrt(w0 w2): the same curve.
      out.push_back(
          Segment::conic(p0, curve.points[1], p2, curve.weights[1] / std::sqrt(curve.weights[0] * curve.weights[2])));
      return;
    case 3:
      if (curve.is_polynomial()) {
        cubic_pieces(Segment::cubic(p0, curve.points[1], curve.points[2], p2), tolerance, 0, out);
        return;
      }
      break;
    default:
      break;
  }
  int budget = kMaxConicsPerCurve;
  approximate(curve, tolerance, 0, out, budget);
}

// The contour just closed (the last of `o`): a closing line within
// tolerance::kCloseGapOfTolerance, and a tiny fraction of the contour's size,
// becomes the segment before it ending on the start, which moves by at most
// that much.
void close_tiny_gap(Outline& o, double tolerance) {
  std::vector<Segment>& segs = o.contours().back().segments;
  if (segs.size() < 3) return;
  const Segment closing = segs.back();
  if (closing.kind != Segment::Kind::Line) return;
  Box box;
  for (const Segment& s : segs) box.add(s.p[0]);
  const double gap = distance(closing.p[0], closing.p[1]);
  // A gap, not an edge of a contour that is itself that small.
  if (!(gap <= tolerance::kCloseGapOfTolerance * tolerance) ||
      !(gap <= tolerance::kCloseGapOfExtent * distance(box.min, box.max)))
    return;
  Segment& before = segs[segs.size() - 2];
  if (before.kind == Segment::Kind::Line && before.p[0] == closing.p[1]) return;
  (before.kind == Segment::Kind::Line ? before.p[1] : before.p[2]) = closing.p[1];
  segs.pop_back();
}

Outline shape_outline(const Shape& shape, double tolerance) {
  Outline o;
  std::vector<Segment> segs;
  for (const ShapeContour& contour : shape.contours) {
    if (contour.pieces.empty()) continue;
    const std::size_t contours_before = o.contours().size();
    o.move_to(contour.pieces.front().points.front());
    for (const RationalBezier& piece : contour.pieces) {
      segs.clear();
      append_quadratics(piece, tolerance, segs);
      o.line_to(piece.points.front());  // joins a gap between pieces; nothing when there is none
      for (const Segment& s : segs) {
        if (s.kind == Segment::Kind::Line)
          o.line_to(s.p[1]);
        else
          o.conic_to(s.p[1], s.p[2], s.weight);
      }
    }
    o.close();
    if (o.contours().size() > contours_before) close_tiny_gap(o, tolerance);
  }
  return o;
}

Outline fill_outline(const Shape& shape, double tolerance) {
  Outline o = shape_outline(shape, tolerance);
  return shape.fill_rule == FillRule::EvenOdd ? even_odd_to_nonzero(o) : o;
}

}  // namespace curvetext
