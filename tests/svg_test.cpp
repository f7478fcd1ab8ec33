// The SVG document reader: XML and its limits, CSS colours, the cascade,
// transforms, basic shapes as exact conics, <use>/<symbol>, what is refused
// by name; and shapes drawn against exact coverage.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <numbers>
#include <string>

#include "curvetext/error.hpp"
#include "curvetext/image.hpp"
#include "curvetext/image_target.hpp"
#include "curvetext/shape_drawing.hpp"
#include "curvetext/shape_image.hpp"
#include "curvetext/shapes.hpp"
#include "shapes/svg_css.hpp"
#include "shapes/svg_style.hpp"
#include "shapes/svg_xml.hpp"
#include "support/coverage.hpp"
#include "support/gpu.hpp"

namespace curvetext {
namespace {

using std::numbers::pi;

std::string refusal(const std::string& text, const SvgOptions& options = {}) {
  try {
    parse_svg(text, options);
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::InvalidArgument);
    return e.what();
  }
  ADD_FAILURE() << "no error for " << text;
  return "";
}

void expect_refused(const std::string& text, const std::string& part) {
  SCOPED_TRACE(text);
  const std::string what = refusal(text);
  EXPECT_NE(what.find(part), std::string::npos) << what;
}

double total_area(const ShapeDocument& doc) {
  double a = 0.0;
  for (const Shape& s : doc.shapes) a += std::abs(fill_outline(s, 1e-9).signed_area());
  return a;
}

// --- XML ----------------------------------------------------------------------------

TEST(SvgXml, ElementTreeWithNamespacesAndPositions) {
  const svg::XmlDocument doc = svg::parse_xml(
      "<svg xmlns='http://www.w3.org/2000/svg' xmlns:x='http://www.w3.org/1999/xlink' "
      "xmlns:i='urn:inkscape'>\n  <i:layer/><use x:href='#a'/><style>.a{fill:red}</style></svg>");
  ASSERT_EQ(doc.elements.size(), 4u);
  EXPECT_EQ(doc.elements[0].name, "svg");
  EXPECT_EQ(doc.elements[1].name, "{urn:inkscape}layer");
  EXPECT_EQ(doc.elements[1].line, 2);
  EXPECT_EQ(doc.elements[1].column, 3);
  ASSERT_NE(doc.elements[2].find("xlink:href"), nullptr);
  EXPECT_EQ(doc.elements[3].text, ".a{fill:red}");
  EXPECT_EQ(doc.elements[0].children.size(), 3u);
}

TEST(SvgXml, HostileInputIsRefusedQuickly) {
  const auto start = std::chrono::steady_clock::now();
  // Billion laughs: nested entity declarations.
  std::string laughs = "<?xml version='1.0'?><!DOCTYPE svg [<!ENTITY a0 'haha'>";
  for (int i = 1; i < 10; ++i) {
    std::string body;
    for (int k = 0; k < 10; ++k) body += "&a" + std::to_string(i - 1) + ";";
    laughs += "<!ENTITY a" + std::to_string(i) + " '" + body + "'>";
  }
  laughs += "]><svg><title>&a9;</title></svg>";
  expect_refused(laughs, "entity declarations are not supported");
  // Deep nesting.
  std::string deep;
  for (int i = 0; i < 100000; ++i) deep += "<g>";
  expect_refused("<svg>" + deep, "nested deeper than 256");
  // Too many elements (a huge flat document).
  std::string flat = "<svg>";
  for (std::size_t i = 0; i <= svg::kMaxXmlElements; ++i) flat += "<g/>";
  expect_refused(flat + "</svg>", "more than 200000 elements");
  // Descendant selectors against deep markup: bounded work.
  std::string chains = "<svg><style>.a .b{fill:red}";
  for (int i = 1; i < 60; ++i) chains += " .a" + std::to_string(i) + " .b{fill:red}";
  chains += "</style>";
  for (int c = 0; c < 700; ++c) {
    for (int d = 0; d < 250; ++d) chains += "<g class='b'>";
    for (int d = 0; d < 250; ++d) chains += "</g>";
  }
  expect_refused(chains + "</svg>", "takes too long");
  // Malformed XML names its position.
  expect_refused("<svg>\n<path d='M0 0'>\n</svg>", "line 3, column 3: mismatched tag");
  // <use> fan-out: each level draws the one below ten times.
  std::string fan = "<svg><defs><path id='p0' d='M0 0 L1 0 L0 1Z'/>";
  for (int i = 1; i < 9; ++i) {
    fan += "<g id='p" + std::to_string(i) + "'>";
    for (int k = 0; k < 10; ++k) fan += "<use href='#p" + std::to_string(i - 1) + "'/>";
    fan += "</g>";
  }
  fan += "</defs><use href='#p8'/></svg>";
  const std::string what = refusal(fan);
  EXPECT_TRUE(what.find("segments in the document") != std::string::npos ||
              what.find("elements drawn") != std::string::npos)
      << what;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("hostile SVG input refused in %.2f s\n", seconds);
  EXPECT_LT(seconds, 30.0);  // bounded work (a generous bound for sanitizer builds)
}

TEST(SvgXml, PredefinedEntitiesAndCharacterReferencesAreRead) {
  const ShapeDocument doc =
      parse_svg("<svg><path d='M0 0 L10&#x20;0 L0&#32;10 Z' fill='&#x23;ff0000' class='a&amp;b'/></svg>");
  ASSERT_EQ(doc.shapes.size(), 1u);
  EXPECT_EQ(doc.shapes[0].color.r, 1.0f);
}

// --- Colours ------------------------------------------------------------------------

TEST(SvgColor, EveryCssForm) {
  struct Case {
    const char* text;
    float r, g, b, a;
  };
  const Case cases[] = {
      {"#f00", 1, 0, 0, 1},
      {"#0f08", 0, 1, 0, 0x88 / 255.0f},
      {"#336699", 0x33 / 255.0f, 0x66 / 255.0f, 0x99 / 255.0f, 1},
      {"#33669980", 0x33 / 255.0f, 0x66 / 255.0f, 0x99 / 255.0f, 0x80 / 255.0f},
      {"rgb(255, 0, 51)", 1, 0, 0.2f, 1},
      {"rgb(100%, 50%, 0%)", 1, 0.5f, 0, 1},
      {"rgba(0, 0, 255, 0.25)", 0, 0, 1, 0.25f},
      {"rgb(0 0 255 / 50%)", 0, 0, 1, 0.5f},
      {"hsl(120, 100%, 50%)", 0, 1, 0, 1},
      {"hsla(240deg, 100%, 25%, .5)", 0, 0, 0.5f, 0.5f},
      {"hsl(0, 0%, 100%)", 1, 1, 1, 1},
      {"CornflowerBlue", 0x64 / 255.0f, 0x95 / 255.0f, 0xed / 255.0f, 1},
      {"rebeccapurple", 0x66 / 255.0f, 0x33 / 255.0f, 0x99 / 255.0f, 1},
      {"grey", 0x80 / 255.0f, 0x80 / 255.0f, 0x80 / 255.0f, 1},
      {"transparent", 0, 0, 0, 0},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.text);
    const std::optional<Color> got = svg::parse_css_color(c.text);
    ASSERT_TRUE(got.has_value());
    EXPECT_NEAR(got->r, c.r, 1e-6);
    EXPECT_NEAR(got->g, c.g, 1e-6);
    EXPECT_NEAR(got->b, c.b, 1e-6);
    EXPECT_NEAR(got->a, c.a, 1e-6);
  }
  // (Longer than #rrggbbaa: read past its digit table, a fuzz finding.)
  for (const char* bad : {"#12", "#12345", "rgb(1,2)", "hsl(1%, 2%, 3%)", "bluish", "url(#a)", "#ggg", "#b22221e10",
                          "#0123456789abcdef0123"})
    EXPECT_FALSE(svg::parse_css_color(bad).has_value()) << bad;
}

