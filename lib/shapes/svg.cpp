// The SVG document reader: the element tree (svg_xml), each element's
// computed style (svg_style's cascade and inheritance), and a walk from the
// root that turns every drawn shape element into a Shape in document space,
// through transforms, <use>, <symbol> and nested <svg>. What would change the
// picture and is not drawn is refused by name with its position; what SVG
// says does not draw (metadata, unknown and foreign elements, defs) is
// skipped. SVG's y axis points down; the document is mirrored to y-up
// (Outline's frame), which leaves both fill rules unchanged.
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <numbers>
#include <string>
#include <unordered_map>

#include "check.hpp"
#include "core/tolerances.hpp"
#include "curvetext/error.hpp"
#include "curvetext/shapes.hpp"
#include "svg_reader.hpp"

namespace curvetext {

namespace svg {
namespace {

[[noreturn]] void fail(const XmlElement& e, const std::string& message) {
  throw Error(ErrorCode::InvalidArgument, "SVG: " + position(e) + message);
}

// Elements that draw something this reader does not: refused by name.
bool refused_element(const std::string& name) {
  static const char* const kRefused[] = {"text",  "image",         "foreignObject",    "switch",      "video",
                                         "audio", "iframe",        "canvas",           "script",      "animate",
                                         "set",   "animateMotion", "animateTransform", "animateColor"};
  return std::any_of(std::begin(kRefused), std::end(kRefused), [&](const char* r) { return name == r; });
}

// Elements that never draw where they stand (only when referenced).
bool definition_element(const std::string& name) {
  static const char* const kDefs[] = {"defs",           "symbol",         "clipPath", "mask",      "pattern", "marker",
                                      "linearGradient", "radialGradient", "filter",   "style",     "title",   "desc",
                                      "metadata",       "cursor",         "font",     "font-face", "view"};
  return std::any_of(std::begin(kDefs), std::end(kDefs), [&](const char* r) { return name == r; });
}

// A number or percentage in [0, 1] (opacity, fill-opacity, stop-opacity).
double unit_value(const XmlElement& e, const char* what, const std::string& text) {
  std::string s = trim(text);
  const bool percent = !s.empty() && s.back() == '%';
  if (percent) s.pop_back();
  double v = 0.0;
  const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (s.empty() || ec != std::errc() || p != s.data() + s.size() || !std::isfinite(v))
    fail(e, std::string(what) + " '" + text + "' is not a number");
  return std::clamp(percent ? v / 100.0 : v, 0.0, 1.0);
}

// True when every point of the contour lies on the line through its first
// point and the point farthest from it (within tolerance::kConicFlatnessRelative
// of that distance): a fill of it covers nothing.
bool on_one_line(const ShapeContour& c) {
  const Vec2 origin = c.pieces.front().points.front();
  Vec2 far = origin;
  double far_length = 0.0;
  for (const RationalBezier& piece : c.pieces)
    for (Vec2 q : piece.points)
      if (const double l = length(q - origin); l > far_length) {
        far = q;
        far_length = l;
      }
  if (far_length == 0.0) return true;
  const Vec2 axis = (far - origin) / far_length;
  for (const RationalBezier& piece : c.pieces)
    for (Vec2 q : piece.points)
      if (std::abs(cross(axis, q - origin)) > tolerance::kConicFlatnessRelative * far_length) return false;
  return true;
}

void scale_alpha(Shape& s, float alpha) {
  s.color.a *= alpha;
  if (s.stroke) s.stroke->color.a *= alpha;
  for (std::optional<Gradient>* g : {&s.gradient, &s.stroke_gradient})
    if (*g)
      for (GradientStop& stop : (*g)->stops) stop.color.a *= alpha;
}

// Limits for fan-out: elements visited (through <use>, one element may be
// visited many times) and <use> nesting.
constexpr std::size_t kMaxVisits = 1000000;
constexpr std::size_t kMaxUseDepth = 64;

class Reader {
 public:
  Reader(const XmlDocument& doc, const SvgOptions& options) : doc_(doc), specified_(cascade(doc)), options_(options) {
    for (std::size_t i = 0; i < doc.elements.size(); ++i)
      if (const std::string* id = doc.elements[i].find("id")) ids_.emplace(*id, i);  // the first wins
  }

  ShapeDocument run();

 private:
  const XmlDocument& doc_;
  std::vector<Specified> specified_;
  SvgOptions options_;
  std::unordered_map<std::string, std::size_t> ids_;
  ShapeDocument out_;
  std::size_t segments_ = 0;
  std::size_t visits_ = 0;
  std::vector<std::size_t> use_stack_;

