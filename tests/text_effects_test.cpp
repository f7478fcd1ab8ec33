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

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "curvetext/error.hpp"
#include "curvetext/font.hpp"
#include "curvetext/font_collection.hpp"
#include "curvetext/layout.hpp"
#include "curvetext/text_block.hpp"
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
      const int pieces =
          std::max(4, static_cast<int>(std::ceil(std::sqrt(std::hypot(dx, dy) / kOracleFlatnessPx))) * 2);
      for (int i = 1; i < pieces; ++i) pts.push_back(conic_at(s, static_cast<double>(i) / pieces));
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
      const Vec2 side{-(b.y - a.y) / len * r, (b.x - a.x) / len * r};
      add_positive(out, quad(a + side, b + side, b - side, a - side));
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

// `c` convolved along x then y with the discrete Gaussian of the shadow
// shader: w_k = exp(-k^2 / (2 sigma^2)) for |k| <= ceil(3 sigma), summing to
// 1; outside the image counts as 0.
test::Coverage gaussian_blur(const test::Coverage& c, double sigma) {
  const int r = static_cast<int>(std::ceil(3.0 * sigma));
  std::vector<double> w(static_cast<std::size_t>(r) + 1);
  double total = 0.0;
  for (int k = 0; k <= r; ++k) {
    w[static_cast<std::size_t>(k)] = sigma > 0.0 ? std::exp(-0.5 * k * k / (sigma * sigma)) : 1.0;
    total += k == 0 ? w[0] : 2.0 * w[static_cast<std::size_t>(k)];
  }
  test::Coverage tmp(c.width, c.height), out(c.width, c.height);
  for (int pass = 0; pass < 2; ++pass) {
    const test::Coverage& from = pass == 0 ? c : tmp;
    test::Coverage& to = pass == 0 ? tmp : out;
    for (int y = 0; y < c.height; ++y)
      for (int x = 0; x < c.width; ++x) {
        double sum = 0.0;
        for (int k = -r; k <= r; ++k) {
          const int sx = pass == 0 ? x + k : x, sy = pass == 0 ? y : y + k;
          if (sx < 0 || sy < 0 || sx >= c.width || sy >= c.height) continue;
          sum += w[static_cast<std::size_t>(std::abs(k))] * from.at(sx, sy);
        }
        to.at(x, y) = static_cast<float>(sum / total);
      }
  }
  return out;
}

TEST(TextShadow, MatchesTheShiftedGlyphsBlurred) {
  const Scene s("Rag");
  struct Case {
    double dx, dy, blur;
  };
  for (const Case c : {Case{3.0, 2.0, 0.0}, Case{3.0, 2.0, 4.0}, Case{0.0, 0.0, 7.0}, Case{-2.5, 1.25, 2.0}}) {
    TextEffects e;
    e.shadow = TextShadow{c.dx, c.dy, c.blur, Color{0, 0, 0, 1}};
    if (c.dx == 0.0 && c.dy == 0.0) e.shadow = TextEffects::glow(c.blur, Color{0, 0, 0, 1});
    const test::Coverage got = test::coverage_from_black_on_white(draw(s, e, Color{0, 0, 0, 0}));
    const Placement moved(s.placement.scale, s.placement.origin_x + c.dx, s.placement.origin_y + c.dy);
    const test::Coverage sharp = test::union_coverage(
        positive(test::place_outline(test::line_outline(s.font, s.line), moved)), s.width, s.height);
    char name[96];
    std::snprintf(name, sizeof name, "text-shadow-%g-%g-%g", c.dx, c.dy, c.blur);
    check(name, got, gaussian_blur(sharp, c.blur / 2.0));
  }
}