TEST(SvgColor, CurrentColorFromColorAndFromTheCaller) {
  const char* square = "M0 0 L1 0 L1 1 Z";
  const std::string doc = std::string("<svg><path fill='currentColor' d='") + square + "'/>" +
                          "<g color='#00f'><path style='fill:currentcolor' d='" + square + "'/></g></svg>";
  SvgOptions options;
  options.current_color = Color{0, 0.5f, 0, 1};
  const ShapeDocument d = parse_svg(doc, options);
  ASSERT_EQ(d.shapes.size(), 2u);
  EXPECT_EQ(d.shapes[0].color.g, 0.5f);               // the caller's
  EXPECT_EQ(d.shapes[1].color.b, 1.0f);               // the document's color
  EXPECT_EQ(parse_svg(doc).shapes[0].color.g, 0.0f);  // black by default
}

// --- Cascade ------------------------------------------------------------------------

float red_of(const std::string& doc, std::size_t shape = 0) {
  const ShapeDocument d = parse_svg(doc);
  EXPECT_GT(d.shapes.size(), shape);
  return d.shapes.size() > shape ? d.shapes[shape].color.r : -1.0f;
}

TEST(SvgCascade, SelectorsSpecificityAndOrigins) {
  const std::string sq = " d='M0 0 L1 0 L1 1 Z'/>";
  // type < class < id; later wins at equal specificity.
  EXPECT_FLOAT_EQ(
      red_of("<svg><style>path{fill:#100} .a{fill:#200} path{fill:#300}</style><path class='a'" + sq + "</svg>"),
      0x22 / 255.0f);
  EXPECT_FLOAT_EQ(red_of("<svg><style>#p{fill:#400} .a.b{fill:#500}</style><path id='p' class='a b'" + sq + "</svg>"),
                  0x44 / 255.0f);
  // Descendant and child combinators.
  const std::string tree = "<svg><g class='x'><g><path" + sq + "</g></g></svg>";
  EXPECT_FLOAT_EQ(red_of("<svg><style>.x path{fill:#600}</style>" + tree.substr(5)), 0x66 / 255.0f);
  EXPECT_FLOAT_EQ(red_of("<svg><style>.x > path{fill:#600}</style>" + tree.substr(5)), 0.0f);
  EXPECT_FLOAT_EQ(red_of("<svg><style>.x > g > path, rect{fill:#700}</style>" + tree.substr(5)), 0x77 / 255.0f);
  EXPECT_FLOAT_EQ(red_of("<svg><style>[data-k=v] path{fill:#800}</style><g data-k='v'><path" + sq + "</g></svg>"),
                  0x88 / 255.0f);
  // Presentation attribute < sheet < style attribute < !important in the sheet.
  EXPECT_FLOAT_EQ(red_of("<svg><style>path{fill:#900}</style><path fill='#a00'" + sq + "</svg>"), 0x99 / 255.0f);
  EXPECT_FLOAT_EQ(red_of("<svg><style>#p{fill:#900}</style><path id='p' style='fill:#b00'" + sq + "</svg>"),
                  0xbb / 255.0f);
  EXPECT_FLOAT_EQ(red_of("<svg><style>path{fill:#900 !important}</style><path style='fill:#b00'" + sq + "</svg>"),
                  0x99 / 255.0f);
  // A sheet of another type is not applied; comments are skipped.
  EXPECT_FLOAT_EQ(red_of("<svg><style type='text/foo'>path{fill:#900}</style><path" + sq + "</svg>"), 0.0f);
  EXPECT_FLOAT_EQ(red_of("<svg><style>/* path{fill:#900} */ path{/*x*/fill:#c00}</style><path" + sq + "</svg>"),
                  0xcc / 255.0f);
}

TEST(SvgCascade, InheritanceThroughGroups) {
  const std::string sq = " d='M0 0 L1 0 L1 1 Z'/>";
  const ShapeDocument d =
      parse_svg("<svg fill='#f00' fill-opacity='0.5'><g style='fill-rule:evenodd'><path" + sq +
                "<path fill='inherit' fill-rule='nonzero'" + sq + "</g><path opacity='.5'" + sq + "</svg>");
  ASSERT_EQ(d.shapes.size(), 3u);
  EXPECT_EQ(d.shapes[0].color.r, 1.0f);
  EXPECT_FLOAT_EQ(d.shapes[0].color.a, 0.5f);
  EXPECT_EQ(d.shapes[0].fill_rule, FillRule::EvenOdd);
  EXPECT_EQ(d.shapes[1].fill_rule, FillRule::NonZero);
  EXPECT_FLOAT_EQ(d.shapes[2].color.a, 0.25f);
  // A group's opacity over one shape is that shape's alpha (exact).
  EXPECT_FLOAT_EQ(parse_svg("<svg><g opacity='0.5'><path" + sq + "</g></svg>").shapes[0].color.a, 0.5f);
}

TEST(SvgCascade, UnsupportedSelectorsAreRefusedByName) {
  expect_refused("<svg><style>path:hover{fill:red}</style></svg>", "pseudo-class");
  expect_refused("<svg><style>g + path{fill:red}</style></svg>", "combinator '+'");
  expect_refused("<svg><style>@media print { path{fill:red} }</style></svg>", "at-rule @media");
  expect_refused("<svg><style>path{fill:red</style></svg>", "unclosed rule");
}

// --- Transforms, viewBox ------------------------------------------------------------