  void element(std::size_t i, const Computed& parent, const Affine& ctm, const Viewport& vp);
  void children(std::size_t i, const Computed& style, const Affine& ctm, const Viewport& vp);
  void layer(std::size_t i, const Computed& style, const Affine& ctm, const Viewport& vp, bool own_children);
  void use(std::size_t i, const Computed& style, const Affine& ctm, const Viewport& vp);
  void viewport_element(std::size_t i, const XmlElement& sizing, const Computed& style, const Affine& ctm,
                        const Viewport& vp);
  void shape(std::size_t i, const Computed& style, const Affine& ctm, const Viewport& vp);
  std::vector<ShapeContour> placed(const XmlElement& e, std::vector<ShapeContour> contours, const Affine& m,
                                   bool area_only);
  void check_unsupported(const XmlElement& e, const Computed& style) const;
  // A paint: none, a colour, or a gradient element (index > 0).
  struct PaintRef {
    std::optional<Color> color;
    std::size_t gradient = 0;
    bool none() const { return !color && gradient == 0; }
  };
  PaintRef paint(const XmlElement& e, const Computed& style, int prop) const;
  PaintRef gradient_paint(std::size_t g) const;
  GradientSource gradient_source() const;
  bool set_paint(Shape& s, const PaintRef& fill, const XmlElement& e, const std::vector<ShapeContour>& user,
                 const Affine& m, const Viewport& vp, double alpha) const;
  std::optional<Shape> fill_shape(const XmlElement& e, const Computed& style, const Affine& m, const Viewport& vp,
                                  const std::vector<ShapeContour>& contours);
  std::optional<Shape> stroke_shape(const XmlElement& e, const Computed& style, const Affine& m, const Viewport& vp,
                                    const std::vector<ShapeContour>& contours);
  const XmlElement* reference(const XmlElement& e, const std::string& href) const;
  bool inside(std::size_t first_shape, const Affine& ctm, double x, double y, double w, double h) const;
  void clip_to_viewport(std::size_t first, const Affine& m, double x, double y, double w, double h);
  void markers(const XmlElement& e, const Computed& style, const Affine& m, const Viewport& vp,
               const std::vector<ShapeContour>& contours);
  void marker(std::size_t k, const MarkerVertex& v, bool at_start, double stroke_width, const Affine& m,
              const Viewport& vp);
  std::vector<std::size_t> marker_stack_;
  Color color_value(const XmlElement& e, const std::string& value) const;
  void fade(std::size_t first_shape, double opacity);
  ShapeGroup& group(std::size_t first_shape);
  void clip(const XmlElement& e, const std::string& value, const Affine& m, const Viewport& vp,
            std::size_t first_shape);
  std::size_t clip_path_element(const XmlElement& e, const std::string& value) const;
  void clip_child(std::size_t c, const Computed& parent, const Affine& m, const Viewport& vp, std::vector<Shape>& out);
  Computed computed_at(std::size_t i) const;
  void drop_from(std::size_t first_shape);