// A paragraph through TextBlock: the same outline ring and shadow, from
// the layout's glyph positions.
TEST(TextBlockEffects, ParagraphOutlineAndShadowMatchTheReference) {
  test::Gpu& g = test::gpu();
  FontCollection fonts;
  ParagraphStyle style;
  style.default_style.fonts = {test::kDejaVuSans};
  style.default_style.size_px = 40.0;
  style.default_style.color = Color{0, 0, 0, 0};
  const Paragraph p = Paragraph::layout(fonts, "R a", {}, style);
  Outline glyphs;
  for (const LayoutLine& line : p.lines())
    for (const GlyphRun& run : line.runs) {
      const double scale = run.size_px / run.font->metrics().units_per_em;
      for (const PositionedGlyph& pg : run.glyphs) {
        const Outline placed =
            test::place_outline(run.font->glyph_outline(pg.id), Placement(scale, 10 + pg.x, 10 + pg.y));
        for (const Contour& c : placed.contours()) glyphs.contours().push_back(c);
      }
    }
  glyphs = positive(glyphs);
  const int w = 100, h = 70;
  auto render = [&](const TextEffects& e) {
    ParagraphStyle with = style;
    with.default_style.effects = e;
    const TextBlock block = TextBlock::from_paragraph(g.cache, Paragraph::layout(fonts, "R a", {}, with));
    g.target.begin(w, h, Color{1, 1, 1, 1});
    block.draw(g.renderer, 10.0, 10.0, DrawOptions{});
    return test::coverage_from_black_on_white(g.target.read_pixels());
  };
  TextEffects outline;
  outline.outline_width = 2.5;
  Outline dilated = glyphs;
  add_capsules(glyphs, 2.5, dilated);
  test::Coverage ring = test::union_coverage(dilated, w, h);
  const test::Coverage fill = test::union_coverage(glyphs, w, h);
  for (std::size_t i = 0; i < ring.value.size(); ++i) ring.value[i] -= fill.value[i];
  check("block-outline", render(outline), ring);
  TextEffects shadow;
  shadow.shadow = TextShadow{2.0, 3.0, 5.0, Color{0, 0, 0, 1}};
  Outline moved = glyphs;
  for (Contour& c : moved.contours())
    for (Segment& sgm : c.segments)
      for (Vec2& q : sgm.p) q = q + Vec2{2.0, 3.0};
  check("block-shadow", render(shadow), gaussian_blur(test::union_coverage(moved, w, h), 2.5));
}

// Effect meshes are cached per glyph and width bucket in ems: the same line
// again builds nothing, and an outline of the same width in ems at another
// size of the same level of detail band (40 and 48 px/em) neither; another
// width builds.
TEST(TextEffectsCache, OutlinesAreBuiltOncePerGlyphAndWidthInEms) {
  (void)test::gpu();  // the cache uploads meshes: a current context, also when this test runs alone
  GlyphCache cache;
  const Font font = Font::open(test::kDejaVuSans);
  const ShapedLine line = shape_line(font, "cache");
  TextEffects e;
  e.outline_width = 2.0;
  (void)EffectBatch::from_text(cache, font, line, 40.0, e);
  const std::size_t built = cache.stats().misses;
  EXPECT_GE(built, 8u);  // four distinct glyphs, each a fill and an outline
  (void)EffectBatch::from_text(cache, font, line, 40.0, e);
  EXPECT_EQ(cache.stats().misses, built);
  e.outline_width = 2.4;  // 0.05 em at 48 px/em, as 2 px at 40
  (void)EffectBatch::from_text(cache, font, line, 48.0, e);
  EXPECT_EQ(cache.stats().misses, built);
  e.outline_width = 3.0;
  (void)EffectBatch::from_text(cache, font, line, 48.0, e);
  EXPECT_GT(cache.stats().misses, built);
}

