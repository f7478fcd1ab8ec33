// A minimal SVG reader: the <svg> element's width, height and viewBox, and
// every <path> with its d, fill and fill-rule (attributes, a style attribute,
// or inherited from enclosing <g> elements). Anything that would change the
// drawing and is not understood (transform, <rect>, <use>, ...) is an error,
// not silently dropped. SVG's y axis points down; the document is mirrored to
// y-up (Outline's frame), which leaves both fill rules unchanged.
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <string>

#include "check.hpp"
#include "curvetext/error.hpp"
#include "curvetext/shapes.hpp"
#include "core/tolerances.hpp"

namespace curvetext {

namespace {

struct Tag {
  std::string name;
  std::vector<std::pair<std::string, std::string>> attributes;
  bool closing = false;       // </name>
  bool self_closing = false;  // <name ... />
  const std::string* find(std::string_view key) const {
    for (const auto& [k, v] : attributes)
      if (k == key) return &v;
    return nullptr;
  }
};

[[noreturn]] void fail(const std::string& message) { throw Error(ErrorCode::InvalidArgument, "SVG: " + message); }

std::string decode_entities(std::string_view s) {
  std::string out;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s[i] != '&') {
      out += s[i];
      continue;
    }
    const std::size_t end = s.find(';', i);
    if (end == std::string_view::npos) fail("unterminated entity in an attribute");
    const std::string_view name = s.substr(i + 1, end - i - 1);
    if (name == "amp")
      out += '&';
    else if (name == "lt")
      out += '<';
    else if (name == "gt")
      out += '>';
    else if (name == "quot")
      out += '"';
    else if (name == "apos")
      out += '\'';
    else if (!name.empty() && name[0] == '#') {
      unsigned cp = 0;
      const bool hex = name.size() > 1 && (name[1] == 'x' || name[1] == 'X');
      const std::string_view digits = name.substr(hex ? 2 : 1);
      const auto [p, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), cp, hex ? 16 : 10);
      if (ec != std::errc() || p != digits.data() + digits.size() || cp > 0x7f)
        fail("unsupported character reference &" + std::string(name) + ";");
      out += static_cast<char>(cp);
    } else {
      fail("unknown entity &" + std::string(name) + ";");
    }
    i = end;
  }
  return out;
}

class XmlScanner {
 public:
  explicit XmlScanner(std::string_view text) : s_(text) {}

  // The next tag, skipping text, comments, processing instructions, DOCTYPE
  // and CDATA; false at the end.
  bool next(Tag& tag) {
    for (;;) {
      const std::size_t lt = s_.find('<', pos_);
      if (lt == std::string_view::npos) return false;
      pos_ = lt;
      if (s_.substr(pos_, 4) == "<!--") {
        skip_past("-->");
      } else if (s_.substr(pos_, 9) == "<![CDATA[") {
        skip_past("]]>");
      } else if (s_.substr(pos_, 2) == "<?") {
        skip_past("?>");
      } else if (s_.substr(pos_, 2) == "<!") {
        skip_past(">");
      } else {
        read_tag(tag);
        return true;
      }
    }
  }

 private:
  std::string_view s_;
  std::size_t pos_ = 0;

  void skip_past(std::string_view end) {
    const std::size_t e = s_.find(end, pos_);
    if (e == std::string_view::npos) fail("unterminated " + std::string(s_.substr(pos_, 4)) + "...");
    pos_ = e + end.size();
  }

