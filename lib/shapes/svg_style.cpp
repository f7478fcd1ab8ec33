// Transforms, lengths, viewBox, and the cascade (svg_style.hpp).
#include "svg_style.hpp"

#include <charconv>
#include <cmath>
#include <numbers>

#include "curvetext/error.hpp"

namespace curvetext::svg {

namespace {

[[noreturn]] void fail(const std::string& where, const std::string& message) {
  throw Error(ErrorCode::InvalidArgument, "SVG: " + where + message);
}

bool separator(char c) { return c == ' ' || c == ',' || c == '\t' || c == '\n' || c == '\r'; }

// Numbers separated by commas or spaces: every one, or nullopt.
std::optional<std::vector<double>> numbers(std::string_view s) {
  std::vector<double> out;
  std::size_t i = 0;
  for (;;) {
    while (i < s.size() && separator(s[i])) ++i;
    if (i >= s.size()) return out;
    if (s[i] == '+') ++i;
    double v = 0.0;
    const auto [p, ec] = std::from_chars(s.data() + i, s.data() + s.size(), v);
    if (ec != std::errc() || !std::isfinite(v)) return std::nullopt;
    out.push_back(v);
    i = static_cast<std::size_t>(p - s.data());
  }
}

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

struct PropInfo {
  const char* name;
  const char* initial;
};

constexpr PropInfo kProps[kPropCount] = {
    {"fill", "black"},
    {"fill-rule", "nonzero"},
    {"fill-opacity", "1"},
    {"stroke", "none"},
    {"stroke-width", "1"},
    {"stroke-linecap", "butt"},
    {"stroke-linejoin", "miter"},
    {"stroke-miterlimit", "4"},
    {"stroke-dasharray", "none"},
    {"stroke-dashoffset", "0"},
    {"stroke-opacity", "1"},
    {"color", "black"},
    {"visibility", "visible"},
    {"clip-rule", "nonzero"},
    {"marker-start", "none"},
    {"marker-mid", "none"},
    {"marker-end", "none"},
    {"paint-order", "normal"},
    {"opacity", "1"},
    {"display", "inline"},
    {"clip-path", "none"},
    {"mask", "none"},
    {"filter", "none"},
    {"stop-color", "black"},
    {"stop-opacity", "1"},
    {"vector-effect", "none"},
    {"mix-blend-mode", "normal"},
    {"transform", "none"},
    {"overflow", "visible"},
};

int find_prop(std::string_view name) {
  for (int i = 0; i < kPropCount; ++i)
    if (name == kProps[i].name) return i;
  return -1;
}

// Cascade rank: important, origin (attribute 0, sheet 1, style 2),
// specificity, order.
struct Rank {
  bool important = false;
  int origin = 0;
  int specificity = 0;
  std::size_t order = 0;
  bool operator<(const Rank& o) const {
    if (important != o.important) return !important;
    if (important && origin != o.origin) return origin < o.origin;
    if (origin != o.origin) return origin < o.origin;
    if (specificity != o.specificity) return specificity < o.specificity;
    return order < o.order;
  }
};

void declare(Specified& s, std::array<Rank, kPropCount>& ranks, const Declaration& d, Rank rank) {
  std::vector<int> props;
  if (d.property == "marker") {
    props = {kMarkerStart, kMarkerMid, kMarkerEnd};
  } else if (const int p = find_prop(d.property); p >= 0) {
    // transform is an attribute of its own, not a presentation attribute here.
    if (!(p == kTransformProperty && rank.origin == 0)) props = {p};
  }
  for (int p : props) {
    if (s[p] && rank < ranks[p]) continue;
    s[p] = d.value;
    ranks[p] = rank;
  }
}

std::vector<Rule> sheets(const XmlDocument& doc) {
  std::vector<Rule> rules;
  for (const XmlElement& e : doc.elements) {
    if (e.name != "style") continue;
    if (const std::string* type = e.find("type"); type && !type->empty() && lower(trim(*type)) != "text/css")
      continue;  // not CSS: SVG says such a sheet is not applied
    parse_style_sheet(e.text, position(e), rules);
  }
  return rules;
}

// Work bound of the cascade: elements times rules.
constexpr double kMaxCascadeWork = 2e7;

}  // namespace

Affine parse_transform(std::string_view text, const std::string& where) {
  Affine m;
  std::size_t i = 0;
  for (;;) {
    while (i < text.size() && separator(text[i])) ++i;
    if (i >= text.size()) return m;
    const std::size_t open = text.find('(', i), close = text.find(')', i);
    if (open == std::string_view::npos || close == std::string_view::npos || close < open)
      fail(where, "transform '" + std::string(text) + "' is malformed");
    const std::string name = trim(text.substr(i, open - i));
    const auto v = numbers(text.substr(open + 1, close - open - 1));
    i = close + 1;
    const std::size_t n = v ? v->size() : 0;
    auto need = [&](bool ok) {
      if (!v || !ok) fail(where, "transform function " + name + " has bad arguments in '" + std::string(text) + "'");
    };
    Affine t;
    if (name == "matrix") {
      need(n == 6);
      t = {(*v)[0], (*v)[1], (*v)[2], (*v)[3], (*v)[4], (*v)[5]};
    } else if (name == "translate") {
      need(n == 1 || n == 2);
      t = Affine::translate((*v)[0], n == 2 ? (*v)[1] : 0.0);
    } else if (name == "scale") {
      need(n == 1 || n == 2);
      t = Affine::scale((*v)[0], n == 2 ? (*v)[1] : (*v)[0]);
    } else if (name == "rotate") {
      need(n == 1 || n == 3);
      const double r = radians((*v)[0]), c = std::cos(r), s = std::sin(r);
      t = {c, s, -s, c, 0, 0};
      if (n == 3) t = Affine::translate((*v)[1], (*v)[2]) * t * Affine::translate(-(*v)[1], -(*v)[2]);
    } else if (name == "skewX") {
      need(n == 1);
      t = {1, 0, std::tan(radians((*v)[0])), 1, 0, 0};
    } else if (name == "skewY") {
      need(n == 1);
      t = {1, std::tan(radians((*v)[0])), 0, 1, 0, 0};
    } else {
      fail(where, "transform function '" + name + "' is not supported");
    }
    m = m * t;
  }
}

std::optional<double> parse_length(std::string_view text, Axis axis, const Viewport& viewport) {
  std::string s = trim(text);
  if (!s.empty() && s.front() == '+') s.erase(0, 1);
  double v = 0.0;
  const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (s.empty() || ec != std::errc() || !std::isfinite(v)) return std::nullopt;
  const std::string unit = lower(std::string_view(s).substr(static_cast<std::size_t>(p - s.data())));
  if (unit.empty() || unit == "px") return v;
  if (unit == "pt") return v * 96.0 / 72.0;
  if (unit == "pc") return v * 16.0;
  if (unit == "mm") return v * 96.0 / 25.4;
  if (unit == "cm") return v * 96.0 / 2.54;
  if (unit == "in") return v * 96.0;
  if (unit == "em") return v * 16.0;  // font-size: medium
  if (unit == "ex") return v * 8.0;
  if (unit == "%") {
    const double ref = axis == Axis::X ? viewport.width
                       : axis == Axis::Y
                           ? viewport.height
                           : std::sqrt(0.5 * (viewport.width * viewport.width + viewport.height * viewport.height));
    return v / 100.0 * ref;
  }
  return std::nullopt;
}

Affine view_box_transform(const std::array<double, 4>& box, std::string_view aspect, double x, double y, double width,
                          double height, const std::string& where) {
  std::string a = trim(aspect);
  if (a.starts_with("defer")) a = trim(std::string_view(a).substr(5));
  std::string align = a.substr(0, a.find(' '));
  const std::string mode = a.find(' ') == std::string::npos ? "meet" : trim(std::string_view(a).substr(a.find(' ')));
  if (align.empty()) align = "xMidYMid";
  double sx = width / box[2], sy = height / box[3];
  if (align != "none") {
    if (align.size() != 8 || align[0] != 'x' || align[4] != 'Y' || (mode != "meet" && mode != "slice"))
      fail(where, "preserveAspectRatio '" + std::string(aspect) + "' is malformed");
    sx = sy = mode == "meet" ? std::min(sx, sy) : std::max(sx, sy);
  }
  auto offset = [&](std::string_view part, double room) {
    if (part == "Min") return 0.0;
    if (part == "Mid") return 0.5 * room;
    if (part == "Max") return room;
    fail(where, "preserveAspectRatio '" + std::string(aspect) + "' is malformed");
  };
  const bool none = align == "none";
  const double tx = x - box[0] * sx + (none ? 0.0 : offset(std::string_view(align).substr(1, 3), width - box[2] * sx));
  const double ty = y - box[1] * sy + (none ? 0.0 : offset(std::string_view(align).substr(5, 3), height - box[3] * sy));
  return {sx, 0, 0, sy, tx, ty};
}

std::optional<std::array<double, 4>> parse_view_box(const XmlElement& e) {
  const std::string* vb = e.find("viewBox");
  if (!vb) return std::nullopt;
  const auto v = numbers(*vb);
  if (!v || v->size() != 4) fail(position(e), "viewBox '" + *vb + "' is not four numbers");
  if (!((*v)[2] > 0 && (*v)[3] > 0)) fail(position(e), "viewBox '" + *vb + "' needs a positive width and height");
  return std::array<double, 4>{(*v)[0], (*v)[1], (*v)[2], (*v)[3]};
}

const char* prop_name(int prop) { return kProps[prop].name; }

Computed initial_style(const std::string& color) {
  Computed c;
  for (int i = 0; i < kPropCount; ++i) c[i] = kProps[i].initial;
  c[kColor] = color;
  return c;
}

Computed compute(const Computed& parent, const Specified& own) {
  Computed c;
  for (int i = 0; i < kPropCount; ++i) {
    const bool inherited = i < kFirstNotInherited;
    if (own[i] && *own[i] == "inherit")
      c[i] = parent[i];
    else if (own[i] && *own[i] != "initial" && *own[i] != "unset")
      c[i] = *own[i];
    else if (own[i] && *own[i] == "initial")
      c[i] = i == kColor ? parent[i] : kProps[i].initial;
    else
      c[i] = inherited ? parent[i] : kProps[i].initial;
  }
  return c;
}

std::vector<Specified> cascade(const XmlDocument& doc) {
  const std::vector<Rule> rules = sheets(doc);
  if (static_cast<double>(rules.size()) * static_cast<double>(doc.elements.size()) > kMaxCascadeWork)
    throw Error(ErrorCode::InvalidArgument, "SVG: " + std::to_string(rules.size()) + " style rules for " +
                                                std::to_string(doc.elements.size()) + " elements is too much work");
  std::vector<Specified> out(doc.elements.size());
  std::size_t steps = 0;  // of all matching, bounded (svg_css.hpp)
  for (std::size_t i = 0; i < doc.elements.size(); ++i) {
    const XmlElement& e = doc.elements[i];
    std::array<Rank, kPropCount> ranks{};
    for (const auto& [key, value] : e.attributes) declare(out[i], ranks, {key, trim(value), false}, {false, 0, 0, 0});
    for (const Rule& r : rules)
      if (matches(r.selector, doc, i, steps))
        for (const Declaration& d : r.declarations)
          declare(out[i], ranks, d, {d.important, 1, r.selector.specificity, r.order});
    if (const std::string* style = e.find("style"))
      for (const Declaration& d : parse_declarations(*style)) declare(out[i], ranks, d, {d.important, 2, 0, 0});
  }
  return out;
}

}  // namespace curvetext::svg