// A translucent fill over an opaque outline: inside the glyph only the fill
// and the background show, never the outline's colour.
TEST(TextOutline, TranslucentFillDoesNotShowTheOutlineUnderIt) {
  const Scene s;
  TextEffects e;
  e.outline_width = 3.0;
  e.outline_color = Color{0, 0, 1, 1};
  const Image img = draw(s, e, Color{1, 0, 0, 0.5f});
  const test::Coverage glyph = test::union_coverage(s.pixel_glyphs, s.width, s.height);
  int inside = 0, blue = 0;
  for (int y = 0; y < s.height; ++y)
    for (int x = 0; x < s.width; ++x) {
      // Pixels wholly inside a glyph and a pixel away from its edge.
      bool deep = true;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int xx = std::clamp(x + dx, 0, s.width - 1), yy = std::clamp(y + dy, 0, s.height - 1);
          deep = deep && glyph.at(xx, yy) >= 1.0f;
        }
      if (!deep) continue;
      ++inside;
      const std::uint8_t* p = img.pixel(x, y);
      // Half red over white: (255, 128, 128); the outline under it would pull green down.
      if (p[1] < 120 || p[0] < 250) ++blue;
    }
  std::printf("%d pixels inside the glyphs, %d showing the outline\n", inside, blue);
  EXPECT_GT(inside, 50);
  EXPECT_EQ(blue, 0);
}

TEST(TextEffectsInput, BadValuesAreRefusedByName) {
  test::Gpu& g = test::gpu();
  const Scene s;
  const double nan = std::numeric_limits<double>::quiet_NaN(), inf = std::numeric_limits<double>::infinity();
  auto refused = [&](const TextEffects& e, const char* word) {
    try {
      (void)EffectBatch::from_text(g.cache, s.font, s.line, s.size_px, e);
      ADD_FAILURE() << "accepted: " << word;
    } catch (const Error& err) {
      EXPECT_EQ(err.code(), ErrorCode::InvalidArgument);
      EXPECT_NE(std::string(err.what()).find(word), std::string::npos) << err.what();
    }
  };
  for (double v : {-1.0, nan, inf, 1e9, 40.5}) {
    TextEffects e;
    e.outline_width = v;
    refused(e, "outline width");
    e = {};
    e.stroke_width = v;
    refused(e, "stroke width");
  }
  for (double v : {-1.0, nan, inf, tolerance::kMaxShadowBlurPx * 2}) {
    TextEffects e;
    e.shadow = TextEffects::glow(v, Color{0, 0, 0, 1});
    refused(e, "blur");
  }
  for (double v : {nan, inf, -1e7}) {
    TextEffects e;
    e.shadow = TextShadow{v, 0.0, 1.0, Color{0, 0, 0, 1}};
    refused(e, "offset");
  }
  TextEffects e;
  e.outline_width = 1.0;
  e.outline_color = Color{0, 0, 2, 1};
  refused(e, "outline colour");
}

// The widest outline and blur allowed on a long line: bounded time, a valid
// mesh (or Error(Geometry)), never a hang.
TEST(TextEffectsInput, WidestOutlineAndBlurFinish) {
  test::Gpu& g = test::gpu();
  const Font font = Font::open(test::kDejaVuSans);
  const ShapedLine line = shape_line(font, "Wide outlines & blur: AVAWg@%");
  TextEffects e;
  e.outline_width = tolerance::kMaxTextEffectWidthEm * 24.0;
  e.shadow = TextEffects::glow(tolerance::kMaxShadowBlurPx, Color{0, 0, 0, 1});
  const auto start = std::chrono::steady_clock::now();
  try {
    const EffectBatch batch = EffectBatch::from_text(g.cache, font, line, 24.0, e);
    g.target.begin(400, 300, Color{1, 1, 1, 1});
    batch.draw(g.renderer, Placement(24.0 / font.metrics().units_per_em, 20, 150), DrawOptions{});
    (void)g.target.read_pixels();
  } catch (const Error& err) {
    EXPECT_EQ(err.code(), ErrorCode::Geometry) << err.what();
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("widest outline and blur: %.2f s\n", seconds);
  EXPECT_LT(seconds, 60.0);
}

}  // namespace
}  // namespace curvetext