TEST(SvgTransform, EveryFunctionAndNesting) {
  const svg::Affine m = svg::parse_transform("translate(10,20) rotate(90 1 1) scale(2, 3) skewX(45)", "");
  // skewX(45): (1, 1) -> (2, 1); scale: (4, 3); rotate 90 about (1,1): (1 - (3 - 1), 1 + (4 - 1)) = (-1, 4).
  const Vec2 p = m.apply({1, 1});
  EXPECT_NEAR(p.x, 9, 1e-12);
  EXPECT_NEAR(p.y, 24, 1e-12);
  const Vec2 q = svg::parse_transform("matrix(1 2 3 4 5 6) skewY(45)", "").apply({1, 0});
  EXPECT_NEAR(q.x, 1 + 3 + 5, 1e-12);
  EXPECT_NEAR(q.y, 2 + 4 + 6, 1e-12);
  for (const char* bad : {"rotate(1 2)", "scale()", "shear(1)", "translate(1", "matrix(1 2 3 4 5)"})
    EXPECT_THROW(svg::parse_transform(bad, ""), Error) << bad;
  // Nested on elements: the points of the drawn shape (y mirrored).
  const ShapeDocument d = parse_svg(
      "<svg><g transform='translate(100 0)'><g transform='scale(2)'>"
      "<path transform='translate(1 1)' d='M0 0 L1 0 L0 1 Z'/></g></g></svg>");
  const Vec2 first = d.shapes[0].contours[0].pieces[0].points[0];
  EXPECT_EQ(first, (Vec2{102, -2}));
}

TEST(SvgTransform, ViewBoxAspectRatioAndUnits) {
  const std::string path = "<path d='M0 0 L10 0 L10 10 Z'/>";
  // viewBox 10x10 into 200x100: meet scales by 10, xMidYMid centres at x 50.
  ShapeDocument d = parse_svg("<svg width='200' height='100' viewBox='0 0 10 10'>" + path + "</svg>");
  EXPECT_EQ(d.shapes[0].contours[0].pieces[0].points[0], (Vec2{50, 0}));
  EXPECT_EQ(d.view.max.x, 200);
  d = parse_svg("<svg width='200' height='100' viewBox='0 0 10 10' preserveAspectRatio='xMinYMax slice'>" + path +
                "</svg>");
  EXPECT_EQ(d.shapes[0].contours[0].pieces[1].points[1], (Vec2{200, -200 + 100}));
  d = parse_svg("<svg width='200' height='100' viewBox='0 0 10 10' preserveAspectRatio='none'>" + path + "</svg>");
  EXPECT_EQ(d.shapes[0].contours[0].pieces[1].points[1], (Vec2{200, -100}));
  // Units: 1in = 96 px, 72pt = 96 px, 2.54cm = 96 px; percentages of the viewBox.
  d = parse_svg("<svg width='1in' height='72pt' viewBox='0 0 50 20'><rect x='10%' width='2.54cm' height='50%'/></svg>");
  EXPECT_NEAR(d.width_px, 96, 1e-12);
  EXPECT_NEAR(d.height_px, 96, 1e-12);
  EXPECT_NEAR(total_area(d), 96 * 10 * (96.0 / 50) * (96.0 / 50), 1e-6);
  expect_refused("<svg viewBox='0 0 1 1' width='9' height='9' preserveAspectRatio='middle'/>", "preserveAspectRatio");
}

// --- Shapes -------------------------------------------------------------------------

TEST(SvgShapes, AreasAreExact) {
  struct Case {
    const char* element;
    double area;
  };
  const double r = 7, rx = 3, ry = 2;
  const Case cases[] = {
      {"<rect x='1' y='2' width='30' height='20'/>", 600},
      {"<rect width='30' height='20' rx='3' ry='2'/>", 600 - (4 - pi) * rx * ry},
      {"<rect width='30' height='20' rx='3'/>", 600 - (4 - pi) * 9},
      {"<rect width='30' height='20' rx='40' ry='2'/>", 600 - (4 - pi) * 15 * 2},  // rx clamped to width / 2
      {"<circle cx='5' cy='5' r='7'/>", pi * r * r},
      {"<ellipse cx='5' cy='5' rx='7' ry='3'/>", pi * 21},
      {"<polygon points='0,0 10,0 10,10'/>", 50},
      {"<polyline points='0 0 10 0 10 10 3'/>", 50},  // closed by the fill; odd number dropped
      {"<line x1='0' y1='0' x2='5' y2='5'/>", 0},     // no area
      {"<rect width='0' height='9'/>", 0},            // not rendered
      {"<circle r='-1'/>", 0},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.element);
    const ShapeDocument d = parse_svg(std::string("<svg>") + c.element + "</svg>");
    EXPECT_NEAR(total_area(d), c.area, 1e-9 * std::max(1.0, c.area));
  }
  // The circle's conics lie on the circle.
  const ShapeDocument d = parse_svg("<svg><circle cx='5' cy='5' r='7'/></svg>");
  for (const RationalBezier& piece : d.shapes[0].contours[0].pieces)
    for (int i = 0; i <= 16; ++i) EXPECT_NEAR(length(evaluate(piece, i / 16.0) - Vec2{5, -5}), r, 1e-12);
}

// --- use, symbol, defs ----------------------------------------------------------------

TEST(SvgUse, PlacesCopiesAndRefusesCycles) {
  const std::string defs =
      "<defs><path id='t' d='M0 0 L2 0 L0 2 Z'/><g id='two'><use href='#t'/>"
      "<use xlink:href='#t' x='10' xmlns:xlink='http://www.w3.org/1999/xlink'/></g>"
      "<symbol id='s' viewBox='0 0 2 2'><path d='M0 0 L2 0 L0 2 Z'/></symbol></defs>";
  const ShapeDocument d = parse_svg("<svg>" + defs +
                                    "<use href='#two' y='5' fill='red'/><use href='#s' x='20' width='4' height='4'/>"
                                    "<use href='#missing'/></svg>");
  ASSERT_EQ(d.shapes.size(), 3u);
  EXPECT_EQ(d.shapes[0].contours[0].pieces[0].points[0], (Vec2{0, -5}));
  EXPECT_EQ(d.shapes[1].contours[0].pieces[0].points[0], (Vec2{10, -5}));
  EXPECT_EQ(d.shapes[1].color.r, 1.0f);          // inherited from the <use>
  EXPECT_NEAR(total_area(d), 2 + 2 + 8, 1e-12);  // the symbol's 2x2 box scaled into 4x4
  expect_refused("<svg><g id='a'><use href='#a'/></g></svg>", "a cycle");
  expect_refused("<svg><defs><g id='a'><use href='#b'/></g><g id='b'><use href='#a'/></g></defs><use href='#a'/></svg>",
                 "a cycle");
  expect_refused("<svg><use href='other.svg#a'/></svg>", "only #id in the same document");
  // A symbol's content outside its viewport is clipped by the viewport's rectangle.
  const ShapeDocument clipped = parse_svg(
      "<svg><symbol id='s' viewBox='0 0 2 2'><path d='M0 0 L3 0 L0 3 Z'/></symbol><use href='#s' "
      "width='2' height='2'/></svg>");
  ASSERT_EQ(clipped.groups.size(), 1u);
  ASSERT_EQ(clipped.groups[0].clip.size(), 1u);
  EXPECT_NEAR(std::abs(fill_outline(clipped.groups[0].clip[0], 1e-9).signed_area()), 4.0, 1e-12);
}

