// Private interface of shapes/ (the SVG reader's parts): the geometry of
// SVG's shape elements.
#pragma once

#include <string>
#include <vector>

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

}  // namespace curvetext::svg