  static bool space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }
  static bool name_char(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_' ||
           c == ':' || c == '.';
  }

  void read_tag(Tag& tag) {
    tag = {};
    ++pos_;
    if (pos_ < s_.size() && s_[pos_] == '/') {
      tag.closing = true;
      ++pos_;
    }
    const std::size_t n0 = pos_;
    while (pos_ < s_.size() && name_char(s_[pos_])) ++pos_;
    tag.name = std::string(s_.substr(n0, pos_ - n0));
    if (tag.name.empty()) fail("a '<' not followed by an element name");
    for (;;) {
      while (pos_ < s_.size() && space(s_[pos_])) ++pos_;
      if (pos_ >= s_.size()) fail("unterminated <" + tag.name + "> tag");
      if (s_[pos_] == '>') {
        ++pos_;
        return;
      }
      if (s_.substr(pos_, 2) == "/>") {
        tag.self_closing = true;
        pos_ += 2;
        return;
      }
      const std::size_t a0 = pos_;
      while (pos_ < s_.size() && name_char(s_[pos_])) ++pos_;
      if (pos_ == a0) fail("unexpected '" + std::string(1, s_[pos_]) + "' in <" + tag.name + ">");
      std::string key(s_.substr(a0, pos_ - a0));
      while (pos_ < s_.size() && space(s_[pos_])) ++pos_;
      if (pos_ >= s_.size() || s_[pos_] != '=') fail("attribute " + key + " of <" + tag.name + "> has no value");
      ++pos_;
      while (pos_ < s_.size() && space(s_[pos_])) ++pos_;
      if (pos_ >= s_.size() || (s_[pos_] != '"' && s_[pos_] != '\'')) fail("attribute " + key + " needs quotes");
      const char q = s_[pos_++];
      const std::size_t end = s_.find(q, pos_);
      if (end == std::string_view::npos) fail("unterminated value of attribute " + key);
      tag.attributes.emplace_back(std::move(key), decode_entities(s_.substr(pos_, end - pos_)));
      pos_ = end + 1;
    }
  }
};

std::string trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t' || s.front() == '\n' || s.front() == '\r'))
    s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\n' || s.back() == '\r'))
    s.remove_suffix(1);
  return std::string(s);
}

// Paint properties that <g> passes down to <path>, and the element's own
// opacity (not inherited: it fades the element as one layer).
struct Paint {
  std::string fill = "black";
  std::string fill_rule = "nonzero";
  std::string fill_opacity = "1";
  std::string stroke = "none";
  std::string display = "inline";
  std::string opacity;  // empty: 1
};

void set_property(Paint& paint, const std::string& key, const std::string& value) {
  if (key == "fill")
    paint.fill = value;
  else if (key == "fill-rule")
    paint.fill_rule = value;
  else if (key == "fill-opacity")
    paint.fill_opacity = value;
  else if (key == "stroke")
    paint.stroke = value;
  else if (key == "display")
    paint.display = value;
  else if (key == "opacity")
    paint.opacity = value;
}

// An opacity value: a number in [0, 1] or a percentage.
double opacity_value(const std::string& key, const std::string& text) {
  if (text.empty()) return 1.0;
  std::string s = text;
  const bool percent = s.ends_with("%");
  if (percent) s.pop_back();
  double v = 0.0;
  const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (s.empty() || ec != std::errc() || p != s.data() + s.size() || !std::isfinite(v))
    fail(key + " '" + text + "' is not a number");
  return std::clamp(percent ? v / 100.0 : v, 0.0, 1.0);
}

// The element's properties over those it inherits; opacity starts at 1.
void apply_paint(const Tag& tag, Paint& paint) {
  paint.opacity.clear();
  for (const char* key : {"fill", "fill-rule", "fill-opacity", "stroke", "display", "opacity"})
    if (const std::string* v = tag.find(key)) set_property(paint, key, trim(*v));
  if (const std::string* style = tag.find("style")) {
    std::string_view rest = *style;
    while (!rest.empty()) {
      const std::size_t semi = rest.find(';');
      const std::string_view decl = rest.substr(0, semi);
      rest = semi == std::string_view::npos ? std::string_view{} : rest.substr(semi + 1);
      const std::size_t colon = decl.find(':');
      if (colon == std::string_view::npos) continue;
      set_property(paint, trim(decl.substr(0, colon)), trim(decl.substr(colon + 1)));
    }
  }
  if (tag.find("transform")) fail("<" + tag.name + "> has a transform attribute, which is not supported");
}

// A group's opacity fades its children as one layer, which is not drawn so.
void refuse_group_opacity(const Tag& tag, const Paint& paint) {
  if (opacity_value("opacity", paint.opacity) != 1.0)
    fail("<" + tag.name + "> has opacity " + paint.opacity +
         ", which is not supported on groups; set fill-opacity or opacity on each path");
}