// --- Refused by name ------------------------------------------------------------------

TEST(SvgRefusals, WhatIsNotDrawnIsNamedWithItsPosition) {
  const std::string sq = " d='M0 0 L1 0 L1 1 Z'";
  expect_refused("<svg>\n <text>hi</text></svg>", "line 2, column 2: <text> is not supported");
  expect_refused("<svg><image href='a.png'/></svg>", "<image> is not supported");
  expect_refused("<svg><script>x()</script></svg>", "<script> is not supported");
  expect_refused("<svg><path" + sq + "><animate attributeName='x'/></path></svg>", "<animate> is not supported");
  expect_refused("<svg><path filter='url(#f)'" + sq + "/></svg>", "filter 'url(#f)' is not supported");
  expect_refused("<svg><g mask='url(#m)'><path" + sq + "/></g></svg>", "mask");
  expect_refused("<svg><path style='clip-path:inset(1px)'" + sq + "/></svg>",
                 "clip-path 'inset(1px)' is not supported");
  expect_refused("<svg><rect id='c'/><path clip-path='url(#c)'" + sq + "/></svg>", "which is not a <clipPath>");
  expect_refused("<svg><clipPath id='c'><text>a</text></clipPath><path clip-path='url(#c)'" + sq + "/></svg>",
                 "<text> is not supported");
  expect_refused("<svg><rect id='m'/><path marker-end='url(#m)'" + sq + "/></svg>", "which is not a <marker>");
  expect_refused("<svg><marker id='m'/><path marker-mid='url(#m)' d='M0 0 A1 1 0 0 0 2 0 L3 3'/></svg>",
                 "marker-mid on a path with arcs is not supported");
  expect_refused(
      "<svg><marker id='m'><path d='M0 0 L1 1' marker-end='url(#m)'/></marker>"
      "<path marker-end='url(#m)'" +
          sq + "/></svg>",
      "a cycle");
  expect_refused("<svg><pattern id='p'/><path fill='url(#p)'" + sq + "/></svg>", "fill refers to <pattern>");
  expect_refused("<svg><path fill='bluish'" + sq + "/></svg>", "fill 'bluish' is not a colour");
  // Not drawn, as SVG says: metadata, foreign and unknown elements, defs, hidden shapes, no-stroke widths.
  const ShapeDocument d =
      parse_svg("<svg xmlns:i='urn:x'><title>t</title><metadata><i:x/></metadata><i:layer><path" + sq +
                "/></i:layer>"
                "<unknown><path" +
                sq + "/></unknown><path visibility='hidden'" + sq + "/><path stroke-width='3'" + sq +
                "/><path stroke='red' stroke-opacity='0'" + sq + "/></svg>");
  EXPECT_EQ(d.shapes.size(), 2u);
  // A gradient of one colour is that colour; one without stops is none.
  const ShapeDocument g = parse_svg(
      "<svg><linearGradient id='a'><stop stop-color='#0f0' stop-opacity='.5'/></linearGradient>"
      "<linearGradient id='b' href='#a'/><linearGradient id='c'/><path fill='url(#b) red'" +
      sq + "/><path fill='url(#c)'" + sq + "/><path fill='url(#none) #00f'" + sq + "/></svg>");
  ASSERT_EQ(g.shapes.size(), 2u);
  EXPECT_EQ(g.shapes[0].color.g, 1.0f);
  EXPECT_FLOAT_EQ(g.shapes[0].color.a, 0.5f);
  EXPECT_EQ(g.shapes[1].color.b, 1.0f);
}

// --- Drawn against exact coverage -----------------------------------------------------

// A rounded rectangle, a circle placed by a rotated <use>, and an ellipse in
// a scaled group, drawn in every AA mode against 32 x 32 point sampling of
// the same analytic shapes.
TEST(SvgRender, ShapesTransformsAndUseMatchExactCoverage) {
  const ShapeDocument doc = parse_svg(
      "<svg width='120' height='100' viewBox='0 0 60 50'>"
      "<defs><circle id='c' r='9'/></defs>"
      "<rect x='3.3' y='4.1' width='24' height='18' rx='5' ry='3'/>"
      "<use href='#c' transform='rotate(30 40 12)' x='40' y='12'/>"
      "<g transform='translate(30 36) scale(1.5 1)'><ellipse rx='12' ry='9.5' transform='rotate(20)'/></g>"
      "</svg>");
  auto inside = [](double px, double py) {
    const double x = px / 2, y = py / 2;  // viewBox units
    auto in_rect = [&] {
      const double x0 = 3.3, y0 = 4.1, w = 24, h = 18, rx = 5, ry = 3;
      if (x < x0 || x > x0 + w || y < y0 || y > y0 + h) return false;
      const double cx = std::clamp(x, x0 + rx, x0 + w - rx), cy = std::clamp(y, y0 + ry, y0 + h - ry);
      const double u = (x - cx) / rx, v = (y - cy) / ry;
      return u * u + v * v <= 1;
    };
    const bool circle = (x - 40) * (x - 40) + (y - 12) * (y - 12) < 81;
    const double ex = (x - 30) / 1.5, ey = y - 36, c = std::cos(20 * pi / 180), s = std::sin(20 * pi / 180);
    const double u = (c * ex + s * ey) / 12, v = (-s * ex + c * ey) / 9.5;
    return in_rect() || circle || u * u + v * v < 1;
  };
  ShapeImageOptions options;
  const ShapeImageLayout layout = layout_shape_image(doc, options);
  ASSERT_EQ(layout.width, 120);
  const test::Coverage ref = test::sampled_reference(inside, layout.width, layout.height, 32);
  for (AntiAliasing aa : {AntiAliasing::Full, AntiAliasing::Vbaa, AntiAliasing::Msaa}) {
    options.antialiasing = aa;
    ShapeDocument black = doc;
    for (Shape& s : black.shapes) s.color = Color{0, 0, 0, 1};
    const test::Coverage got =
        test::coverage_from_black_on_white(render_shape_image(test::gpu().renderer, black, layout, options));
    const test::CoverageStats st = test::compare(got, ref);
    const std::string name = "svg-shapes-aa" + std::to_string(static_cast<int>(aa));
    const double edge_limit = aa == AntiAliasing::Msaa ? 0.08 : 0.01;
    std::printf("%s: edge %.4f max %.3f ink %.4f\n", name.c_str(), st.edge_mean_abs, st.max_abs, st.ink_ratio);
    test::expect_coverage(name, got, ref, st, edge_limit, aa == AntiAliasing::Msaa ? 0.02 : 0.005);
  }
}

