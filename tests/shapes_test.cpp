// Shapes (issue 4, item 4): JSON and SVG input, NURBS -> Bezier -> conics,
// even-odd through the nonzero mesher, and rendering against analytic
// coverage. Units: document units are pixels wherever a bound is in px.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <numbers>
#include <string>

#include "curvetext/curves.hpp"
#include "curvetext/error.hpp"
#include "curvetext/headless.hpp"
#include "curvetext/mesh.hpp"
#include "curvetext/renderer.hpp"
#include "curvetext/shape_image.hpp"
#include "curvetext/shapes.hpp"
#include "curvetext/tolerances.hpp"
#include "shapes/json.hpp"
#include "support/coverage.hpp"
#include "support/union_coverage.hpp"
#include "support/gpu.hpp"

namespace curvetext {
namespace {

const std::string kFixtures = std::string(CURVETEXT_SOURCE_DIR) + "/tests/fixtures/shapes/";

// --- Tolerances (with units) ----------------------------------------------------
// Exact conversions (knot insertion, arcs) agree with direct evaluation to
// rounding: relative to the shape's size.
constexpr double kExactRelative = 1e-9;
// docs/design.md section 3: the drawn outline within 1/16 px of the true one.
constexpr double kBoundPx = tolerance::kCubicApproximationPx;
// Dense polylines stand in for curves in the Hausdorff measurement; their
// chords are at most this far (px) from the curves they sample.
constexpr double kPolylineSlackPx = 2e-3;

// --- JSON syntax ------------------------------------------------------------------

struct JsonCase {
  const char* text;
  const char* error;  // nullptr: must parse; else a part of the message
};

TEST(Json, SyntaxCases) {
  const JsonCase cases[] = {
      {R"({"a": [1, -2.5e3, 0, 0.5, true, false, null, "x\u00e9\n"]})", nullptr},
      {R"(  [ ]  )", nullptr},
      {R"({"a": 1e-400})", nullptr},  // underflow to 0 is harmless
      {R"({"a": 01})", "line 1, column 8: a number may not have leading zeros"},
      {R"({"a": [1,]})", "line 1, column 10: unexpected ']'"},
      {R"({"a": 1 "b": 2})", "expected ',' or '}'"},
      {R"({"a": NaN})", "unexpected 'N'"},
      {R"({"a": Infinity})", "unexpected 'I'"},
      {R"({"a": 1e400})", "out of range"},
      {R"({"a": 1, "a": 2})", "line 1, column 10: duplicate key \"a\""},
      {"\"tab\there\"", "control character"},
      {R"("\ud800")", "surrogate"},
      {R"("\q")", "invalid escape"},
      {R"({"a": .5})", "unexpected '.'"},
      {R"({"a": -})", "a digit must follow '-'"},
      {R"({} x)", "after the end"},
      {R"({"a": 1)", "expected ',' or '}'"},
      {"{\"a\":\n  tru}", "line 2, column 3: invalid literal"},
      {R"({'a': 1})", "expected a string key"},
      {"", "unexpected end"},
  };
  for (const JsonCase& c : cases) {
    SCOPED_TRACE(c.text);
    if (!c.error) {
      EXPECT_NO_THROW(json::parse(c.text));
      continue;
    }
    try {
      json::parse(c.text);
      ADD_FAILURE() << "no error";
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), ErrorCode::InvalidArgument);
      EXPECT_NE(std::string(e.what()).find(c.error), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(json::parse(std::string(1000, '[') + std::string(1000, ']')), Error);  // depth limit, no stack overflow
  const json::Value v = json::parse(R"({"s": "\ud83d\ude00"})");
  EXPECT_EQ(v.find("s")->string, "\xF0\x9F\x98\x80");
}

// --- Shape documents: errors ------------------------------------------------------

std::string with_item(const std::string& item) { return R"({"shapes": [{"contours": [[)" + item + "]]}]}"; }

TEST(ShapeJson, BadInputGivesClearErrors) {
  const std::pair<std::string, const char*> cases[] = {
      {R"([])", "document: expected an object"},
      {R"({})", "\"shapes\" is required"},
      {R"({"shapes": [], "colour": 1})", "unknown key \"colour\""},
      {R"({"shapes": [{"contours": [], "fill_rule": "odd"}]})", "unknown fill rule 'odd'"},
      {R"({"shapes": [{"contours": [], "color": "#12"}]})", "shapes[0].color"},
      {R"({"size": [0, 10], "shapes": []})", "size"},
      {R"({"view": [0, 0, 0, 10], "shapes": []})", "xmin < xmax"},
      {with_item(R"({"line": [[0, 0]]})"), "at least 2 points"},
      {with_item(R"({"line": [[0, 0], [1, 2, 3]]})"), "a point is [x, y]"},
      {with_item(R"({"line": [[0, 0], [1e12, 0]]})"), "larger than"},
      {with_item(R"({"line": [[0, 0], ["1", 0]]})"), "expected a number"},
      {with_item(R"({"arc": {}})"), "unknown contour item \"arc\""},
      {with_item(R"({"line": [[0,0],[1,1]], "nurbs": {}})"), "a contour item is one of"},
      {with_item(R"({"bezier": {"points": [[0,0],[1,1],[2,0]], "weights": [0, 1, 1]}})"),
       "middle weight of a quadratic"},
      {with_item(R"({"bezier": {"points": [[0,0],[1,1],[2,0],[3,0]], "weights": [1, 0, 1, 1]}})"),
       "weight 0 is allowed only"},
      {with_item(R"({"bezier": {"points": [[0,0],[1,1],[2,0]], "weights": [1, -0.5, 1]}})"), "must be a positive"},
      {with_item(R"({"bezier": {"points": [[0,0],[1,1],[2,0]], "weights": [1, -2, 1]}})"), "must be a positive"},
      {with_item(R"({"bezier": {"points": [[0,0],[1,1],[2,0]], "weights": [1, 1]}})"), "need as many weights"},
      {with_item(R"({"nurbs": {"degree": 0, "points": [[0,0],[1,1]]}})"), "degree"},
      {with_item(R"({"nurbs": {"degree": 2.5, "points": [[0,0],[1,1],[2,0]]}})"), "whole number"},
      {with_item(R"({"nurbs": {"degree": 3, "points": [[0,0],[1,1],[2,0]]}})"), "at least 4 control points"},
      {with_item(R"({"nurbs": {"degree": 2, "points": [[0,0],[1,1],[2,0]], "knots": [0,0,0,1,1]}})"),
       "knot vector has 5 values; 3 control points of degree 2 need 6"},
      {with_item(R"({"nurbs": {"degree": 2, "points": [[0,0],[1,1],[2,0]], "knots": [0,0,1,0,1,1]}})"),
       "non-decreasing"},
      {with_item(R"({"nurbs": {"degree": 2, "points": [[0,0],[1,1],[2,0]], "knots": [0,0,0,0,0,0]}})"), "domain"},
      {with_item(R"({"nurbs": {"degree": 1, "points": [[0,0],[1,1],[2,0],[3,3]], "knots": [0,0,0.5,0.5,1,1]}})"),
       "multiplicity 2 > degree 1"},
      {with_item(R"({"nurbs": {"degree": 2, "points": [[0,0],[1,1],[2,0]], "weights": [0, 1, 1]}})"), "weight 0"},
      {with_item(R"({"nurbs": {"degree": 3, "points": [[0,0],[1,1],[2,0],[3,0]], "weights": [1, 0, 1, 1]}})"),
       "weight 0"},
      {with_item(R"({"nurbs": {"degree": 2, "points": [[0,0],[1,1],[2,0],[3,-1],[4,0]], "weights": [1, 1, 0, 1, 1],
                     "knots": [0,0,0,1,1,2,2,2]}})"),
       "an end at infinity"},
      {with_item(R"({"nurbs": {"degree": 2, "points": [[0,0],[1,1],[2,0]], "wieghts": [1, 1, 1]}})"),
       "unknown key \"wieghts\""},
  };
  for (const auto& [text, error] : cases) {
    SCOPED_TRACE(text);
    try {
      parse_shape_json(text);
      ADD_FAILURE() << "no error";
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), ErrorCode::InvalidArgument);
      EXPECT_NE(std::string(e.what()).find(error), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("line "), std::string::npos) << "no position: " << e.what();
    }
  }
}

