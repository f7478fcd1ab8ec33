// Curve mathematics: evaluation, exact subdivision of rational quadratics,
// areas, and the approximation of cubics by quadratics with a guaranteed bound.
#pragma once

#include <utility>
#include <vector>

#include "curvetext/export.hpp"
#include "curvetext/outline.hpp"

namespace curvetext {

// Point at parameter t in [0,1] (rational evaluation for conics), in the
// segment's units.
CURVETEXT_API Vec2 evaluate(const Segment& s, double t);

// Splits at t (de Casteljau in homogeneous coordinates: exact for conics, whose
// halves get re-normalised weights).
CURVETEXT_API std::pair<Segment, Segment> split(const Segment& s, double t);

// Signed area between a conic and its chord, positive when the curve bulges to
// the left of p0->p2 (control point on the left, y up): the signed area of the
// loop "along the chord from p0 to p2, then back along the arc".
// Equals (2/3) * triangle area for weight 1.
CURVETEXT_API double conic_chord_area(const Segment& conic);

// Ratio (area between conic arc and chord) / (area of the control triangle) for
// a given middle weight; 2/3 at weight 1, pi/2 - 1 for a quarter circle.
CURVETEXT_API double conic_area_ratio(double weight);

// Appends to `out` conics of weight 1 approximating `cubic` so that every point
// of the cubic is within `tolerance` (same unit as the points) of the
// approximation and vice versa. Returns how many were appended. The count is
// the smallest n with (sqrt(3)/36) * |p3 - 3p2 + 3p1 - p0| / n^3 <= tolerance,
// capped at tolerance::kMaxQuadraticsPerCubic (also the count for a
// tolerance that is not positive).
CURVETEXT_API int cubic_to_quadratics(const Segment& cubic, double tolerance, std::vector<Segment>& out);

// A copy of the outline with every cubic replaced as above; lines and conics
// kept.
CURVETEXT_API Outline to_quadratic_outline(const Outline& outline, double tolerance);

}  // namespace curvetext