// Strokes under a transform that skews and scales unevenly are SVG's: the
// stroke region of user space mapped through the transform (its width varies
// with direction). A stroked circle and a square-capped line, in every AA
// mode, against point sampling of that region (pixels mapped back into user
// space); and a non-scaling stroke under the same transform, whose width is
// in device pixels whatever the direction.
TEST(SvgRender, StrokesUnderASkewAreMappedFromUserSpace) {
  const double a = 1.2, b = 0.25, c = 0.45, d = 0.75, e = 2, f = 4;  // the group's matrix
  const ShapeDocument doc = parse_svg(
      "<svg width='96' height='96' viewBox='0 0 96 96'><g transform='matrix(1.2 0.25 0.45 0.75 2 4)' "
      "fill='none' stroke='#000'>"
      "<circle cx='28' cy='36' r='16' stroke-width='7'/>"
      "<path d='M6 66 L36 88' stroke-width='5' stroke-linecap='square'/>"
      "<path d='M10 6 L60 16' stroke-width='3' vector-effect='non-scaling-stroke'/></g></svg>");
  ASSERT_EQ(doc.shapes.size(), 3u);
  EXPECT_FALSE(doc.shapes[0].stroke->user_to_document.is_identity());
  // A band of half-width h about the segment p q (square caps reach h past its ends when `square`).
  auto near_segment = [](Vec2 u, Vec2 p, Vec2 q, double h, bool square) {
    const double len = distance(p, q);
    const Vec2 t = (q - p) * (1.0 / len);
    const Vec2 r = u - p;
    const double along = r.x * t.x + r.y * t.y, across = std::abs(t.x * r.y - t.y * r.x);
    const double ext = square ? h : 0.0;
    return along >= -ext && along <= len + ext && across <= h;
  };
  auto inside = [&](double px, double py) {
    const double k = 1.0 / (a * d - b * c), x = px - e, y = py - f;
    const Vec2 u{(d * x - c * y) * k, (-b * x + a * y) * k};  // user space
    const bool ring = std::abs(distance(u, Vec2{28, 36}) - 16) <= 3.5;
    const bool line = near_segment(u, {6, 66}, {36, 88}, 2.5, true);
    auto device = [&](Vec2 v) { return Vec2{a * v.x + c * v.y + e, b * v.x + d * v.y + f}; };
    const bool thin = near_segment({px, py}, device({10, 6}), device({60, 16}), 1.5, false);
    return ring || line || thin;
  };
  ShapeImageOptions options;
  const ShapeImageLayout layout = layout_shape_image(doc, options);
  ASSERT_EQ(layout.width, 96);
  const test::Coverage ref = test::sampled_reference(inside, layout.width, layout.height, 32);
  for (AntiAliasing aa : {AntiAliasing::Full, AntiAliasing::Vbaa, AntiAliasing::Msaa}) {
    options.antialiasing = aa;
    const test::Coverage got =
        test::coverage_from_black_on_white(render_shape_image(test::gpu().renderer, doc, layout, options));
    const test::CoverageStats st = test::compare(got, ref);
    const std::string name = "svg-skewed-strokes-aa" + std::to_string(static_cast<int>(aa));
    std::printf("%s: edge %.4f max %.3f ink %.4f\n", name.c_str(), st.edge_mean_abs, st.max_abs, st.ink_ratio);
    test::expect_coverage(name, got, ref, st, aa == AntiAliasing::Msaa ? 0.08 : 0.01,
                          aa == AntiAliasing::Msaa ? 0.02 : 0.005);
  }
}

// Gradients: each pixel inside a rectangle is the gradient at its centre
// (stops interpolated in straight alpha, as SVG renderers do), over white; edge pixels are
// that colour times their exact coverage. Linear with reflect, and radial
// with a focal point and repeat, in every offscreen AA mode.
TEST(SvgRender, GradientsArePaintedPerPixel) {
  const ShapeDocument doc = parse_svg(
      "<svg width='80' height='60' viewBox='0 0 80 60'>"
      "<linearGradient id='l' x1='0.2' x2='0.6' spreadMethod='reflect'>"
      "<stop offset='0' stop-color='#f00'/><stop offset='.5' stop-color='#00f' stop-opacity='.5'/>"
      "<stop offset='1' stop-color='#0f0'/></linearGradient>"
      "<radialGradient id='r' gradientUnits='userSpaceOnUse' cx='40' cy='45' r='10' fx='44' fy='43' "
      "spreadMethod='repeat' gradientTransform='translate(0 0)'><stop offset='0' stop-color='#ff0'/>"
      "<stop offset='1' stop-color='#008'/></radialGradient>"
      "<rect x='10.5' y='5.25' width='60' height='20' fill='url(#l)'/>"
      "<rect x='10' y='30' width='60' height='28' fill='url(#r)'/></svg>");
  ASSERT_EQ(doc.shapes.size(), 2u);
  ASSERT_TRUE(doc.shapes[0].gradient.has_value());
  struct Rgba {
    double r, g, b, a;  // straight alpha
  };
  auto mix = [](Rgba p, Rgba q, double t) {
    return Rgba{p.r + (q.r - p.r) * t, p.g + (q.g - p.g) * t, p.b + (q.b - p.b) * t, p.a + (q.a - p.a) * t};
  };
  auto linear = [&](double x) {
    double t = (x - 10.5) / 60.0;
    t = (t - 0.2) / 0.4;
    t = std::fmod(std::abs(t), 2.0);
    if (t > 1) t = 2 - t;
    const Rgba red{1, 0, 0, 1}, blue{0, 0, 1, 0.5}, green{0, 1, 0, 1};
    return t < 0.5 ? mix(red, blue, t / 0.5) : mix(blue, green, (t - 0.5) / 0.5);
  };
  auto radial = [&](double x, double y) {
    // The largest t with |p - f - t (c - f)| = 10 t.
    const double cdx = 40 - 44, cdy = 45 - 43, pdx = x - 44, pdy = y - 43;
    const double a = cdx * cdx + cdy * cdy - 100, b = pdx * cdx + pdy * cdy, c = pdx * pdx + pdy * pdy;
    double t = (b - std::sqrt(b * b - a * c)) / a;
    t -= std::floor(t);
    return mix(Rgba{1, 1, 0, 1}, Rgba{0, 0, 0x88 / 255.0, 1}, t);
  };
  ShapeImageOptions options;
  const ShapeImageLayout layout = layout_shape_image(doc, options);
  for (AntiAliasing aa : {AntiAliasing::Full, AntiAliasing::Vbaa, AntiAliasing::Msaa}) {
    options.antialiasing = aa;
    const Image image = render_shape_image(test::gpu().renderer, doc, layout, options);
    double worst = 0.0;
    int checked = 0;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) {
        const double cx = x + 0.5, cy = y + 0.5;
        // Pixels wholly inside one rectangle (edges are the coverage tests' business).
        const bool in_l = x >= 11 && x < 70 && y >= 6 && y < 25, in_r = x >= 10 && x < 70 && y >= 30 && y < 58;
        if (!in_l && !in_r) continue;
        const Rgba p = in_l ? linear(cx) : radial(cx, cy);
        const double want[3] = {p.r * p.a + (1 - p.a), p.g * p.a + (1 - p.a), p.b * p.a + (1 - p.a)};
        for (int k = 0; k < 3; ++k) worst = std::max(worst, std::abs(image.pixel(x, y)[k] / 255.0 - want[k]));
        ++checked;
      }
    std::printf("gradients aa %d: %d pixels, largest difference %.4f\n", static_cast<int>(aa), checked, worst);
    if (worst > 2.5 / 255) write_png(image, std::string(CURVETEXT_TEST_OUTPUT_DIR) + "/svg-gradients.png");
    EXPECT_GT(checked, 2500);
    EXPECT_LE(worst, 2.5 / 255);  // 8-bit rounding of the target, float32 evaluation
  }
  // Bad gradients are refused by name.
  expect_refused(
      "<svg><radialGradient id='r' fx='2'><stop/><stop offset='1' stop-color='red'/></radialGradient>"
      "<rect width='9' height='9' fill='url(#r)'/></svg>",
      "focal point lies outside");
  std::string many = "<svg><linearGradient id='m'>";
  for (int i = 0; i < 20; ++i)
    many += "<stop offset='" + std::to_string(i / 20.0) + "' stop-color='#" + (i % 2 ? "f00" : "00f") + "'/>";
  expect_refused(many + "</linearGradient><rect width='9' height='9' fill='url(#m)'/></svg>", "20 stops");
}