// docs/design.md section 3: a rational quadratic with middle weight 0 (end weights
// > 0) is its chord: the reader keeps it as a line, in a bezier and in a
// NURBS piece whose middle control point has weight 0.
TEST(ShapeJson, ZeroMiddleWeightIsTheChord) {
  const ShapeDocument b = parse_shape_json(
      R"({"shapes": [{"contours": [[{"bezier": {"points": [[0,0],[5,9],[10,0]], "weights": [2, 0, 0.5]}}]]}]})");
  ASSERT_EQ(b.shapes[0].contours[0].pieces.size(), 1u);
  const RationalBezier& line = b.shapes[0].contours[0].pieces[0];
  ASSERT_EQ(line.degree(), 1);
  EXPECT_EQ(line.points[0].x, 0.0);
  EXPECT_EQ(line.points[1].x, 10.0);
  EXPECT_EQ(line.points[1].y, 0.0);

  // Two pieces (double knot at 1): the first has middle weight 0.
  const ShapeDocument n = parse_shape_json(R"({"shapes": [{"contours": [[{"nurbs": {"degree": 2,
      "points": [[0,0],[1,1],[2,0],[3,-1],[4,0]], "weights": [1,0,1,1,1], "knots": [0,0,0,1,1,2,2,2]}}]]}]})");
  const auto& pieces = n.shapes[0].contours[0].pieces;
  ASSERT_EQ(pieces.size(), 2u);
  EXPECT_EQ(pieces[0].degree(), 1);
  EXPECT_NEAR(pieces[0].points[1].x, 2.0, 1e-12);
  EXPECT_EQ(pieces[1].degree(), 2);

  // The API accepts the quadratic itself and draws its chord.
  std::vector<Segment> segs;
  append_quadratics(RationalBezier{{{0, 0}, {5, 9}, {10, 0}}, {1, 0, 1}}, 0.01, segs);
  ASSERT_EQ(segs.size(), 1u);
  EXPECT_EQ(segs[0].kind, Segment::Kind::Line);
  EXPECT_THROW(append_quadratics(RationalBezier{{{0, 0}, {5, 9}, {10, 0}}, {0, 1, 1}}, 0.01, segs), Error);
}

TEST(ShapeJson, FixturesLoad) {
  for (const char* name : {"circle-nurbs.json", "cubic-nurbs.json", "pentagram-evenodd.json", "handle-weights.json"}) {
    SCOPED_TRACE(name);
    const ShapeDocument doc = read_shape_file(kFixtures + name);
    ASSERT_FALSE(doc.shapes.empty());
    EXPECT_GT(doc.width_px, 0.0);
    EXPECT_FALSE(shape_outline(doc.shapes[0], 0.01).empty());
  }
  const ShapeDocument eo = read_shape_file(kFixtures + "pentagram-evenodd.json");
  EXPECT_EQ(eo.shapes[0].fill_rule, FillRule::EvenOdd);
  EXPECT_THROW(read_shape_file(kFixtures + "missing.json"), Error);
}

// --- SVG path data --------------------------------------------------------------

// Degrees of the pieces, contours separated by '|', and the last end point.
std::string signature(const std::vector<ShapeContour>& contours) {
  std::string s;
  for (const ShapeContour& c : contours) {
    if (!s.empty()) s += '|';
    for (const RationalBezier& b : c.pieces) s += static_cast<char>('0' + b.degree());
  }
  if (!contours.empty()) {
    const Vec2 e = contours.back().pieces.back().points.back();
    char buf[64];
    std::snprintf(buf, sizeof buf, " (%.6g,%.6g)", e.x, e.y);
    s += buf;
  }
  return s;
}

TEST(SvgPath, Cases) {
  const std::pair<const char*, const char*> cases[] = {
      {"M0 0 L10 0 L10 10 Z", "11 (10,10)"},
      {"M0 0 10 0 10 10z", "11 (10,10)"},         // implicit lineto after M
      {"m1 1 l2 0 0 2 h-2 v-2 z", "1111 (1,1)"},  // relative, implicit repeats
      {"M0,0C1,2 3,4 5,6S9,10 11,12", "33 (11,12)"},
      {"M0 0Q1 1 2 0T4 0", "22 (4,0)"},
      {"M.5.5L1e-3-2", "1 (0.001,-2)"},  // compact numbers
      {"M0 0L1E+1 2e0", "1 (10,2)"},
      {"M0 0A10 10 0 0 1 20 0", "22 (20,0)"},   // half circle: two 90 degree conics
      {"M0 0A5 5 0 0 1 20 0", "22 (20,0)"},     // radii too small: scaled up
      {"M0 0A0 5 0 0 1 20 0", "1 (20,0)"},      // zero radius: a line
      {"M0 0A5 5 0 0 1 0 0", ""},               // same end point: omitted
      {"M0 0a10 10 0 0010 10", "2 (10,10)"},    // compact flags
      {"M0 0a10 10 0 1010 10", "222 (10,10)"},  // large arc: 270 degrees, three pieces
      {"M0 0 L10 0 M20 20 L30 20 L30 30", "1|11 (30,30)"},
      {"M0 0 L10 0 Z L5 5", "1|1 (5,5)"},  // after Z: new subpath from the start
      {"M 0 0", ""},
  };
  for (const auto& [d, want] : cases) {
    SCOPED_TRACE(d);
    EXPECT_EQ(signature(parse_svg_path(d)), want);
  }
  // S reflects the previous cubic's second control point; T the quadratic's.
  const auto s = parse_svg_path("M0,0C1,2 3,4 5,6S9,10 11,12");
  EXPECT_EQ(s[0].pieces[1].points[1], (Vec2{7, 8}));
  const auto t = parse_svg_path("M0 0Q1 1 2 0T4 0");
  EXPECT_EQ(t[0].pieces[1].points[1], (Vec2{3, -1}));
  const auto half = parse_svg_path("M0 0A10 10 0 0 1 20 0");
  EXPECT_NEAR(half[0].pieces[0].weights[1], std::cos(std::numbers::pi / 4), 1e-15);
}

TEST(SvgPath, Errors) {
  const std::pair<const char*, const char*> cases[] = {
      {"L0 0", "must start with M"},
      {"0 0", "must start with M"},
      {"M0 0 L1", "expected a number, got the end"},
      {"M0 0 X1 1", "expected a number, got 'X'"},
      {"M0 0 L1e999 0", "out of range"},
      {"M0 0 L2e9 0", "larger than"},
      {"M0 0 A1 1 0 2 0 1 1", "arc flag"},
      {"M0 0 Z 1 1", "numbers after Z"},
      {"M0 0 L--1 0", "expected a number"},
  };
  for (const auto& [d, error] : cases) {
    SCOPED_TRACE(d);
    try {
      parse_svg_path(d);
      ADD_FAILURE() << "no error";
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), ErrorCode::InvalidArgument);
      EXPECT_NE(std::string(e.what()).find(error), std::string::npos) << e.what();
    }
  }
}

TEST(SvgFile, ReadsPathsFillsAndViewBox) {
  const ShapeDocument doc = read_shape_file(kFixtures + "star-rules.svg");
  ASSERT_EQ(doc.shapes.size(), 2u);
  EXPECT_EQ(doc.shapes[0].fill_rule, FillRule::EvenOdd);  // attribute; colour inherited from <g>
  EXPECT_NEAR(doc.shapes[0].color.r, 0x1b / 255.0, 1e-6);
  EXPECT_EQ(doc.shapes[1].fill_rule, FillRule::NonZero);  // from style
  EXPECT_NEAR(doc.shapes[1].color.r, 0xb2 / 255.0, 1e-6);
  EXPECT_EQ(doc.width_px, 440);
  EXPECT_EQ(doc.view.min.y, -220);  // mirrored to y-up
  EXPECT_EQ(doc.shapes[0].contours[0].pieces[0].points[0], (Vec2{110, -10}));

  const std::pair<const char*, const char*> errors[] = {
      {"<svg><path d='M0 0 L1 1' transform='rotate(3'/></svg>", "line 1, column 6: transform 'rotate(3' is malformed"},
      {"<svg><text>Hi</text></svg>", "line 1, column 6: <text> is not supported"},
      {"<html/>", "first element must be <svg>"},
      {"", "no element found"},
      {"<svg><pattern id='g'/><path d='M0 0 L1 1 L1 0' fill='url(#g)'/></svg>", "fill refers to <pattern>"},
      {"<svg><path d='M0 0 L1 1 L1 0' fill-rule='odd'/></svg>", "fill rule"},
      {"<svg viewBox='0 0 -1 4'></svg>", "viewBox"},
      {"<svg><path d='M0 0 L1 1 Q'/></svg>", "SVG path data"},
      {"<svg><path d='M0 0 L1 1></svg>", "not well-formed"},
  };
  for (const auto& [text, error] : errors) {
    SCOPED_TRACE(text);
    try {
      parse_svg(text);
      ADD_FAILURE() << "no error";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(error), std::string::npos) << e.what();
    }
  }
  // Paths in <defs> are not drawn; fill="none" draws nothing.
  const ShapeDocument skip = parse_svg(
      "<svg><defs><path d='M0 0 L1 1 L0 1'/></defs><path fill='none' d='M0 0 L1 1 L0 1'/>"
      "<path fill='rgb(255, 0, 0)' d='M0 0 L1 1 L0 1'/></svg>");
  ASSERT_EQ(skip.shapes.size(), 1u);
  EXPECT_EQ(skip.shapes[0].color.r, 1.0f);
}

