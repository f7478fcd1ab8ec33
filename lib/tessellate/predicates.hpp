// Robust geometric predicates for the tessellator. Every decision that the
// mesh's topology depends on (left/right of a line, inside a triangle, do two
// segments meet) goes through orient2d, which returns the exact sign of the
// determinant for any finite double input (no overflow assumed).
#pragma once

#include <cmath>
#include <cstddef>
#include <utility>

#include "curvetext/geometry.hpp"

namespace curvetext::detail {

// The exact slow path of orient2d, for inputs its filter cannot decide.
int orient2d_exact(Vec2 a, Vec2 b, Vec2 c);

// Shewchuk's bound for orient2d's filter ("Adaptive Precision Floating-Point
// Arithmetic", 1997, ccwerrboundA): with eps = 2^-53, the double value of
// detleft - detright is within (3 + 16 eps) eps (|detleft| + |detright|) of the
// exact determinant, the rounding of the coordinate differences included.
// Every filtered orientation sign in the tessellator uses this one bound.
inline constexpr double kOrient2dErrorBound = (3.0 + 16.0 * 0x1p-53) * 0x1p-53;

// Sign of the orientation determinant |a-c b-c|: +1 when a, b, c turn
// counter-clockwise (c left of a->b, y up), -1 clockwise, 0 collinear. Exact.
// Inline filter (kOrient2dErrorBound): outside that band the double sign is
// the exact sign. Most calls end here; the rest go to orient2d_exact.
inline int orient2d(Vec2 a, Vec2 b, Vec2 c) {
  const double detleft = (a.x - c.x) * (b.y - c.y);
  const double detright = (a.y - c.y) * (b.x - c.x);
  const double det = detleft - detright;
  // (fabs and a sign written as a difference of comparisons: no branch on
  // the sign, which is data-dependent and mispredicted half the time; the one
  // branch left, "decided by the filter", almost always goes the same way.)
  const double errbound = kOrient2dErrorBound * (std::fabs(detleft) + std::fabs(detright));
  if (std::fabs(det) > errbound) return static_cast<int>(det > 0) - static_cast<int>(det < 0);
  // Exactly collinear along an axis (common in fonts: horizontal and vertical
  // stems): a difference of doubles is zero only for equal operands, so when
  // each product has an exactly zero factor both products, and det, are 0.
  if ((a.x == c.x || b.y == c.y) && (a.y == c.y || b.x == c.x)) return 0;
  return orient2d_exact(a, b, c);
}

// Twice the signed area of (a, b, c) in plain double arithmetic, for
// magnitudes only (areas, quality measures); never use its sign for topology.
inline double orient2d_value(Vec2 a, Vec2 b, Vec2 c) { return cross(b - a, c - a); }

// > 0 when d lies strictly inside the circumcircle of the counter-clockwise
// triangle (a, b, c). Evaluated in long double without an exactness guarantee:
// it only steers Delaunay flips, whose count is bounded by the caller, so a
// wrong sign near zero costs mesh quality, never validity.
long double incircle(Vec2 a, Vec2 b, Vec2 c, Vec2 d);

// Sign of incircle(a, b, c, d), decided in double when Shewchuk's filter is
// certain and by incircle (long double, x87: slow) otherwise. With eps =
// 2^-53, the double determinant of the rounded differences is within
// (10 + 96 eps) eps * permanent of the exact one (iccerrboundA in
// "Adaptive Precision Floating-Point Arithmetic", 1997), so outside that
// band its sign is the exact sign.
inline int incircle_sign(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  const double adx = a.x - d.x, ady = a.y - d.y;
  const double bdx = b.x - d.x, bdy = b.y - d.y;
  const double cdx = c.x - d.x, cdy = c.y - d.y;
  const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
  const double cdxady = cdx * ady, adxcdy = adx * cdy;
  const double adxbdy = adx * bdy, bdxady = bdx * ady;
  const double alift = adx * adx + ady * ady;
  const double blift = bdx * bdx + bdy * bdy;
  const double clift = cdx * cdx + cdy * cdy;
  const double det = alift * (bdxcdy - cdxbdy) + blift * (cdxady - adxcdy) + clift * (adxbdy - bdxady);
  // (fabs, not a branch on the sign, as in orient2d.)
  const double permanent = (std::fabs(bdxcdy) + std::fabs(cdxbdy)) * alift +
                           (std::fabs(cdxady) + std::fabs(adxcdy)) * blift +
                           (std::fabs(adxbdy) + std::fabs(bdxady)) * clift;
  constexpr double kEps = 0x1p-53;
  constexpr double kIccErrBoundA = (10.0 + 96.0 * kEps) * kEps;
  const double errbound = kIccErrBoundA * permanent;
  if (std::fabs(det) > errbound) return static_cast<int>(det > 0) - static_cast<int>(det < 0);
  const long double slow = incircle(a, b, c, d);
  return slow > 0 ? 1 : slow < 0 ? -1 : 0;
}

enum class Where { Outside, Boundary, Inside };

// Defined here (inline) because the tessellator calls them in its inner loops.
// True when p lies on the closed segment [a, b].
inline bool point_on_segment(Vec2 a, Vec2 b, Vec2 p) {
  // The box test is exact and cheap, and rejects most calls before orient2d.
  if (!(std::fmin(a.x, b.x) <= p.x && p.x <= std::fmax(a.x, b.x) && std::fmin(a.y, b.y) <= p.y &&
        p.y <= std::fmax(a.y, b.y)))
    return false;
  return orient2d(a, b, p) == 0;
}

// Position of p relative to the closed triangle (a, b, c) of either orientation;
// Outside for a degenerate (zero-area) triangle unless p lies on it.
inline Where point_in_triangle(Vec2 a, Vec2 b, Vec2 c, Vec2 p) {
  int o = orient2d(a, b, c);
  if (o == 0) {
    return (point_on_segment(a, b, p) || point_on_segment(b, c, p) || point_on_segment(c, a, p)) ? Where::Boundary
                                                                                                 : Where::Outside;
  }
  const int s1 = orient2d(a, b, p) * o;
  const int s2 = orient2d(b, c, p) * o;
  const int s3 = orient2d(c, a, p) * o;
  if (s1 < 0 || s2 < 0 || s3 < 0) return Where::Outside;
  if (s1 == 0 || s2 == 0 || s3 == 0) return Where::Boundary;
  return Where::Inside;
}

// True when the open segments (a, b) and (c, d) cross at a single point
// interior to both (a proper crossing).
inline bool segments_cross_properly(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  const int o1 = orient2d(a, b, c), o2 = orient2d(a, b, d);
  if (o1 * o2 >= 0) return false;  // exact signs: the second pair is not needed
  const int o3 = orient2d(c, d, a), o4 = orient2d(c, d, b);
  return o3 * o4 < 0;
}

// True when the closed segments [a, b] and [c, d] share any point.
inline bool segments_intersect(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  const int o1 = orient2d(a, b, c), o2 = orient2d(a, b, d);
  // c and d strictly on one side of line ab: no common point (with exact
  // signs, a or b on [c, d] would put c and d on different sides or on it).
  if (o1 * o2 > 0) return false;
  const int o3 = orient2d(c, d, a), o4 = orient2d(c, d, b);
  if (o3 * o4 > 0) return false;
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;
  return (o1 == 0 && point_on_segment(a, b, c)) || (o2 == 0 && point_on_segment(a, b, d)) ||
         (o3 == 0 && point_on_segment(c, d, a)) || (o4 == 0 && point_on_segment(c, d, b));
}

// Nonzero winding of a closed polygon around p, or Boundary when p lies on it.
// `edge(i)` returns the i-th directed edge as {start, end}, i < count. Exact:
// only orient2d and point_on_segment decide.
template <class EdgeAt>
Where point_in_polygon(std::size_t count, EdgeAt edge, Vec2 p) {
  int winding = 0;
  for (std::size_t i = 0; i < count; ++i) {
    const auto [a, b] = edge(i);
    if (point_on_segment(a, b, p)) return Where::Boundary;
    if (a.y <= p.y) {
      if (b.y > p.y && orient2d(a, b, p) > 0) ++winding;
    } else if (b.y <= p.y && orient2d(a, b, p) < 0) {
      --winding;
    }
  }
  return winding != 0 ? Where::Inside : Where::Outside;
}

// Exact sign of a double sum given as non-overlapping-free terms: used by
// orient2d's slow path and exposed for tests.
int exact_sign_of_sum(const double* terms, int count);

inline bool boxes_overlap(const Box& a, const Box& b) {
  return (a.min.x <= b.max.x) & (b.min.x <= a.max.x) & (a.min.y <= b.max.y) & (b.min.y <= a.max.y);  // no branches
}

}  // namespace curvetext::detail