// SVG 2's fr: t = 0 on the focal circle (fx, fy, fr), pad inside it; one
// reaching outside the circle is refused by name.
TEST(SvgRender, FocalRadiusStartsTheGradientOnACircle) {
  const ShapeDocument doc = parse_svg(
      "<svg width='80' height='60' viewBox='0 0 80 60'><radialGradient id='r' gradientUnits='userSpaceOnUse' "
      "cx='40' cy='30' r='25' fx='36' fy='28' fr='8'><stop offset='0' stop-color='#f00'/>"
      "<stop offset='1' stop-color='#00f'/></radialGradient><rect width='80' height='60' fill='url(#r)'/></svg>");
  ASSERT_TRUE(doc.shapes.at(0).gradient.has_value());
  EXPECT_EQ(doc.shapes[0].gradient->focal_radius, 8.0);
  // The largest t with |p - f - t (c - f)| = 8 + 17 t.
  auto t_at = [](double x, double y) {
    const double cdx = 4, cdy = 2, pdx = x - 36, pdy = y - 28, dr = 17;
    const double a = cdx * cdx + cdy * cdy - dr * dr, b = pdx * cdx + pdy * cdy + 8 * dr,
                 c = pdx * pdx + pdy * pdy - 64;
    return std::clamp((b - std::sqrt(b * b - a * c)) / a, 0.0, 1.0);
  };
  ShapeImageOptions options;
  const Image image = render_shape_image(test::gpu().renderer, doc, layout_shape_image(doc, options), options);
  double worst = 0.0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const double t = t_at(x + 0.5, y + 0.5);
      worst = std::max(
          {worst, std::abs(image.pixel(x, y)[0] / 255.0 - (1 - t)), std::abs(image.pixel(x, y)[2] / 255.0 - t)});
    }
  std::printf("fr: largest difference %.4f\n", worst);
  EXPECT_LE(worst, 2.5 / 255);
  expect_refused(
      "<svg><radialGradient id='r' fr='.4' fx='.3'><stop/><stop offset='1' stop-color='red'/></radialGradient>"
      "<rect width='9' height='9' fill='url(#r)'/></svg>",
      "focal circle (fr) reaches outside");
}

// Opacity on a group of overlapping shapes, and on a shape with both fill
// and stroke, composites them as one layer (SVG): where they overlap the top
// one shows alone at that opacity, not blended twice. Pixel-aligned shapes,
// so every pixel has one exact colour over white, in every AA mode; nested
// groups multiply.
TEST(SvgRender, GroupOpacityCompositesOneLayer) {
  const ShapeDocument doc = parse_svg(
      "<svg width='48' height='40' viewBox='0 0 48 40'>"
      "<g opacity='0.5'><rect x='4' y='4' width='20' height='14' fill='#f00'/>"
      "<rect x='14' y='10' width='20' height='14' fill='#00f'/></g>"
      "<rect x='8' y='28' width='12' height='8' fill='#0f0' stroke='#000' stroke-width='2' opacity='0.5'/>"
      "<g opacity='0.5'><g opacity='0.5'><rect x='36' y='4' width='8' height='8' fill='#000'/>"
      "<rect x='36' y='8' width='8' height='8' fill='#000'/></g><rect x='36' y='30' width='4' height='4'/></g>"
      "</svg>");
  EXPECT_EQ(doc.shapes.size(), 7u);
  ASSERT_EQ(doc.groups.size(), 4u);  // the two rectangles, fill and stroke, the outer and the inner group
  EXPECT_EQ(doc.groups[0].end, 2u);
  EXPECT_EQ(doc.groups[1].end, 4u);
  EXPECT_EQ(doc.groups[2].end, 7u);
  EXPECT_EQ(doc.groups[3].begin, 4u);  // the inner group, after the outer one that holds it
  EXPECT_EQ(doc.groups[3].end, 6u);
  auto want = [](int x, int y) -> std::array<double, 3> {
    auto in = [&](int x0, int y0, int w, int h) { return x >= x0 && x < x0 + w && y >= y0 && y < y0 + h; };
    if (in(14, 10, 20, 14)) return {0.5, 0.5, 1.0};  // blue on top of red: blue alone at 0.5
    if (in(4, 4, 20, 14)) return {1.0, 0.5, 0.5};
    if (in(7, 27, 14, 10) && !in(9, 29, 10, 6)) return {0.5, 0.5, 0.5};  // the stroke hides the fill under it
    if (in(9, 29, 10, 6)) return {0.5, 1.0, 0.5};
    if (in(36, 4, 8, 12)) return {0.75, 0.75, 0.75};  // 0.5 * 0.5, once
    if (in(36, 30, 4, 4)) return {0.5, 0.5, 0.5};
    return {1.0, 1.0, 1.0};
  };
  ShapeImageOptions options;
  const ShapeImageLayout layout = layout_shape_image(doc, options);
  ASSERT_EQ(layout.width, 48);
  for (AntiAliasing aa : {AntiAliasing::Full, AntiAliasing::Vbaa, AntiAliasing::Msaa, AntiAliasing::Auto}) {
    options.antialiasing = aa;
    const Image image = render_shape_image(test::gpu().renderer, doc, layout, options);
    double worst = 0.0;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) {
        const std::array<double, 3> w = want(x, y);
        for (int k = 0; k < 3; ++k) worst = std::max(worst, std::abs(image.pixel(x, y)[k] / 255.0 - w[k]));
      }
    std::printf("group opacity aa %d: largest difference %.4f\n", static_cast<int>(aa), worst);
    if (worst > 2.5 / 255)
      write_png(image, std::string(CURVETEXT_TEST_OUTPUT_DIR) + "/svg-group-opacity-" +
                           std::to_string(static_cast<int>(aa)) + ".png");
    EXPECT_LE(worst, 2.5 / 255);  // 8-bit rounding of the layer and of the target
  }
  // Each nested group holds a layer the size of the viewport: too deep a nest is refused.
  std::string deep = "<svg width='8' height='8'>";
  for (int i = 0; i < 40; ++i) deep += "<g opacity='0.9'><rect width='4' height='4'/>";
  for (int i = 0; i < 40; ++i) deep += "</g>";
  const ShapeDocument nested = parse_svg(deep + "</svg>");
  EXPECT_EQ(nested.groups.size(), 39u);  // the innermost group draws one shape: its alpha
  try {
    (void)ShapeDrawing::from_document(nested, 1.0);
    ADD_FAILURE() << "no error for 39 nested groups";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("nested deeper than 32"), std::string::npos) << e.what();
  }
  // Each group is an offscreen pass per draw: too many are refused.
  std::string many = "<svg width='8' height='8'>";
  for (int i = 0; i < 4097; ++i)
    many += "<g opacity='0.5'><rect width='4' height='4'/><rect width='2' height='2'/></g>";
  const ShapeDocument crowded = parse_svg(many + "</svg>");
  EXPECT_EQ(crowded.groups.size(), 4097u);
  EXPECT_THROW((void)ShapeDrawing::from_document(crowded, 1.0), Error);
}

