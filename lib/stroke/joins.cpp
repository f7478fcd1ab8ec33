// Joins, caps and dots as SVG 2 defines them; round pieces are exact circle
// arcs (rational quadratics of weight cos(half their angle)).
#include <algorithm>
#include <cmath>

#include "stroke/stroke_parts.hpp"

namespace curvetext::stroke {

namespace {

constexpr double kPi = 3.14159265358979323846;
// Largest angle of one conic of a circle arc: the control point stays near.
constexpr double kMaxArcPiece = 0.5 * kPi;

Vec2 rotate(Vec2 v, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * v.x - s * v.y, s * v.x + c * v.y};
}

// The arc of the circle about `centre` from `from` (|from - centre| = r)
// through `angle` radians (> 0 counter-clockwise, < 0 clockwise), as conics
// of at most kMaxArcPiece each.
void append_arc(Vec2 centre, Vec2 from, double angle, std::vector<Segment>& out) {
  const int n = std::max(1, static_cast<int>(std::ceil(std::abs(angle) / kMaxArcPiece - 1e-9)));
  const double step = angle / n;
  Vec2 v = from - centre, start = from;
  for (int i = 0; i < n; ++i) {
    const Vec2 next = rotate(v, step);
    const Vec2 end = i + 1 == n ? centre + rotate(from - centre, angle) : centre + next;
    out.push_back(Segment::conic(start, centre + (v + next) / (1.0 + std::cos(step)), end, std::cos(0.5 * step)));
    v = next;
    start = end;
  }
}

void lines(std::vector<Segment>& out, std::initializer_list<Vec2> points) {
  const Vec2* prev = nullptr;
  for (const Vec2& p : points) {
    if (prev && !(*prev == p)) out.push_back(Segment::line(*prev, p));
    prev = &p;
  }
}

// SVG 2 miter-clip: the miter when its tip lies within clip_distance of p,
// else the miter cut by the line at clip_distance from p perpendicular to
// the bisector u (a bevel when that line lies inside it).
void miter_clip(Vec2 p, Vec2 a, Vec2 t0, Vec2 b, Vec2 t1, Vec2 u, double clip_distance, std::vector<Segment>& out) {
  const double da = dot(a - p, u);
  const double sa = dot(t0, u), sb = -dot(t1, u);
  // The tip is where both edges reach the bisector: at da + sa * s along u.
  const double tip = sa > 0.0 ? da + sa * (dot(b - a, left_normal(t1)) / dot(t0, left_normal(t1))) : HUGE_VAL;
  if (sa > 0.0 && sb > 0.0 && std::isfinite(tip) && tip <= clip_distance) {
    const double s = dot(b - a, left_normal(t1)) / dot(t0, left_normal(t1));
    return lines(out, {a, a + t0 * s, b});
  }
  if (clip_distance <= da || !(sa > 0.0) || !(sb > 0.0)) return lines(out, {a, b});
  lines(out, {a, a + t0 * ((clip_distance - da) / sa), b - t1 * ((clip_distance - dot(b - p, u)) / sb), b});
}

struct Corner {
  Vec2 p, a, b, t0, t1, u;  // join point, side ends, tangents, outer bisector
  double cos_half = 1.0;    // cosine of half the turning angle
  double h = 0.5;
};

// The circle continuing a side with curvature k (0: a line) from `at` with
// tangent t: sets centre and returns whether there is one.
bool osculating(Vec2 at, Vec2 t, double k, Vec2& centre) {
  if (!(std::abs(k) > 1e-300)) return false;
  centre = at + left_normal(t) / k;
  return true;
}

// Points where two circles (or a circle and a line through `q` along `dir`)
// meet; returns how many (0 to 2) in out[].
int meet_circles(Vec2 c1, double r1, Vec2 c2, double r2, Vec2 out[2]) {
  const double d = distance(c1, c2);
  if (!(d > 0.0) || d > r1 + r2 || d < std::abs(r1 - r2)) return 0;
  const double x = (d * d + r1 * r1 - r2 * r2) / (2.0 * d), y2 = r1 * r1 - x * x;
  const Vec2 e = (c2 - c1) / d, base = c1 + e * x, off = left_normal(e) * std::sqrt(std::max(0.0, y2));
  out[0] = base + off;
  out[1] = base - off;
  return 2;
}

int meet_line(Vec2 c, double r, Vec2 q, Vec2 dir, Vec2 out[2]) {
  const double along = dot(c - q, dir), gap2 = r * r - (dot(c - q, c - q) - along * along);
  if (gap2 < 0.0) return 0;
  out[0] = q + dir * (along + std::sqrt(gap2));
  out[1] = q + dir * (along - std::sqrt(gap2));
  return 2;
}

// The signed angle travelled from `from` to `to` about centre, in the
// direction of curvature k (counter-clockwise for k > 0), in [0, 2 pi).
double travel(Vec2 centre, Vec2 from, Vec2 to, double k) {
  const Vec2 v0 = from - centre, v1 = to - centre;
  double angle = std::atan2(cross(v0, v1), dot(v0, v1)) * (k > 0.0 ? 1.0 : -1.0);
  if (angle < 0.0) angle += 2.0 * kPi;
  return angle * (k > 0.0 ? 1.0 : -1.0);
}

// SVG 2 arcs: each side's edge continued as the circle of its curvature
// (a line where that is 0) to where they meet; miter-clip where they do
// not meet ahead of the join or meet beyond the miter limit.
void arcs_join(const Corner& c, double ka, double kb, double limit, std::vector<Segment>& out) {
  Vec2 ca, cb, hits[2];
  const bool ha = osculating(c.a, c.t0, ka, ca), hb = osculating(c.b, c.t1, kb, cb);
  int n = 0;
  if (ha && hb)
    n = meet_circles(ca, 1.0 / std::abs(ka), cb, 1.0 / std::abs(kb), hits);
  else if (ha)
    n = meet_line(ca, 1.0 / std::abs(ka), c.b, c.t1, hits);
  else if (hb)
    n = meet_line(cb, 1.0 / std::abs(kb), c.a, c.t0, hits);
  const double clip = limit * c.h;
  if (!ha && !hb) {
    if (c.cos_half > 0.0 && 1.0 / c.cos_half <= limit) return lines(out, {c.a, c.p + c.u * (c.h / c.cos_half), c.b});
    return miter_clip(c.p, c.a, c.t0, c.b, c.t1, c.u, clip, out);
  }
  // The meeting point reached first going forward from a (and backward
  // from b); edges that must turn more than a quarter circle to meet count
  // as not meeting.
  int best = -1;
  double first = 0.0, second = 0.0;
  for (int i = 0; i < n; ++i) {
    const double t1 = ha ? travel(ca, c.a, hits[i], ka) : (dot(hits[i] - c.a, c.t0) >= 0.0 ? 0.0 : kPi);
    const double t2 = hb ? travel(cb, hits[i], c.b, kb) : (dot(c.b - hits[i], c.t1) >= 0.0 ? 0.0 : kPi);
    if (std::abs(t1) > 0.5 * kPi || std::abs(t2) > 0.5 * kPi || (best >= 0 && std::abs(t1) >= std::abs(first)))
      continue;
    best = i;
    first = t1;
    second = t2;
  }
  if (best < 0 || distance(hits[best], c.p) > clip) return miter_clip(c.p, c.a, c.t0, c.b, c.t1, c.u, clip, out);
  const Vec2 x = hits[best];
  if (ha)
    append_arc(ca, c.a, first, out);
  else
    lines(out, {c.a, x});
  if (hb)
    append_arc(cb, x, second, out);
  else
    lines(out, {x, c.b});
}

}  // namespace