// The conics of a rotated elliptical arc lie on the exact ellipse.
TEST(SvgPath, ArcsAreExactConics) {
  const double cx = 160, cy = 120, rx = 120, ry = 60, phi = std::numbers::pi / 6;
  const auto contours = parse_svg_path(
      "M 263.92304845413264 180 A 120 60 30 1 1 56.076951545867359 60 A 120 60 30 1 1 263.92304845413264 180 Z");
  ASSERT_EQ(contours.size(), 1u);
  double worst = 0.0;
  for (const RationalBezier& piece : contours[0].pieces) {
    ASSERT_EQ(piece.degree(), 2);
    EXPECT_GE(piece.weights[1], std::cos(std::numbers::pi / 4) - 1e-12);  // pieces of at most 90 degrees
    for (int i = 0; i <= 100; ++i) {
      const Vec2 p = evaluate(piece, i / 100.0) - Vec2{cx, cy};
      const double u = std::cos(phi) * p.x + std::sin(phi) * p.y, v = -std::sin(phi) * p.x + std::cos(phi) * p.y;
      // |implicit| ~ 2 * (radial offset) / radius
      worst = std::max(worst, std::abs(std::hypot(u / rx, v / ry) - 1.0));
    }
  }
  std::printf("SVG arc -> conics: largest relative deviation from the ellipse %.2e\n", worst);
  EXPECT_LE(worst, kExactRelative);
}

// Radii far too small (1e-300) are scaled up to a half ellipse (SVG 1.1
// F.6.6); squaring them gave NaN (undefined behaviour, then a blank image).
TEST(SvgPath, TinyArcRadiiScaleUpToAHalfEllipse) {
  for (const char* radii : {"1e-300 1e-300", "1e-160 1e-160", "1e-300 2e-300", "3e-320 3e-320"}) {
    SCOPED_TRACE(radii);
    const std::string d = std::string("M10 50 A") + radii + " 0 0 1 90 50 Z";
    const auto contours = parse_svg_path(d);
    ASSERT_EQ(contours.size(), 1u);
    for (const RationalBezier& piece : contours[0].pieces)
      for (Vec2 q : piece.points) ASSERT_TRUE(std::isfinite(q.x) && std::isfinite(q.y));
    // Equal radii: a half circle of radius 40 about (50, 50); radii 1:2 keep
    // their ratio, a half ellipse through both end points: rx = 40, ry = 80.
    const bool circle = std::string(radii) != "1e-300 2e-300";
    Shape shape;
    shape.contours = contours;
    const double area = std::abs(shape_outline(shape, 1e-3).signed_area());
    const double want = std::numbers::pi * 40 * (circle ? 40 : 80) / 2;
    EXPECT_NEAR(area, want, 1e-9 * want);
  }
}

// Strokes become unfilled shapes with their style in document units, fill
// and stroke in paint order; fill-opacity and a path's opacity fade its fill.
TEST(SvgFile, StrokesAndOpacity) {
  const ShapeDocument strokes = parse_svg(
      "<svg><g transform='scale(2)' stroke-linejoin='round'><path d='M0 0 L9 0 L9 9' fill='none' stroke='black' "
      "stroke-width='3' stroke-dasharray='1, 2' stroke-opacity='.5' stroke-linecap='square'/>"
      "<path d='M0 0 L9 0 L9 9Z' stroke='red' paint-order='stroke' vector-effect='non-scaling-stroke'/></g></svg>");
  ASSERT_EQ(strokes.shapes.size(), 3u);
  const Shape& a = strokes.shapes[0];
  ASSERT_TRUE(a.stroke.has_value());
  EXPECT_FALSE(a.filled);
  EXPECT_FALSE(a.contours[0].closed);
  EXPECT_EQ(a.stroke->style.width, 6.0);  // user width times the transform's scale
  EXPECT_EQ(a.stroke->style.join, LineJoin::Round);
  EXPECT_EQ(a.stroke->style.cap, LineCap::Square);
  EXPECT_EQ(a.stroke->style.dashes, (std::vector<double>{2.0, 4.0}));
  EXPECT_FLOAT_EQ(a.stroke->color.a, 0.5f);
  EXPECT_TRUE(strokes.shapes[1].stroke.has_value());  // stroke first
  EXPECT_TRUE(strokes.shapes[1].contours[0].closed);
  EXPECT_EQ(strokes.shapes[1].stroke->style.width_unit, StrokeWidthUnit::Device);
  EXPECT_TRUE(strokes.shapes[2].filled);
  const std::pair<const char*, const char*> errors[] = {
      {"<svg><path d='M0 0 L9 0 L9 9' stroke='red' stroke-linejoin='mitre'/></svg>", "stroke-linejoin 'mitre'"},
      {"<svg><path d='M0 0 L9 0 L9 9' fill-opacity='half'/></svg>", "fill-opacity 'half'"},
  };
  for (const auto& [text, error] : errors) {
    SCOPED_TRACE(text);
    try {
      parse_svg(text);
      ADD_FAILURE() << "no error";
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), ErrorCode::InvalidArgument);
      EXPECT_NE(std::string(e.what()).find(error), std::string::npos) << e.what();
    }
  }
  // Opacity on a group of two shapes: one layer at that opacity (the shapes keep their alpha).
  const ShapeDocument layered =
      parse_svg("<svg><g opacity='0.5'><path d='M0 0 L9 0 L9 9'/><path d='M0 0 L9 0 L9 9'/></g></svg>");
  ASSERT_EQ(layered.groups.size(), 1u);
  EXPECT_EQ(layered.groups[0].end, 2u);
  EXPECT_FLOAT_EQ(layered.groups[0].opacity, 0.5f);
  EXPECT_FLOAT_EQ(layered.shapes[0].color.a, 1.0f);
  const ShapeDocument doc = parse_svg(
      "<svg><g fill-opacity='0.5'><path d='M0 0 L9 0 L9 9'/>"
      "<path d='M0 0 L9 0 L9 9' style='opacity: 50%' stroke='none' stroke-width='4'/></g>"
      "<path d='M0 0 L9 0 L9 9' display='none'/><g style='display:none'><path d='M0 0 L9 0 L9 9'/></g></svg>");
  ASSERT_EQ(doc.shapes.size(), 2u);
  EXPECT_FLOAT_EQ(doc.shapes[0].color.a, 0.5f);
  EXPECT_FLOAT_EQ(doc.shapes[1].color.a, 0.25f);
}

// A subpath without area (an open two-point line) is drawn in SVG only by
// a stroke: its fill covers nothing, and is left out as rsvg leaves it out.
// An "S" from a Breeze icon (applets/256/org.kde.plasma.kickoff.svg, text
// converted to paths) whose subpath ends 5e-6 below its start, arriving and
// leaving straight down: the closing line folds back over the first curve.
// Closed by moving the last point onto the start instead (within a quarter of
// the tolerance), it meshes; with the hairpin line build_mesh refused it.
TEST(SvgPath, TinyClosingGapIsClosedByTheLastCurve) {
  Shape shape;
  shape.contours = parse_svg_path(
      "M 115.51794875625801 -26.410854216091316 Q 115.51794875625801 -27.147288332290948 114.97972675914801 "
      "-27.558141028762456 Q 114.44150476203799 -27.968993725233968 113.528869643278 -27.968993725233968 Q "
      "113.060845717844 -27.968993725233968 112.663029895248 -27.899231120203368 Q 112.265214072652 "
      "-27.829468515172767 112.000000180534 -27.705432038954957 L 112.000000180534 -27.038765512253278 Q "
      "112.280812529562 -27.162797004003735 112.69423684023 -27.263571967992565 Q 113.115455363772 "
      "-27.364346931981398 113.560066557098 -27.364346931981398 Q 114.184095113956 -27.364346931981398 "
      "114.49610437680401 -27.124036788996669 Q 114.81591788368802 -26.883726646011937 114.81591788368802 "
      "-26.472873949540428 Q 114.81591788368802 -26.20155643206482 114.69891441012001 -26.015510191332599 Q "
      "114.58191093655201 -25.829462953706905 114.29330437465001 -25.674425084359036 Q 114.01249202562201 "
      "-25.511634374494975 113.50546694233201 -25.333338980492009 Q 112.795641856888 -25.077525150261838 "
      "112.42902294811201 -24.705432668797396 Q 112.07020828337201 -24.333339190439489 112.07020828337201 "
      "-23.689928194605969 Q 112.07020828337201 -23.248068123643577 112.29642101763402 -22.937990391160898 "
      "Q 112.52262372073402 -22.620160815055499 112.92043954333 -22.44961826156872 Q 113.326059609962 "
      "-22.27907570808194 113.848683150162 -22.27907570808194 Q 114.30890283156 -22.27907570808194 "
      "114.69112019724601 -22.364349975505739 Q 115.07333756293201 -22.449624242929541 115.38534682578002 "
      "-22.58915643124503 L 115.16693833555401 -23.186055368448763 Q 114.87832174249002 -23.062024873591771 "
      "114.53510553466002 -22.976753596848383 Q 114.199693570866 -22.89147932942458 113.83308469325202 "
      "-22.89147932942458 Q 113.31046115305202 -22.89147932942458 113.04524726093402 -23.116284788270399 Q "
      "112.78003336881601 -23.333339400386969 112.78003336881601 -23.69768003822869 Q 112.78003336881601 "
      "-23.976750396220492 112.89703684238401 -24.162796636952713 Q 113.01405034711402 -24.34884287768493 "
      "113.27925420807 -24.496129900303551 Q 113.54446810018801 -24.643416922922171 113.99688353755 "
      "-24.81395947640895 Q 114.48831016393001 -24.99225387351845 114.82372212772401 -25.201556642012299 Q "
      "115.16693833555401 -25.403106569989959 115.33854142388802 -25.689928771604478 Q 115.51794875625801 "
      "-25.976749976325529 115.51794875625801 -26.410859200558669 Z");
  const double tolerance = 1.0 / 64;
  const Outline outline = fill_outline(shape, tolerance);
  ASSERT_EQ(outline.contours().size(), 1u);
  const Segment& last = outline.contours()[0].segments.back();
  EXPECT_EQ(last.kind, Segment::Kind::Conic);
  EXPECT_EQ(last.p[2], outline.contours()[0].segments.front().p[0]);
  Mesh mesh;
  ASSERT_NO_THROW(mesh = build_mesh(outline));
  EXPECT_TRUE(check_mesh(mesh, outline).ok());
  EXPECT_NEAR(mesh_area(mesh), std::abs(outline.signed_area()), 1e-9);
  // A contour as small as the gap keeps its closing edge.
  Shape tiny;
  tiny.contours = parse_svg_path("M 0 0 L 1e-6 0 L 1e-6 1e-6 Z");
  EXPECT_EQ(fill_outline(tiny, tolerance).contours().at(0).segments.size(), 3u);
}