  // Draws through `draw`, then applies the element's clip-path and opacity
  // to what it drew; `m` is the element's user space (clip-path's).
  template <class Draw>
  void with_opacity(const XmlElement& e, const Computed& style, const Affine& m, const Viewport& vp, Draw draw) {
    const double opacity = unit_value(e, "opacity", style[kOpacity]);
    const std::size_t first = out_.shapes.size();
    draw();
    if (style[kClipPath] != "none") clip(e, style[kClipPath], m, vp, first);
    fade(first, opacity);
  }
};

// The token standing for the caller's current colour among computed values.
constexpr const char* kCallerColor = "-curvetext-current-color";

ShapeDocument Reader::run() {
  const XmlElement& root = doc_.elements[0];
  if (root.name != "svg") fail(root, "the first element must be <svg>, got <" + root.name + ">");
  const auto box = parse_view_box(root);
  Viewport vp = box ? Viewport{(*box)[2], (*box)[3]} : Viewport{};
  auto side = [&](const char* name, Axis axis) -> double {
    const std::string* v = root.find(name);
    const std::string t = v ? trim(*v) : "";
    if (t.empty() || t.back() == '%' || t == "auto") return 0.0;  // from the viewBox, else the content
    const std::optional<double> l = parse_length(t, axis, vp);
    if (!l) fail(root, std::string(name) + " '" + *v + "' is not a length");
    if (!(*l > 0.0)) fail(root, "width/height must be positive, got '" + *v + "'");
    if (*l > 16384) fail(root, "width/height " + *v + " is larger than 16384 px");
    return *l;
  };
  double w = side("width", Axis::X), h = side("height", Axis::Y);
  Affine user;  // user space to the viewport, y down
  if (box) {
    if (w > 0.0 && h == 0.0) h = w * (*box)[3] / (*box)[2];
    if (h > 0.0 && w == 0.0) w = h * (*box)[2] / (*box)[3];
    if (w > 0.0) {
      const std::string* aspect = root.find("preserveAspectRatio");
      user = view_box_transform(*box, aspect ? *aspect : "", 0, 0, w, h, position(root));
    } else {
      user = Affine::translate(-(*box)[0], -(*box)[1]);
      w = (*box)[2];
      h = (*box)[3];
    }
  } else if (w > 0.0 && h > 0.0) {
    vp = {w, h};
  }
  if (box || (w > 0.0 && h > 0.0)) {
    out_.view.add({0, -h});
    out_.view.add({w, 0});
  }
  if (!box || root.find("width") || root.find("height")) {
    out_.width_px = w;
    out_.height_px = h;
  }
  const Affine mirror{1, 0, 0, -1, 0, 0};
  const Computed style = compute(initial_style(kCallerColor), specified_[0]);
  if (style[kDisplay] == "none") return std::move(out_);
  check_unsupported(root, style);
  with_opacity(root, style, mirror * user, vp, [&] { children(0, style, mirror * user, vp); });
  // Groups were made innermost first; drawn outer first (ShapeDocument::groups).
  std::reverse(out_.groups.begin(), out_.groups.end());
  std::stable_sort(out_.groups.begin(), out_.groups.end(), [](const ShapeGroup& a, const ShapeGroup& b) {
    return a.begin != b.begin ? a.begin < b.begin : a.end > b.end;
  });
  return std::move(out_);
}

void Reader::element(std::size_t i, const Computed& parent, const Affine& ctm, const Viewport& vp) {
  const XmlElement& e = doc_.elements[i];
  if (++visits_ > kMaxVisits) fail(e, "more than " + std::to_string(kMaxVisits) + " elements drawn (through <use>)");
  if (e.name.starts_with("{")) return;  // another namespace's element: not rendered
  if (refused_element(e.name)) fail(e, "<" + e.name + "> is not supported");
  if (definition_element(e.name)) return;
  if (e.name != "g" && e.name != "a" && e.name != "use" && e.name != "svg" && !is_shape_element(e.name))
    return;  // SVG: unknown elements are not rendered
  const Computed style = compute(parent, specified_[i]);
  if (style[kDisplay] == "none") return;
  Affine m = ctm;
  if (const std::string* t = e.find("transform")) m = ctm * parse_transform(*t, position(e));
  if (!(std::abs(m.determinant()) > 0.0) || !std::isfinite(m.determinant())) return;  // SVG: not rendered
  check_unsupported(e, style);
  if (e.name == "use") return use(i, style, m, vp);
  if (e.name == "svg") return viewport_element(i, e, style, m, vp);
  if (is_shape_element(e.name)) {
    for (std::size_t c : e.children)  // animation of the shape
      if (refused_element(doc_.elements[c].name))
        fail(doc_.elements[c], "<" + doc_.elements[c].name + "> is not supported");
    return shape(i, style, m, vp);
  }
  with_opacity(e, style, m, vp, [&] { children(i, style, m, vp); });
}

void Reader::children(std::size_t i, const Computed& style, const Affine& ctm, const Viewport& vp) {
  for (std::size_t c : doc_.elements[i].children) element(c, style, ctm, vp);
}

// Opacity on what one element drew: exact for one shape (its alpha); a
// group of several (or a shape's fill and stroke) is one layer composited
// at that opacity (ShapeGroup), so that they do not show through each other.
void Reader::fade(std::size_t first_shape, double opacity) {
  const std::size_t n = out_.shapes.size() - first_shape;
  if (opacity == 1.0 || n == 0) return;
  if (n == 1) return scale_alpha(out_.shapes.back(), static_cast<float>(opacity));
  group(first_shape).opacity *= static_cast<float>(opacity);
}

// The group of shapes [first_shape, end): one made already with that range
// (an element inside another with nothing else: their opacities multiply,
// and an opacity and a clip of one range commute), else a new one.
ShapeGroup& Reader::group(std::size_t first_shape) {
  const std::size_t end = out_.shapes.size();
  for (ShapeGroup& g : out_.groups)
    if (g.begin == first_shape && g.end == end) return g;
  out_.groups.push_back(ShapeGroup{first_shape, end, 1.0f, {}});
  return out_.groups.back();
}

Computed Reader::computed_at(std::size_t i) const {
  if (i == 0) return compute(initial_style(kCallerColor), specified_[0]);
  return compute(computed_at(doc_.elements[i].parent), specified_[i]);
}

// What the element drew from first_shape on is not rendered (an empty clip).
void Reader::drop_from(std::size_t first_shape) {
  out_.shapes.erase(out_.shapes.begin() + static_cast<std::ptrdiff_t>(first_shape), out_.shapes.end());
  std::erase_if(out_.groups, [&](const ShapeGroup& g) { return g.begin >= first_shape; });
}

// The <clipPath> `value` names; 0 where the reference names nothing (no
// clip, as CSS Masking says). Refuses anything else by name.
std::size_t Reader::clip_path_element(const XmlElement& e, const std::string& value) const {
  const std::string v = trim(value);
  if (!lower(v).starts_with("url(") || v.back() != ')') fail(e, "clip-path '" + value + "' is not supported");
  std::string ref = trim(std::string_view(v).substr(4, v.size() - 5));
  if (ref.size() >= 2 && (ref.front() == '"' || ref.front() == '\'')) ref = ref.substr(1, ref.size() - 2);
  const XmlElement* target = reference(e, ref);
  if (!target) return 0;
  if (target->name != "clipPath") fail(e, "clip-path refers to <" + target->name + ">, which is not a <clipPath>");
  return static_cast<std::size_t>(target - doc_.elements.data());
}

// SVG's clip-path on what an element drew (shapes [first_shape, end)): the
// union of the <clipPath>'s shapes, each with its clip-rule, in the
// element's user space `m` (or its bounding box's, objectBoundingBox), as a
// ShapeGroup's clip.
void Reader::clip(const XmlElement& e, const std::string& value, const Affine& m, const Viewport& vp,
                  std::size_t first_shape) {
  if (out_.shapes.size() == first_shape) return;
  const std::size_t c = clip_path_element(e, value);
  if (c == 0) return;
  const XmlElement& ce = doc_.elements[c];
  const Computed style = computed_at(c);
  if (style[kClipPath] != "none") fail(ce, "clip-path on a <clipPath> is not supported");
  Affine cm = m;
  if (const std::string* t = ce.find("transform")) cm = m * parse_transform(*t, position(ce));
  const std::string* units = ce.find("clipPathUnits");
  const std::string u = units ? trim(*units) : "userSpaceOnUse";
  if (u == "objectBoundingBox") {
    // The bounding box of the element's geometry in its user space.
    const Affine back = m.inverse();
    std::vector<ShapeContour> user;
    for (std::size_t i = first_shape; i < out_.shapes.size(); ++i)
      for (ShapeContour k : out_.shapes[i].contours) {
        for (RationalBezier& piece : k.pieces)
          for (Vec2& q : piece.points) q = back.apply(q);
        user.push_back(std::move(k));
      }
    const Box b = tight_box(user);
    const double w = b.max.x - b.min.x, h = b.max.y - b.min.y;
    if (b.empty() || !(w > 0.0) || !(h > 0.0)) return drop_from(first_shape);
    cm = m * Affine{w, 0, 0, h, b.min.x, b.min.y};
    if (const std::string* t = ce.find("transform")) cm = cm * parse_transform(*t, position(ce));
  } else if (u != "userSpaceOnUse") {
    fail(ce, "clipPathUnits '" + *units + "' is not userSpaceOnUse or objectBoundingBox");
  }
  std::vector<Shape> shapes;
  for (std::size_t k : ce.children) clip_child(k, style, cm, vp, shapes);
  if (shapes.empty()) return drop_from(first_shape);  // an empty clip shows nothing
  ShapeGroup& g = group(first_shape);
  if (!g.clip.empty()) {  // clipped twice: the inner clip's group, inside a new one
    out_.groups.push_back(ShapeGroup{first_shape, out_.shapes.size(), 1.0f, {}});
    out_.groups.back().clip = std::move(shapes);
    return;
  }
  g.clip = std::move(shapes);
}

// One child of a <clipPath>: a shape, or a <use> of one, as a fill with its
// clip-rule. Other elements do not clip (SVG); text is refused.
void Reader::clip_child(std::size_t c, const Computed& parent, const Affine& m, const Viewport& vp,
                        std::vector<Shape>& out) {
  const XmlElement& k = doc_.elements[c];
  if (k.name.starts_with("{")) return;
  if (refused_element(k.name)) fail(k, "<" + k.name + "> is not supported");
  if (k.name != "use" && !is_shape_element(k.name)) return;
  Computed style = compute(parent, specified_[c]);
  Affine km = m;
  if (const std::string* t = k.find("transform")) km = m * parse_transform(*t, position(k));
  const XmlElement* shape = &k;
  if (k.name == "use") {
    const std::string* href = k.find("href");
    if (!href) href = k.find("xlink:href");
    shape = href ? reference(k, *href) : nullptr;
    if (!shape) return;
    if (!is_shape_element(shape->name))
      fail(k, "<use> in a <clipPath> must refer to a shape, not <" + shape->name + ">");
    const std::size_t t = static_cast<std::size_t>(shape - doc_.elements.data());
    km = km * Affine::translate(parse_length(k.find("x") ? *k.find("x") : "0", Axis::X, vp).value_or(0),
                                parse_length(k.find("y") ? *k.find("y") : "0", Axis::Y, vp).value_or(0));
    if (const std::string* t2 = shape->find("transform")) km = km * parse_transform(*t2, position(*shape));
    if (style[kClipPath] != "none") fail(k, "clip-path on <clipPath> content is not supported");
    style = compute(style, specified_[t]);
  }
  if (style[kDisplay] == "none" || style[kVisibility] != "visible") return;
  if (style[kClipPath] != "none") fail(*shape, "clip-path on <clipPath> content is not supported");
  if (!(std::abs(km.determinant()) > 0.0) || !std::isfinite(km.determinant())) return;
  Shape s;
  try {
    s.fill_rule = parse_fill_rule(style[kClipRule]);
  } catch (const Error& err) {
    fail(*shape, err.what());
  }
  s.contours = placed(*shape, element_geometry(*shape, vp), km, true);
  if (!s.contours.empty()) out.push_back(std::move(s));
}

void Reader::check_unsupported(const XmlElement& e, const Computed& style) const {
  for (int p : {kMask, kFilter})
    if (style[p] != "none") fail(e, std::string(prop_name(p)) + " '" + style[p] + "' is not supported");
  if (style[kMixBlendMode] != "normal") fail(e, "mix-blend-mode '" + style[kMixBlendMode] + "' is not supported");
  if (style[kTransformProperty] != "none")
    fail(e, "the CSS transform property is not supported (the transform attribute is)");
}

const XmlElement* Reader::reference(const XmlElement& e, const std::string& href) const {
  const std::string h = trim(href);
  if (h.empty() || h[0] != '#') fail(e, "reference '" + href + "' is not supported (only #id in the same document)");
  const auto it = ids_.find(h.substr(1));
  return it == ids_.end() ? nullptr : &doc_.elements[it->second];
}

void Reader::use(std::size_t i, const Computed& style, const Affine& m, const Viewport& vp) {
  const XmlElement& e = doc_.elements[i];
  const std::string* href = e.find("href");
  if (!href) href = e.find("xlink:href");
  if (!href) return;  // refers to nothing: draws nothing
  const XmlElement* target = reference(e, *href);
  if (!target) return;  // SVG 2: a missing reference is not rendered
  const std::size_t t = static_cast<std::size_t>(target - doc_.elements.data());
  bool cycle = std::find(use_stack_.begin(), use_stack_.end(), t) != use_stack_.end();
  for (std::size_t up = i; up != 0 && !cycle;) cycle = (up = doc_.elements[up].parent) == t;
  if (cycle || t == i) fail(e, "<use> refers to " + *href + ", which contains it (a cycle)");
  if (use_stack_.size() >= kMaxUseDepth) fail(e, "<use> nested deeper than " + std::to_string(kMaxUseDepth));
  const Affine placed = m * Affine::translate(parse_length(e.find("x") ? *e.find("x") : "0", Axis::X, vp).value_or(0),
                                              parse_length(e.find("y") ? *e.find("y") : "0", Axis::Y, vp).value_or(0));
  use_stack_.push_back(t);
  with_opacity(e, style, m, vp, [&] {
    if (target->name == "symbol" || target->name == "svg") {
      const Computed own = compute(style, specified_[t]);
      if (own[kDisplay] == "none") return;
      check_unsupported(*target, own);
      viewport_element(t, e, own, placed, vp);
    } else {
      element(t, style, placed, vp);
    }
  });
  use_stack_.pop_back();
}

// A nested <svg> (sized by itself) or a <symbol> or <svg> placed by <use>
// (sized by the <use>): a new viewport with its viewBox. Content reaching
// outside a clipping viewport (overflow hidden, their default) is refused.
void Reader::viewport_element(std::size_t t, const XmlElement& sizing, const Computed& style, const Affine& m,
                              const Viewport& vp) {
  const XmlElement& v = doc_.elements[t];
  auto len = [&](const char* name, Axis axis, const char* fallback) {
    const std::string* s = sizing.find(name);
    if (!s && &sizing != &v) s = v.find(name);
    const std::optional<double> l = parse_length(s && trim(*s) != "auto" ? *s : fallback, axis, vp);
    if (!l) fail(sizing, std::string(name) + " '" + *s + "' is not a length");
    return *l;
  };
  const bool placed_by_use = &sizing != &v;
  const double x = placed_by_use ? 0.0 : len("x", Axis::X, "0"), y = placed_by_use ? 0.0 : len("y", Axis::Y, "0");
  const double w = len("width", Axis::X, "100%"), h = len("height", Axis::Y, "100%");
  if (!(w > 0.0) || !(h > 0.0)) return;
  const auto box = parse_view_box(v);
  Affine inner = m * Affine::translate(x, y);
  Viewport inner_vp{w, h};
  if (box) {
    const std::string* aspect = v.find("preserveAspectRatio");
    inner = m * view_box_transform(*box, aspect ? *aspect : "", x, y, w, h, position(v));
    inner_vp = {(*box)[2], (*box)[3]};
  }
  const std::size_t first = out_.shapes.size();
  with_opacity(v, style, m, vp, [&] { children(t, style, inner, inner_vp); });
  const std::optional<std::string>& overflow = specified_[t][kOverflow];
  if (!overflow || (*overflow != "visible" && *overflow != "auto")) clip_to_viewport(first, m, x, y, w, h);
}

// A viewport clips what reaches outside it: a clip of its rectangle
// (x, y, w, h) in user space `m` on shapes [first_shape, end), where any
// reaches out.
void Reader::clip_to_viewport(std::size_t first, const Affine& m, double x, double y, double w, double h) {
  if (inside(first, m, x, y, w, h)) return;
  Shape r;
  ShapeContour k;
  const Vec2 c[4] = {m.apply({x, y}), m.apply({x + w, y}), m.apply({x + w, y + h}), m.apply({x, y + h})};
  for (int j = 0; j < 4; ++j) k.pieces.push_back(RationalBezier::line(c[j], c[(j + 1) % 4]));
  r.contours.push_back(std::move(k));
  ShapeGroup& g = group(first);
  if (g.clip.empty())
    g.clip.push_back(std::move(r));
  else
    out_.groups.push_back(ShapeGroup{first, out_.shapes.size(), 1.0f, {std::move(r)}});
}

// Whether shapes [first_shape, end) lie inside the viewport (x, y, w, h) of
// user space `ctm` (within a flatness slack).
bool Reader::inside(std::size_t first_shape, const Affine& ctm, double x, double y, double w, double h) const {
  const Affine back = ctm.inverse();
  const double slack = tolerance::kConicFlatnessRelative * std::max(w, h);
  for (std::size_t s = first_shape; s < out_.shapes.size(); ++s)
    for (const ShapeContour& c : out_.shapes[s].contours)
      for (const RationalBezier& piece : c.pieces)
        for (Vec2 p : piece.points) {
          const Vec2 q = back.apply(p);
          if (q.x < x - slack || q.x > x + w + slack || q.y < y - slack || q.y > y + h + slack) return false;
        }
  return true;
}

Color Reader::color_value(const XmlElement& e, const std::string& value) const {
  if (value == kCallerColor || lower(value) == "currentcolor") return options_.current_color;
  const std::optional<Color> c = parse_css_color(value);
  if (!c) fail(e, "color '" + value + "' is not a colour");
  return *c;
}

Reader::PaintRef Reader::paint(const XmlElement& e, const Computed& style, int prop) const {
  std::string v = style[prop];
  const std::string name = prop_name(prop);
  if (lower(v).starts_with("url(")) {
    const std::size_t close = v.find(')');
    if (close == std::string::npos) fail(e, name + " '" + v + "' is malformed");
    std::string ref = trim(std::string_view(v).substr(4, close - 4));
    if (ref.size() >= 2 && (ref.front() == '"' || ref.front() == '\'')) ref = ref.substr(1, ref.size() - 2);
    if (const XmlElement* target = reference(e, ref)) {
      if (target->name == "linearGradient" || target->name == "radialGradient")
        return gradient_paint(static_cast<std::size_t>(target - doc_.elements.data()));
      fail(e, name + " refers to <" + target->name + ">, which is not supported as paint");
    }
    v = trim(std::string_view(v).substr(close + 1));  // the fallback, else none
    if (v.empty()) return {};
  }
  const std::string l = lower(v);
  if (l == "none") return {};
  if (l == "currentcolor") return {color_value(e, style[kColor])};
  if (l.starts_with("context-")) fail(e, name + " '" + v + "' is not supported");
  const std::optional<Color> c = parse_css_color(v);
  if (!c) fail(e, name + " '" + v + "' is not a colour");
  return {c};
}

GradientSource Reader::gradient_source() const {
  return {doc_, specified_, [this](const XmlElement& from, const std::string& href) { return reference(from, href); },
          [this](const XmlElement& at, const std::string& value) { return color_value(at, value); }, kCallerColor};
}

// A gradient whose stops all have one colour is that colour (and one without
// stops is none, as SVG says).
Reader::PaintRef Reader::gradient_paint(std::size_t g) const {
  const std::vector<GradientStop> stops = gradient_stops(gradient_source(), g);
  if (stops.empty()) return {};
  for (const GradientStop& k : stops) {
    const Color& a = k.color;
    const Color& b = stops[0].color;
    if (a.r != b.r || a.g != b.g || a.b != b.b || a.a != b.a) return {std::nullopt, g};
  }
  return {stops[0].color};
}

// The fill's paint as the shape's colour or gradient, times `alpha`; false
// when it paints nothing.
bool Reader::set_paint(Shape& s, const PaintRef& fill, const XmlElement& e, const std::vector<ShapeContour>& user,
                       const Affine& m, const Viewport& vp, double alpha) const {
  if (fill.color) {
    s.color = *fill.color;
  } else {
    const GradientSource source = gradient_source();
    std::optional<Gradient> g =
        make_gradient(source, fill.gradient, e, user, m, vp, gradient_stops(source, fill.gradient));
    if (!g) return false;
    if (g->stops.size() == 1)
      s.color = g->stops[0].color;
    else
      s.gradient = std::move(g);
  }
  scale_alpha(s, static_cast<float>(alpha));
  return s.gradient || s.color.a > 0.0f;
}

// The element's contours in document space, each checked; `area_only`
// leaves out those that enclose nothing (a fill of them draws nothing).
std::vector<ShapeContour> Reader::placed(const XmlElement& e, std::vector<ShapeContour> contours, const Affine& m,
                                         bool area_only) {
  std::vector<ShapeContour> out;
  for (ShapeContour& c : contours) {
    for (RationalBezier& piece : c.pieces)
      for (Vec2& q : piece.points) {
        q = m.apply(q);
        shapes_detail::check_point(q, "SVG: " + position(e) + "<" + e.name + ">");
      }
    if (area_only && on_one_line(c)) continue;
    segments_ += c.pieces.size();
    if (segments_ > tolerance::kMaxSegmentsPerDocument)
      fail(e, "more than " + std::to_string(tolerance::kMaxSegmentsPerDocument) + " path segments in the document");
    out.push_back(std::move(c));
  }
  return out;
}

// The stroke as a shape that is not filled, or nothing.
std::optional<Shape> Reader::stroke_shape(const XmlElement& e, const Computed& style, const Affine& m,
                                          const Viewport& vp, const std::vector<ShapeContour>& contours) {
  const PaintRef stroke = paint(e, style, kStroke);
  if (stroke.none()) return std::nullopt;
  std::optional<ShapeStroke> st = stroke_style(e, style, m, vp);
  if (!st) return std::nullopt;
  // The paint is set as a fill's, then moved to the stroke.
  Shape paint_of;
  const double alpha =
      unit_value(e, "stroke-opacity", style[kStrokeOpacity]) * unit_value(e, "opacity", style[kOpacity]);
  if (!set_paint(paint_of, stroke, e, contours, m, vp, alpha)) return std::nullopt;
  Shape s;
  s.filled = false;
  st->color = paint_of.color;
  s.stroke = std::move(*st);
  s.stroke_gradient = std::move(paint_of.gradient);
  s.contours = placed(e, contours, m, false);
  if (s.contours.empty()) return std::nullopt;
  return s;
}

std::optional<Shape> Reader::fill_shape(const XmlElement& e, const Computed& style, const Affine& m, const Viewport& vp,
                                        const std::vector<ShapeContour>& contours) {
  const PaintRef fill = paint(e, style, kFill);
  if (fill.none()) return std::nullopt;
  Shape s;
  const double alpha = unit_value(e, "fill-opacity", style[kFillOpacity]) * unit_value(e, "opacity", style[kOpacity]);
  if (!set_paint(s, fill, e, contours, m, vp, alpha)) return std::nullopt;
  try {
    s.fill_rule = parse_fill_rule(style[kFillRule]);
  } catch (const Error& err) {
    fail(e, err.what());
  }
  s.contours = placed(e, contours, m, true);
  if (s.contours.empty()) return std::nullopt;
  return s;
}

// Fill and stroke as two shapes in paint order. With opacity below 1 the
// element is one layer of both where both draw (fade).
void Reader::shape(std::size_t i, const Computed& style, const Affine& m, const Viewport& vp) {
  const XmlElement& e = doc_.elements[i];
  if (style[kVisibility] != "visible") return;
  const std::vector<ShapeContour> contours = element_geometry(e, vp);
  if (contours.empty()) return;
  const double opacity = unit_value(e, "opacity", style[kOpacity]);
  Computed opaque = style;
  opaque[kOpacity] = "1";  // applied once, by fade, to what the element drew
  std::optional<Shape> fill = fill_shape(e, opaque, m, vp, contours);
  std::optional<Shape> stroke = stroke_shape(e, opaque, m, vp, contours);
  const std::size_t first = out_.shapes.size();
  const bool stroke_first = style[kPaintOrder].starts_with("stroke");
  if (stroke && stroke_first) out_.shapes.push_back(std::move(*stroke));
  if (fill) out_.shapes.push_back(std::move(*fill));
  if (stroke && !stroke_first) out_.shapes.push_back(std::move(*stroke));
  if (e.name != "rect" && e.name != "circle" && e.name != "ellipse") markers(e, style, m, vp, contours);
  if (style[kClipPath] != "none") clip(e, style[kClipPath], m, vp, first);
  fade(first, opacity);
}

// marker-start, marker-mid and marker-end, drawn over the fill and stroke
// (paint-order's markers last).
void Reader::markers(const XmlElement& e, const Computed& style, const Affine& m, const Viewport& vp,
                     const std::vector<ShapeContour>& contours) {
  if (style[kMarkerStart] == "none" && style[kMarkerMid] == "none" && style[kMarkerEnd] == "none") return;
  const std::vector<MarkerVertex> vertices = marker_vertices(contours);
  if (vertices.empty()) return;
  const std::optional<double> width = parse_length(style[kStrokeWidth], Axis::Other, vp);
  if (!width) fail(e, "stroke-width '" + style[kStrokeWidth] + "' is not a length");
  for (int p : {kMarkerStart, kMarkerMid, kMarkerEnd}) {
    if (style[p] == "none") continue;
    const std::string v = trim(style[p]);
    const std::string name = prop_name(p);
    if (!lower(v).starts_with("url(") || v.back() != ')') fail(e, name + " '" + style[p] + "' is not supported");
    std::string ref = trim(std::string_view(v).substr(4, v.size() - 5));
    if (ref.size() >= 2 && (ref.front() == '"' || ref.front() == '\'')) ref = ref.substr(1, ref.size() - 2);
    const XmlElement* target = reference(e, ref);
    if (!target) continue;  // names nothing: no marker
    if (target->name != "marker") fail(e, name + " refers to <" + target->name + ">, which is not a <marker>");
    // Arcs are cut into several conics, whose joins are no vertices of the path.
    if (p == kMarkerMid && e.name == "path" && e.find("d") && e.find("d")->find_first_of("Aa") != std::string::npos)
      fail(e, "marker-mid on a path with arcs is not supported");
    const std::size_t k = static_cast<std::size_t>(target - doc_.elements.data());
    // The path's first and last marker take the direction out and in alone
    // (as librsvg, also where a subpath is closed).
    if (p == kMarkerStart) {
      MarkerVertex first = vertices.front();
      first.angle = first.out_angle;
      marker(k, first, true, *width, m, vp);
    }
    if (p == kMarkerMid)
      for (std::size_t j = 1; j + 1 < vertices.size(); ++j) marker(k, vertices[j], false, *width, m, vp);
    if (p == kMarkerEnd) {
      MarkerVertex last = vertices.back();
      last.angle = last.in_angle;
      marker(k, last, false, *width, m, vp);
    }
  }
}

// One marker's content at vertex `v` of a path in user space `m`: its
// viewBox in markerWidth x markerHeight, (refX, refY) on the vertex, turned
// by orient, scaled by the stroke width (markerUnits strokeWidth), clipped
// by its viewport unless overflow is visible.
void Reader::marker(std::size_t k, const MarkerVertex& v, bool at_start, double stroke_width, const Affine& m,
                    const Viewport& vp) {
  const XmlElement& mk = doc_.elements[k];
  if (std::find(marker_stack_.begin(), marker_stack_.end(), k) != marker_stack_.end())
    fail(mk, "<marker> is drawn inside itself (a cycle)");
  if (marker_stack_.size() >= kMaxUseDepth) fail(mk, "markers nested deeper than " + std::to_string(kMaxUseDepth));
  auto length = [&](const char* name, Axis axis, const char* fallback) {
    const std::string* s = mk.find(name);
    const std::optional<double> l = parse_length(s ? *s : fallback, axis, vp);
    if (!l) fail(mk, std::string(name) + " '" + *s + "' is not a length");
    return *l;
  };
  const double w = length("markerWidth", Axis::X, "3"), h = length("markerHeight", Axis::Y, "3");
  if (!(w > 0.0) || !(h > 0.0)) return;
  const std::string* units = mk.find("markerUnits");
  const std::string u = units ? trim(*units) : "strokeWidth";
  if (u != "strokeWidth" && u != "userSpaceOnUse") fail(mk, "markerUnits '" + *units + "' is not supported");
  const double scale = u == "strokeWidth" ? stroke_width : 1.0;
  if (!(scale > 0.0)) return;  // scaled to nothing
  const std::string* orient = mk.find("orient");
  const std::string o = orient ? trim(*orient) : "0";
  double angle = v.angle;
  if (o == "auto-start-reverse") {
    if (at_start) angle += std::numbers::pi;
  } else if (o != "auto") {
    const std::string deg = o.ends_with("deg") ? o.substr(0, o.size() - 3) : o;
    double a = 0.0;
    const auto [end, ec] = std::from_chars(deg.data(), deg.data() + deg.size(), a);
    if (ec != std::errc() || end != deg.data() + deg.size() || !std::isfinite(a))
      fail(mk, "orient '" + *orient + "' is not auto, auto-start-reverse or an angle in degrees");
    angle = a * std::numbers::pi / 180.0;
  }
  Affine box;  // content to the marker's viewport
  Viewport inner{w, h};
  if (const auto b = parse_view_box(mk)) {
    const std::string* aspect = mk.find("preserveAspectRatio");
    box = view_box_transform(*b, aspect ? *aspect : "", 0, 0, w, h, position(mk));
    inner = {(*b)[2], (*b)[3]};
  }
  const Vec2 ref = box.apply({length("refX", Axis::X, "0"), length("refY", Axis::Y, "0")});
  const double c = std::cos(angle), s = std::sin(angle);
  const Affine port = m * Affine::translate(v.at.x, v.at.y) * Affine{c, s, -s, c, 0, 0} * Affine::scale(scale, scale) *
                      Affine::translate(-ref.x, -ref.y);
  const Computed style = computed_at(k);
  const std::size_t first = out_.shapes.size();
  marker_stack_.push_back(k);
  children(k, style, port * box, inner);
  marker_stack_.pop_back();
  const std::optional<std::string>& overflow = specified_[k][kOverflow];
  if (!overflow || (*overflow != "visible" && *overflow != "auto")) clip_to_viewport(first, port, 0, 0, w, h);
}

}  // namespace
}  // namespace svg

ShapeDocument parse_svg(std::string_view text, const SvgOptions& options) {
  const svg::XmlDocument doc = svg::parse_xml(text);
  return svg::Reader(doc, options).run();
}

ShapeDocument parse_svg(std::string_view text) { return parse_svg(text, SvgOptions{}); }

ShapeDocument read_shape_file(const std::string& path) { return read_shape_file(path, SvgOptions{}); }

ShapeDocument read_shape_file(const std::string& path, const SvgOptions& options) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(ErrorCode::Io, "cannot read shape file " + path);
  // Chunk by chunk up to the limit: an endless file (/dev/zero) stops there.
  std::string text;
  char chunk[1 << 16];
  while (in.read(chunk, sizeof chunk) || in.gcount() > 0) {
    text.append(chunk, static_cast<std::size_t>(in.gcount()));
    if (text.size() > tolerance::kMaxShapeFileBytes)
      throw Error(ErrorCode::Io, "shape file " + path + " is larger than the limit of " +
                                     std::to_string(tolerance::kMaxShapeFileBytes) + " bytes");
  }
  if (in.bad()) throw Error(ErrorCode::Io, "cannot read shape file " + path);
  auto ends_with = [&](std::string_view ext) {
    if (path.size() < ext.size()) return false;
    for (std::size_t i = 0; i < ext.size(); ++i)
      if (std::tolower(static_cast<unsigned char>(path[path.size() - ext.size() + i])) != ext[i]) return false;
    return true;
  };
  try {
    if (ends_with(".json")) return parse_shape_json(text);
    if (ends_with(".svg")) return parse_svg(text, options);
  } catch (const Error& e) {
    throw Error(e.code(), path + ": " + e.what());
  }
  throw Error(ErrorCode::InvalidArgument, "shape file " + path + " must end in .json or .svg");
}

}  // namespace curvetext
