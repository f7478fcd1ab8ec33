// Tests between the hulls of ring pieces (a line's segment, a conic's
// control triangle), for hull separation (hull_separation.cpp) and, through
// hulls_overlap (rings.hpp), the crossing resolver and check_mesh. Inline:
// the hull separation's pair loop calls them for most pairs of pieces whose
// boxes meet.
#pragma once

#include <cmath>

#include "curvetext/geometry.hpp"
#include "tessellate/predicates.hpp"

namespace curvetext::detail::hulls {

inline bool in_closed_hull(const Vec2* hull, int n, Vec2 p) {
  if (n == 2) return point_on_segment(hull[0], hull[1], p);
  return point_in_triangle(hull[0], hull[1], hull[2], p) != Where::Outside;
}

inline bool triangle_interiors_intersect(const Vec2* p, const Vec2* q) {
  // Separating axis theorem on the edges of both (convex) triangles; touching
  // (all on the closed outer side) counts as separated.
  auto separated_by_edges_of = [](const Vec2* t, const Vec2* other) {
    const int o = orient2d(t[0], t[1], t[2]);
    if (o == 0) return true;  // a degenerate triangle has no interior
    for (int k = 0; k < 3; ++k) {
      const Vec2 a = t[k], b = t[(k + 1) % 3];
      bool all_outside = true;
      for (int m = 0; m < 3 && all_outside; ++m) all_outside = orient2d(a, b, other[m]) * o <= 0;
      if (all_outside) return true;
    }
    return false;
  };
  return !separated_by_edges_of(p, q) && !separated_by_edges_of(q, p);
}

// Filtered orientation sign: +1 / -1 when certain (orient2d's error bound),
// 0 when exactly collinear because c is a or b, 2 when undecided.
inline int certain_side(Vec2 a, Vec2 b, Vec2 c) {
  if (c == a || c == b) return 0;
  const double detleft = (a.x - c.x) * (b.y - c.y);
  const double detright = (a.y - c.y) * (b.x - c.x);
  const double det = detleft - detright;
  const double errbound = kOrient2dErrorBound * (std::fabs(detleft) + std::fabs(detright));
  if (det > errbound) return 1;
  if (-det > errbound) return -1;
  return 2;
}

// True when the line through edge (a, b) of hull `own` (whose other vertex
// `opposite` is strictly on one side) has every point of `other` strictly on
// the other side or equal to a or b: then the hulls share no point but common
// vertices (hulls_overlap would say false). Only certain signs count.
inline bool separates(Vec2 a, Vec2 b, int inner, const Vec2* other, int n) {
  for (int k = 0; k < n; ++k) {
    const int side = certain_side(a, b, other[k]);
    if (side == 2 || side == inner) return false;
  }
  return true;
}

// A quick, conservative "no" for hulls_overlap: a separating line along an
// edge of either hull, decided with filtered signs only. False means "not
// known", and the exact test decides.
inline bool hulls_clearly_apart(const Vec2* p, int np, const Vec2* q, int nq) {
  auto by_edges_of = [](const Vec2* t, int nt, const Vec2* other, int no) {
    if (nt == 2) {
      // A segment's own line separates when the other hull is strictly on one
      // side of it (shared end points aside).
      int side = 0;
      for (int k = 0; k < no; ++k) {
        const int s = certain_side(t[0], t[1], other[k]);
        if (s == 2) return false;
        if (s == 0) continue;
        if (side != 0 && s != side) return false;
        side = s;
      }
      return side != 0;
    }
    const int o = certain_side(t[0], t[1], t[2]);
    if (o != 1 && o != -1) return false;
    // The chord (t[2], t[0]) first: at a smooth join of consecutive pieces
    // the legs through the shared vertex are collinear with the neighbour's
    // (undecided), while the chord separates.
    return separates(t[2], t[0], o, other, no) || separates(t[0], t[1], o, other, no) ||
           separates(t[1], t[2], o, other, no);
  };
  // A conic's hull first, for the same reason.
  if (np == 2 && nq == 3) return by_edges_of(q, nq, p, np) || by_edges_of(p, np, q, nq);
  return by_edges_of(p, np, q, nq) || by_edges_of(q, nq, p, np);
}

// hulls_overlap (rings.hpp).
inline bool overlap(const Vec2* p, int np, const Vec2* q, int nq) {
  if (hulls_clearly_apart(p, np, q, nq)) return false;
  auto is_vertex_of = [](Vec2 v, const Vec2* hull, int n) {
    for (int k = 0; k < n; ++k) {
      if (hull[k] == v) return true;
    }
    return false;
  };
  for (int k = 0; k < nq; ++k) {
    if (!is_vertex_of(q[k], p, np) && in_closed_hull(p, np, q[k])) return true;
  }
  for (int k = 0; k < np; ++k) {
    if (!is_vertex_of(p[k], q, nq) && in_closed_hull(q, nq, p[k])) return true;
  }
  const int ep = np == 2 ? 1 : 3, eq = nq == 2 ? 1 : 3;
  for (int i = 0; i < ep; ++i) {
    for (int j = 0; j < eq; ++j) {
      if (segments_cross_properly(p[i], p[i + 1 == np ? 0 : i + 1], q[j], q[j + 1 == nq ? 0 : j + 1])) return true;
    }
  }
  return np == 3 && nq == 3 && triangle_interiors_intersect(p, q);
}

// Certain sign of cross(x, y) for x and y differences from a common point v:
// that is orient2d(x + v, y + v, v), with orient2d's filter (Shewchuk's bound
// covers the rounding of the differences too); 0 when the filter cannot
// decide (or an overflow made the products infinite). Written without
// branches.
inline int certain_cross_sign(Vec2 x, Vec2 y) {
  const double left = x.x * y.y, right = x.y * y.x, det = left - right;
  const double errbound = kOrient2dErrorBound * (std::fabs(left) + std::fabs(right));
  return static_cast<int>(det > errbound) - static_cast<int>(-det > errbound);
}

// Consecutive pieces of a ring, p (a -> v, control c when a conic) and q
// (v -> b, control d): true when their hulls certainly meet only at v, so
// that their pair test would find nothing (no overlap, and for two lines no
// run along each other). A line through v separates them: p's chord (v, a)
// with b and d strictly on one side and c strictly on the other, or q's
// chord (v, b) likewise. At a glyph's smooth joins (legs on one line through
// v) and corners one of the two chords does. Decided in straight-line code
// from five signs: a ring's consecutive pairs are most of the pairs whose
// boxes meet, and the branches of the general test, taken in a data-dependent
// order, cost more than these few products. For a line p, c is taken as v,
// for a line q, d as b (their hulls' middle points: no select between points,
// which compiles to a branch on the piece kind); the conditions on a line's
// control are then not asked.
inline bool joint_apart(Vec2 a, Vec2 c, bool p_conic, Vec2 v, Vec2 d, bool q_conic, Vec2 b) {
  const Vec2 va = a - v, vb = b - v, vc = c - v, vd = d - v;
  const int ab = certain_cross_sign(va, vb);
  const int ad = certain_cross_sign(va, vd), ac = certain_cross_sign(va, vc);
  const int bc = certain_cross_sign(vb, vc), bd = certain_cross_sign(vb, vd);
  const bool by_p_chord = (ad == ab) & ((!p_conic) | (ac == -ab));
  const bool by_q_chord = ((!p_conic) | (bc == -ab)) & ((!q_conic) | (bd == ab));
  return (ab != 0) & (by_p_chord | by_q_chord);
}

// A piece's point and derivative at parameter t: a line a + t (b - a), or
// a conic N(t) / D(t), N = (1-t)^2 a + 2t(1-t) w c + t^2 b, D its weights.
inline void piece_at(const Vec2* h, int n, double w, double t, Vec2& point, Vec2& derivative) {
  if (n == 2) {
    derivative = h[1] - h[0];
    point = h[0] + derivative * t;
    return;
  }
  const double u = 1.0 - t;
  const Vec2 numerator = h[0] * (u * u) + h[1] * (2.0 * t * u * w) + h[2] * (t * t);
  const double denominator = u * u + 2.0 * t * u * w + t * t;
  const Vec2 numerator_d = ((h[1] * w - h[0]) * u + (h[2] - h[1] * w) * t) * 2.0;
  const double denominator_d = 2.0 * (w - 1.0) * (u - t);
  point = numerator / denominator;
  derivative = (numerator_d * denominator - numerator * denominator_d) / (denominator * denominator);
}

// Parameters t on p and s on q where their curves cross, for splitting both
// there. Asked only when their chords cross properly (exact signs), from
// the chords' crossing, by Newton's method on p(t) = q(s); accepted when the
// steps fall below 1e-12 with a conic's parameter in [1/64, 63/64] (no
// sliver of a curve next to its end: halving moves such a crossing inward)
// and a line's anywhere inside (halving the conic never moves the crossing
// along the line). Tangent curves (a singular step), curves that do not
// cross, and slow convergence give false: the pieces are then halved.
inline bool crossing_parameters(const Vec2* p, int np, double wp, const Vec2* q, int nq, double wq, double& t,
                                double& s) {
  const Vec2 pa = p[0], pb = p[np - 1], qa = q[0], qb = q[nq - 1];
  if (orient2d(pa, pb, qa) * orient2d(pa, pb, qb) >= 0 || orient2d(qa, qb, pa) * orient2d(qa, qb, pb) >= 0)
    return false;
  const Vec2 r = pb - pa, d = qb - qa;
  const double denominator = cross(r, d);
  t = cross(qa - pa, d) / denominator;
  s = cross(qa - pa, r) / denominator;
  constexpr int kSteps = 12;
  constexpr double kSettled = 1e-12, kMargin = 1.0 / 64.0;
  for (int step = 0; step < kSteps; ++step) {
    Vec2 at_p, dp, at_q, dq;
    piece_at(p, np, wp, t, at_p, dp);
    piece_at(q, nq, wq, s, at_q, dq);
    const Vec2 gap = at_p - at_q;
    const double det = cross(dp, dq);
    if (!(std::fabs(det) > 0.0)) return false;
    const double dt = -cross(gap, dq) / det, ds = cross(dp, gap) / det;
    t += dt;
    s += ds;
    if (!(t > 0.0 && t < 1.0 && s > 0.0 && s < 1.0)) return false;
    if (std::fabs(dt) < kSettled && std::fabs(ds) < kSettled)
      return (np == 2 || (t >= kMargin && t <= 1.0 - kMargin)) && (nq == 2 || (s >= kMargin && s <= 1.0 - kMargin));
  }
  return false;
}

}  // namespace curvetext::detail::hulls