TEST(SvgFile, SubpathsWithoutAreaFillNothing) {
  for (const char* d : {"M10 10 L90 90", "M0 0 L10 0 L5 0 Z", "M0 0 L9 0 L9 9 Z M3 3 L3 3"}) {
    SCOPED_TRACE(d);
    const ShapeDocument doc = parse_svg(std::string("<svg><path d='") + d + "'/></svg>");
    std::size_t contours = 0;
    for (const Shape& s : doc.shapes) contours += s.contours.size();
    EXPECT_EQ(contours, std::string(d).starts_with("M0 0 L9") ? 1u : 0u);
    // Stroked, every subpath is kept (a line's stroke has area).
    const ShapeDocument stroked = parse_svg(std::string("<svg><path fill='none' stroke='red' d='") + d + "'/></svg>");
    ASSERT_EQ(stroked.shapes.size(), 1u);
    EXPECT_EQ(stroked.shapes[0].contours.size(), std::string(d).starts_with("M0 0 L9") ? 2u : 1u);
  }
  EXPECT_EQ(parse_svg("<svg><path d='M0 0 L9 0 L9 9'/></svg>").shapes.size(), 1u);  // open, with area
}

TEST(SvgFile, SegmentCountsAreLimited) {
  std::string zigzag = "M0 0";
  for (std::size_t i = 0; i <= tolerance::kMaxSegmentsPerPath / 2; ++i) zigzag += "l1 1l1 -1";
  try {
    parse_svg_path(zigzag);
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("segments in one path"), std::string::npos) << e.what();
  }
  std::string half = "M0 0";
  for (std::size_t i = 0; i < tolerance::kMaxSegmentsPerPath / 4; ++i) half += "l1 1l1 -1";
  std::string doc = "<svg>";
  for (std::size_t k = 0; k <= tolerance::kMaxSegmentsPerDocument / (tolerance::kMaxSegmentsPerPath / 2); ++k)
    doc += "<path d='" + half + "'/>";
  doc += "</svg>";
  try {
    parse_svg(doc);
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("segments in the document"), std::string::npos) << e.what();
  }
}

// A file without end (/dev/zero) stops at the size limit instead of reading forever.
TEST(SvgFile, EndlessFileStopsAtTheLimit) {
  const std::filesystem::path link = std::filesystem::temp_directory_path() / "curvetext-endless-shape.svg";
  std::filesystem::remove(link);
  std::filesystem::create_symlink("/dev/zero", link);
  try {
    read_shape_file(link.string());
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::Io);
    EXPECT_NE(std::string(e.what()).find("larger than the limit"), std::string::npos) << e.what();
  }
  std::filesystem::remove(link);
}

// --- NURBS --------------------------------------------------------------------------

// Direct de Boor evaluation (The NURBS Book, A4.1), independent of the blossom
// code in lib/shapes.
Vec2 de_boor(const Nurbs& c, double u) {
  const int p = c.degree, n = static_cast<int>(c.points.size()) - 1;
  const std::vector<double>& U = c.knots;
  int k = p;
  while (k < n && !(u < U[static_cast<std::size_t>(k) + 1])) ++k;
  while (k > p && !(U[static_cast<std::size_t>(k)] < U[static_cast<std::size_t>(k) + 1])) --k;
  struct Hv {
    double x, y, w;
  };
  std::vector<Hv> d(static_cast<std::size_t>(p) + 1);
  for (int j = 0; j <= p; ++j) {
    const auto i = static_cast<std::size_t>(j + k - p);
    const double w = c.weights.empty() ? 1.0 : c.weights[i];
    d[static_cast<std::size_t>(j)] = {c.points[i].x * w, c.points[i].y * w, w};
  }
  for (int r = 1; r <= p; ++r)
    for (int j = p; j >= r; --j) {
      const double lo = U[static_cast<std::size_t>(j + k - p)], hi = U[static_cast<std::size_t>(j + 1 + k - r)];
      const double a = (u - lo) / (hi - lo);
      Hv& dj = d[static_cast<std::size_t>(j)];
      const Hv& dm = d[static_cast<std::size_t>(j) - 1];
      dj = {(1 - a) * dm.x + a * dj.x, (1 - a) * dm.y + a * dj.y, (1 - a) * dm.w + a * dj.w};
    }
  return {d[static_cast<std::size_t>(p)].x / d[static_cast<std::size_t>(p)].w,
          d[static_cast<std::size_t>(p)].y / d[static_cast<std::size_t>(p)].w};
}

// Largest distance from the Bezier pieces (sampled at their own parameters,
// mapped linearly to the knot spans) to the de Boor points.
double bezier_vs_de_boor(const Nurbs& c) {
  const std::vector<RationalBezier> pieces = nurbs_to_beziers(c);
  const std::size_t p = static_cast<std::size_t>(c.degree);
  std::size_t k = 0;
  double worst = 0.0;
  for (std::size_t span = p; span + 1 < c.knots.size() - p; ++span) {
    const double a = c.knots[span], b = c.knots[span + 1];
    if (!(a < b)) continue;
    for (int i = 0; i <= 50; ++i) {
      const double t = i / 50.0;
      worst = std::max(worst, distance(evaluate(pieces.at(k), t), de_boor(c, a + t * (b - a))));
    }
    ++k;
  }
  EXPECT_EQ(k, pieces.size());
  return worst;
}

double point_segment(Vec2 q, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double l2 = dot(ab, ab);
  const double t = l2 > 0 ? std::clamp(dot(q - a, ab) / l2, 0.0, 1.0) : 0.0;
  return distance(q, a + ab * t);
}

double polyline_distance(Vec2 q, const std::vector<Vec2>& line) {
  double best = INFINITY;
  for (std::size_t i = 0; i + 1 < line.size(); ++i) best = std::min(best, point_segment(q, line[i], line[i + 1]));
  return best;
}

// Two-sided distance between the NURBS (dense de Boor samples) and its lines
// and conics (dense samples), in the curve's units (px here).
double hausdorff_to_approximation(const Nurbs& c, double tolerance, std::size_t* count = nullptr) {
  std::vector<Segment> segs;
  for (const RationalBezier& b : nurbs_to_beziers(c)) append_quadratics(b, tolerance, segs);
  if (count) *count = segs.size();
  const std::size_t p = static_cast<std::size_t>(c.degree);
  const double lo = c.knots[p], hi = c.knots[c.points.size()];
  std::vector<Vec2> truth, approx;
  for (int i = 0; i <= 6000; ++i) truth.push_back(de_boor(c, lo + (hi - lo) * i / 6000.0));
  for (const Segment& s : segs)
    for (int i = 0; i <= 300; ++i) approx.push_back(evaluate(s, i / 300.0));
  double worst = 0.0;
  for (Vec2 q : truth) worst = std::max(worst, polyline_distance(q, approx));
  for (std::size_t i = 0; i < approx.size(); i += 3) worst = std::max(worst, polyline_distance(approx[i], truth));
  return worst;
}

