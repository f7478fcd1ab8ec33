// How a path is stroked, as SVG 2 and Canvas define it: width and its unit,
// joins, miter limit, caps and dashes. A plain value type (copyable, no
// invariants enforced while building it); stroke.hpp turns a path and a
// style into the outline of the stroke region. Thread-safe (a value).
#pragma once

#include <vector>

namespace curvetext {

// SVG stroke-linejoin. Miter falls back to Bevel past the miter limit;
// MiterClip clips the miter at miter_limit * width / 2 from the join point;
// Arcs extends the two outer edges as circles of their curvature where they
// end (SVG 2), falling back to MiterClip where those circles do not meet or
// meet beyond the miter limit.
enum class LineJoin { Miter, MiterClip, Round, Bevel, Arcs };

// SVG stroke-linecap, at both ends of every open subpath and every dash.
enum class LineCap { Butt, Round, Square };

// What StrokeStyle::width is measured in.
//  - User: the path's own units, scaled with it by every transform.
//  - Device: device pixels, whatever the transform (SVG's
//    `vector-effect: non-scaling-stroke`); the stroke is built for the scale
//    it is drawn at (stroke.hpp).
//  - Hairline: one device pixel at any zoom; `width` is ignored.
enum class StrokeWidthUnit { User, Device, Hairline };

struct StrokeStyle {
  // Full width of the stroke (w; the region reaches w / 2 on each side), in
  // `width_unit`. A width <= 0 strokes nothing (SVG: a negative width is an
  // error in the document, which draws no stroke).
  double width = 1.0;
  StrokeWidthUnit width_unit = StrokeWidthUnit::User;
  LineJoin join = LineJoin::Miter;
  // Largest ratio of miter length to width (SVG stroke-miterlimit; values
  // below 1 are read as 1).
  double miter_limit = 4.0;
  LineCap cap = LineCap::Butt;
  // Lengths of dashes and gaps, alternating, starting with a dash, in the
  // path's units (after path_length scaling). An odd count is repeated to
  // make it even (SVG). Empty, or any negative value, or a sum of 0: the
  // path is drawn solid (SVG's rule for an invalid dash array).
  std::vector<double> dashes;
  // Distance into the dash pattern at the start of each subpath (SVG
  // stroke-dashoffset; negative values and values past the pattern's length
  // wrap around).
  double dash_offset = 0.0;
  // The author's length of the whole path (SVG pathLength): > 0 scales every
  // dash length and the dash offset by (true length / path_length); 0: none.
  double path_length = 0.0;
};

}  // namespace curvetext
