// Gradient paint: linear and radial gradients (SVG's and COLR's), evaluated
// per pixel in the composite pass of full, vbaa and msaa antialiasing and
// multiplied by the pixel's exact coverage. A DrawOptions with a gradient
// draws it instead of its colour.
#pragma once

#include <vector>

#include "curvetext/color.hpp"
#include "curvetext/export.hpp"
#include "curvetext/geometry.hpp"
#include "curvetext/transform.hpp"

namespace curvetext {

struct GradientStop {
  float offset = 0.0f;  // in [0, 1], not below the previous stop's
  Color color;          // straight alpha, sRGB; interpolated so, then premultiplied
};

struct Gradient {
  enum class Kind { Linear, Radial };
  // Beyond [0, 1]: the end colours (pad), mirrored (reflect) or repeated.
  enum class Spread { Pad, Reflect, Repeat };
  Kind kind = Kind::Linear;
  Spread spread = Spread::Pad;
  std::vector<GradientStop> stops;  // 1 to kMaxGradientStops
  // Linear: t is 0 at `start` and 1 at `end`, constant across the line.
  Vec2 start{0, 0}, end{1, 0};
  // Radial: t is 1 on the circle (centre, radius) and 0 at `focus`, on the
  // circles between the focus (radius 0) and that one (SVG 1.1's gradient);
  // the focus must lie inside the circle.
  Vec2 centre{0, 0}, focus{0, 0};
  double radius = 1.0;
  // Outline units (the coordinates of the DrawBatch drawn) to the
  // gradient's coordinates. Projective maps are allowed.
  Transform from_outline;
};

// Stops a gradient may have: they are uniforms of the composite shader
// (GLES 2 guarantees few uniform vectors).
inline constexpr int kMaxGradientStops = 16;

// Throws Error(InvalidArgument) naming the problem: no stops or more than
// kMaxGradientStops, an offset out of [0, 1] or below the previous one, a
// non-finite value, start == end, a radius that is not positive, a focus
// not strictly inside the circle, or a transform that is singular or not finite.
CURVETEXT_API void validate_gradient(const Gradient& gradient);

}  // namespace curvetext
