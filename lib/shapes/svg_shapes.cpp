// SVG's basic shapes as contours in user space: rectangles (rounded corners
// are quarter ellipses), circles and ellipses as four exact conics each (a
// quarter of the unit circle is the conic with weight sqrt(2)/2 through the
// corner of its box; affine images keep the weight), lines, polylines and
// polygons; path elements through parse_svg_path.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numbers>

#include "curvetext/error.hpp"
#include "curvetext/shapes.hpp"
#include "svg_reader.hpp"

namespace curvetext::svg {

namespace {

constexpr double kQuarterWeight = std::numbers::sqrt2 / 2.0;

double length_attribute(const XmlElement& e, const char* name, Axis axis, const Viewport& vp, double fallback) {
  const std::string* v = e.find(name);
  if (!v || trim(*v).empty() || trim(*v) == "auto") return fallback;
  const std::optional<double> l = parse_length(*v, axis, vp);
  if (!l)
    throw Error(ErrorCode::InvalidArgument,
                "SVG: " + position(e) + "<" + e.name + "> " + name + " '" + *v + "' is not a length");
  return *l;
}

// The closed contour of an ellipse's quarters, from (cx + rx, cy) through
// (cx, cy + ry) (SVG 2's start and direction), as conics.
ShapeContour ellipse(double cx, double cy, double rx, double ry) {
  ShapeContour c;
  const Vec2 p[4] = {{cx + rx, cy}, {cx, cy + ry}, {cx - rx, cy}, {cx, cy - ry}};
  for (int i = 0; i < 4; ++i) {
    const Vec2 a = p[i], b = p[(i + 1) % 4];
    const Vec2 corner = i % 2 == 0 ? Vec2{a.x, b.y} : Vec2{b.x, a.y};
    c.pieces.push_back(RationalBezier::conic(a, corner, b, kQuarterWeight));
  }
  return c;
}

ShapeContour rect(double x, double y, double w, double h, double rx, double ry) {
  ShapeContour c;
  if (rx <= 0.0 || ry <= 0.0) {
    const Vec2 p[4] = {{x, y}, {x + w, y}, {x + w, y + h}, {x, y + h}};
    for (int i = 0; i < 4; ++i) c.pieces.push_back(RationalBezier::line(p[i], p[(i + 1) % 4]));
    return c;
  }
  auto side = [&](Vec2 a, Vec2 b) {
    if (a.x != b.x || a.y != b.y) c.pieces.push_back(RationalBezier::line(a, b));
  };
  auto corner = [&](Vec2 a, Vec2 k, Vec2 b) { c.pieces.push_back(RationalBezier::conic(a, k, b, kQuarterWeight)); };
  side({x + rx, y}, {x + w - rx, y});
  corner({x + w - rx, y}, {x + w, y}, {x + w, y + ry});
  side({x + w, y + ry}, {x + w, y + h - ry});
  corner({x + w, y + h - ry}, {x + w, y + h}, {x + w - rx, y + h});
  side({x + w - rx, y + h}, {x + rx, y + h});
  corner({x + rx, y + h}, {x, y + h}, {x, y + h - ry});
  side({x, y + h - ry}, {x, y + ry});
  corner({x, y + ry}, {x, y}, {x + rx, y});
  return c;
}

// polyline/polygon points: pairs of numbers; an odd last number is dropped
// (SVG renders up to the error).
std::vector<Vec2> points(const XmlElement& e) {
  std::vector<Vec2> out;
  const std::string* text = e.find("points");
  if (!text) return out;
  std::vector<double> v;
  std::size_t i = 0;
  const std::string& s = *text;
  while (i < s.size()) {
    while (i < s.size() && (s[i] == ' ' || s[i] == ',' || s[i] == '\t' || s[i] == '\n' || s[i] == '\r')) ++i;
    if (i >= s.size()) break;
    char* end = nullptr;
    const double x = std::strtod(s.c_str() + i, &end);
    if (end == s.c_str() + i || !std::isfinite(x)) break;
    v.push_back(x);
    i = static_cast<std::size_t>(end - s.c_str());
  }
  for (std::size_t k = 0; k + 1 < v.size(); k += 2) out.push_back({v[k], v[k + 1]});
  return out;
}

std::vector<ShapeContour> poly(const XmlElement& e) {
  const std::vector<Vec2> p = points(e);
  if (p.size() < 2) return {};
  ShapeContour c;
  c.closed = e.name == "polygon";
  for (std::size_t i = 0; i + 1 < p.size(); ++i) c.pieces.push_back(RationalBezier::line(p[i], p[i + 1]));
  return {c};
}

}  // namespace

std::vector<ShapeContour> element_geometry(const XmlElement& e, const Viewport& vp) {
  auto len = [&](const char* name, Axis axis, double fallback = 0.0) {
    return length_attribute(e, name, axis, vp, fallback);
  };
  if (e.name == "path") {
    const std::string* d = e.find("d");
    if (!d) return {};
    try {
      return parse_svg_path(*d);
    } catch (const Error& err) {
      throw Error(err.code(), "SVG: " + position(e) + err.what());
    }
  }
  if (e.name == "rect") {
    const double w = len("width", Axis::X), h = len("height", Axis::Y);
    if (!(w > 0.0) || !(h > 0.0)) return {};
    double rx = len("rx", Axis::X, -1.0), ry = len("ry", Axis::Y, -1.0);
    if (rx < 0.0) rx = ry;
    if (ry < 0.0) ry = rx;
    rx = std::clamp(rx, 0.0, w / 2.0);
    ry = std::clamp(ry, 0.0, h / 2.0);
    return {rect(len("x", Axis::X), len("y", Axis::Y), w, h, rx, ry)};
  }
  if (e.name == "circle") {
    const double r = len("r", Axis::Other);
    if (!(r > 0.0)) return {};
    return {ellipse(len("cx", Axis::X), len("cy", Axis::Y), r, r)};
  }
  if (e.name == "ellipse") {
    double rx = len("rx", Axis::X, -1.0), ry = len("ry", Axis::Y, -1.0);
    if (rx < 0.0) rx = ry;
    if (ry < 0.0) ry = rx;
    if (!(rx > 0.0) || !(ry > 0.0)) return {};
    return {ellipse(len("cx", Axis::X), len("cy", Axis::Y), rx, ry)};
  }
  if (e.name == "line") {
    ShapeContour c;
    c.closed = false;
    c.pieces.push_back(
        RationalBezier::line({len("x1", Axis::X), len("y1", Axis::Y)}, {len("x2", Axis::X), len("y2", Axis::Y)}));
    return {c};
  }
  if (e.name == "polyline" || e.name == "polygon") return poly(e);
  return {};
}

bool is_shape_element(const std::string& name) {
  return name == "path" || name == "rect" || name == "circle" || name == "ellipse" || name == "line" ||
         name == "polyline" || name == "polygon";
}

}  // namespace curvetext::svg