bool outer_side(Vec2 t0, Vec2 t1, double side) {
  const double turn = cross(t0, t1);
  return turn == 0.0 ? (dot(t0, t1) < 0.0 && side < 0.0) : side * turn < 0.0;
}

void append_join(Vec2 p, Vec2 t0, Vec2 t1, double k0, double k1, double side, const JoinStyle& style,
                 std::vector<Segment>& out) {
  const double h = style.half_width, turn = cross(t0, t1), cos_turn = dot(t0, t1);
  const Vec2 r0 = left_normal(t0) * side, r1 = left_normal(t1) * side;
  const Vec2 a = p + r0 * h, b = p + r1 * h;
  if (a == b) return;
  if (cos_turn > 0.0 && std::abs(turn) < 1e-9) return lines(out, {a, b});  // smooth: a gap of rounding
  if (!outer_side(t0, t1, side)) return lines(out, {a, p, b});             // the inner side pivots through p
  Corner c{p, a, b, t0, t1, {}, std::sqrt(std::max(0.0, 0.5 * (1.0 + cos_turn))), h};
  const Vec2 bis = r0 + r1;
  c.u = length(bis) > 1e-12 ? unit(bis) : t0;
  const double limit = std::max(1.0, style.miter_limit);
  switch (style.join) {
    case LineJoin::Bevel:
      return lines(out, {a, b});
    case LineJoin::Round:
      // The short way from r0 to r1 (cross(r0, r1) = turn); a reversal
      // counter-clockwise, through p + h t0.
      return append_arc(p, a, std::acos(std::clamp(dot(r0, r1), -1.0, 1.0)) * (turn < 0.0 ? -1.0 : 1.0), out);
    case LineJoin::Miter:
      if (c.cos_half > 0.0 && 1.0 / c.cos_half <= limit) return lines(out, {a, p + c.u * (h / c.cos_half), b});
      return lines(out, {a, b});
    case LineJoin::MiterClip:
      if (c.cos_half > 0.0 && 1.0 / c.cos_half <= limit) return lines(out, {a, p + c.u * (h / c.cos_half), b});
      return miter_clip(p, a, t0, b, t1, c.u, limit * h, out);
    case LineJoin::Arcs: {
      // Curvature of the side at signed distance s: k / (1 - s k).
      const double s = side * h;
      double ka = std::abs(1.0 - s * k0) > 0.0 ? k0 / (1.0 - s * k0) : 0.0;
      double kb = std::abs(1.0 - s * k1) > 0.0 ? k1 / (1.0 - s * k1) : 0.0;
      // A circle departs from its tangent by k r^2 / 2 at distance r: below
      // the tolerance over the join's reach it is that line (and a radius of
      // 1e16 would only lose the intersection's digits).
      const double reach = limit * h;
      if (std::abs(ka) * reach * reach * 0.5 < style.tolerance) ka = 0.0;
      if (std::abs(kb) * reach * reach * 0.5 < style.tolerance) kb = 0.0;
      return arcs_join(c, ka, kb, limit, out);
    }
  }
}

void append_cap(Vec2 p, Vec2 t, double h, LineCap cap, std::vector<Segment>& out) {
  const Vec2 n = left_normal(t) * h, ahead = t * h;
  switch (cap) {
    case LineCap::Butt:
      return lines(out, {p - n, p + n});
    case LineCap::Square:
      return lines(out, {p - n, p - n + ahead, p + n + ahead, p + n});
    case LineCap::Round:
      return append_arc(p, p - n, kPi, out);
  }
}

void append_dot(Vec2 p, Vec2 t, double h, LineCap cap, std::vector<Segment>& out) {
  const Vec2 n = left_normal(t) * h, ahead = t * h;
  switch (cap) {
    case LineCap::Butt:
      return;
    case LineCap::Square:
      return lines(out, {p - n - ahead, p - n + ahead, p + n + ahead, p + n - ahead, p - n - ahead});
    case LineCap::Round:
      return append_arc(p, p - n, 2.0 * kPi, out);
  }
}

}  // namespace curvetext::stroke