// "#rgb", "#rrggbb", names parse_color knows, and rgb(r, g, b) with 0..255.
Color svg_color(const std::string& text) {
  if (text.starts_with("rgb(") && text.ends_with(")")) {
    std::string_view inner(text);
    inner = inner.substr(4, inner.size() - 5);
    float c[3] = {};
    for (int i = 0; i < 3; ++i) {
      const std::size_t comma = inner.find(',');
      const std::string part = trim(inner.substr(0, comma));
      int v = -1;
      const auto [p, ec] = std::from_chars(part.data(), part.data() + part.size(), v);
      if (ec != std::errc() || p != part.data() + part.size() || v < 0 || v > 255 ||
          (i < 2) == (comma == std::string_view::npos))
        fail("unsupported colour '" + text + "'");
      c[i] = static_cast<float>(v) / 255.0f;
      inner = comma == std::string_view::npos ? std::string_view{} : inner.substr(comma + 1);
    }
    return {c[0], c[1], c[2], 1.0f};
  }
  try {
    return parse_color(text);
  } catch (const Error& e) {
    fail(std::string("fill: ") + e.what());
  }
}

// The path's fill colour with fill-opacity and opacity (one path fades
// alone as one layer would); refuses a stroke rather than drop it.
Color path_color(const Paint& paint) {
  if (paint.stroke != "none")
    fail("<path> has stroke '" + paint.stroke +
         "': strokes are not drawn (only fills are); convert the stroke to a filled path or set stroke=\"none\"");
  Color c = svg_color(paint.fill);
  c.a *=
      static_cast<float>(opacity_value("fill-opacity", paint.fill_opacity) * opacity_value("opacity", paint.opacity));
  return c;
}

// A length in user units: a plain number or "...px"; other units and
// percentages give 0 (the viewBox decides then).
double length_attribute(const std::string* value) {
  if (!value) return 0.0;
  std::string s = trim(*value);
  if (s.ends_with("px")) s.resize(s.size() - 2);
  double v = 0.0;
  const auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  if (ec != std::errc() || p != s.data() + s.size()) return 0.0;
  if (!std::isfinite(v) || v <= 0.0) fail("width/height must be positive, got '" + *value + "'");
  if (v > 16384) fail("width/height " + *value + " is larger than 16384 px");
  return v;
}

// True when every point of the contour lies on the line through its first
// point and the point farthest from it (within tolerance::kConicFlatnessRelative
// of that distance): it encloses no area.
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

void add_path(ShapeDocument& doc, const std::string& d, const Paint& paint, std::size_t& segments) {
  Shape shape;
  shape.color = path_color(paint);
  try {
    shape.fill_rule = parse_fill_rule(paint.fill_rule);
  } catch (const Error& e) {
    fail(e.what());
  }
  for (ShapeContour& c : parse_svg_path(d)) {
    // A line (an open two-point subpath) is drawn by a stroke in SVG; filled,
    // it would draw nothing without a word.
    if (on_one_line(c))
      fail("<path> " + std::to_string(doc.shapes.size() + 1) + ", subpath " +
           std::to_string(shape.contours.size() + 1) +
           ": its points lie on one line, so it encloses no area and would draw nothing (only fills are drawn, not "
           "strokes)");
    segments += c.pieces.size();
    if (segments > tolerance::kMaxSegmentsPerDocument)
      fail("more than " + std::to_string(tolerance::kMaxSegmentsPerDocument) + " path segments in the document");
    for (RationalBezier& piece : c.pieces)
      for (Vec2& q : piece.points) q.y = -q.y;
    shape.contours.push_back(std::move(c));
  }
  doc.shapes.push_back(std::move(shape));
}

}  // namespace

