// SVG's linearGradient and radialGradient as Gradient paint (paint.hpp):
// attributes and stops through href, gradientUnits (the element's bounding
// box or user space), gradientTransform and spreadMethod, mapped into the
// document's coordinates.
#include <algorithm>
#include <cmath>
#include <string>

#include "curvetext/error.hpp"
#include "svg_reader.hpp"

namespace curvetext::svg {

namespace {

constexpr int kMaxHrefChain = 32;

[[noreturn]] void fail(const XmlElement& e, const std::string& message) {
  throw Error(ErrorCode::InvalidArgument, "SVG: " + position(e) + message);
}

// The gradient referenced by `e`'s href, if it is one.
const XmlElement* next_gradient(const GradientSource& s, const XmlElement& e) {
  const std::string* href = e.find("href");
  if (!href) href = e.find("xlink:href");
  if (!href) return nullptr;
  const XmlElement* next = s.reference(e, *href);
  if (!next || (next->name != "linearGradient" && next->name != "radialGradient")) return nullptr;
  return next;
}

// An attribute of the gradient or of those its href chain names.
const std::string* attribute(const GradientSource& s, std::size_t g, const char* name) {
  const XmlElement* e = &s.doc.elements[g];
  for (int hop = 0; e && hop <= kMaxHrefChain; ++hop, e = next_gradient(s, *e))
    if (const std::string* v = e->find(name)) return v;
  return nullptr;
}

double number_in(const XmlElement& e, const std::string& text, Axis axis, const Viewport& vp) {
  const std::optional<double> v = parse_length(text, axis, vp);
  if (!v) fail(e, "gradient attribute '" + text + "' is not a length");
  return *v;
}

Transform to_transform(const Affine& a) { return Transform{{a.a, a.c, a.e, a.b, a.d, a.f, 0.0, 0.0, 1.0}}; }

double stop_offset(const XmlElement& stop) {
  const std::string* o = stop.find("offset");
  if (!o) return 0.0;
  std::string t = trim(*o);
  const bool percent = !t.empty() && t.back() == '%';
  if (percent) t.pop_back();
  char* end = nullptr;
  const double v = std::strtod(t.c_str(), &end);
  if (t.empty() || *end != '\0' || !std::isfinite(v)) fail(stop, "stop offset '" + *o + "' is not a number");
  return std::clamp(percent ? v / 100.0 : v, 0.0, 1.0);
}

// Golden-section search for the extreme of f on [a, b].
double extreme(const std::function<double(double)>& f, double a, double b, bool largest) {
  const double k = 0.5 * (std::sqrt(5.0) - 1.0);
  auto better = [&](double u, double v) { return largest ? f(u) > f(v) : f(u) < f(v); };
  double c = b - k * (b - a), d = a + k * (b - a);
  for (int i = 0; i < 80; ++i) {
    if (better(c, d))
      b = d;
    else
      a = c;
    c = b - k * (b - a);
    d = a + k * (b - a);
  }
  return f(0.5 * (a + b));
}

}  // namespace

Box tight_box(const std::vector<ShapeContour>& contours) {
  Box box;
  constexpr int kSamples = 32;
  for (const ShapeContour& c : contours)
    for (const RationalBezier& piece : c.pieces) {
      box.add(piece.points.front());
      box.add(piece.points.back());
      if (piece.degree() < 2) continue;
      for (int axis = 0; axis < 2; ++axis) {
        const auto f = [&](double t) { return axis == 0 ? evaluate(piece, t).x : evaluate(piece, t).y; };
        for (int i = 1; i < kSamples; ++i) {
          const double a = (i - 1.0) / kSamples, b = (i + 1.0) / kSamples;
          for (bool largest : {false, true}) {
            const double v = extreme(f, a, b, largest);
            box.add(axis == 0 ? Vec2{v, piece.points.front().y} : Vec2{piece.points.front().x, v});
          }
        }
      }
    }
  return box;
}

std::vector<GradientStop> gradient_stops(const GradientSource& s, std::size_t g) {
  const XmlElement* holder = &s.doc.elements[g];
  for (int hop = 0; hop < kMaxHrefChain; ++hop) {
    const bool has_stops = std::any_of(holder->children.begin(), holder->children.end(),
                                       [&](std::size_t c) { return s.doc.elements[c].name == "stop"; });
    const XmlElement* next = has_stops ? nullptr : next_gradient(s, *holder);
    if (!next) break;
    holder = next;
  }
  const std::size_t h = static_cast<std::size_t>(holder - s.doc.elements.data());
  const Computed gradient_style = compute(initial_style(s.initial_color), s.specified[h]);
  std::vector<GradientStop> stops;
  double previous = 0.0;
  for (std::size_t c : holder->children) {
    const XmlElement& stop = s.doc.elements[c];
    if (stop.name != "stop") continue;
    const Computed st = compute(gradient_style, s.specified[c]);
    const bool current = lower(st[kStopColor]) == "currentcolor";
    Color k = s.color_value(stop, current ? st[kColor] : st[kStopColor]);
    const std::optional<double> opacity = parse_length(st[kStopOpacity], Axis::X, Viewport{1.0, 1.0});
    if (!opacity) fail(stop, "stop-opacity '" + st[kStopOpacity] + "' is not a number");
    k.a *= static_cast<float>(std::clamp(*opacity, 0.0, 1.0));
    previous = std::max(previous, stop_offset(stop));
    stops.push_back({static_cast<float>(previous), k});
  }
  return stops;
}

std::optional<Gradient> make_gradient(const GradientSource& s, std::size_t g, const XmlElement& at,
                                      const std::vector<ShapeContour>& user, const Affine& m, const Viewport& vp,
                                      std::vector<GradientStop> stops) {
  const XmlElement& e = s.doc.elements[g];
  const std::string* units = attribute(s, g, "gradientUnits");
  const bool box_units = !units || trim(*units) != "userSpaceOnUse";
  Affine to_user;
  Viewport unit_vp = vp;
  if (box_units) {
    const Box b = tight_box(user);
    if (!(b.max.x > b.min.x) || !(b.max.y > b.min.y)) return std::nullopt;  // SVG: not rendered
    to_user = Affine::translate(b.min.x, b.min.y) * Affine::scale(b.max.x - b.min.x, b.max.y - b.min.y);
    unit_vp = {1.0, 1.0};
  }
  if (const std::string* t = attribute(s, g, "gradientTransform")) to_user = to_user * parse_transform(*t, position(e));
  auto value = [&](const char* name, Axis axis, const char* fallback) {
    const std::string* v = attribute(s, g, name);
    return number_in(e, v ? *v : fallback, axis, unit_vp);
  };
  Gradient out;
  const std::string* spread = attribute(s, g, "spreadMethod");
  const std::string sp = spread ? trim(*spread) : "pad";
  out.spread = sp == "reflect"  ? Gradient::Spread::Reflect
               : sp == "repeat" ? Gradient::Spread::Repeat
                                : Gradient::Spread::Pad;
  bool collapsed = false;
  if (e.name == "linearGradient") {
    out.start = {value("x1", Axis::X, "0%"), value("y1", Axis::Y, "0%")};
    out.end = {value("x2", Axis::X, "100%"), value("y2", Axis::Y, "0%")};
    collapsed = out.start == out.end;
  } else {
    out.kind = Gradient::Kind::Radial;
    out.centre = {value("cx", Axis::X, "50%"), value("cy", Axis::Y, "50%")};
    out.radius = value("r", Axis::Other, "50%");
    const std::string* fx = attribute(s, g, "fx");
    const std::string* fy = attribute(s, g, "fy");
    out.focus = {fx ? number_in(e, *fx, Axis::X, unit_vp) : out.centre.x,
                 fy ? number_in(e, *fy, Axis::Y, unit_vp) : out.centre.y};
    // SVG 2's focal radius: t = 0 on the circle (fx, fy, fr).
    if (const std::string* fr = attribute(s, g, "fr")) out.focal_radius = number_in(e, *fr, Axis::Other, unit_vp);
    if (!(out.focal_radius >= 0.0)) fail(at, "the radialGradient's fr is negative");
    collapsed = !(out.radius > 0.0);
    if (!collapsed && !(length(out.focus - out.centre) < out.radius))
      fail(at, "the radialGradient's focal point lies outside its circle, which is not supported");
    if (!collapsed && !(length(out.focus - out.centre) + out.focal_radius < out.radius))
      fail(at, "the radialGradient's focal circle (fr) reaches outside its circle, which is not supported");
  }
  if (collapsed) {  // SVG: the area is painted with the last stop
    out = Gradient{};
    stops = {stops.back()};
  }
  out.stops = std::move(stops);
  const Affine to_document = m * to_user;
  if (!(std::abs(to_document.determinant()) > 0.0)) return std::nullopt;
  out.from_outline = to_transform(to_document.inverse());
  try {
    validate_gradient(out);
  } catch (const Error& err) {
    fail(at, err.what());
  }
  return out;
}

}  // namespace curvetext::svg