TEST(Nurbs, QuadraticCircleIsExact) {
  const double s = std::numbers::sqrt2 / 2, r = 1000;
  const Nurbs circle{2,
                     {{r, 0}, {r, r}, {0, r}, {-r, r}, {-r, 0}, {-r, -r}, {0, -r}, {r, -r}, {r, 0}},
                     {1, s, 1, s, 1, s, 1, s, 1},
                     {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1}};
  const auto pieces = nurbs_to_beziers(circle);
  ASSERT_EQ(pieces.size(), 4u);
  double worst = 0.0;
  for (const RationalBezier& b : pieces) {
    std::vector<Segment> segs;
    append_quadratics(b, 1e-3, segs);
    ASSERT_EQ(segs.size(), 1u);
    EXPECT_NEAR(segs[0].weight, s, 1e-15);
    for (int i = 0; i <= 100; ++i) worst = std::max(worst, std::abs(length(evaluate(segs[0], i / 100.0)) - r));
  }
  EXPECT_LE(worst, kExactRelative * r);
  EXPECT_LE(bezier_vs_de_boor(circle), kExactRelative * r);
}

TEST(Nurbs, UnclampedAndRationalQuadraticsAreExact) {
  // Uniform unclamped knots: the curve is the part over [u_2, u_5].
  const Nurbs c{2, {{0, 0}, {100, 200}, {250, 180}, {300, 20}, {420, 90}}, {1, 3, 0.5, 2, 1}, {0, 1, 2, 3, 4, 5, 6, 7}};
  EXPECT_LE(bezier_vs_de_boor(c), kExactRelative * 420);
  double worst = 0.0;
  for (const RationalBezier& b : nurbs_to_beziers(c)) {
    std::vector<Segment> segs;
    append_quadratics(b, 1e-3, segs);
    ASSERT_EQ(segs.size(), 1u);  // degree 2: one exact conic per span, whatever the tolerance
    for (int i = 0; i <= 20; ++i) {
      const Vec2 q = evaluate(segs[0], i / 20.0);
      double best = INFINITY;
      for (int j = 0; j <= 4000; ++j) best = std::min(best, distance(q, evaluate(b, j / 4000.0)));
      worst = std::max(worst, best);
    }
  }
  EXPECT_LE(worst, 0.05);  // sampling of the reference at 4000 points, px
}

TEST(Nurbs, CubicNonUniformWithinTheBound) {
  // The same curve as tests/fixtures/shapes/cubic-nurbs.json.
  const Nurbs cubic{3,
                    {{20, 20}, {40, 180}, {120, 190}, {150, 60}, {220, 20}, {260, 170}, {300, 30}},
                    {},
                    {0, 0, 0, 0, 0.1, 0.45, 0.5, 1, 1, 1, 1}};
  const double exact = bezier_vs_de_boor(cubic);
  std::size_t count = 0;
  const double d = hausdorff_to_approximation(cubic, kBoundPx, &count);
  std::printf(
      "cubic NURBS (non-uniform knots): Bezier pieces vs de Boor %.2e px; %zu conics, Hausdorff %.4f px "
      "(bound %.4f px)\n",
      exact, count, d, kBoundPx);
  EXPECT_LE(exact, kExactRelative * 300);
  EXPECT_LE(d, kBoundPx + kPolylineSlackPx);

  Nurbs rational = cubic;
  rational.weights = {1, 2, 0.5, 1, 3, 1, 1};
  const double dr = hausdorff_to_approximation(rational, kBoundPx, &count);
  std::printf("rational cubic NURBS: %zu conics, Hausdorff %.4f px\n", count, dr);
  EXPECT_LE(bezier_vs_de_boor(rational), kExactRelative * 300);
  EXPECT_LE(dr, kBoundPx + kPolylineSlackPx);

  const Nurbs quintic{5,
                      {{0, 0}, {60, 240}, {160, -80}, {260, 260}, {330, 10}, {420, 200}, {500, 0}},
                      {1, 0.7, 1.8, 1, 0.4, 2.5, 1},
                      {0, 0, 0, 0, 0, 0, 0.3, 1, 1, 1, 1, 1, 1}};
  const double dq = hausdorff_to_approximation(quintic, kBoundPx, &count);
  std::printf("rational quintic NURBS: %zu conics, Hausdorff %.4f px\n", count, dq);
  EXPECT_LE(bezier_vs_de_boor(quintic), kExactRelative * 500);
  EXPECT_LE(dq, kBoundPx + kPolylineSlackPx);
  // A tighter tolerance is honoured as well.
  EXPECT_LE(hausdorff_to_approximation(rational, 0.01), 0.01 + kPolylineSlackPx);
}

// --- Even-odd -----------------------------------------------------------------------

Outline pentagram(double r, Vec2 c = {0, 0}) {
  Outline o;
  for (int k = 0; k < 5; ++k) {
    const double a = (90 + 144 * k) * std::numbers::pi / 180;
    const Vec2 p = c + Vec2{r * std::cos(a), r * std::sin(a)};
    if (k == 0)
      o.move_to(p);
    else
      o.line_to(p);
  }
  o.close();
  return o;
}

Outline circle(Vec2 c, double r, bool clockwise = false) {
  const double w = std::numbers::sqrt2 / 2, s = clockwise ? -1 : 1;
  Outline o;
  o.move_to(c + Vec2{r, 0});
  o.conic_to(c + Vec2{r, s * r}, c + Vec2{0, s * r}, w);
  o.conic_to(c + Vec2{-r, s * r}, c + Vec2{-r, 0}, w);
  o.conic_to(c + Vec2{-r, -s * r}, c + Vec2{0, -s * r}, w);
  o.conic_to(c + Vec2{r, -s * r}, c + Vec2{r, 0}, w);
  o.close();
  return o;
}

Outline merged(const Outline& a, const Outline& b) {
  Outline o = a;
  for (const Contour& c : b.contours()) o.contours().push_back(c);
  return o;
}

// The nonzero area of the converted outline (through the mesher) is the
// even-odd area, and every loop winds with its odd side on the left.
void expect_even_odd_area(const Outline& in, double want, const char* name) {
  const Outline out = even_odd_to_nonzero(in);
  const double mesh = mesh_area(build_mesh(out));
  std::printf("even-odd %s: area %.6f (mesh %.6f), analytic %.6f\n", name, out.signed_area(), mesh, want);
  EXPECT_NEAR(out.signed_area(), want, 1e-9 * want) << name;
  EXPECT_NEAR(mesh, want, 1e-6 * want) << name;
}

TEST(EvenOdd, AreasAgainstClosedForms) {
  const double R = 100, ri = R * std::cos(2 * std::numbers::pi / 5) / std::cos(std::numbers::pi / 5);
  const double star = 10 * 0.5 * R * ri * std::sin(std::numbers::pi / 5);
  const double pentagon = 2.5 * ri * ri * std::sin(2 * std::numbers::pi / 5);
  expect_even_odd_area(pentagram(R), star - pentagon, "pentagram");
  EXPECT_NEAR(mesh_area(build_mesh(pentagram(R))), star, 1e-6 * star);  // nonzero: the pentagon filled

  // Nested, non-crossing: a ring, whatever the orientations.
  const double pi = std::numbers::pi;
  expect_even_odd_area(merged(circle({0, 0}, 50), circle({0, 0}, 20)), pi * (2500 - 400), "ring (same direction)");
  expect_even_odd_area(merged(circle({0, 0}, 50), circle({5, 3}, 20, true)), pi * (2500 - 400), "ring (opposite)");
  // Crossing conics: two discs overlapping, the lens is even.
  const double r = 40, d = 30;
  const double lens = 2 * r * r * std::acos(d / (2 * r)) - 0.5 * d * std::sqrt(4 * r * r - d * d);
  expect_even_odd_area(merged(circle({0, 0}, r), circle({d, 0}, r)), 2 * pi * r * r - 2 * lens, "two discs");
  // A disc crossing a pentagram (line/conic crossings), offset so no crossing is at a vertex: checked
  // against the mesh of the same outline, as the closed form is long.
  const Outline mixed = merged(pentagram(R), circle({7, 3}, 45));
  const Outline mixed_out = even_odd_to_nonzero(mixed);
  EXPECT_NEAR(mixed_out.signed_area(), mesh_area(build_mesh(mixed_out)), 1e-6 * star);
}

Outline repeated(const Outline& o, int times) {
  Outline out;
  for (int k = 0; k < times; ++k)
    for (const Contour& c : o.contours()) out.contours().push_back(c);
  return out;
}