ShapeDocument parse_svg(std::string_view text) {
  XmlScanner scanner(text);
  Tag tag;
  ShapeDocument doc;
  bool in_svg = false;
  std::vector<Paint> stack;  // paint of each open <svg>/<g>
  // Inside <defs>, <clipPath>, <mask>, ... paths are not drawn directly.
  std::string skipping;
  int skip_depth = 0;
  std::size_t segments = 0;  // in the document so far
  while (scanner.next(tag)) {
    if (skip_depth > 0) {
      if (tag.name == skipping && !tag.self_closing) skip_depth += tag.closing ? -1 : 1;
      continue;
    }
    if (!in_svg) {
      if (tag.name != "svg" || tag.closing) fail("the first element must be <svg>, got <" + tag.name + ">");
      in_svg = true;
      doc.width_px = length_attribute(tag.find("width"));
      doc.height_px = length_attribute(tag.find("height"));
      if (const std::string* vb = tag.find("viewBox")) {
        std::vector<double> v;
        std::string_view rest = *vb;
        for (;;) {
          while (!rest.empty() && (rest.front() == ' ' || rest.front() == ',' || rest.front() == '\t' ||
                                   rest.front() == '\n' || rest.front() == '\r'))
            rest.remove_prefix(1);
          if (rest.empty()) break;
          double x = 0.0;
          const auto [p, ec] = std::from_chars(rest.data(), rest.data() + rest.size(), x);
          if (ec != std::errc()) fail("viewBox '" + *vb + "' is not four numbers");
          v.push_back(x);
          rest.remove_prefix(static_cast<std::size_t>(p - rest.data()));
        }
        if (v.size() != 4) fail("viewBox '" + *vb + "' is not four numbers");
        for (double c : v) shapes_detail::check_coordinate(c, "SVG viewBox");
        if (!(v[2] > 0 && v[3] > 0)) fail("viewBox '" + *vb + "' needs a positive width and height");
        // Mirrored: SVG y in [min-y, min-y + height] is y-up [-(min-y + height), -min-y].
        doc.view.add({v[0], -(v[1] + v[3])});
        doc.view.add({v[0] + v[2], -v[1]});
      } else if (doc.width_px > 0 && doc.height_px > 0) {
        doc.view.add({0, -doc.height_px});
        doc.view.add({doc.width_px, 0});
      }
      Paint root;
      apply_paint(tag, root);
      refuse_group_opacity(tag, root);
      if (root.display == "none") break;
      stack.push_back(root);
      if (tag.self_closing) break;
      continue;
    }
    if (tag.closing) {
      if (tag.name == "svg" || tag.name == "g") {
        if (stack.empty()) fail("unbalanced </" + tag.name + ">");
        stack.pop_back();
        if (stack.empty()) break;  // the end of the root <svg>
      }
      continue;
    }
    if (tag.name == "defs" || tag.name == "clipPath" || tag.name == "mask" || tag.name == "pattern" ||
        tag.name == "marker" || tag.name == "symbol") {
      if (!tag.self_closing) {
        skipping = tag.name;
        skip_depth = 1;
      }
      continue;
    }
    if (tag.name == "g" || tag.name == "svg") {
      if (tag.name == "svg") fail("nested <svg> elements are not supported");
      Paint p = stack.back();
      apply_paint(tag, p);
      refuse_group_opacity(tag, p);
      if (p.display == "none" && !tag.self_closing) {  // not drawn, nor anything inside
        skipping = tag.name;
        skip_depth = 1;
      } else if (!tag.self_closing) {
        stack.push_back(p);
      }
      continue;
    }
    if (tag.name == "path") {
      Paint p = stack.back();
      apply_paint(tag, p);
      const std::string* d = tag.find("d");
      if (!d || p.display == "none") continue;  // draws nothing
      if (p.fill == "none" && p.stroke == "none") continue;
      add_path(doc, *d, p, segments);
      continue;
    }
    static const char* const kRefused[] = {"rect", "circle", "ellipse", "line",   "polyline", "polygon",
                                           "text", "image",  "use",     "switch", "a"};
    for (const char* name : kRefused)
      if (tag.name == name)
        fail("<" + tag.name + "> is not supported (only <path> elements are read; convert shapes to paths)");
    // Everything else (title, desc, metadata, defs, style, ...) does not draw
    // by itself here; it is skipped.
  }
  if (!in_svg) fail("no <svg> element");
  return doc;
}

ShapeDocument read_shape_file(const std::string& path) {
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
    if (ends_with(".svg")) return parse_svg(text);
  } catch (const Error& e) {
    throw Error(e.code(), path + ": " + e.what());
  }
  throw Error(ErrorCode::InvalidArgument, "shape file " + path + " must end in .json or .svg");
}

}  // namespace curvetext
