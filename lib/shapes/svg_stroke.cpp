// SVG stroke properties as a StrokeStyle (stroke_style.hpp) in document
// units.
#include <cmath>
#include <string>

#include "curvetext/error.hpp"
#include "svg_reader.hpp"

namespace curvetext::svg {

namespace {

[[noreturn]] void fail(const XmlElement& e, const std::string& message) {
  throw Error(ErrorCode::InvalidArgument, "SVG: " + position(e) + message);
}

// The scale of a similarity (rotation, mirror, uniform scale, translation);
// nullopt for any other map.
std::optional<double> similarity_scale(const Affine& m) {
  const double sx = std::hypot(m.a, m.b), sy = std::hypot(m.c, m.d);
  const double dot = m.a * m.c + m.b * m.d;
  if (!(std::abs(sx - sy) <= 1e-9 * std::max(sx, sy)) || !(std::abs(dot) <= 1e-9 * sx * sy)) return std::nullopt;
  return sx;
}

double length_value(const XmlElement& e, const char* what, const std::string& text, const Viewport& vp) {
  const std::optional<double> v = parse_length(text, Axis::Other, vp);
  if (!v) fail(e, std::string(what) + " '" + text + "' is not a length");
  return *v;
}

std::vector<double> dash_array(const XmlElement& e, const std::string& text, const Viewport& vp) {
  std::vector<double> out;
  if (trim(text) == "none") return out;
  std::string s = text;
  for (char& c : s)
    if (c == ',') c = ' ';
  std::size_t i = 0;
  while (i < s.size()) {
    while (i < s.size() && (s[i] == ' ' || s[i] == '\t' || s[i] == '\n' || s[i] == '\r')) ++i;
    if (i >= s.size()) break;
    std::size_t j = i;
    while (j < s.size() && !(s[j] == ' ' || s[j] == '\t' || s[j] == '\n' || s[j] == '\r')) ++j;
    out.push_back(length_value(e, "stroke-dasharray", s.substr(i, j - i), vp));
    i = j;
  }
  return out;
}

}  // namespace

std::optional<ShapeStroke> stroke_style(const XmlElement& e, const Computed& style, const Affine& m,
                                        const Viewport& vp) {
  StrokeStyle st;
  st.width = length_value(e, "stroke-width", style[kStrokeWidth], vp);
  if (!(st.width > 0.0)) return std::nullopt;
  const std::string& join = style[kStrokeLinejoin];
  if (join == "miter")
    st.join = LineJoin::Miter;
  else if (join == "miter-clip")
    st.join = LineJoin::MiterClip;
  else if (join == "round")
    st.join = LineJoin::Round;
  else if (join == "bevel")
    st.join = LineJoin::Bevel;
  else if (join == "arcs")
    st.join = LineJoin::Arcs;
  else
    fail(e, "stroke-linejoin '" + join + "' is not one of miter, miter-clip, round, bevel, arcs");
  const std::string& cap = style[kStrokeLinecap];
  if (cap == "butt")
    st.cap = LineCap::Butt;
  else if (cap == "round")
    st.cap = LineCap::Round;
  else if (cap == "square")
    st.cap = LineCap::Square;
  else
    fail(e, "stroke-linecap '" + cap + "' is not one of butt, round, square");
  char* end = nullptr;
  st.miter_limit = std::strtod(style[kStrokeMiterlimit].c_str(), &end);
  if (*end != '\0' || !std::isfinite(st.miter_limit))
    fail(e, "stroke-miterlimit '" + style[kStrokeMiterlimit] + "' is not a number");
  st.dashes = dash_array(e, style[kStrokeDasharray], vp);
  st.dash_offset = length_value(e, "stroke-dashoffset", style[kStrokeDashoffset], vp);
  if (const std::string* pl = e.find("pathLength")) {
    st.path_length = std::strtod(pl->c_str(), &end);
    if (*end != '\0' || !std::isfinite(st.path_length) || st.path_length < 0.0)
      fail(e, "pathLength '" + *pl + "' is not a non-negative number");
  }
  if (style[kVectorEffect] == "non-scaling-stroke") {
    // Device pixels of the root viewport as drawn (SVG's host coordinates).
    if (!st.dashes.empty()) fail(e, "dashes with vector-effect: non-scaling-stroke are not supported");
    st.width_unit = StrokeWidthUnit::Device;
    ShapeStroke out;
    out.style = st;
    return out;
  }
  if (style[kVectorEffect] != "none") fail(e, "vector-effect '" + style[kVectorEffect] + "' is not supported");
  const std::optional<double> scale = similarity_scale(m);
  if (!scale) {
    // SVG strokes in user space: built there and mapped (stroke_outline_mapped).
    ShapeStroke out;
    out.style = st;
    out.user_to_document.m = {m.a, m.c, m.e, m.b, m.d, m.f, 0.0, 0.0, 1.0};
    return out;
  }
  st.width *= *scale;
  for (double& d : st.dashes) d *= *scale;
  st.dash_offset *= *scale;
  st.path_length *= *scale;
  ShapeStroke out;
  out.style = st;
  return out;
}

}  // namespace curvetext::svg
