#include "curvetext/curves.hpp"

#include <algorithm>
#include <cmath>

#include "curvetext/tolerances.hpp"

namespace curvetext {

Vec2 evaluate(const Segment& s, double t) {
  const double u = 1.0 - t;
  switch (s.kind) {
    case Segment::Kind::Line:
      return lerp(s.p[0], s.p[1], t);
    case Segment::Kind::Conic: {
      const double b0 = u * u, b1 = 2.0 * u * t * s.weight, b2 = t * t;
      return (s.p[0] * b0 + s.p[1] * b1 + s.p[2] * b2) / (b0 + b1 + b2);
    }
    case Segment::Kind::Cubic:
      return s.p[0] * (u * u * u) + s.p[1] * (3 * u * u * t) + s.p[2] * (3 * u * t * t) + s.p[3] * (t * t * t);
  }
  return s.p[0];
}

namespace {

// One de Casteljau step on a cubic's control points: head gets [0, t], tail
// [t, 1] (split() and cubic_to_quadratics share it, so both give the same
// points).
void split_cubic(const Vec2 (&p)[4], double t, Vec2 (&head)[4], Vec2 (&tail)[4]) {
  const Vec2 ab = lerp(p[0], p[1], t), bc = lerp(p[1], p[2], t), cd = lerp(p[2], p[3], t);
  const Vec2 abc = lerp(ab, bc, t), bcd = lerp(bc, cd, t);
  const Vec2 m = lerp(abc, bcd, t);
  head[0] = p[0];
  head[1] = ab;
  head[2] = abc;
  head[3] = m;
  tail[0] = m;
  tail[1] = bcd;
  tail[2] = cd;
  tail[3] = p[3];
}

}  // namespace

std::pair<Segment, Segment> split(const Segment& s, double t) {
  switch (s.kind) {
    case Segment::Kind::Line: {
      const Vec2 m = lerp(s.p[0], s.p[1], t);
      return {Segment::line(s.p[0], m), Segment::line(m, s.p[1])};
    }
    case Segment::Kind::Conic: {
      // De Casteljau on the homogeneous points (w_i p_i, w_i) keeps the curve
      // exact; each half is then re-normalised to end weights 1 with middle
      // weight w_mid / sqrt(w_start * w_end).
      const double w = s.weight;
      const Vec2 h1 = s.p[1] * w;
      const Vec2 q0 = lerp(s.p[0], h1, t);
      const double q0w = (1.0 - t) + t * w;
      const Vec2 q1 = lerp(h1, s.p[2], t);
      const double q1w = (1.0 - t) * w + t;
      const Vec2 r = lerp(q0, q1, t);
      const double rw = (1.0 - t) * q0w + t * q1w;
      const Vec2 mid = r / rw;
      const double root = std::sqrt(rw);
      return {Segment::conic(s.p[0], q0 / q0w, mid, q0w / root), Segment::conic(mid, q1 / q1w, s.p[2], q1w / root)};
    }
    case Segment::Kind::Cubic: {
      Vec2 head[4], tail[4];
      split_cubic(s.p, t, head, tail);
      return {Segment::cubic(head[0], head[1], head[2], head[3]), Segment::cubic(tail[0], tail[1], tail[2], tail[3])};
    }
  }
  return {s, s};
}

double conic_area_ratio(double w) {
  if (!(w > 0.0)) return 0.0;
  // Close to w = 1 the closed forms cancel; r(1) = 2/3 and r'(1) = 4/15.
  const double e = w - 1.0;
  if (std::abs(e) < 1e-6) return 2.0 / 3.0 + (4.0 / 15.0) * e;
  if (w < 1.0) {
    const double k = 1.0 - w * w;  // ellipse arc
    return (w / k) * (std::acos(w) / std::sqrt(k) - w);
  }
  // Far from 1, w * w overflows (past 1.3e154): there r = 1 - (ln 2w - 1) / w^2
  // + O(ln w / w^4), whose next terms are below 1e-26 from w = 1e7 on.
  if (w > 1e7) return 1.0 - (std::log(2.0) + std::log(w) - 1.0) / w / w;
  const double k = w * w - 1.0;  // hyperbola arc
  return (w / k) * (w - std::acosh(w) / std::sqrt(k));
}

double conic_chord_area(const Segment& conic) {
  const double triangle = 0.5 * cross(conic.p[1] - conic.p[0], conic.p[2] - conic.p[0]);
  // The loop p0 -> chord -> p2 -> arc -> p0 turns the opposite way to the
  // control triangle p0 -> control -> p2.
  return -conic_area_ratio(conic.weight) * triangle;
}

int cubic_to_quadratics(const Segment& cubic, double tolerance, std::vector<Segment>& out) {
  const Vec2 a = cubic.p[0], b = cubic.p[1], c = cubic.p[2], d = cubic.p[3];
  // The quadratic with control (3(b + c) - (a + d)) / 4 differs from the cubic
  // by (d - 3c + 3b - a) * t(1-t)(1-2t) / 2 at every parameter t, whose
  // largest size is sqrt(3)/36 * |d - 3c + 3b - a|. A piece of 1/n of the
  // parameter range has its third difference scaled by 1/n^3.
  const Vec2 difference = d - c * 3.0 + b * 3.0 - a;
  // sqrt of the squared length, not hypot (several times slower, and run for
  // every cubic of every CFF glyph); hypot only where the square overflows.
  double third = std::sqrt(dot(difference, difference));
  if (!std::isfinite(third)) third = length(difference);
  const double single_error = std::sqrt(3.0) / 36.0 * third;
  int pieces = 1;
  if (tolerance > 0.0 && single_error > tolerance) {
    // The fewest pieces n with (n + 1e-12)^3 >= single_error / tolerance
    // (the 1e-12 so that an exact cube gives its root, as ceil(cbrt(x) -
    // 1e-12) did): counted up, as
    // n is small (cbrt costs more than the two or three steps).
    const double ratio = single_error / tolerance;
    pieces = 2;
    while (pieces < tolerance::kMaxQuadraticsPerCubic && (pieces + 1e-12) * (pieces + 1e-12) * (pieces + 1e-12) < ratio)
      ++pieces;
  }
  if (!(tolerance > 0.0) && single_error > 0.0) pieces = tolerance::kMaxQuadraticsPerCubic;
  pieces = std::clamp(pieces, 1, tolerance::kMaxQuadraticsPerCubic);

  // De Casteljau on plain points (no Segments copied around).
  Vec2 rest[4] = {a, b, c, d};
  for (int i = 0; i < pieces; ++i) {
    Vec2 piece[4] = {rest[0], rest[1], rest[2], rest[3]};
    const int remaining = pieces - i;
    if (remaining > 1) {
      Vec2 tail[4];
      split_cubic(rest, 1.0 / remaining, piece, tail);
      std::copy(tail, tail + 4, rest);
    }
    // Written in place (see append() in outline.cpp for why not a copied temporary).
    Segment& quadratic = out.emplace_back();
    quadratic.kind = Segment::Kind::Conic;
    quadratic.p[0] = piece[0];
    quadratic.p[1] = ((piece[1] + piece[2]) * 3.0 - (piece[0] + piece[3])) * 0.25;
    quadratic.p[2] = piece[3];
  }
  // Make the chain end exactly where the cubic ends (splitting rounds).
  out.back().p[2] = cubic.p[3];
  return pieces;
}

Outline to_quadratic_outline(const Outline& outline, double tolerance) {
  Outline result = outline;
  for (Contour& contour : result.contours()) {
    if (std::none_of(contour.segments.begin(), contour.segments.end(),
                     [](const Segment& s) { return s.kind == Segment::Kind::Cubic; }))
      continue;
    std::vector<Segment> replaced;
    replaced.reserve(contour.segments.size() * 2);
    for (const Segment& s : contour.segments) {
      if (s.kind == Segment::Kind::Cubic)
        cubic_to_quadratics(s, tolerance, replaced);
      else
        replaced.push_back(s);
    }
    contour.segments = std::move(replaced);
  }
  return result;
}

}  // namespace curvetext
