// Private interface of shapes/ (the SVG reader's parts): the geometry of
// SVG's shape elements.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "curvetext/paint.hpp"
#include "curvetext/stroke_style.hpp"

#include "curvetext/shapes.hpp"
#include "svg_style.hpp"
#include "svg_xml.hpp"

namespace curvetext::svg {

// path, rect, circle, ellipse, line, polyline, polygon.
bool is_shape_element(const std::string& name);

// The element's contours in its user space (empty when SVG says the element
// is not rendered: a rect of zero width, a circle of radius 0, ...). Open
// subpaths are returned as they are; a fill closes them. Throws
// Error(InvalidArgument) with the element's position for bad path data or
// lengths.
std::vector<ShapeContour> element_geometry(const XmlElement& e, const Viewport& viewport);

// What gradients need of the reader: the element tree with each element's
// specified style, #id references and colour values.
struct GradientSource {
  const XmlDocument& doc;
  const std::vector<Specified>& specified;
  std::function<const XmlElement*(const XmlElement& from, const std::string& href)> reference;
  std::function<Color(const XmlElement& at, const std::string& value)> color_value;
  std::string initial_color;  // the computed `color` at the root
};

// The stops of gradient element `g` (its own, else those of the gradient
// its href names, and so on): colours with stop-opacity, offsets clamped to
// [0, 1] and made non-decreasing, as SVG says.
std::vector<GradientStop> gradient_stops(const GradientSource& source, std::size_t g);

// The gradient `g` paints on an element whose contours (user space) are
// `user` and whose user space reaches the document through `m`, with
// percentages of viewport `vp`. nullopt where SVG says the paint draws
// nothing (a bounding box without width or height). A gradient that
// collapses to its last stop (start == end, radius 0) comes back with that
// stop only. Throws Error(InvalidArgument) with the element's position for
// what is not drawn (a focus outside the circle, too many stops).
std::optional<Gradient> make_gradient(const GradientSource& source, std::size_t g, const XmlElement& at,
                                      const std::vector<ShapeContour>& user, const Affine& m, const Viewport& vp,
                                      std::vector<GradientStop> stops);

// The element's stroke geometry from its computed style (stroke-width,
// -linejoin, -linecap, -miterlimit, -dasharray, -dashoffset, pathLength,
// vector-effect), its colour left to the caller: in document units
// (user-space lengths times the uniform scale of `m`) where `m` is a
// similarity; otherwise in user space with user_to_document set to `m`.
// nullopt when the width is 0 or less (no stroke). Throws
// Error(InvalidArgument) with the element's position for a malformed value.
std::optional<ShapeStroke> stroke_style(const XmlElement& e, const Computed& style, const Affine& m,
                                        const Viewport& vp);

// A vertex of a path where a marker goes, in the path's user space, and
// the angle (radians, from +x towards +y) that orient="auto" gives it; the
// directions in and out alone (each the other where it is missing).
struct MarkerVertex {
  Vec2 at;
  double angle = 0.0;
  double in_angle = 0.0, out_angle = 0.0;
};
// Every vertex of the contours in order (each piece's start, each
// subpath's end, and a closed subpath's closing vertex), oriented as SVG
// says: the bisector of the directions in and out; the direction out at an
// open subpath's start and in at its end; a closed subpath's first and last
// vertex bisect its closing segment and its first one.
std::vector<MarkerVertex> marker_vertices(const std::vector<ShapeContour>& contours);

// The tight bounding box of the contours (extremes of each piece found by
// sampling and refining to double precision).
Box tight_box(const std::vector<ShapeContour>& contours);

}  // namespace curvetext::svg