// clip-path by the coverage of the clip's shapes: a circle clipped by a
// rectangle (userSpaceOnUse), a group clipped by a circle in its bounding
// box's units (the ellipse inscribed in it), and a rectangle clipped by an
// even-odd ring and a <use> of a shape, moved by the clipPath's transform;
// in every AA mode against point sampling of the intersections. A clip that
// draws nothing hides the element.
TEST(SvgRender, ClipPathsMultiplyByTheClipsCoverage) {
  const ShapeDocument doc = parse_svg(
      "<svg width='64' height='48' viewBox='0 0 64 48'>"
      "<clipPath id='a'><rect x='10.3' y='6.6' width='30.2' height='20.5'/></clipPath>"
      "<clipPath id='b' clipPathUnits='objectBoundingBox'><circle cx='.5' cy='.5' r='.5'/></clipPath>"
      "<defs><rect id='r' x='30' y='36' width='6' height='6'/></defs>"
      "<clipPath id='c' transform='translate(2 0)'><path clip-rule='evenodd' d='M4 33h20v10h-20z M8 35h12v6h-12z'/>"
      "<use href='#r'/></clipPath>"
      "<clipPath id='empty'/>"
      "<circle cx='25' cy='18' r='14.5' clip-path='url(#a)'/>"
      "<g clip-path='url(#b)'><rect x='44' y='4' width='16' height='12'/><rect x='44' y='16' width='16' "
      "height='12'/></g>"
      "<rect x='3' y='32.5' width='58' height='12' clip-path='url(#c)'/>"
      "<rect x='40' y='40' width='20' height='6' clip-path='url(#empty)'/></svg>");
  ASSERT_EQ(doc.shapes.size(), 4u);
  ASSERT_EQ(doc.groups.size(), 3u);
  auto inside = [](double x, double y) {
    const bool a =
        (x - 25) * (x - 25) + (y - 18) * (y - 18) < 14.5 * 14.5 && x > 10.3 && x < 40.5 && y > 6.6 && y < 27.1;
    const double u = (x - 52) / 8, v = (y - 16) / 12;
    const bool b = u * u + v * v < 1;
    const bool ring = x > 6 && x < 26 && y > 33 && y < 43 && !(x > 10 && x < 22 && y > 35 && y < 41);
    const bool used = x > 32 && x < 38 && y > 36 && y < 42;
    const bool c = (ring || used) && x > 3 && x < 61 && y > 32.5 && y < 44.5;
    return a || b || c;
  };
  ShapeImageOptions options;
  const ShapeImageLayout layout = layout_shape_image(doc, options);
  ASSERT_EQ(layout.width, 64);
  const test::Coverage ref = test::sampled_reference(inside, layout.width, layout.height, 32);
  for (AntiAliasing aa : {AntiAliasing::Full, AntiAliasing::Vbaa, AntiAliasing::Msaa}) {
    options.antialiasing = aa;
    const test::Coverage got =
        test::coverage_from_black_on_white(render_shape_image(test::gpu().renderer, doc, layout, options));
    const test::CoverageStats st = test::compare(got, ref);
    const std::string name = "svg-clip-paths-aa" + std::to_string(static_cast<int>(aa));
    std::printf("%s: edge %.4f max %.3f ink %.4f\n", name.c_str(), st.edge_mean_abs, st.max_abs, st.ink_ratio);
    test::expect_coverage(name, got, ref, st, aa == AntiAliasing::Msaa ? 0.08 : 0.01,
                          aa == AntiAliasing::Msaa ? 0.02 : 0.005);
  }
  // A rectangle clipped by a rectangle whose edges meet it only at right angles: every pixel's
  // coverage is the product of the two (a box's area is the product of its extents), exact
  // but for 8-bit rounding, against the box (10.5, 4.2)-(20.7, 12.4) computed here.
  const ShapeDocument boxes = parse_svg(
      "<svg width='32' height='20' viewBox='0 0 32 20'><clipPath id='k'><rect x='10.5' y='2' width='19.75' "
      "height='10.4'/></clipPath><rect x='3.3' y='4.2' width='17.4' height='11.4' clip-path='url(#k)'/></svg>");
  ShapeImageOptions full;
  const ShapeImageLayout box_layout = layout_shape_image(boxes, full);
  const test::Coverage got =
      test::coverage_from_black_on_white(render_shape_image(test::gpu().renderer, boxes, box_layout, full));
  double worst = 0.0;
  for (int y = 0; y < got.height; ++y)
    for (int x = 0; x < got.width; ++x) {
      const double fx = std::max(0.0, std::min(x + 1.0, 20.7) - std::max(double(x), 10.5));
      const double fy = std::max(0.0, std::min(y + 1.0, 12.4) - std::max(double(y), 4.2));
      worst = std::max(worst, std::abs(got.at(x, y) - fx * fy));
    }
  std::printf("rectangle clipped by a rectangle: largest difference %.4f\n", worst);
  EXPECT_LE(worst, 2.5 / 255);
}

