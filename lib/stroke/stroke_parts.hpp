// The parts of the stroker (lib/stroke): geometry of one segment (tangents,
// arc length, exact circle offsets, fitted offsets), the joins and caps
// between offset sides, and dashing. Segments here are lines and conics
// only (the stroker turns everything else into conics first).
#pragma once

#include <cstddef>
#include <vector>

#include "curvetext/outline.hpp"
#include "curvetext/stroke_style.hpp"

namespace curvetext::stroke {

// The derivative of a line or conic at t.
Vec2 derivative(const Segment& s, double t);
// Unit tangent at the start (t = 0) and end (t = 1), from the control
// points (robust where the derivative vanishes); {0, 0} for a point.
Vec2 start_tangent(const Segment& s);
Vec2 end_tangent(const Segment& s);
// Unit left normal of a unit tangent (y-up: counter-clockwise by 90 degrees).
inline Vec2 left_normal(Vec2 t) { return {-t.y, t.x}; }
inline Vec2 unit(Vec2 v) {
  const double l = length(v);
  return l > 0.0 ? v / l : Vec2{};
}
Segment reversed(const Segment& s);

// Counts the segments a stroke makes against tolerance::kMaxStrokeSegments
// and throws Error(Geometry) past it.
class Budget {
 public:
  void spend(std::size_t n);
  void reset() { used_ = 0; }

 private:
  std::size_t used_ = 0;
};

// Arc length of s over [0, t], integrated (adaptive Gauss-Legendre) within
// `tolerance` (path units). Exact for lines.
double arc_length(const Segment& s, double t, double tolerance);
// The parameter where the arc length from 0 reaches `target` (0 <= target
// <= arc_length(s, 1)), within `tolerance` of arc length.
double parameter_at_length(const Segment& s, double target, double total, double tolerance);

// Appends the curve at signed distance `d` from s (d > 0: its left) to
// `out`: exact for lines and circular arcs, conics within `tolerance`
// (sampled Hausdorff distance) otherwise.
void append_offset(const Segment& s, double d, double tolerance, Budget& budget, std::vector<Segment>& out);

// Joins and caps, appended as segments continuing the side being built.
struct JoinStyle {
  LineJoin join = LineJoin::Miter;
  double half_width = 0.5;
  double miter_limit = 4.0;
  // Arcs joins: an edge whose circle departs from its tangent line by less
  // than this within the miter limit's reach counts as straight (path units).
  double tolerance = 1e-3;
};
// Whether the side at `side` (+1 left, -1 right) is the outer one of a
// corner from unit tangent t0 to t1 (a reversal turns round on the right).
bool outer_side(Vec2 t0, Vec2 t1, double side);
// The join at p between a segment ending with unit tangent t0 and one
// starting with t1, on the side at signed distance `side * half_width`
// (side = +1 left, -1 right), from p + side*h*n0 to p + side*h*n1. `k0`,
// `k1`: curvatures (1/radius, signed, > 0 turning left) where the segments
// meet, for arcs joins.
void append_join(Vec2 p, Vec2 t0, Vec2 t1, double k0, double k1, double side, const JoinStyle& style,
                 std::vector<Segment>& out);
// The cap at p with unit tangent t pointing out of the path, from
// p - h*n(t) to p + h*n(t).
void append_cap(Vec2 p, Vec2 t, double half_width, LineCap cap, std::vector<Segment>& out);
// The region of a zero-length subpath (or dash) at p whose direction is t:
// a circle for round caps, a square for square caps, nothing for butt.
void append_dot(Vec2 p, Vec2 t, double half_width, LineCap cap, std::vector<Segment>& out);
// Signed curvature of s at t = 0 or 1.
double end_curvature(const Segment& s, bool at_end);

// The dashes of one subpath: calls emit(first, last_exclusive) on a scratch
// vector of the dash's segments, or emit_dot(point, tangent) for a dash of
// zero length. For a closed subpath whose pattern is on at both its start and
// end, the last dash continues into the first (one piece).
struct DashPattern {
  std::vector<double> lengths;  // even count, scaled, each >= 0, sum > 0
  double phase = 0.0;           // in [0, sum)
};

}  // namespace curvetext::stroke
