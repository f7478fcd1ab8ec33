// Rendering through the whole pipeline (shaping -> glyph meshes -> GLES2 curve
// shader on llvmpipe -> pixels), compared with exact area coverage of the same
// outlines from FreeType's AA rasterizer, supersampled (docs/design.md section 6).
// Failing cases write result, reference and diff images to build/test-output.
#include <GLES2/gl2.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <numbers>
#include <string>
#include <tuple>
#include <vector>

#include <hb.h>

#include "curvetext/curves.hpp"
#include "curvetext/error.hpp"
#include "curvetext/font.hpp"
#include "curvetext/headless.hpp"
#include "curvetext/mesh.hpp"
#include "curvetext/renderer.hpp"
#include "curvetext/text_image.hpp"
#include "core/tolerances.hpp"
#include "support/coverage.hpp"
#include "support/fonts.hpp"
#include "support/gpu.hpp"
#include "support/union_coverage.hpp"

namespace curvetext {
namespace {

using test::Gpu;
using test::gpu;

using test::line_outline;

struct Case {
  const char* font_name;
  const char* font_path;
  const char* script;
  const char* text;
  double size;
};

std::string case_name(const Case& c, const char* mode) {
  std::string n =
      std::string(c.font_name) + "_" + c.script + "_" + std::to_string(static_cast<int>(c.size)) + "px_" + mode;
  return n;
}

struct Rendered {
  test::Coverage result;
  test::Coverage reference;
  test::CoverageStats stats;
};

Rendered render_case(const Case& c, AntiAliasing aa) {
  Font font = Font::open(c.font_path);
  TextImageOptions options;
  options.size_px = c.size;
  options.antialiasing = aa;
  const TextImageLayout layout = layout_text_image(font, c.text, options);
  const Image image = render_text_image(gpu().renderer, gpu().cache, font, layout, options);
  Rendered r;
  r.result = test::coverage_from_black_on_white(image);
  // 16x supersampling below 48 px, 4x above: FreeType's chord and 1/64 px
  // rounding errors shrink by that factor.
  const int supersample = c.size < 48 ? 16 : 4;
  r.reference = test::freetype_reference(line_outline(font, layout.line), layout.placement, layout.width, layout.height,
                                         supersample);
  r.stats = test::compare(r.result, r.reference);
  return r;
}

const char* kLatin = "Hamburgefontsiv";
const char* kGreek = "Καλημέρα κόσμε";
const char* kCyrillic = "Съешь ещё этих";

std::vector<Case> all_cases() {
  std::vector<Case> cases;
  const struct {
    const char* name;
    const char* path;
  } fonts[] = {{"DejaVuSans", test::kDejaVuSans}, {"NotoSans", test::kNotoSans}, {"NimbusRoman", test::kNimbusRoman}};
  const struct {
    const char* name;
    const char* text;
  } scripts[] = {{"Latin", kLatin}, {"Greek", kGreek}, {"Cyrillic", kCyrillic}};
  for (const auto& f : fonts)
    for (const auto& s : scripts)
      for (double size : {12.0, 16.0, 24.0, 48.0, 200.0}) cases.push_back({f.name, f.path, s.name, s.text, size});
  return cases;
}

class FullAntialiasing : public ::testing::TestWithParam<Case> {};

// Issue targets: edge-band mean error <= 0.04 at 12-16 px, <= 0.03 from 24 px
// up; ink within 3%.
TEST_P(FullAntialiasing, MatchesExactCoverage) {
  const Case& c = GetParam();
  const Rendered r = render_case(c, AntiAliasing::Full);
  const double limit = c.size <= 16 ? 0.04 : 0.03;
  std::printf("%-34s edge %.4f  mean %.5f  max %.3f  ink %.4f\n", case_name(c, "full").c_str(), r.stats.edge_mean_abs,
              r.stats.mean_abs, r.stats.max_abs, r.stats.ink_ratio);
  const bool ok = r.stats.edge_mean_abs <= limit && std::abs(r.stats.ink_ratio - 1.0) <= 0.03;
  if (!ok) test::write_comparison(case_name(c, "full"), r.result, r.reference);
  EXPECT_LE(r.stats.edge_mean_abs, limit);
  EXPECT_NEAR(r.stats.ink_ratio, 1.0, 0.03);
}

INSTANTIATE_TEST_SUITE_P(Strings, FullAntialiasing, ::testing::ValuesIn(all_cases()),
                         [](const ::testing::TestParamInfo<Case>& param) { return case_name(param.param, "full"); });

// `curves` is the paper's single pass: curved edges are antialiased inside
// their triangles only and straight edges are aliased (pixel centres decide).
// It is measurably worse than `full`; these bounds record how far it is off
// (measured: ink 0.926 and edge error 0.081 at 16 px, 0.989 and 0.059 at 48 px).
TEST(CurvesAntialiasing, PaperSinglePassIsCloseInInkAndWorseThanFull) {
  for (double size : {16.0, 48.0}) {
    const Case c{"DejaVuSans", test::kDejaVuSans, "Latin", kLatin, size};
    const Rendered curves = render_case(c, AntiAliasing::Curves);
    const Rendered full = render_case(c, AntiAliasing::Full);
    std::printf("%-34s edge %.4f  ink %.4f (full: edge %.4f)\n", case_name(c, "curves").c_str(),
                curves.stats.edge_mean_abs, curves.stats.ink_ratio, full.stats.edge_mean_abs);
    const double ink_limit = size < 24 ? 0.10 : 0.03;
    if (std::abs(curves.stats.ink_ratio - 1.0) > ink_limit || curves.stats.edge_mean_abs > 0.12)
      test::write_comparison(case_name(c, "curves"), curves.result, curves.reference);
    EXPECT_NEAR(curves.stats.ink_ratio, 1.0, ink_limit);
    EXPECT_LE(curves.stats.edge_mean_abs, 0.12);
    EXPECT_GT(curves.stats.edge_mean_abs, 2 * full.stats.edge_mean_abs);
  }
}

// `none` is the bare in/out test: every pixel is fully in or out, and the ink
// is right on average.
TEST(NoAntialiasing, BinaryPixelsWithRightInk) {
  for (double size : {24.0, 200.0}) {
    const Case c{"NotoSans", test::kNotoSans, "Latin", kLatin, size};
    const Rendered r = render_case(c, AntiAliasing::None);
    std::size_t partial = 0;
    for (float v : r.result.value)
      if (v > 0.002f && v < 0.998f) ++partial;
    std::printf("%-34s ink %.4f partial pixels %zu\n", case_name(c, "none").c_str(), r.stats.ink_ratio, partial);
    EXPECT_EQ(partial, 0u);
    EXPECT_NEAR(r.stats.ink_ratio, 1.0, size < 48 ? 0.08 : 0.02);
    if (::testing::Test::HasFailure()) test::write_comparison(case_name(c, "none"), r.result, r.reference);
  }
}

// --- Geometry contract (docs/design.md section 6) ------------------------------------

TEST(GeometryContract, ImageSizeAndPenFollowHarfBuzzAtThePixelSize) {
  const double size = 24;
  const char* text = "Hamburgefontsiv";
  Font font = Font::open(test::kDejaVuSans);
  TextImageOptions options;
  options.size_px = size;
  const TextImageLayout layout = layout_text_image(font, text, options);

  // Independently: HarfBuzz at size * 64 (26.6), as other renderers call it.
  hb_blob_t* blob = hb_blob_create_from_file(test::kDejaVuSans);
  hb_face_t* face = hb_face_create(blob, 0);
  hb_font_t* hb = hb_font_create(face);
  const int scale = static_cast<int>(size * 64);
  hb_font_set_scale(hb, scale, scale);
  hb_font_extents_t ext{};
  hb_font_get_h_extents(hb, &ext);
  hb_buffer_t* buf = hb_buffer_create();
  hb_buffer_add_utf8(buf, text, -1, 0, -1);
  hb_buffer_guess_segment_properties(buf);
  hb_shape(hb, buf, nullptr, 0);
  unsigned n = 0;
  const hb_glyph_position_t* pos = hb_buffer_get_glyph_positions(buf, &n);
  double advance = 0;
  for (unsigned i = 0; i < n; ++i) advance += pos[i].x_advance / 64.0;
  const double a = ext.ascender / 64.0, d = ext.descender / 64.0;
  hb_buffer_destroy(buf);
  hb_font_destroy(hb);
  hb_face_destroy(face);
  hb_blob_destroy(blob);

  EXPECT_EQ(layout.width, static_cast<int>(std::ceil(2 * 16 + advance)));
  EXPECT_EQ(layout.height, static_cast<int>(std::ceil(2 * 16 + a - d)));
  EXPECT_NEAR(layout.placement.origin_x, 16.0, 1e-12);
  EXPECT_NEAR(layout.placement.origin_y, 16.0 + a, 1.0 / 64);
  EXPECT_NEAR(layout.placement.scale, size / font.metrics().units_per_em, 1e-15);
  EXPECT_NEAR(layout.line.advance * layout.placement.scale, advance, 1.0 / 64 * n);
}

// Moving a batch is a uniform change: the same buffer drawn at an origin moved
// by whole pixels gives the same pixels, moved; drawn at twice the scale it
// still matches exact coverage (no rebuild, no atlas).
TEST(DrawBatchTransform, MovingAndScalingChangeOnlyUniforms) {
  Font font = Font::open(test::kNotoSans);
  const ShapedLine line = shape_line(font, "Moving text");
  DrawBatch batch = DrawBatch::from_text(gpu().cache, font, line, 24.0);
  const std::size_t vertices = batch.vertex_count();
  ASSERT_GT(vertices, 0u);
  const double scale = 24.0 / font.metrics().units_per_em;
  auto draw = [&](Placement p, int w, int h) {
    gpu().target.begin(w, h, Color{1, 1, 1, 1});
    gpu().renderer.draw(batch, p, DrawOptions{});
    return test::coverage_from_black_on_white(gpu().target.read_pixels());
  };
  const test::Coverage a = draw({scale, 10.25, 40.5}, 220, 80);
  const test::Coverage b = draw({scale, 13.25, 45.5}, 220, 80);
  double worst = 0;
  for (int y = 0; y + 5 < 80; ++y)
    for (int x = 0; x + 3 < 220; ++x)
      worst = std::max(worst, static_cast<double>(std::abs(a.at(x, y) - b.at(x + 3, y + 5))));
  EXPECT_LE(worst, 1.0 / 255 + 1e-6) << "a whole-pixel move changed pixel values";
  EXPECT_EQ(batch.vertex_count(), vertices);

  const Placement big{2 * scale, 10.25, 80.5};
  const test::Coverage c = draw(big, 420, 120);
  const test::Coverage ref = test::freetype_reference(line_outline(font, line), big, 420, 120, 8);
  const test::CoverageStats s = test::compare(c, ref);
  if (s.edge_mean_abs > 0.03) test::write_comparison("moving-text-scaled", c, ref);
  EXPECT_LE(s.edge_mean_abs, 0.03);
  EXPECT_NEAR(s.ink_ratio, 1.0, 0.03);
}

// A block moved by a fraction of a pixel (text scrolling or animating) is
// drawn as the exact coverage of its outline moved by that fraction, in the
// modes that antialias every edge. Control: compared with the reference of
// the block a third of a pixel away, the same image must fail.
TEST(DrawBatchTransform, FractionalOffsetMatchesExactCoverageShifted) {
  Font font = Font::open(test::kDejaVuSans);
  const ShapedLine line = shape_line(font, "Scrolling by 0.37 px");
  DrawBatch batch = DrawBatch::from_text(gpu().cache, font, line, 16.0);
  const double scale = 16.0 / font.metrics().units_per_em;
  const Outline outline = line_outline(font, line);
  const int w = 190, h = 28;
  constexpr double kLimit = 0.005;  // edge-band mean error (full measures 0.001-0.002 here)
  for (AntiAliasing aa : {AntiAliasing::Full, AntiAliasing::Vbaa}) {
    for (const Vec2 offset : {Vec2{0.0, 0.0}, Vec2{0.37, 0.0}, Vec2{0.5, 0.61}, Vec2{0.83, 0.29}}) {
      const Placement placement{scale, 4.0 + offset.x, 20.0 + offset.y};
      gpu().target.begin(w, h, Color{1, 1, 1, 1});
      gpu().renderer.draw(batch, placement, DrawOptions(Color{0, 0, 0, 1}, aa));
      const test::Coverage got = test::coverage_from_black_on_white(gpu().target.read_pixels());
      const test::Coverage want = test::union_coverage(test::place_outline(outline, placement), w, h);
      const Placement away{scale, placement.origin_x + 1.0 / 3.0, placement.origin_y};
      const test::Coverage control = test::union_coverage(test::place_outline(outline, away), w, h);
      const test::CoverageStats s = test::compare(got, want);
      const test::CoverageStats off = test::compare(got, control);
      std::printf("%s offset (%.2f, %.2f): edge %.4f, max %.3f, ink %.4f; a third of a pixel away: edge %.4f\n",
                  aa == AntiAliasing::Full ? "full" : "vbaa", offset.x, offset.y, s.edge_mean_abs, s.max_abs,
                  s.ink_ratio, off.edge_mean_abs);
      if (s.edge_mean_abs > kLimit) test::write_comparison("fractional-offset", got, want);
      EXPECT_LE(s.edge_mean_abs, kLimit);
      EXPECT_NEAR(s.ink_ratio, 1.0, 0.01);
      EXPECT_GT(off.edge_mean_abs, 4 * kLimit) << "the control should fail";
    }
  }
}

// vbaa's and msaa's offscreen targets are bounded (tolerances.hpp): a block
// larger than a tile at r texels per pixel is drawn tile by tile. Three lines
// of about 1,250 px at r = 8 take several tiles: no seam may show against the
// exact coverage (every pixel within the mode's own error).
TEST(OffscreenTiles, WideBlocksAreDrawnTileByTileWithoutSeams) {
  Font font = Font::open(test::kDejaVuSans);
  const ShapedLine line = shape_line(font, "Tiles of a bounded offscreen target, drawn one after another.");
  const double ppem = 40.0;
  const double scale = ppem / font.metrics().units_per_em;
  const double line_units = 1.2 * font.metrics().units_per_em;
  std::vector<PlacedGlyph> placed;
  const int kLines = 3;
  for (int k = 0; k < kLines; ++k) {
    double pen = 0.0;
    for (const ShapedGlyph& g : line.glyphs) {
      placed.push_back(PlacedGlyph{g.glyph_id, pen + g.x_offset, g.y_offset - k * line_units});
      pen += g.x_advance;
    }
  }
  DrawBatch batch = DrawBatch::from_glyphs(gpu().cache, font, placed, ppem);
  const Placement placement{scale, 6.3, 40.6};
  const int w = static_cast<int>(std::ceil(line.advance * scale)) + 12;
  const int h = static_cast<int>(std::ceil(40.6 + (kLines - 1) * line_units * scale)) + 16;
  ASSERT_GT(static_cast<double>(w) * h * 64, 2.0 * tolerance::kCoverageTileTexels * tolerance::kCoverageTileTexels);
  test::Coverage want(w, h);
  for (int k = 0; k < kLines; ++k) {
    const Placement at{scale, placement.origin_x, placement.origin_y + k * line_units * scale};
    test::add_union_coverage(test::place_outline(line_outline(font, line), at), want);
  }
  struct Mode {
    AntiAliasing aa;
    double edge, max;  // limits: edge-band mean and largest pixel error
  };
  // msaa's 4 samples leave up to half a pixel of error at thin features; a
  // seam (a column drawn twice or not at all) would leave a whole one.
  for (const Mode& m : {Mode{AntiAliasing::Vbaa, 0.004, 0.06}, Mode{AntiAliasing::Msaa, 0.06, 0.75}}) {
    if (m.aa == AntiAliasing::Msaa && gpu().renderer.msaa_samples() < 2) continue;
    DrawOptions options(Color{0, 0, 0, 1}, m.aa);
    options.vbaa_factor = 8;
    const std::size_t passes = gpu().renderer.offscreen_passes();
    gpu().target.begin(w, h, Color{1, 1, 1, 1});
    gpu().renderer.draw(batch, placement, options);
    const std::size_t tiles = gpu().renderer.offscreen_passes() - passes;
    const test::Coverage got = test::coverage_from_black_on_white(gpu().target.read_pixels());
    const test::CoverageStats s = test::compare(got, want);
    std::printf("%s over %d px in %zu tiles: edge %.4f, max %.3f, ink %.4f\n",
                m.aa == AntiAliasing::Vbaa ? "vbaa r=8" : "msaa", w, tiles, s.edge_mean_abs, s.max_abs, s.ink_ratio);
    if (s.edge_mean_abs > m.edge || s.max_abs > m.max) test::write_comparison("offscreen-tiles", got, want);
    if (m.aa == AntiAliasing::Vbaa) {
      EXPECT_GE(tiles, 3u);
    }
    EXPECT_LE(s.edge_mean_abs, m.edge);
    EXPECT_LE(s.max_abs, m.max);
    EXPECT_NEAR(s.ink_ratio, 1.0, 0.02);
  }
}

// Split screen: two viewports of one framebuffer, each showing its own text,
// as an application draws them (viewport set, then Renderer::draw). Pixel
// (0, 0) of a draw is its viewport's top left in every mode; each half must
// match the exact coverage of its own text there, and nothing may leak into
// the other half.
TEST(Viewport, SplitScreenDrawsEachTextInItsOwnViewport) {
  Font font = Font::open(test::kDejaVuSans);
  const ShapedLine left = shape_line(font, "Left eye");
  const ShapedLine right = shape_line(font, "Right eye");
  Gpu& g = gpu();
  DrawBatch left_batch = DrawBatch::from_text(g.cache, font, left, 24.0);
  DrawBatch right_batch = DrawBatch::from_text(g.cache, font, right, 24.0);
  const double scale = 24.0 / font.metrics().units_per_em;
  const int W = 400, H = 100;
  // Viewports (GL: x, y from the bottom, w, h) and where their top-left pixel
  // lands in the image (rows from the top).
  struct View {
    int x, y, w, h;
    const DrawBatch* batch;
    const ShapedLine* line;
  };
  const View views[2] = {{0, 0, 200, 60, &left_batch, &left}, {200, 40, 200, 60, &right_batch, &right}};
  const Placement in_view{scale, 8.4, 36.3};
  test::Coverage want(W, H);
  for (const View& v : views) {
    const Placement at{scale, in_view.origin_x + v.x, in_view.origin_y + (H - v.y - v.h)};
    test::add_union_coverage(test::place_outline(line_outline(font, *v.line), at), want);
  }
  struct Mode {
    AntiAliasing aa;
    double edge;
  };
  for (const Mode& m : {Mode{AntiAliasing::Full, 0.005}, Mode{AntiAliasing::Vbaa, 0.005},
                        Mode{AntiAliasing::Msaa, 0.06}, Mode{AntiAliasing::Curves, 0.12}}) {
    g.target.begin(W, H, Color{1, 1, 1, 1});
    for (const View& v : views) {
      glViewport(v.x, v.y, v.w, v.h);
      g.renderer.draw(*v.batch, in_view, DrawOptions(Color{0, 0, 0, 1}, m.aa));
    }
    const test::Coverage got = test::coverage_from_black_on_white(g.target.read_pixels());
    const test::CoverageStats st = test::compare(got, want);
    std::printf("split screen, mode %d: edge %.4f, max %.3f, ink %.4f\n", static_cast<int>(m.aa), st.edge_mean_abs,
                st.max_abs, st.ink_ratio);
    if (st.edge_mean_abs > m.edge) test::write_comparison("split-screen", got, want);
    EXPECT_LE(st.edge_mean_abs, m.edge) << "mode " << static_cast<int>(m.aa);
    EXPECT_NEAR(st.ink_ratio, 1.0, m.aa == AntiAliasing::Curves ? 0.1 : 0.03) << "mode " << static_cast<int>(m.aa);
  }
}

// --- Zoom accuracy: cubic (CFF) glyphs at 2,000 and 10,000 px/em ---------------
// A window of the glyph is drawn; the mesh's cubic approximation is chosen for
// the drawn scale (lod.hpp), so the outline stays within 1/16 px of the true
// one. A boundary displaced by e changes a pixel's coverage by at most about
// e times the boundary length inside the pixel (up to sqrt 2), so no pixel may
// be off by more than sqrt(2)/16 plus the reference's own error.
TEST(ZoomAccuracy, CubicGlyphWindowsStayWithinASixteenthPixel) {
  Font font = Font::open(test::kNimbusRoman);
  const double upem = font.metrics().units_per_em;
  for (const char* text : {"S", "g"}) {
    const ShapedLine line = shape_line(font, text);
    const Outline outline = line_outline(font, line);
    ASSERT_TRUE(outline.has_cubics());
    for (double ppem : {2000.0, 10000.0}) {
      DrawBatch batch = DrawBatch::from_text(gpu().cache, font, line, ppem);
      const double scale = ppem / upem;
      // A 200 x 200 window centred on the middle of the glyph's first cubic.
      Vec2 centre{};
      for (const Contour& c : outline.contours())
        for (const Segment& seg : c.segments)
          if (seg.kind == Segment::Kind::Cubic && centre == Vec2{}) centre = evaluate(seg, 0.5);
      const int size = 200;
      const Placement p{scale, size / 2.0 - scale * centre.x - 0.37, size / 2.0 + scale * centre.y + 0.21};
      gpu().target.begin(size, size, Color{1, 1, 1, 1});
      gpu().renderer.draw(batch, p, DrawOptions{});
      const test::Coverage got = test::coverage_from_black_on_white(gpu().target.read_pixels());
      const test::Coverage ref = test::freetype_reference(outline, p, size, size, 16);
      const test::CoverageStats s = test::compare(got, ref);
      std::printf("zoom %s at %.0f px/em: edge %.4f max %.4f (%zu edge pixels)\n", text, ppem, s.edge_mean_abs,
                  s.max_abs, s.edge_pixels);
      const double limit = std::sqrt(2.0) / 16 + 0.02;
      if (s.max_abs > limit)
        test::write_comparison(std::string("zoom-") + text + "-" + std::to_string(static_cast<int>(ppem)), got, ref);
      EXPECT_GT(s.edge_pixels, 100u) << "the window must contain the outline";
      EXPECT_LE(s.max_abs, limit);
    }
  }
}

// --- A circle from four rational quadratic arcs (w = sqrt(2)/2) ---------------

Outline circle(double r) {
  const double w = std::numbers::sqrt2 / 2;
  Outline o;
  o.move_to({r, 0});
  o.conic_to({r, r}, {0, r}, w);
  o.conic_to({-r, r}, {-r, 0}, w);
  o.conic_to({-r, -r}, {0, -r}, w);
  o.conic_to({r, -r}, {r, 0}, w);
  o.close();
  return o;
}

// Largest radial offset of the drawn circle from the true one, in pixels, from
// exact band areas: the coverage summed over one pixel row (column) is the
// drawn area in that band; the true area of a circle in a band has a closed
// form. The difference over the band's two edges is the horizontal (vertical)
// edge offset, converted to a radial offset with the edge's angle. Rows are
// used where the edge is within 45 degrees of vertical, columns elsewhere.
double max_radial_offset(const test::Coverage& cov, double cx, double cy, double r) {
  auto band_area = [&](double t0, double t1) {  // area of the circle with t0 < (coord - centre) < t1
    auto f = [&](double t) {
      t = std::clamp(t, -r, r);
      return t * std::sqrt(r * r - t * t) + r * r * std::asin(t / r);
    };
    return f(t1) - f(t0);
  };
  double worst = 0.0;
  const double limit = r * std::numbers::sqrt2 / 2 - 1.0;
  for (int y = 0; y < cov.height; ++y) {
    const double t0 = y - cy, t1 = y + 1 - cy;
    if (std::max(std::abs(t0), std::abs(t1)) > limit) continue;
    double sum = 0;
    for (int x = 0; x < cov.width; ++x) sum += cov.at(x, y);
    const double dx = (sum - band_area(t0, t1)) / 2.0;
    const double mid = 0.5 * (t0 + t1);
    worst = std::max(worst, std::abs(dx) * std::sqrt(r * r - mid * mid) / r);
  }
  for (int x = 0; x < cov.width; ++x) {
    const double t0 = x - cx, t1 = x + 1 - cx;
    if (std::max(std::abs(t0), std::abs(t1)) > limit) continue;
    double sum = 0;
    for (int y = 0; y < cov.height; ++y) sum += cov.at(x, y);
    const double dy = (sum - band_area(t0, t1)) / 2.0;
    const double mid = 0.5 * (t0 + t1);
    worst = std::max(worst, std::abs(dy) * std::sqrt(r * r - mid * mid) / r);
  }
  return worst;
}

test::Coverage draw_circle(double radius, CurveMode mode, double cx, double cy, int size) {
  Gpu& g = gpu();  // the GL context must exist before the batch uploads
  const Mesh mesh = build_mesh(circle(radius));
  DrawBatch batch = DrawBatch::from_mesh(mesh);
  g.target.begin(size, size, Color{1, 1, 1, 1});
  DrawOptions options;
  options.curve_mode = mode;
  g.renderer.draw(batch, Placement{1.0, cx, cy}, options);
  return test::coverage_from_black_on_white(g.target.read_pixels());
}

// Full antialiasing grows every triangle by a pixel's reach (miters, and
// bevels at corners sharper than about 29 degrees) so that every pixel its
// area touches gets a fragment. Needles, slivers and sharp wedges at
// fractional positions, in both orientations, drawn at three scales, must
// then match exact area coverage everywhere, tips included: a pixel the
// growth missed would keep its whole share of coverage.
// Each edge grows by how far a pixel's box reaches past it: 0.5 px for an
// edge along an axis, sqrt(2)/2 for a diagonal one (curve.vert.glsl). A box
// that overlaps the shape by a thin strip has its centre just inside that
// reach; grown any less, such a pixel would lose its strip. Axis-aligned and
// diagonal edges swept across a pixel in steps of 1/64 px put some edge within
// 1/64 px of every pixel boundary position: each must match exact coverage.
TEST(FullAntialiasingGrowth, EdgesGrowByThePixelBoxReach) {
  Outline shapes;
  auto polygon = [&](std::initializer_list<Vec2> points) {
    bool first = true;
    for (Vec2 p : points) {
      if (first)
        shapes.move_to(p);
      else
        shapes.line_to(p);
      first = false;
    }
    shapes.close();
  };
  polygon({{2, 2}, {14, 2}, {14, 9}, {2, 9}});          // axis-aligned edges
  polygon({{24, 2}, {31, 9}, {24, 16}, {17, 9}});       // diagonal ones
  polygon({{34, 2}, {46, 4.5}, {44, 14}, {36.5, 12}});  // others
  const Mesh mesh = build_mesh(shapes);
  Gpu& g = gpu();  // the context, before the batch uploads
  DrawBatch batch = DrawBatch::from_mesh(mesh);
  double worst = 0.0;
  for (int step = 0; step < 64; ++step) {
    const double f = step / 64.0;
    const Placement placement{1.0, 1.0 + f, 19.0 + f * 0.75};
    g.target.begin(50, 22, Color{1, 1, 1, 1});
    g.renderer.draw(batch, placement, DrawOptions(Color{0, 0, 0, 1}, AntiAliasing::Full));
    const test::Coverage got = test::coverage_from_black_on_white(g.target.read_pixels());
    const test::Coverage want = test::union_coverage(test::place_outline(shapes, placement), 50, 22);
    const test::CoverageStats s = test::compare(got, want);
    worst = std::max(worst, s.max_abs);
    if (s.max_abs > 2.0 / 255.0) test::write_comparison("edge-reach-" + std::to_string(step), got, want);
    EXPECT_LE(s.max_abs, 2.0 / 255.0) << "offset " << f << " px";
  }
  std::printf("edges swept over a pixel in 64 steps: largest pixel error %.4f\n", worst);
}

TEST(FullAntialiasingGrowth, SharpTrianglesGetEveryPixelTheyTouch) {
  Outline shapes;
  auto triangle = [&](Vec2 a, Vec2 b, Vec2 c) {
    shapes.move_to(a);
    shapes.line_to(b);
    shapes.line_to(c);
    shapes.close();
  };
  triangle({2.3, 2.6}, {40.7, 4.1}, {2.9, 3.4});       // a needle of about 1 degree
  triangle({3.1, 9.2}, {41.4, 13.7}, {3.6, 12.8});     // about 5 degrees
  triangle({44.2, 2.3}, {80.6, 12.9}, {47.5, 14.1});   // about 22 degrees, clockwise below
  triangle({6.2, 18.4}, {44.9, 18.55}, {6.2, 18.7});   // a sliver 0.3 px high
  triangle({50.3, 18.2}, {78.4, 18.2}, {50.3, 38.9});  // a right triangle
  triangle({4.4, 24.1}, {12.5, 38.6}, {20.6, 24.3});   // an acute isosceles one
  triangle({24.7, 38.3}, {45.1, 36.2}, {26.0, 23.4});  // a clockwise one
  const Mesh mesh = build_mesh(shapes);
  for (double scale : {1.0, 0.37, 2.6}) {
    Gpu& g = gpu();
    DrawBatch batch = DrawBatch::from_mesh(mesh);
    const int width = static_cast<int>(std::ceil(84 * scale)) + 4, height = static_cast<int>(std::ceil(42 * scale)) + 4;
    const Placement placement{scale, 1.3, height - 1.7};
    g.target.begin(width, height, Color{1, 1, 1, 1});
    g.renderer.draw(batch, placement, DrawOptions(Color{0, 0, 0, 1}, AntiAliasing::Full));
    const test::Coverage got = test::coverage_from_black_on_white(g.target.read_pixels());
    const test::Coverage want = test::union_coverage(test::place_outline(shapes, placement), width, height);
    const test::CoverageStats s = test::compare(got, want);
    std::printf("sharp triangles at scale %.2f: max %.4f, edge %.4f, ink %.4f\n", scale, s.max_abs, s.edge_mean_abs,
                s.ink_ratio);
    // 8-bit steps of the coverage buffer where a few triangles add up, and
    // the output's own rounding: a few 1/255.
    const double limit = 3.0 / 255.0;
    if (s.max_abs > limit) test::write_comparison("sharp-triangles-" + std::to_string(scale), got, want);
    EXPECT_LE(s.max_abs, limit) << "scale " << scale;
    EXPECT_NEAR(s.ink_ratio, 1.0, 0.005) << "scale " << scale;
  }
}

// The largest pixel error of `mesh` drawn with full antialiasing against the
// exact coverage of `regions`, over 8 x 8 sub-pixel phases at each scale, the
// outline point `anchor` placed near pixel (margin, margin) of a width x 16
// image (width from `span`, the mesh's extent in font units). Writes the
// worst comparison over 3/255 as `name`.
double worst_sliver_error(const Mesh& mesh, const Outline& regions, std::initializer_list<double> scales, Vec2 anchor,
                          double span, const std::string& name) {
  Gpu& g = gpu();
  DrawBatch batch = DrawBatch::from_mesh(mesh);
  double worst = 0.0;
  for (double scale : scales) {
    const int width = static_cast<int>(std::ceil(span * scale)) + 16, height = 16;
    for (int i = 0; i < 8; ++i)
      for (int j = 0; j < 8; ++j) {
        const Placement placement{scale, 8.0 + i / 8.0 - anchor.x * scale, 8.0 + j / 8.0 + anchor.y * scale};
        g.target.begin(width, height, Color{1, 1, 1, 1});
        g.renderer.draw(batch, placement, DrawOptions(Color{0, 0, 0, 1}, AntiAliasing::Full));
        const test::Coverage got = test::coverage_from_black_on_white(g.target.read_pixels());
        const test::Coverage want = test::union_coverage(test::place_outline(regions, placement), width, height);
        const double e = test::compare(got, want).max_abs;
        if (e > 3.0 / 255.0 && e > worst) test::write_comparison(name, got, want);
        worst = std::max(worst, e);
      }
  }
  return worst;
}

Outline triangle_outline(const std::vector<Vec2>& p) {
  Outline t;
  t.move_to(p[0]);
  t.line_to(p[1]);
  t.line_to(p[2]);
  t.close();
  return t;
}

// Full antialiasing finds a triangle's part of each pixel from its
// barycentrics' screen gradients (and a curved triangle's control points by
// inverting them). For a triangle almost flat (here 6e-6 font units high and
// 0.12 long, a piece of a nearly straight cubic of Noto Serif Myanmar glyph
// 674) both lost their digits and put up to 0.3 of coverage into empty
// pixels next to it. A triangle thinner than tolerance::kThinTrianglePx
// now counts as empty (it lies within 1/256 px of a line). Drawn at many
// sub-pixel phases and three scales, as concave and convex curved triangles
// and as an interior triangle, the pixels must match the exact coverage of
// the (tiny) regions.
TEST(FullAntialiasingSlivers, NearlyFlatTrianglesAddNoStrayCoverage) {
  const std::vector<Vec2> points = {{574.99995422363281, 267.23043251037598},
                                    {574.99997711181641, 267.17283344268799},
                                    {574.9999885559082, 267.11522531509399}};
  Mesh curves;
  curves.points = points;
  curves.curves = {CurvedTriangle{0, 1, 2, 1.0, false}, CurvedTriangle{2, 1, 0, 1.0, true}};
  // The concave curve's region and the convex one's cap tile the control
  // triangle.
  Mesh interior;
  interior.points = points;
  interior.triangles = {{0, 1, 2}};
  const Outline triangle = triangle_outline(points);
  for (const auto& [mesh, name] : {std::pair{&curves, "curved"}, std::pair{&interior, "interior"}}) {
    const double worst =
        worst_sliver_error(*mesh, triangle, {0.032, 0.4, 3.0}, {575.0, 267.0}, 0.0, std::string("sliver-") + name);
    std::printf("nearly flat %s triangles: largest pixel error %.4f\n", name, worst);
    EXPECT_LE(worst, 3.0 / 255.0) << name;
  }
}

// A long, flat curved triangle (Noto Sans CJK glyph 1666: 362 font units long,
// its control point 0.19 off the chord, 11.6 px by 0.006 px at 32 px/em; its
// longest edge is about 2,000 times its altitude): the shader's gradient
// inversion and tangent clipping lost their digits on it and put 0.17 of
// coverage into an empty pixel next to it. Where that loss (about 1e-7 k^2 px)
// would exceed the triangle's altitude, the region now counts as empty
// (shaders/area.frag.glsl). Pixels must match the exact
// coverage within 3/255 at 32 and 48 px/em, convex and concave.
TEST(FullAntialiasingSlivers, LongFlatCurvesAddNoStrayCoverage) {
  const std::vector<Vec2> points = {
      {391.99999999999994, 7.9629629629629628}, {511.41666666666652, 10.75925925925926}, {754.0, 17.0}};
  Mesh mesh;
  mesh.points = points;
  mesh.curves = {CurvedTriangle{0, 1, 2, 1.0, true}, CurvedTriangle{2, 1, 0, 1.0, false}};
  const double worst =
      worst_sliver_error(mesh, triangle_outline(points), {0.032, 0.048}, {392.0, 12.0}, 362.0, "long-flat-curve");
  std::printf("long flat curved triangles: largest pixel error %.4f\n", worst);
  EXPECT_LE(worst, 3.0 / 255.0);
}

TEST(Circle, ExactModeWithinAnEighthPixelAtRadius400) {
  const double r = 400, cx = 432.3, cy = 431.6;
  const test::Coverage cov = draw_circle(r, CurveMode::Exact, cx, cy, 864);
  const double offset = max_radial_offset(cov, cx, cy, r);
  std::printf("circle r=400 exact mode: largest radial offset %.4f px\n", offset);
  const test::Coverage ref = test::sampled_reference(
      [&](double x, double y) { return (x - cx) * (x - cx) + (y - cy) * (y - cy) < r * r; }, 864, 864, 16);
  const test::CoverageStats s = test::compare(cov, ref);
  std::printf("circle r=400 exact mode: edge error %.4f, max %.3f, ink %.6f\n", s.edge_mean_abs, s.max_abs,
              s.ink_ratio);
  if (offset > 0.125) test::write_comparison("circle-exact", cov, ref);
  EXPECT_LE(offset, 0.125);
  EXPECT_LE(s.edge_mean_abs, 0.03);
}

TEST(Circle, PaperModeIsOffByPercentOfTheRadius) {
  const double r = 400, cx = 432.3, cy = 431.6;
  const test::Coverage cov = draw_circle(r, CurveMode::Paper, cx, cy, 864);
  const double offset = max_radial_offset(cov, cx, cy, r);
  // Recorded, not hidden: equation 2 of the paper is exact only for w = 1
  // (docs/design.md section 3 predicts up to 2.1% of the radius, ~8 px here).
  std::printf("circle r=400 paper mode: largest radial offset %.3f px (%.2f%% of r)\n", offset, 100 * offset / r);
  RecordProperty("paper_mode_radial_offset_px", std::to_string(offset));
  EXPECT_GT(offset, 1.0);
}

}  // namespace
}  // namespace curvetext
