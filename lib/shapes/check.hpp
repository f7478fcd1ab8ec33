// Input checks shared by the shape readers: every value that reaches the
// geometry is finite and of a sane magnitude, or the caller gets an Error that
// names it.
#pragma once

#include <cmath>
#include <string>
#include <string_view>

#include "curvetext/error.hpp"
#include "curvetext/geometry.hpp"
#include "curvetext/shapes.hpp"
#include "core/format.hpp"

namespace curvetext::shapes_detail {

inline std::string number_text(double v) { return detail::format_number_exact(v); }

// Throws Error(InvalidArgument) "<what>: coordinate ... is not finite / too large".
inline void check_coordinate(double v, const std::string& what) {
  if (!std::isfinite(v))
    throw Error(ErrorCode::InvalidArgument, what + ": coordinate " + number_text(v) + " is not a finite number");
  if (std::abs(v) > kMaxShapeCoordinate)
    throw Error(ErrorCode::InvalidArgument, what + ": coordinate " + number_text(v) + " is larger than " +
                                                number_text(kMaxShapeCoordinate) + " in magnitude");
}

inline void check_point(Vec2 p, const std::string& what) {
  check_coordinate(p.x, what);
  check_coordinate(p.y, what);
}

// Weights must be positive (a zero or negative weight makes the curve pass
// through infinity or leave the control hull); the range keeps the normalised
// conic weights and the homogeneous coordinates far from overflow.
inline constexpr double kMinWeight = 1e-9;
inline constexpr double kMaxWeight = 1e9;

inline void check_weight(double w, const std::string& what) {
  if (w == 0.0)
    throw Error(ErrorCode::InvalidArgument,
                what + ": weight 0 is allowed only as the middle weight of a quadratic (where it gives the chord)");
  if (!std::isfinite(w) || w <= 0.0)
    throw Error(ErrorCode::InvalidArgument, what + ": weight " + number_text(w) + " must be a positive finite number");
  if (w < kMinWeight || w > kMaxWeight)
    throw Error(ErrorCode::InvalidArgument, what + ": weight " + number_text(w) + " is outside [" +
                                                number_text(kMinWeight) + ", " + number_text(kMaxWeight) + "]");
}

// docs/design.md section 3: a rational quadratic with middle weight 0 (end
// weights > 0) is its chord. True when piece `index` of a degree-2 curve
// with `count` weights may be 0 (the middle one) and is.
inline bool is_zero_middle_weight(std::size_t degree, std::size_t index, std::size_t count, double w) {
  return degree == 2 && index > 0 && index + 1 < count && w == 0.0;
}

}  // namespace curvetext::shapes_detail

namespace curvetext {

// A fill rule as SVG and the JSON format spell it: "nonzero" | "evenodd"
// ("even-odd" is accepted too). Throws Error(InvalidArgument).
FillRule parse_fill_rule(std::string_view text);

}  // namespace curvetext