// Pieces on top of each other cancel in pairs under the even-odd rule: a
// contour drawn an even number of times fills nothing, an odd number of
// times fills itself (the nonzero fill is the disc every time).
TEST(EvenOdd, RetracedContoursCancelInPairs) {
  const double pi = std::numbers::pi;
  for (int times = 1; times <= 4; ++times) {
    const Outline disc = repeated(circle({3, 1}, 10), times);
    const double want = times % 2 ? pi * 100 : 0.0;
    const Outline out = fill_boundary(disc, FillRule::EvenOdd);
    EXPECT_NEAR(out.signed_area(), want, 1e-9 * pi * 100) << times << " times";
    EXPECT_NEAR(even_odd_to_nonzero(disc).signed_area(), want, 1e-9 * pi * 100) << times << " times";
    MeshOptions options;
    options.fill_rule = FillRule::EvenOdd;
    EXPECT_NEAR(mesh_area(build_mesh(disc, options)), want, 1e-6 * pi * 100) << times << " times";
    EXPECT_NEAR(mesh_area(build_mesh(disc)), pi * 100, 1e-6 * pi * 100) << times << " times";
  }
}

// even_odd_to_nonzero (its own arrangement, parity by rays) against the
// mesher's even-odd rule (the crossing resolver's side windings): two
// independent constructions of one region. Random self-crossing paths of
// lines, quadratics, cubics and arcs.
TEST(EvenOdd, AgreesWithTheMeshersRule) {
  const char* paths[] = {
      "M 51.561 33.912 L 35.661 9.219 Q 1.948 55.405 44.046 1.808 Q 51.743 29.545 96.077 11.285 L 97.170 10.478 "
      "Q 27.192 90.590 18.155 75.578 C 84.959 67.597 94.600 40.595 53.660 51.478 C 70.042 8.946 5.753 68.821 "
      "42.532 7.241 Z",
      "M 21.952 51.053 C 11.044 55.094 50.334 25.953 8.694 61.509 Q 38.262 7.883 21.178 62.162 L 59.202 40.781 Z "
      "M 53.912 67.256 Q 66.923 95.637 46.155 61.109 C 56.279 11.625 47.059 29.448 16.724 52.442 A 28.67 27.45 "
      "60.3 1 0 22.626 71.969 A 22.21 22.96 30.9 0 0 79.169 86.327 Q 39.991 43.558 0.867 53.689 Z M 99.066 90.982 "
      "Q 34.385 32.576 8.699 80.375 A 12.90 36.73 4.8 0 0 86.789 51.546 C 74.414 78.831 60.054 13.858 12.100 8.959 "
      "A 19.08 15.22 27.2 1 0 30.413 29.491 A 7.04 46.56 55.0 1 1 61.282 15.336 L 0.653 63.885 L 54.429 94.779 Z",
      "M 18.602 5.470 L 24.509 86.235 A 31.05 34.54 25.7 1 1 20.733 42.388 A 47.04 41.13 78.0 1 1 18.859 44.449 "
      "Q 92.272 23.042 12.351 57.112 L 45.530 54.949 Q 51.255 88.388 41.357 93.952 Z",
      "M 66.449 86.980 C 92.643 79.682 35.519 53.638 8.478 6.139 L 87.429 58.125 Q 21.029 21.687 22.029 93.347 "
      "L 98.992 30.951 Z M 89.409 50.999 L 72.544 89.673 A 27.47 8.41 87.9 0 1 62.313 54.869 Q 94.949 83.115 "
      "41.760 4.493 A 7.34 19.95 24.2 1 0 40.059 31.424 L 92.473 62.089 Z",
  };
  MeshOptions odd;
  odd.fill_rule = FillRule::EvenOdd;
  for (const char* d : paths) {
    Shape shape;
    shape.contours = parse_svg_path(d);
    const Outline nonzero = fill_outline(shape, 1.0 / 64);
    shape.fill_rule = FillRule::EvenOdd;
    const double converted = mesh_area(build_mesh(fill_outline(shape, 1.0 / 64)));
    const double meshed = mesh_area(build_mesh(nonzero, odd));
    EXPECT_NEAR(converted, meshed, 1e-6 * meshed) << d;
  }
}

// Scribbles: three subpaths of lines, quadratics, cubics and arcs crossing
// themselves and each other at random. Their hulls overlap in many places,
// which hull separation must split within its work budget; both rules mesh
// and pass the mesh's own check.
TEST(EvenOdd, SelfCrossingScribblesAreMeshed) {
  const char* paths[] = {
      "M 27.286 16.482 A 48.86 9.52 64.3 1 0 67.591 32.083 A 35.52 19.99 41.7 0 1 1.891 16.498 L 67.208 91.341 "
      "A 29.31 30.40 63.4 1 0 55.009 69.620 Q 58.860 32.722 90.414 70.110 L 92.430 56.291 A 42.14 12.54 9.2 0 1 "
      "81.850 14.243 Z M 41.759 63.042 C 63.940 41.029 89.202 83.957 58.819 81.715 L 43.138 49.835 L 70.788 0.580 "
      "L 80.787 45.367 A 48.48 36.99 78.9 1 1 90.885 91.044 A 39.41 33.65 74.0 1 1 37.205 77.847 Q 96.062 71.816 "
      "66.577 7.936 Z M 41.232 24.040 C 95.292 8.292 1.711 16.026 54.690 66.810 Q 83.352 68.946 9.003 68.345 Z",
      "M 2.668 93.240 Q 41.069 8.530 45.764 34.436 L 75.530 38.438 A 41.56 27.42 43.6 1 1 42.353 78.763 L 78.243 "
      "37.834 C 98.164 5.077 5.589 71.795 62.265 82.130 L 24.923 57.568 Z M 91.608 88.964 L 82.393 80.167 A 12.51 "
      "30.76 29.1 1 1 96.570 64.693 C 34.336 78.945 59.326 13.876 17.078 10.774 C 13.667 17.303 92.205 59.285 "
      "15.683 51.411 C 27.684 69.349 35.651 38.304 14.432 79.178 C 72.863 78.051 32.993 27.408 56.374 75.904 L "
      "51.607 15.256 Z M 91.318 13.656 L 60.469 56.543 L 16.688 49.260 A 7.06 31.54 80.3 1 0 1.617 34.622 C 72.590 "
      "49.288 75.352 36.733 95.255 38.235 Q 37.079 49.843 72.824 44.246 A 18.39 6.11 3.1 0 0 22.907 94.862 L "
      "16.905 26.834 C 32.279 77.198 18.626 75.274 97.225 70.602 Z",
  };
  for (const char* d : paths) {
    Shape shape;
    shape.contours = parse_svg_path(d);
    const Outline outline = fill_outline(shape, 1.0 / 64);
    for (const FillRule rule : {FillRule::NonZero, FillRule::EvenOdd}) {
      MeshOptions options;
      options.fill_rule = rule;
      Mesh mesh;
      ASSERT_NO_THROW(mesh = build_mesh(outline, options)) << d;
      const MeshCheck check = check_mesh(mesh, outline, rule);
      EXPECT_TRUE(check.ok()) << d << (check.problems.empty() ? "" : check.problems.front());
    }
  }
}

// build_mesh takes the rule itself, and check_mesh takes the outline's area
// under the rule the mesh was built with.
TEST(EvenOdd, BuildMeshAndCheckMeshTakeTheRule) {
  const double R = 100, ri = R * std::cos(2 * std::numbers::pi / 5) / std::cos(std::numbers::pi / 5);
  const double star = 10 * 0.5 * R * ri * std::sin(std::numbers::pi / 5);
  const double pentagon = 2.5 * ri * ri * std::sin(2 * std::numbers::pi / 5);
  MeshOptions options;
  options.fill_rule = FillRule::EvenOdd;
  const Mesh odd = build_mesh(pentagram(R), options);
  EXPECT_NEAR(mesh_area(odd), star - pentagon, 1e-9 * star);
  EXPECT_TRUE(check_mesh(odd, pentagram(R), FillRule::EvenOdd).ok());
  EXPECT_FALSE(check_mesh(odd, pentagram(R)).ok());  // the nonzero area has the pentagon too
  const Mesh nonzero = build_mesh(pentagram(R));
  EXPECT_TRUE(check_mesh(nonzero, pentagram(R)).ok());
  EXPECT_FALSE(check_mesh(nonzero, pentagram(R), FillRule::EvenOdd).ok());
}

