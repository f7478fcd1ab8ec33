// Gradient paint: linear, radial and sweep gradients (SVG's and COLR's), evaluated
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
  enum class Kind { Linear, Radial, Sweep };
  // Beyond [0, 1]: the end colours (pad), mirrored (reflect) or repeated.
  enum class Spread { Pad, Reflect, Repeat };
  Kind kind = Kind::Linear;
  Spread spread = Spread::Pad;
  std::vector<GradientStop> stops;  // 1 to kMaxGradientStops
  // Linear: t is 0 at `start` and 1 at `end`, constant across the line.
  Vec2 start{0, 0}, end{1, 0};
  // Radial: t is 0 on the circle (focus, focal_radius) and 1 on the circle
  // (centre, radius); centre and radius move linearly with t, and a pixel
  // takes the largest t whose circle passes through it with a radius >= 0
  // (the two-point conical gradient of canvas and COLR). A pixel on no such
  // circle is transparent: where neither circle holds the other, outside
  // the cone they span. SVG 1.1's gradient is focal_radius 0 with the focus
  // inside the circle. Radii may be negative (a COLR colour line normalised
  // to [0, 1]): those circles are simply never drawn.
  Vec2 centre{0, 0}, focus{0, 0};
  double radius = 1.0, focal_radius = 0.0;
  // Sweep: around `centre`, t is 0 at start_angle and 1 at end_angle
  // (degrees from the +x axis towards +y of the gradient's coordinates:
  // counter-clockwise where y points up, as in font units), angles taken
  // in [0, 360).
  double start_angle = 0.0, end_angle = 360.0;
  // Outline units (the coordinates of the DrawBatch drawn) to the
  // gradient's coordinates. Projective maps are allowed.
  Transform from_outline;
};

// Stops a gradient may have: they are uniforms of the composite shader
// (GLES 2 guarantees few uniform vectors).
inline constexpr int kMaxGradientStops = 16;

// Throws Error(InvalidArgument) naming the problem: no stops or more than
// kMaxGradientStops, an offset out of [0, 1] or below the previous one, a
// non-finite value, start == end, a radial gradient whose two circles are
// one or whose radii are both below or at 0, a sweep with start_angle ==
// end_angle, or a transform that is singular or not finite.
CURVETEXT_API void validate_gradient(const Gradient& gradient);

}  // namespace curvetext