// Markers at a polyline's vertices: a triangle (viewBox 0 0 4 4, refX 0,
// refY 2) scaled by the stroke width, turned by orient="auto" (the first
// segment's direction at the start, the bisector at the middle vertex, the
// last segment's at the end) and by a fixed angle; in every AA mode against
// point sampling of the placed triangles and the stroke.
TEST(SvgRender, MarkersArePlacedAtVerticesAndOriented) {
  const ShapeDocument doc = parse_svg(
      "<svg width='64' height='48' viewBox='0 0 64 48'>"
      "<marker id='m' markerWidth='4' markerHeight='4' refY='2' orient='auto' viewBox='0 0 4 4'>"
      "<path d='M0 0 L4 2 L0 4 z'/></marker>"
      "<marker id='f' markerWidth='3' markerHeight='3' refX='1.5' refY='1.5' orient='90' markerUnits='userSpaceOnUse'>"
      "<rect width='3' height='1'/></marker>"
      "<polyline points='8,40 28,10 56,30' fill='none' stroke='#000' stroke-width='1.5' stroke-linejoin='round' "
      "marker-start='url(#m)' marker-mid='url(#m)' marker-end='url(#m)'/>"
      "<line x1='40' y1='44' x2='60' y2='44' stroke='none' marker-end='url(#f)'/></svg>");
  const Vec2 p0{8, 40}, p1{28, 10}, p2{56, 30};
  const double a0 = std::atan2(p1.y - p0.y, p1.x - p0.x), a2 = std::atan2(p2.y - p1.y, p2.x - p1.x);
  struct Placed {
    Vec2 at;
    double angle;
  };
  const Placed placed[3] = {{p0, a0}, {p1, 0.5 * (a0 + a2)}, {p2, a2}};
  auto near_segment = [](Vec2 u, Vec2 p, Vec2 q, double h) {
    const double len = distance(p, q);
    const Vec2 t = (q - p) * (1.0 / len), r = u - p;
    const double along = r.x * t.x + r.y * t.y, across = std::abs(t.x * r.y - t.y * r.x);
    return along >= 0 && along <= len && across <= h;
  };
  auto inside = [&](double x, double y) {
    const Vec2 u{x, y};
    // The stroke with its round join.
    bool in = near_segment(u, p0, p1, 0.75) || near_segment(u, p1, p2, 0.75) || distance(u, p1) <= 0.75;
    for (const Placed& pl : placed) {
      // Back into the marker's content: unrotate, unscale by the stroke width, add the reference point.
      const Vec2 d = u - pl.at;
      const double c = std::cos(pl.angle), s = std::sin(pl.angle);
      const Vec2 q{(c * d.x + s * d.y) / 1.5, (-s * d.x + c * d.y) / 1.5 + 2};
      in = in || (q.x >= 0 && q.x <= 4 && std::abs(q.y - 2) <= 0.5 * (4 - q.x));
    }
    // The rectangle (0, 0)-(3, 1) less the reference point (1.5, 1.5), turned 90 degrees, at (60, 44).
    return in || (x >= 60.5 && x <= 61.5 && y >= 42.5 && y <= 45.5);
  };
  ShapeImageOptions options;
  const ShapeImageLayout layout = layout_shape_image(doc, options);
  const test::Coverage ref = test::sampled_reference(inside, layout.width, layout.height, 32);
  for (AntiAliasing aa : {AntiAliasing::Full, AntiAliasing::Vbaa, AntiAliasing::Msaa}) {
    options.antialiasing = aa;
    const test::Coverage got =
        test::coverage_from_black_on_white(render_shape_image(test::gpu().renderer, doc, layout, options));
    const test::CoverageStats st = test::compare(got, ref);
    const std::string name = "svg-markers-aa" + std::to_string(static_cast<int>(aa));
    std::printf("%s: edge %.4f max %.3f ink %.4f\n", name.c_str(), st.edge_mean_abs, st.max_abs, st.ink_ratio);
    test::expect_coverage(name, got, ref, st, aa == AntiAliasing::Msaa ? 0.08 : 0.01,
                          aa == AntiAliasing::Msaa ? 0.02 : 0.005);
  }
}

// The drawing object draws into the framebuffer bound, at any placement:
// the same pixels as render_shape_image, moved; built for twice the scale,
// the same as render_shape_image at twice the size.
TEST(SvgRender, DrawingObjectDrawsWhereThePlacementSays) {
  const ShapeDocument doc = parse_svg(
      "<svg width='40' height='30' viewBox='0 0 40 30'><radialGradient id='r' fx='.4'><stop stop-color='#fc0'/>"
      "<stop offset='1' stop-color='#06c' stop-opacity='.7'/></radialGradient>"
      "<ellipse cx='20' cy='15' rx='18' ry='12' fill='url(#r)' stroke='#333' stroke-width='1.5'/>"
      "<path d='M5 25 L35 5' stroke='red' stroke-linecap='round' stroke-dasharray='4 3'/></svg>");
  for (double k : {1.0, 2.0}) {
    ShapeImageOptions options;
    options.width = static_cast<int>(40 * k);
    options.height = static_cast<int>(30 * k);
    const ShapeImageLayout layout = layout_shape_image(doc, options);
    const Image want = render_shape_image(test::gpu().renderer, doc, layout, options);
    const ShapeDrawing drawing = ShapeDrawing::from_document(doc, layout.placement.scale);
    EXPECT_EQ(drawing.layer_count(), 3u);
    const int dx = 13, dy = 7;
    ImageTarget target;
    target.begin(want.width + 30, want.height + 20, Color{1, 1, 1, 1});
    Placement at = layout.placement;
    at.origin_x += dx;
    at.origin_y += dy;
    drawing.draw(test::gpu().renderer, at, DrawOptions{});
    const Image got = target.read_pixels();
    int worst = 0;
    for (int y = 0; y < want.height; ++y)
      for (int x = 0; x < want.width; ++x)
        for (int c = 0; c < 4; ++c)
          worst = std::max(worst, std::abs(got.pixel(x + dx, y + dy)[c] - want.pixel(x, y)[c]));
    std::printf("drawing object at %gx, moved by (%d, %d): largest difference %d/255\n", k, dx, dy, worst);
    EXPECT_LE(worst, 1);
  }
  EXPECT_THROW(ShapeDrawing::from_document(doc, 0.0), Error);
}

}  // namespace
}  // namespace curvetext