// fill_boundary's contours neither cross nor overlap and carry the fill on
// their left: their nonzero and even-odd fills are the region, and each
// contour's signed area is the area it adds.
TEST(FillBoundary, ContoursBoundTheFillUnderEitherRule) {
  const double pi = std::numbers::pi, r = 40, d = 30;
  const double lens = 2 * r * r * std::acos(d / (2 * r)) - 0.5 * d * std::sqrt(4 * r * r - d * d);
  const Outline discs = merged(circle({0, 0}, r), circle({d, 0}, r));
  const struct {
    FillRule rule;
    double area;
  } cases[] = {{FillRule::NonZero, 2 * pi * r * r - lens}, {FillRule::EvenOdd, 2 * pi * r * r - 2 * lens}};
  for (const auto& c : cases) {
    const Outline boundary = fill_boundary(discs, c.rule);
    EXPECT_NEAR(boundary.signed_area(), c.area, 1e-9 * c.area);
    MeshOptions odd;
    odd.fill_rule = FillRule::EvenOdd;
    EXPECT_NEAR(mesh_area(build_mesh(boundary)), c.area, 1e-6 * c.area);
    EXPECT_NEAR(mesh_area(build_mesh(boundary, odd)), c.area, 1e-6 * c.area);
  }
  // Oriented with the fill on the left: a clockwise disc comes back counter-clockwise.
  EXPECT_NEAR(fill_boundary(circle({0, 0}, r, true), FillRule::NonZero).signed_area(), pi * r * r, 1e-9 * r * r);
  EXPECT_TRUE(fill_boundary(Outline{}, FillRule::EvenOdd).empty());
}

TEST(EvenOdd, BadInput) {
  Outline o;
  o.move_to({0, 0});
  o.cubic_to({1, 1}, {2, 1}, {3, 0});
  o.close();
  EXPECT_THROW(even_odd_to_nonzero(o), Error);
  EXPECT_TRUE(even_odd_to_nonzero(Outline{}).empty());
  Outline nan;
  nan.move_to({0, 0});
  nan.line_to({std::nan(""), 1});
  nan.line_to({1, 0});
  EXPECT_THROW(even_odd_to_nonzero(nan), Error);
}

// --- Rendering against analytic coverage ------------------------------------------

using test::Gpu;
using test::gpu;

test::Coverage draw(ShapeDocument doc, const ShapeImageLayout& layout) {
  for (Shape& s : doc.shapes) s.color = Color{0, 0, 0, 1};
  Gpu& g = gpu();
  return test::coverage_from_black_on_white(render_shape_image(g.renderer, doc, layout, ShapeImageOptions{}));
}

// A window on the edge of a circle of radius 1,000 px (a JSON quadratic NURBS):
// each pixel row's summed coverage is the drawn area in that band; the true
// area has a closed form, and the difference is the horizontal offset of the
// edge, converted to a radial offset with the edge's angle (as render_test
// does for the whole circle).
TEST(ShapeRender, CircleOfRadius1000WithinASixteenthPixel) {
  const double r = 1000;
  const ShapeDocument doc = parse_shape_json(R"({"shapes": [{"contours": [[{"nurbs": {"degree": 2,
      "points": [[1000,0],[1000,1000],[0,1000],[-1000,1000],[-1000,0],[-1000,-1000],[0,-1000],[1000,-1000],[1000,0]],
      "weights": [1,0.70710678118654757,1,0.70710678118654757,1,0.70710678118654757,1,0.70710678118654757,1],
      "knots": [0,0,0,1,1,2,2,3,3,4,4,4]}}]]}]})");
  ShapeImageLayout layout;
  layout.width = 160;
  layout.height = 200;
  const double cx = -850.3, cy = 450.4;  // circle centre in pixels; rows are 250..450 px above it
  layout.placement = Placement{1.0, cx, cy};
  const test::Coverage cov = draw(doc, layout);
  auto F = [&](double t) { return t * std::sqrt(r * r - t * t) + r * r * std::asin(t / r); };  // 2 * integral of sqrt
  double worst = 0.0;
  for (int y = 0; y < layout.height; ++y) {
    const double t0 = y - cy, t1 = y + 1 - cy;
    double sum = 0;
    for (int x = 0; x < layout.width; ++x) sum += cov.at(x, y);
    const double area = cx + 0.5 * (F(t1) - F(t0));  // from x = 0 to the edge, one pixel high
    const double mid = 0.5 * (t0 + t1);
    worst = std::max(worst, std::abs(sum - area) * std::sqrt(r * r - mid * mid) / r);
  }
  const test::Coverage ref = test::sampled_reference(
      [&](double x, double y) { return (x - cx) * (x - cx) + (y - cy) * (y - cy) < r * r; }, 160, 200, 16);
  const test::CoverageStats s = test::compare(cov, ref);
  std::printf(
      "circle r=1000 (JSON NURBS): largest radial offset %.4f px (bound %.4f); vs 16x16 sampling: edge "
      "%.4f, max %.3f\n",
      worst, kBoundPx, s.edge_mean_abs, s.max_abs);
  if (worst > kBoundPx) test::write_comparison("shape-circle-1000", cov, ref);
  EXPECT_GT(s.edge_pixels, 150u);
  EXPECT_LE(worst, kBoundPx);
  EXPECT_LE(s.edge_mean_abs, 0.03);
}

// A rotated ellipse from two SVG arcs (rx 120, ry 60, 30 degrees), drawn at
// one pixel per SVG unit. Per row: the exact chord length integrated over the
// row (Simpson, 64 steps) against the summed coverage gives the mean offset of
// the row's two edges along their normals. Rows within 10% of the top and
// bottom tangents are skipped (the chord length is not smooth there).
TEST(ShapeRender, RotatedEllipseFromSvgArcs) {
  const ShapeDocument doc = read_shape_file(kFixtures + "ellipse-arc.svg");
  const ShapeImageLayout layout = layout_shape_image(doc, ShapeImageOptions{});
  ASSERT_EQ(layout.width, 320);
  ASSERT_EQ(layout.height, 240);
  const test::Coverage cov = draw(doc, layout);
  const double cx = 160, cy = 120, a = 120, b = 60, phi = std::numbers::pi / 6;
  const double c = std::cos(phi), sn = std::sin(phi);
  const double A = c * c / (a * a) + sn * sn / (b * b);
  auto roots = [&](double y, double& x1, double& x2) {  // edge x at height y (pixels = SVG units)
    const double dy = y - cy;
    const double B = 2 * dy * c * sn * (1 / (a * a) - 1 / (b * b));
    const double C = dy * dy * (sn * sn / (a * a) + c * c / (b * b)) - 1;
    const double disc = B * B - 4 * A * C;
    if (disc <= 0) return false;
    x1 = cx + (-B - std::sqrt(disc)) / (2 * A);
    x2 = cx + (-B + std::sqrt(disc)) / (2 * A);
    return true;
  };
  auto normal_x = [&](double x, double y) {  // |n_x| of the ellipse normal at (x, y)
    const double u = c * (x - cx) + sn * (y - cy), v = -sn * (x - cx) + c * (y - cy);
    const Vec2 g = Vec2{c, sn} * (u / (a * a)) + Vec2{-sn, c} * (v / (b * b));
    return std::abs(g.x) / length(g);
  };
  const double ymax = std::sqrt(a * a * sn * sn + b * b * c * c);  // half height of the ellipse
  double worst = 0.0;
  for (int y = 0; y < layout.height; ++y) {
    if (std::abs(y + 0.5 - cy) > 0.9 * ymax) continue;
    double area = 0.0;
    for (int k = 0; k <= 64; ++k) {
      double x1 = 0, x2 = 0;
      roots(y + k / 64.0, x1, x2);
      area += (k == 0 || k == 64 ? 1 : (k % 2 ? 4 : 2)) * (x2 - x1);
    }
    area /= 3 * 64;
    double sum = 0;
    for (int x = 0; x < layout.width; ++x) sum += cov.at(x, y);
    double x1 = 0, x2 = 0;
    roots(y + 0.5, x1, x2);
    const double offset = (sum - area) / (1 / normal_x(x1, y + 0.5) + 1 / normal_x(x2, y + 0.5));
    worst = std::max(worst, std::abs(offset));
  }
  const test::Coverage ref = test::sampled_reference(
      [&](double x, double y) {
        const double u = c * (x - cx) + sn * (y - cy), v = -sn * (x - cx) + c * (y - cy);
        return (u * u) / (a * a) + (v * v) / (b * b) < 1;
      },
      layout.width, layout.height, 16);
  const test::CoverageStats s = test::compare(cov, ref);
  std::printf(
      "rotated ellipse (SVG arcs): largest mean edge offset per row %.4f px (bound %.4f); vs 16x16 "
      "sampling: edge %.4f, max %.3f, ink %.5f\n",
      worst, kBoundPx, s.edge_mean_abs, s.max_abs, s.ink_ratio);
  if (worst > kBoundPx) test::write_comparison("shape-ellipse", cov, ref);
  EXPECT_LE(worst, kBoundPx);
  // 16x16 point sampling quantises coverage to 1/256 per sample row crossed.
  EXPECT_LE(s.edge_mean_abs, 0.03);
  EXPECT_NEAR(s.ink_ratio, 1.0, 2e-3);
}

