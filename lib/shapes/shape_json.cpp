// Shape documents in JSON (format: docs/shapes/README.md). Unknown keys are
// errors, so a misspelt "wieghts" is reported instead of silently ignored.
#include <cmath>
#include <string>

#include "check.hpp"
#include "curvetext/error.hpp"
#include "curvetext/shapes.hpp"
#include "curvetext/tolerances.hpp"
#include "json.hpp"

namespace curvetext {

namespace {

using json::Value;
using shapes_detail::check_point;
using shapes_detail::check_weight;

[[noreturn]] void fail(const Value& v, const std::string& path, const std::string& message) {
  throw Error(ErrorCode::InvalidArgument, "JSON " + v.where() + ": " + path + ": " + message);
}

void expect(const Value& v, Value::Type type, const std::string& path) {
  if (v.type != type)
    fail(v, path, std::string("expected ") + json::type_name(type) + ", got " + json::type_name(v.type));
}

void only_keys(const Value& v, std::initializer_list<std::string_view> keys, const std::string& path) {
  for (const auto& [k, member] : v.object) {
    bool known = false;
    for (std::string_view key : keys) known = known || k == key;
    if (!known) {
      std::string list;
      for (std::string_view key : keys) list += (list.empty() ? "" : ", ") + std::string(key);
      fail(member, path, "unknown key \"" + k + "\" (known: " + list + ")");
    }
  }
}

double number(const Value& v, const std::string& path) {
  expect(v, Value::Type::Number, path);
  return v.number;
}

Vec2 point(const Value& v, const std::string& path) {
  expect(v, Value::Type::Array, path);
  if (v.array.size() != 2) fail(v, path, "a point is [x, y], got " + std::to_string(v.array.size()) + " values");
  const Vec2 p{number(v.array[0], path + "[0]"), number(v.array[1], path + "[1]")};
  try {
    check_point(p, path);
  } catch (const Error& e) {
    fail(v, path, e.what());
  }
  return p;
}

std::vector<Vec2> points(const Value& v, const std::string& path, std::size_t at_least) {
  expect(v, Value::Type::Array, path);
  if (v.array.size() < at_least)
    fail(v, path, "needs at least " + std::to_string(at_least) + " points, got " + std::to_string(v.array.size()));
  std::vector<Vec2> out;
  for (std::size_t i = 0; i < v.array.size(); ++i)
    out.push_back(point(v.array[i], path + "[" + std::to_string(i) + "]"));
  return out;
}

std::vector<double> numbers(const Value& v, const std::string& path) {
  expect(v, Value::Type::Array, path);
  std::vector<double> out;
  for (std::size_t i = 0; i < v.array.size(); ++i)
    out.push_back(number(v.array[i], path + "[" + std::to_string(i) + "]"));
  return out;
}

void read_item(const Value& item, const std::string& path, ShapeContour& contour) {
  expect(item, Value::Type::Object, path);
  if (item.object.size() != 1)
    fail(item, path, "a contour item is one of {\"line\": ...}, {\"bezier\": ...}, {\"nurbs\": ...}");
  const auto& [kind, body] = item.object.front();
  const std::string p = path + "." + kind;
  if (kind == "line") {
    const std::vector<Vec2> pts = points(body, p, 2);
    for (std::size_t i = 0; i + 1 < pts.size(); ++i) contour.pieces.push_back(RationalBezier::line(pts[i], pts[i + 1]));
    return;
  }
  if (kind == "bezier") {
    expect(body, Value::Type::Object, p);
    only_keys(body, {"points", "weights"}, p);
    const Value* pts = body.find("points");
    if (!pts) fail(body, p, "\"points\" is required");
    RationalBezier b;
    b.points = points(*pts, p + ".points", 2);
    if (b.points.size() > static_cast<std::size_t>(kMaxNurbsDegree) + 1)
      fail(*pts, p + ".points", "degree above " + std::to_string(kMaxNurbsDegree));
    if (const Value* w = body.find("weights")) {
      b.weights = numbers(*w, p + ".weights");
      if (b.weights.size() != b.points.size())
        fail(*w, p + ".weights",
             std::to_string(b.points.size()) + " points need as many weights, got " + std::to_string(b.weights.size()));
      for (std::size_t i = 0; i < b.weights.size(); ++i) {
        try {
          if (shapes_detail::is_zero_middle_weight(b.points.size() - 1, i, b.weights.size(), b.weights[i])) continue;
          check_weight(b.weights[i], p + ".weights[" + std::to_string(i) + "]");
        } catch (const Error& e) {
          fail(w->array[i], p + ".weights", e.what());
        }
      }
    } else {
      b.weights.assign(b.points.size(), 1.0);
    }
    // A rational quadratic with middle weight 0 is its chord.
    if (b.points.size() == 3 && b.weights[1] == 0.0) b = RationalBezier::line(b.points[0], b.points[2]);
    contour.pieces.push_back(std::move(b));
    return;
  }
  if (kind == "nurbs") {
    expect(body, Value::Type::Object, p);
    only_keys(body, {"degree", "points", "weights", "knots"}, p);
    const Value* deg = body.find("degree");
    const Value* pts = body.find("points");
    if (!deg) fail(body, p, "\"degree\" is required");
    if (!pts) fail(body, p, "\"points\" is required");
    Nurbs n;
    const double d = number(*deg, p + ".degree");
    if (d != std::floor(d) || d < 1 || d > kMaxNurbsDegree)
      fail(*deg, p + ".degree", "must be a whole number from 1 to " + std::to_string(kMaxNurbsDegree));
    n.degree = static_cast<int>(d);
    n.points = points(*pts, p + ".points", 2);
    if (const Value* w = body.find("weights")) n.weights = numbers(*w, p + ".weights");
    if (const Value* k = body.find("knots")) {
      n.knots = numbers(*k, p + ".knots");
    } else {
      // Clamped and uniform: 0 (p+1 times), 1, 2, ..., n-p (p+1 times).
      const int count = static_cast<int>(n.points.size());
      for (int i = 0; i <= n.degree; ++i) n.knots.push_back(0.0);
      for (int i = 1; i < count - n.degree; ++i) n.knots.push_back(i);
      for (int i = 0; i <= n.degree; ++i) n.knots.push_back(std::max(1, count - n.degree));
    }
    try {
      for (RationalBezier& b : nurbs_to_beziers(n)) contour.pieces.push_back(std::move(b));
    } catch (const Error& e) {
      fail(body, p, e.what());
    }
    return;
  }
  fail(item, path, "unknown contour item \"" + kind + "\" (known: line, bezier, nurbs)");
}

template <typename T>
T named(const Value& v, const std::string& path, std::initializer_list<std::pair<std::string_view, T>> names) {
  expect(v, Value::Type::String, path);
  std::string list;
  for (const auto& [name, value] : names) {
    if (v.string == name) return value;
    list += (list.empty() ? "" : ", ") + std::string(name);
  }
  fail(v, path, "unknown value \"" + v.string + "\" (known: " + list + ")");
}

double non_negative(const Value& v, const std::string& path) {
  const double x = number(v, path);
  if (!(x >= 0.0) || x > kMaxShapeCoordinate)
    fail(v, path, "must be from 0 to " + std::to_string(static_cast<long long>(kMaxShapeCoordinate)));
  return x;
}

void read_dashes(const Value& v, const std::string& path, StrokeStyle& st) {
  expect(v, Value::Type::Array, path);
  if (v.array.size() > tolerance::kMaxSegmentsPerPath)
    fail(v, path, "more than " + std::to_string(tolerance::kMaxSegmentsPerPath) + " dash lengths");
  for (std::size_t i = 0; i < v.array.size(); ++i)
    st.dashes.push_back(non_negative(v.array[i], path + "[" + std::to_string(i) + "]"));
}

// docs/shapes/README.md, "Strokes".
ShapeStroke read_stroke(const Value& v, const std::string& path) {
  expect(v, Value::Type::Object, path);
  only_keys(
      v, {"width", "units", "color", "opacity", "join", "miter_limit", "cap", "dashes", "dash_offset", "path_length"},
      path);
  ShapeStroke stroke;
  StrokeStyle& st = stroke.style;
  if (const Value* w = v.find("width")) st.width = non_negative(*w, path + ".width");
  if (const Value* u = v.find("units"))
    st.width_unit = named<StrokeWidthUnit>(
        *u, path + ".units",
        {{"user", StrokeWidthUnit::User}, {"px", StrokeWidthUnit::Device}, {"hairline", StrokeWidthUnit::Hairline}});
  if (const Value* c = v.find("color")) {
    expect(*c, Value::Type::String, path + ".color");
    try {
      stroke.color = parse_color(c->string);
    } catch (const Error& e) {
      fail(*c, path + ".color", e.what());
    }
  }
  if (const Value* o = v.find("opacity")) {
    const double a = number(*o, path + ".opacity");
    if (!(a >= 0.0 && a <= 1.0)) fail(*o, path + ".opacity", "must be from 0 to 1");
    stroke.color.a *= static_cast<float>(a);
  }
  if (const Value* j = v.find("join"))
    st.join = named<LineJoin>(*j, path + ".join",
                              {{"miter", LineJoin::Miter},
                               {"miter-clip", LineJoin::MiterClip},
                               {"round", LineJoin::Round},
                               {"bevel", LineJoin::Bevel},
                               {"arcs", LineJoin::Arcs}});
  if (const Value* m = v.find("miter_limit")) {
    st.miter_limit = number(*m, path + ".miter_limit");
    if (!(st.miter_limit >= 1.0) || st.miter_limit > 1e9) fail(*m, path + ".miter_limit", "must be from 1 to 1e9");
  }
  if (const Value* c = v.find("cap"))
    st.cap = named<LineCap>(*c, path + ".cap",
                            {{"butt", LineCap::Butt}, {"round", LineCap::Round}, {"square", LineCap::Square}});
  if (const Value* d = v.find("dashes")) read_dashes(*d, path + ".dashes", st);
  if (const Value* o = v.find("dash_offset")) {
    st.dash_offset = number(*o, path + ".dash_offset");
    if (std::abs(st.dash_offset) > kMaxShapeCoordinate) fail(*o, path + ".dash_offset", "beyond 1e9");
  }
  if (const Value* l = v.find("path_length")) st.path_length = non_negative(*l, path + ".path_length");
  return stroke;
}

// A contour: a list of items (closed), or {"items": [...], "closed": false}.
ShapeContour read_contour(const Value& cv, const std::string& cp) {
  ShapeContour contour;
  const Value* items = &cv;
  if (cv.type == Value::Type::Object) {
    only_keys(cv, {"items", "closed"}, cp);
    items = cv.find("items");
    if (!items) fail(cv, cp, "\"items\" is required");
    if (const Value* c = cv.find("closed")) {
      expect(*c, Value::Type::Bool, cp + ".closed");
      contour.closed = c->boolean;
    }
  }
  expect(*items, Value::Type::Array, cp);
  for (std::size_t k = 0; k < items->array.size(); ++k)
    read_item(items->array[k], cp + "[" + std::to_string(k) + "]", contour);
  return contour;
}

void read_paint(const Value& sv, const std::string& sp, Shape& shape) {
  if (const Value* f = sv.find("fill")) {
    expect(*f, Value::Type::Bool, sp + ".fill");
    shape.filled = f->boolean;
  }
  if (const Value* s = sv.find("stroke")) shape.stroke = read_stroke(*s, sp + ".stroke");
  if (const Value* o = sv.find("paint_order"))
    shape.paint_order = named<PaintOrder>(
        *o, sp + ".paint_order", {{"fill stroke", PaintOrder::FillStroke}, {"stroke fill", PaintOrder::StrokeFill}});
}

}  // namespace

ShapeDocument parse_shape_json(std::string_view text) {
  const Value root = json::parse(text);
  expect(root, Value::Type::Object, "document");
  only_keys(root, {"size", "view", "shapes"}, "document");
  ShapeDocument doc;
  if (const Value* size = root.find("size")) {
    const std::vector<double> s = numbers(*size, "size");
    if (s.size() != 2 || !(s[0] >= 1 && s[1] >= 1) || s[0] > 16384 || s[1] > 16384)
      fail(*size, "size", "must be [width, height] in pixels, each from 1 to 16384");
    doc.width_px = s[0];
    doc.height_px = s[1];
  }
  if (const Value* view = root.find("view")) {
    const std::vector<double> v = numbers(*view, "view");
    if (v.size() != 4) fail(*view, "view", "must be [xmin, ymin, xmax, ymax]");
    for (double c : v) {
      try {
        shapes_detail::check_coordinate(c, "view");
      } catch (const Error& e) {
        fail(*view, "view", e.what());
      }
    }
    if (!(v[0] < v[2] && v[1] < v[3])) fail(*view, "view", "needs xmin < xmax and ymin < ymax");
    doc.view.add({v[0], v[1]});
    doc.view.add({v[2], v[3]});
  }
  const Value* shapes = root.find("shapes");
  if (!shapes) fail(root, "document", "\"shapes\" is required");
  expect(*shapes, Value::Type::Array, "shapes");
  for (std::size_t i = 0; i < shapes->array.size(); ++i) {
    const Value& sv = shapes->array[i];
    const std::string sp = "shapes[" + std::to_string(i) + "]";
    expect(sv, Value::Type::Object, sp);
    only_keys(sv, {"color", "fill_rule", "contours", "fill", "stroke", "paint_order"}, sp);
    Shape shape;
    if (const Value* c = sv.find("color")) {
      expect(*c, Value::Type::String, sp + ".color");
      try {
        shape.color = parse_color(c->string);
      } catch (const Error& e) {
        fail(*c, sp + ".color", e.what());
      }
    }
    if (const Value* r = sv.find("fill_rule")) {
      expect(*r, Value::Type::String, sp + ".fill_rule");
      try {
        shape.fill_rule = parse_fill_rule(r->string);
      } catch (const Error& e) {
        fail(*r, sp + ".fill_rule", e.what());
      }
    }
    read_paint(sv, sp, shape);
    const Value* contours = sv.find("contours");
    if (!contours) fail(sv, sp, "\"contours\" is required");
    expect(*contours, Value::Type::Array, sp + ".contours");
    for (std::size_t j = 0; j < contours->array.size(); ++j) {
      ShapeContour contour = read_contour(contours->array[j], sp + ".contours[" + std::to_string(j) + "]");
      if (!contour.pieces.empty()) shape.contours.push_back(std::move(contour));
    }
    doc.shapes.push_back(std::move(shape));
  }
  return doc;
}

}  // namespace curvetext