// Even-odd vs nonzero on a self-overlapping star: the centre pentagon is
// empty for even-odd and filled for nonzero; both against a 16x16 sampled
// crossing-number reference.
TEST(ShapeRender, PentagramEvenOddAndNonzero) {
  for (const char* rule : {"evenodd", "nonzero"}) {
    SCOPED_TRACE(rule);
    const ShapeDocument doc = read_shape_file(kFixtures + "pentagram-" + rule + ".json");
    const ShapeImageLayout layout = layout_shape_image(doc, ShapeImageOptions{});
    const test::Coverage cov = draw(doc, layout);
    const Placement& pl = layout.placement;
    std::vector<Vec2> star;
    for (const RationalBezier& b : doc.shapes[0].contours[0].pieces)
      star.push_back({pl.origin_x + pl.scale * b.points[0].x, pl.origin_y - pl.scale * b.points[0].y});
    const bool even_odd = std::string(rule) == "evenodd";
    auto inside = [&](double x, double y) {
      int winding = 0;
      for (std::size_t i = 0; i < star.size(); ++i) {
        const Vec2 p = star[i], q = star[(i + 1) % star.size()];
        if ((p.y <= y) != (q.y <= y)) {
          const double xi = p.x + (y - p.y) * (q.x - p.x) / (q.y - p.y);
          if (xi > x) winding += q.y > p.y ? 1 : -1;
        }
      }
      return even_odd ? (winding % 2 != 0) : winding != 0;
    };
    const test::Coverage ref = test::sampled_reference(inside, layout.width, layout.height, 16);
    const test::CoverageStats s = test::compare(cov, ref);
    const int c = layout.width / 2;
    std::printf("pentagram %s: centre coverage %.3f, edge %.4f, max %.3f, ink %.5f\n", rule, cov.at(c, c),
                s.edge_mean_abs, s.max_abs, s.ink_ratio);
    EXPECT_NEAR(cov.at(c, c), even_odd ? 0.0 : 1.0, 1e-6);
    EXPECT_NEAR(cov.at(c, c / 4 + 8), 1.0, 1e-6);  // inside the top tip for both rules
    if (s.edge_mean_abs > 0.03) test::write_comparison(std::string("shape-pentagram-") + rule, cov, ref);
    EXPECT_LE(s.edge_mean_abs, 0.03);
    EXPECT_NEAR(s.ink_ratio, 1.0, 5e-3);
  }
}

TEST(ShapeRender, LayoutErrors) {
  EXPECT_THROW(layout_shape_image(ShapeDocument{}, ShapeImageOptions{}), Error);
  const ShapeDocument doc = read_shape_file(kFixtures + "circle-nurbs.json");
  ShapeImageOptions o;
  o.scale = 1e9;
  EXPECT_THROW(layout_shape_image(doc, o), Error);  // image too large
  o.scale = -1;
  EXPECT_THROW(layout_shape_image(doc, o), Error);
  o.scale = 2;
  const ShapeImageLayout l = layout_shape_image(doc, o);
  EXPECT_EQ(l.width, 440);
}

// --- ImageStyle on shapes: transforms, auto, vbaa filter ----------------------

// A w = 0.5 arc closed by its chord and a w = 1 arc (a parabola) with a hole
// side, each its own shape, in a 120 x 60 unit view.
const char* kStyledShapes = R"({"size": [240, 120], "view": [-10, -10, 230, 110], "shapes": [
  {"contours": [[{"bezier": {"points": [[0, 0], [50, 100], [100, 0]], "weights": [1, 0.5, 1]}}, {"line": [[100, 0], [0, 0]]}]]},
  {"contours": [[{"bezier": {"points": [[120, 0], [170, 100], [220, 0]], "weights": [1, 2, 1]}}, {"line": [[220, 0], [120, 0]]}]]}]})";

struct StyledShape {
  test::Coverage result, reference;
  test::CoverageStats stats;
  ShapeImageLayout layout;
};

// Draws the document in black and compares with the exact coverage of its
// fill outlines placed and transformed as the layout says.
StyledShape draw_styled(ShapeDocument doc, const ShapeImageOptions& options) {
  for (Shape& sh : doc.shapes) sh.color = Color{0, 0, 0, 1};
  StyledShape r;
  r.layout = layout_shape_image(doc, options);
  r.result = test::coverage_from_black_on_white(render_shape_image(gpu().renderer, doc, r.layout, options));
  Placement untransformed = r.layout.placement;
  untransformed.transform = Transform{};
  Outline all;
  for (const Shape& sh : doc.shapes) {
    const Outline fill = fill_outline(sh, 1e-3);
    for (const Contour& c : fill.contours()) all.contours().push_back(c);
  }
  r.reference = test::union_coverage(
      test::transform_outline(test::place_outline(all, untransformed), r.layout.placement.transform), r.layout.width,
      r.layout.height);
  r.stats = test::compare(r.result, r.reference);
  return r;
}

void expect_styled(const std::string& name, const StyledShape& r, double edge_limit, double ink_limit) {
  test::expect_coverage("shape-" + name, r.result, r.reference, r.stats, edge_limit, ink_limit);
}

TEST(ShapeTransform, RotationPerspectiveSkewMatchExactCoverage) {
  const ShapeDocument doc = parse_shape_json(kStyledShapes);
  const struct {
    const char* name;
    Transform t;
  } maps[] = {{"rotate30", Transform::rotation(30.0)},
              {"perspective50", Transform::perspective(50.0, 400.0)},
              {"skew-15,5_scale1.5,0.75", Transform::scale(1.5, 0.75) * Transform::skew(-15.0, 5.0)}};
  for (const auto& m : maps) {
    ShapeImageOptions options;
    options.transform = m.t;
    const StyledShape r = draw_styled(doc, options);
    expect_styled(m.name, r, 0.01, 0.01);
    EXPECT_GT(r.layout.largest_stretch, 0.99) << m.name;
  }
  ShapeImageOptions options;
  options.transform = Transform::rotation(90.0);
  const ShapeImageLayout turned = layout_shape_image(doc, options);
  EXPECT_EQ(turned.width, 120);
  EXPECT_EQ(turned.height, 240);
  options.transform = Transform::perspective(85.0, 10.0);
  EXPECT_THROW(layout_shape_image(doc, options), Error);  // behind the viewer
  options.transform = Transform::scale(1e4, 1.0);
  EXPECT_THROW(layout_shape_image(doc, options), Error);  // too large
}

// auto per shape from its on-screen size: vbaa for these (about 200 px), the
// same image as vbaa and closer to the exact coverage than full; full when
// the scale puts a shape above tolerance::kAutoVbaaMaxPx.
TEST(ShapeAntialiasing, AutoPicksPerOnScreenSize) {
  EXPECT_EQ(resolve_antialiasing(AntiAliasing::Auto, tolerance::kAutoVbaaMaxPx), AntiAliasing::Vbaa);
  EXPECT_EQ(resolve_antialiasing(AntiAliasing::Auto, tolerance::kAutoVbaaMaxPx + 1), AntiAliasing::Full);
  EXPECT_EQ(resolve_antialiasing(AntiAliasing::Msaa, 1e6), AntiAliasing::Msaa);
  const ShapeDocument doc = parse_shape_json(kStyledShapes);
  ShapeImageOptions options;
  options.transform = Transform::rotation(20.0);
  options.antialiasing = AntiAliasing::Auto;
  const StyledShape autod = draw_styled(doc, options);
  expect_styled("auto_rotate20", autod, 0.005, 0.01);
  options.antialiasing = AntiAliasing::Vbaa;
  const StyledShape vbaa = draw_styled(doc, options);
  EXPECT_EQ(autod.result.value, vbaa.result.value) << "auto at about 200 px is not vbaa";
  options.antialiasing = AntiAliasing::Full;
  const StyledShape full = draw_styled(doc, options);
  EXPECT_LT(vbaa.stats.edge_mean_abs, full.stats.edge_mean_abs);

  // 4 px per unit: each shape is 400 px wide on screen.
  options = ShapeImageOptions{};
  options.scale = 4.0;
  options.antialiasing = AntiAliasing::Auto;
  const StyledShape big_auto = draw_styled(doc, options);
  options.antialiasing = AntiAliasing::Full;
  const StyledShape big_full = draw_styled(doc, options);
  EXPECT_EQ(big_auto.result.value, big_full.result.value) << "auto at 400 px is not full";
}

TEST(ShapeAntialiasing, VbaaFilterRingIsApplied) {
  const ShapeDocument doc = parse_shape_json(kStyledShapes);
  ShapeImageOptions options;
  options.antialiasing = AntiAliasing::Vbaa;
  const StyledShape box = draw_styled(doc, options);
  options.vbaa_ring = 0.5f;
  const StyledShape ring = draw_styled(doc, options);
  std::printf("shape vbaa box edge %.4f, ring 0.5 edge %.4f ink %.4f\n", box.stats.edge_mean_abs,
              ring.stats.edge_mean_abs, ring.stats.ink_ratio);
  EXPECT_GT(ring.stats.edge_mean_abs, box.stats.edge_mean_abs + 0.005);
  EXPECT_NEAR(ring.stats.ink_ratio, 1.0, 0.02);
}

}  // namespace
}  // namespace curvetext
