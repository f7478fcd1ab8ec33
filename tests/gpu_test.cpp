// GPU side: headless EGL, the curve shader's coverage against exact area
// coverage, framebuffer limits, PNG round trip, option parsing.
// Meshes are built by hand so these tests do not depend on the tessellator.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "core/tolerances.hpp"
#include "curvetext/color.hpp"
#include "curvetext/error.hpp"
#include "curvetext/headless.hpp"
#include "curvetext/image.hpp"
#include "curvetext/image_style.hpp"
#include "curvetext/renderer.hpp"
#include "curvetext/font.hpp"
#include "curvetext/shaping.hpp"
#include "curvetext/text_image.hpp"
#include "gpu/bands.hpp"
#include "gpu/bands_es2.hpp"
#include "gpu/paint.hpp"
#include "gpu/batch_impl.hpp"
#include "gpu/vertex_format.hpp"
#include "support/coverage.hpp"
#include "support/fonts.hpp"
#include "support/gpu.hpp"

namespace curvetext {
namespace {

constexpr int kW = 64;
constexpr int kH = 48;

// One context per test program: llvmpipe is required here, so failing to
// create it fails the tests that need it.
HeadlessContext& context() {
  static std::optional<HeadlessContext> ctx;
  if (!ctx) ctx.emplace(HeadlessContext::create());
  return *ctx;
}

using Coverage = std::vector<double>;  // kW * kH, row 0 at the top

// Renders black on white and returns coverage 1 - value/255 per pixel.
Coverage render(const Mesh& mesh, AntiAliasing aa, CurveMode mode = CurveMode::Exact) {
  context();
  Renderer renderer;
  ImageTarget target;
  target.begin(kW, kH, Color{1, 1, 1, 1});
  DrawBatch batch = DrawBatch::from_mesh(mesh);
  // Outline units are pixels with y up: y_px = kH - y.
  renderer.draw(batch, Placement{1.0, 0.0, kH}, DrawOptions{Color{0, 0, 0, 1}, aa, mode});
  Image img = target.read_pixels();
  Coverage cov(static_cast<std::size_t>(kW) * kH);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) cov[static_cast<std::size_t>(y) * kW + x] = 1.0 - img.pixel(x, y)[0] / 255.0;
  return cov;
}

// Supersampled reference: `inside` takes screen coordinates (y down).
Coverage supersample(const std::function<bool(double, double)>& inside, int n) {
  Coverage cov(static_cast<std::size_t>(kW) * kH);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      int hits = 0;
      for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
          if (inside(x + (i + 0.5) / n, y + (j + 0.5) / n)) ++hits;
      cov[static_cast<std::size_t>(y) * kW + x] = static_cast<double>(hits) / (n * n);
    }
  return cov;
}

Image to_image(const Coverage& c) {
  Image img(kW, kH);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      auto v = static_cast<std::uint8_t>(std::lround(255.0 * (1.0 - c[static_cast<std::size_t>(y) * kW + x])));
      std::uint8_t* p = img.pixel(x, y);
      p[0] = p[1] = p[2] = v;
      p[3] = 255;
    }
  return img;
}

// On failure: result, reference and an amplified diff (red = too dark, blue = too light).
void save_failure(const std::string& name, const Coverage& result, const Coverage& reference) {
  std::filesystem::create_directories(CURVETEXT_TEST_OUTPUT_DIR);
  const std::string base = std::string(CURVETEXT_TEST_OUTPUT_DIR) + "/gpu_" + name;
  write_png(to_image(result), base + "_result.png");
  write_png(to_image(reference), base + "_reference.png");
  Image diff(kW, kH);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const double d = result[static_cast<std::size_t>(y) * kW + x] - reference[static_cast<std::size_t>(y) * kW + x];
      std::uint8_t* p = diff.pixel(x, y);
      const auto m = static_cast<std::uint8_t>(std::min(255.0, std::fabs(d) * 255.0 * 8.0));
      p[0] = d > 0 ? 255 : static_cast<std::uint8_t>(255 - m);
      p[1] = static_cast<std::uint8_t>(255 - m);
      p[2] = d < 0 ? 255 : static_cast<std::uint8_t>(255 - m);
      p[3] = 255;
    }
  write_png(diff, base + "_diff.png");
}

struct Stats {
  double mean_edge = 0.0;
  double max_error = 0.0;
  std::size_t edge_pixels = 0;
};

// Error over the edge band: pixels partially covered in either image.
Stats compare(const Coverage& result, const Coverage& reference) {
  Stats s;
  double sum = 0.0;
  for (std::size_t i = 0; i < result.size(); ++i) {
    const double e = std::fabs(result[i] - reference[i]);
    s.max_error = std::max(s.max_error, e);
    const bool edge = (reference[i] > 0.0 && reference[i] < 1.0) || (result[i] > 0.0 && result[i] < 1.0);
    if (edge) {
      sum += e;
      ++s.edge_pixels;
    }
  }
  s.mean_edge = s.edge_pixels ? sum / static_cast<double>(s.edge_pixels) : 0.0;
  return s;
}

// A convex quadrilateral a,b,c,d (counter-clockwise, y up) as 2 triangles and 4 boundary lines.
Mesh quad_mesh(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  Mesh m;
  m.points = {a, b, c, d};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  m.boundary_lines = {{0, 1}, {1, 2}, {2, 3}, {3, 0}};
  return m;
}

// Screen rectangle [x0,x1] x [y0,y1] (y down) as a mesh in y-up outline units.
Mesh rect_mesh(double x0, double x1, double y0, double y1) {
  return quad_mesh({x0, kH - y1}, {x1, kH - y1}, {x1, kH - y0}, {x0, kH - y0});
}

double overlap(double a0, double a1, double b0, double b1) {
  return std::max(0.0, std::min(a1, b1) - std::max(a0, b0));
}

TEST(Headless, CreatesContextWithRenderer) {
  HeadlessContext& ctx = context();
  EXPECT_FALSE(ctx.renderer().empty());
  EXPECT_FALSE(ctx.version().empty());
  std::printf("GL_RENDERER: %s\nGL_VERSION: %s\n", ctx.renderer().c_str(), ctx.version().c_str());
}

TEST(Headless, NoVendorGivesNoDeviceError) {
  // Re-executed in a fresh process so EGL is loaded with the broken vendor list.
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(
      {
        setenv("__EGL_VENDOR_LIBRARY_FILENAMES", "/nonexistent", 1);
        int code = 2;
        try {
          HeadlessContext::create();
        } catch (const Error& e) {
          code = (e.code() == ErrorCode::NoDevice && std::string(e.what()).rfind("no EGL display", 0) == 0) ? 0 : 3;
        }
        std::exit(code);
      },
      testing::ExitedWithCode(0), "");
}

TEST(Coverage, AxisAlignedSquareFullIsExactArea) {
  const double x0 = 10.25, x1 = 30.75, y0 = 5.5, y1 = 20.125;
  const Coverage got = render(rect_mesh(x0, x1, y0, y1), AntiAliasing::Full);
  Coverage want(got.size());
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x)
      want[static_cast<std::size_t>(y) * kW + x] = overlap(x, x + 1, x0, x1) * overlap(y, y + 1, y0, y1);
  const Stats s = compare(got, want);
  std::printf("aligned square full: max error %.5f, mean edge error %.5f over %zu pixels\n", s.max_error, s.mean_edge,
              s.edge_pixels);
  const double tol = 1.0 / 255.0 + 0.002;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * kW + x;
      EXPECT_NEAR(got[i], want[i], tol) << "pixel " << x << "," << y;
    }
  if (s.max_error > tol) save_failure("aligned_full", got, want);
}

TEST(Coverage, AxisAlignedSquareNoneUsesPixelCentres) {
  const double x0 = 10.25, x1 = 30.75, y0 = 5.25, y1 = 20.125;
  const Coverage got = render(rect_mesh(x0, x1, y0, y1), AntiAliasing::None);
  Coverage want(got.size());
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const double cx = x + 0.5, cy = y + 0.5;
      want[static_cast<std::size_t>(y) * kW + x] = (cx > x0 && cx < x1 && cy > y0 && cy < y1) ? 1.0 : 0.0;
    }
  const Stats s = compare(got, want);
  EXPECT_EQ(s.max_error, 0.0);
  if (s.max_error > 0) save_failure("aligned_none", got, want);
}

TEST(Coverage, RotatedSquareFull) {
  const double cx = 31.3, cy = 23.7, half = 13.1, angle = M_PI / 6;
  std::vector<Vec2> screen;
  for (int k = 0; k < 4; ++k) {
    const double a = angle + k * M_PI / 2 + M_PI / 4;
    screen.push_back({cx + half * std::sqrt(2.0) * std::cos(a), cy + half * std::sqrt(2.0) * std::sin(a)});
  }
  // Increasing angle in y-down screen space is clockwise once flipped to y up: reverse.
  auto up = [](Vec2 p) { return Vec2{p.x, kH - p.y}; };
  const Mesh mesh = quad_mesh(up(screen[3]), up(screen[2]), up(screen[1]), up(screen[0]));
  ASSERT_GT(cross(mesh.points[1] - mesh.points[0], mesh.points[2] - mesh.points[0]), 0.0);
  const Coverage got = render(mesh, AntiAliasing::Full);
  const Coverage want = supersample(
      [&](double x, double y) {
        const Vec2 p{x, kH - y};
        for (int k = 0; k < 4; ++k) {
          const Vec2 a = mesh.points[static_cast<std::size_t>(k)];
          const Vec2 b = mesh.points[static_cast<std::size_t>((k + 1) % 4)];
          if (cross(b - a, p - a) < 0) return false;
        }
        return true;
      },
      64);
  const Stats s = compare(got, want);
  std::printf("rotated square full: mean edge error %.5f, max %.5f over %zu pixels\n", s.mean_edge, s.max_error,
              s.edge_pixels);
  EXPECT_LE(s.mean_edge, 0.01);
  EXPECT_LE(s.max_error, 0.06);
  if (s.mean_edge > 0.01 || s.max_error > 0.06) save_failure("rotated_full", got, want);
}

// A region bounded by one conic (p0, control, p2, w) and its chord. The chord
// lies on a pixel row boundary so the (aliased, non-curve) chord edge is exact.
struct ConicRegion {
  Vec2 p0{8, 6}, control{30, 40}, p2{56, 6};  // y up
  double w = 1.0;

  Mesh mesh() const {
    Mesh m;
    m.points = {p0, control, p2};
    m.curves = {CurvedTriangle{0, 1, 2, w, true}};
    return m;
  }
  bool inside(double sx, double sy) const {
    const Vec2 p{sx, kH - sy};
    const double area2 = cross(control - p0, p2 - p0);
    const double t1 = cross(p - p0, p2 - p0) / area2;
    const double t2 = cross(control - p0, p - p0) / area2;
    const double t0 = 1 - t1 - t2;
    if (t0 < 0 || t1 < 0 || t2 < 0) return false;
    return t1 * t1 - 4 * w * w * t0 * t2 < 0;
  }
};

Stats conic_stats(const ConicRegion& region, CurveMode mode, const std::string& name, Coverage* out = nullptr) {
  const Coverage got = render(region.mesh(), AntiAliasing::Full, mode);
  const Coverage want = supersample([&](double x, double y) { return region.inside(x, y); }, 32);
  const Stats s = compare(got, want);
  std::printf("conic w=%.2f %s: mean edge error %.5f, max %.5f over %zu pixels\n", region.w,
              mode == CurveMode::Exact ? "exact" : "paper", s.mean_edge, s.max_error, s.edge_pixels);
  if (mode == CurveMode::Exact && s.mean_edge > 0.02) save_failure(name, got, want);
  if (out) *out = got;
  return s;
}

TEST(Coverage, ConicExactAndPaper) {
  for (double w : {1.0, 0.5}) {
    ConicRegion region;
    region.w = w;
    Coverage exact_img, paper_img;
    const Stats exact = conic_stats(region, CurveMode::Exact, "conic_exact_w" + std::to_string(w), &exact_img);
    const Stats paper = conic_stats(region, CurveMode::Paper, "conic_paper_w" + std::to_string(w), &paper_img);
    EXPECT_LE(exact.mean_edge, 0.02) << "w=" << w;
    const Stats between = compare(paper_img, exact_img);
    if (w == 1.0) {
      // Equation 2 is exact for parabolas: only rounding separates the modes.
      EXPECT_LE(between.max_error, 3.0 / 255.0);
      EXPECT_NEAR(paper.mean_edge, exact.mean_edge, 0.005);
    } else {
      // Equation 2 draws a different curve for w != 1 (docs/design.md section 3).
      EXPECT_GT(between.max_error, 0.2);
      EXPECT_GT(paper.mean_edge, 2.0 * exact.mean_edge);
    }
  }
}

TEST(Coverage, ConcaveConicIsComplementOfConvex) {
  // The same conic drawn as convex (chord side) and as concave (control side):
  // inside the hull the two coverages must add up to one in every pixel.
  ConicRegion region;
  region.w = 0.7;
  Mesh convex = region.mesh();
  Mesh concave = region.mesh();
  concave.curves[0].convex = false;
  const Coverage a = render(convex, AntiAliasing::Full);
  const Coverage b = render(concave, AntiAliasing::Full);
  const Vec2 p0 = region.p0, c = region.control, p2 = region.p2;
  const Coverage hull = supersample(
      [&](double x, double y) {
        const Vec2 p{x, kH - y};
        return cross(c - p0, p - p0) <= 0 && cross(p2 - c, p - c) <= 0 && cross(p0 - p2, p - p2) <= 0;
      },
      16);
  double worst = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (hull[i] == 1.0) worst = std::max(worst, std::fabs(a[i] + b[i] - 1.0));
  std::printf("convex + concave inside the hull: worst |sum - 1| %.4f\n", worst);
  EXPECT_LE(worst, 2.5 / 255.0);
}

TEST(Coverage, FlatSkewedCurveNextToInteriorTriangle) {
  // A convex curve all but on its chord, with the control point near one end:
  // the parabola's axis then lies almost along the chord and its other arm
  // passes within a pixel on the interior side. The interior triangle across
  // the chord is solid there, whatever that arm does.
  Mesh m;
  const Vec2 a{10, 20}, b{40, 22};
  const Vec2 ctrl{38, a.y + (b.y - a.y) * 28.0 / 30.0 + 0.002};
  m.points = {a, b, ctrl, {40, 10}, {10, 10}};
  m.triangles = {{4, 3, 1}, {4, 1, 0}};
  m.boundary_lines = {{4, 3}, {3, 1}, {0, 4}};
  m.curves = {CurvedTriangle{1, 2, 0, 1.0, true}};
  const Coverage got = render(m, AntiAliasing::Full);
  const Coverage want = supersample(
      [&](double x, double y) {
        const Vec2 p{x, kH - y};
        return p.x >= 10 && p.x <= 40 && p.y >= 10 && cross(b - a, p - a) <= 0;
      },
      16);
  const Stats s = compare(got, want);
  // The same outline with a straight top edge: the curve must do as well.
  Mesh straight = m;
  straight.curves.clear();
  straight.boundary_lines.push_back({1, 0});
  const Stats line = compare(render(straight, AntiAliasing::Full), want);
  std::printf("flat skewed curve: edge %.4f, max %.4f (as a line: edge %.4f, max %.4f)\n", s.mean_edge, s.max_error,
              line.mean_edge, line.max_error);
  EXPECT_LE(s.max_error, std::max(0.1, line.max_error + 0.02));
  EXPECT_LE(s.mean_edge, line.mean_edge + 0.01);
  if (s.max_error > 0.1) save_failure("flat_skewed_curve", got, want);
}

TEST(Coverage, FanIsWatertightUnderTranslucentColor) {
  // A 24-gon meshed as a fan around an off-centre point: every interior
  // pixel must be blended exactly once (a double hit would show as 0.75, a
  // crack as less than 0.5).
  Mesh m;
  const Vec2 centre{31.7, 24.3};
  m.points.push_back({29.1, 22.9});
  const int n = 24;
  for (int k = 0; k < n; ++k) {
    const double a = 2 * M_PI * k / n + 0.1;
    m.points.push_back({centre.x + 19.3 * std::cos(a), centre.y + 19.3 * std::sin(a)});
  }
  for (std::uint32_t k = 0; k < static_cast<std::uint32_t>(n); ++k) {
    const std::uint32_t a = 1 + k, b = 1 + (k + 1) % static_cast<std::uint32_t>(n);
    m.triangles.push_back({0, a, b});
    m.boundary_lines.push_back({a, b});
  }
  context();
  Renderer renderer;
  ImageTarget target;
  target.begin(kW, kH, Color{1, 1, 1, 1});
  DrawBatch batch = DrawBatch::from_mesh(m);
  renderer.draw(batch, Placement{1.0, 0.0, kH},
                DrawOptions{Color{0, 0, 0, 0.5f}, AntiAliasing::Full, CurveMode::Exact});
  const Image img = target.read_pixels();
  int checked = 0, bad = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      if (std::hypot(x + 0.5 - centre.x, (kH - y - 0.5) - centre.y) > 17.0) continue;
      ++checked;
      if (std::abs(img.pixel(x, y)[0] - 128) > 1) ++bad;
    }
  EXPECT_GT(checked, 500);
  EXPECT_EQ(bad, 0);
}

TEST(Text, GlyphBatchMatchesFreeTypeReference) {
  context();
  const Font font = Font::open(test::kDejaVuSans);
  const ShapedLine line = shape_line(font, "Hamburgefonstiv 0123");
  const FontMetrics fm = font.metrics();
  const double ppem = 24.0;
  const double scale = ppem / fm.units_per_em;
  const double margin = 4.0;
  const Placement placement{scale, margin, margin + fm.ascender * scale};
  const int width = static_cast<int>(std::ceil(2 * margin + line.advance * scale));
  const int height = static_cast<int>(std::ceil(2 * margin + (fm.ascender - fm.descender) * scale));

  GlyphCache cache;
  Renderer renderer;
  ImageTarget target;
  DrawBatch batch = DrawBatch::from_text(cache, font, line, ppem);
  EXPECT_GT(batch.vertex_count(), 0u);
  if (batch.instanced()) {
    // Per glyph but the space: an offset (the meshes' instances) and the
    // glyph's box, offset and bands (full's quads).
    EXPECT_EQ(batch.gpu_bytes(), (DrawBatchAccess::impl(batch).banded ? 40u : 8u) * (line.glyphs.size() - 1));
  } else {
    EXPECT_GT(batch.gpu_bytes(), batch.vertex_count() * sizeof(gpu::Vertex));  // and the indices
  }
  target.begin(width, height, Color{1, 1, 1, 1});
  renderer.draw(batch, placement, DrawOptions{});
  const test::Coverage got = test::coverage_from_black_on_white(target.read_pixels());

  const test::Coverage want = test::freetype_reference(test::line_outline(font, line), placement, width, height, 8);
  const test::CoverageStats s = test::compare(got, want);
  std::printf("text 24px: edge mean %.4f, max %.4f, ink ratio %.4f over %zu edge pixels\n", s.edge_mean_abs, s.max_abs,
              s.ink_ratio, s.edge_pixels);
  // Interior triangles next to curves evaluate them (kinds 3, 4) and curve
  // coverage accounts for curvature, so ink is right to the issue's 3%.
  EXPECT_LE(s.edge_mean_abs, 0.03);
  EXPECT_NEAR(s.ink_ratio, 1.0, 0.03);
  if (s.edge_mean_abs > 0.03 || std::fabs(s.ink_ratio - 1.0) > 0.03) test::write_comparison("gpu_text", got, want);

  // A second batch of the same text hits the cache for every glyph.
  const GlyphCache::Stats before = cache.stats();
  DrawBatch again = DrawBatch::from_text(cache, font, line, ppem);
  const GlyphCache::Stats after = cache.stats();
  EXPECT_EQ(after.misses, before.misses);
  EXPECT_EQ(after.hits - before.hits, line.glyphs.size());
  EXPECT_EQ(again.vertex_count(), batch.vertex_count());
}

// The GL tests run twice (tests/CMakeLists.txt): in the context Mesa gives
// by default (OpenGL ES 3.2), where text blocks are instanced, and in a true
// OpenGL ES 2.0 context, where they take the GLES2 path. This checks that each
// run is on the path it is meant to test.
TEST(Context, TextBlocksTakeThePathOfTheContext) {
  context();
  const std::string version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  const Font font = Font::open(test::kDejaVuSans);
  GlyphCache cache;
  const DrawBatch batch = DrawBatch::from_text(cache, font, shape_line(font, "path"), 16.0);
  std::printf("GL_VERSION %s: %s text blocks\n", version.c_str(), batch.instanced() ? "instanced" : "expanded");
  if (test::expects_gles2()) {
    EXPECT_EQ(version.rfind("OpenGL ES 2.0", 0), 0u) << version;
    EXPECT_FALSE(batch.instanced());
    // llvmpipe's GLES 2 fragment shaders have 24-bit highp floats and it has
    // OES_texture_float: its text takes the GLES 2 band path.
    const std::string renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    std::printf("%s: GLES 2 band path %s\n", renderer.c_str(), gpu::es2_band_context() ? "yes" : "no");
    if (renderer.find("llvmpipe") != std::string::npos) {
      EXPECT_TRUE(gpu::es2_band_context());
      EXPECT_TRUE(DrawBatchAccess::impl(batch).banded && DrawBatchAccess::impl(batch).band_quads);
    }
  } else {
    EXPECT_EQ(batch.instanced(), gpu::context_instances());
  }
}

// Shapes with conic arcs (a circle's quarters, w = cos 45; a flat ellipse
// arc, w = 0.05; a heavy hyperbola arc, w = 40) take the band program
// compiled with CURVETEXT_CONICS (the weights, the segment's closed forms);
// every pixel matches the CPU reference within the 8-bit rounding, at two
// sizes whose pixels read the cell grids and the band loop.
TEST(Bands, ConicProgramMatchesCpuReference) {
  context();
  if (!gpu::context_instances() && !gpu::es2_band_context()) GTEST_SKIP() << "GLES2 without highp: no band program";
  std::vector<Mesh> meshes;
  {
    Outline circle;
    const double r = 40.0, k = std::sqrt(0.5);
    circle.move_to({r, 0.0});
    circle.conic_to({r, r}, {0.0, r}, k);
    circle.conic_to({-r, r}, {-r, 0.0}, k);
    circle.conic_to({-r, -r}, {0.0, -r}, k);
    circle.conic_to({r, -r}, {r, 0.0}, k);
    circle.close();
    meshes.push_back(build_mesh(circle));
    Outline arcs;
    arcs.move_to({0.0, 0.0});
    arcs.conic_to({40.0, 70.0}, {80.0, 0.0}, 0.05);
    arcs.conic_to({40.0, -30.0}, {0.0, 0.0}, 40.0);
    arcs.close();
    meshes.push_back(build_mesh(arcs));
  }
  const std::vector<Vec2> offsets{{50.0, 50.0}, {110.0, 20.0}};
  std::vector<const Mesh*> pointers{&meshes[0], &meshes[1]};
  std::vector<gpu::GlyphBands> bands(meshes.size());
  gpu::BandScratch scratch;
  for (std::size_t i = 0; i < meshes.size(); ++i) {
    gpu::build_bands(meshes[i], bands[i], scratch);
    ASSERT_TRUE(bands[i].conics) << i;
  }
  Renderer renderer;
  ImageTarget target;
  // Two scales, and one turned 35 degrees about the image's centre (the
  // program with CURVETEXT_FOOTPRINT and CURVETEXT_CONICS).
  for (const auto& [scale, degrees] : {std::pair{0.25, 0.0}, std::pair{1.3, 0.0}, std::pair{1.1, -35.0}}) {
    // GLES 2's band program serves maps that keep the axes only.
    if (degrees != 0.0 && !gpu::context_instances()) continue;
    // The batch's mesh (the first shape, unmoved) is drawn only where the
    // bands are not: a pixel off the CPU's shows it.
    auto impl = gpu::upload(gpu::pack_mesh(meshes[0]));
    gpu::add_mesh_bands(*impl, pointers, offsets);
    ASSERT_TRUE(impl->banded && impl->band_conics);
    const DrawBatch batch = DrawBatchAccess::make(std::move(impl));
    const int width = static_cast<int>(std::ceil(220 * scale)), height = static_cast<int>(std::ceil(120 * scale));
    const Transform turn = Transform::translation(width / 2.0, height / 2.0) * Transform::rotation(degrees) *
                           Transform::translation(-width / 2.0, -height / 2.0);
    const Placement placement{scale, 0.31, 0.77 + 100 * scale, turn};
    const Transform inv = gpu::inverse(
        turn * Transform{{scale, 0.0, placement.origin_x, 0.0, -scale, placement.origin_y, 0.0, 0.0, 1.0}});
    const gpu::Footprint f{{inv.m[0], inv.m[3]}, {inv.m[1], inv.m[4]}};
    target.begin(width, height, Color{1, 1, 1, 1});
    renderer.draw(batch, placement, DrawOptions(Color{0, 0, 0, 1}, AntiAliasing::Full));
    const Image image = target.read_pixels();
    double worst = 0.0, ink = 0.0;
    for (int j = 0; j < height; ++j)
      for (int i = 0; i < width; ++i) {
        double clear = 1.0;
        for (std::size_t g = 0; g < meshes.size(); ++g) {
          const Vec2 centre = inv.apply({i + 0.5, j + 0.5}) - offsets[g];
          const double c = degrees == 0.0 ? gpu::band_box_coverage(bands[g], centre, Vec2{0.5 / scale, 0.5 / scale})
                                          : gpu::band_footprint_coverage(bands[g], centre, f);
          clear *= 1.0 - std::clamp(c, 0.0, 1.0);
        }
        const double got = 1.0 - image.rgba[4 * (static_cast<std::size_t>(j) * width + i)] / 255.0;
        worst = std::max(worst, std::abs(got - (1.0 - clear)));
        ink += 1.0 - clear;
      }
    std::printf("conic bands at scale %.2f, turned %g degrees: largest difference to the CPU %.4f (ink %.1f px)\n",
                scale, degrees, worst, ink);
    EXPECT_GT(ink, 10.0);
    EXPECT_LE(worst, 0.5 / 255.0 + 1e-3) << scale;
  }
}

// The CPU side of a shaped line: each glyph's bands built as the cache
// builds them, with its pen position (font units).
std::vector<std::pair<gpu::GlyphBands, Vec2>> line_bands(const Font& font, const ShapedLine& line) {
  std::vector<std::pair<gpu::GlyphBands, Vec2>> glyphs;
  gpu::BandScratch scratch;
  double pen = 0.0;
  for (const ShapedGlyph& g : line.glyphs) {
    gpu::GlyphBands bands;
    gpu::build_bands(build_mesh(font.glyph_outline(g.glyph_id)), bands, scratch);
    glyphs.push_back({std::move(bands), Vec2{pen + g.x_offset, g.y_offset}});
    pen += g.x_advance;
  }
  return glyphs;
}

// full for a text block where the context instances (docs/design.md
// section 9): one quad per glyph evaluating the exact area from the glyph's
// curve bands, no offscreen pass. Every pixel matches the CPU reference of
// the same computation (gpu::band_box_coverage over the same texels, the
// glyphs' coverages composed as source-over blending composes them) within
// the 8-bit image's rounding, at sizes from 9 to 120 px with fractional
// origins.
TEST(Bands, ShaderMatchesCpuReferenceInOnePass) {
  context();
  if (!gpu::context_instances() && !gpu::es2_band_context())
    GTEST_SKIP() << "GLES2 without highp: text blocks draw through their meshes";
  const Font font = Font::open(test::kDejaVuSans);
  const ShapedLine line = shape_line(font, "Band@gq&%Wj");
  GlyphCache cache;
  Renderer renderer;
  ImageTarget target;
  const FontMetrics& fm = font.metrics();
  const std::vector<std::pair<gpu::GlyphBands, Vec2>> glyphs = line_bands(font, line);
  for (double ppem : {9.0, 16.0, 33.3, 120.0}) {
    const DrawBatch batch = DrawBatch::from_text(cache, font, line, ppem);
    ASSERT_TRUE(DrawBatchAccess::impl(batch).banded) << ppem;
    const double scale = ppem / fm.units_per_em;
    const Placement placement{scale, 3.37, 2.61 + fm.ascender * scale};
    const int width = static_cast<int>(std::ceil(8 + line.advance * scale));
    const int height = static_cast<int>(std::ceil(6 + (fm.ascender - fm.descender) * scale));
    target.begin(width, height, Color{1, 1, 1, 1});
    const std::size_t passes = renderer.offscreen_passes();
    renderer.draw(batch, placement, DrawOptions(Color{0, 0, 0, 1}, AntiAliasing::Full));
    EXPECT_EQ(renderer.offscreen_passes(), passes) << ppem;
    const Image image = target.read_pixels();
    double worst = 0.0, ink = 0.0;
    for (int j = 0; j < height; ++j)
      for (int i = 0; i < width; ++i) {
        double clear = 1.0;  // 1 - coverage after each glyph's source-over
        for (const auto& [bands, at] : glyphs) {
          const Vec2 centre{(i + 0.5 - placement.origin_x) / scale - at.x,
                            (placement.origin_y - j - 0.5) / scale - at.y};
          const double c = gpu::band_box_coverage(bands, centre, Vec2{0.5 / scale, 0.5 / scale});
          clear *= 1.0 - std::clamp(c, 0.0, 1.0);
        }
        const double got = 1.0 - image.rgba[4 * (static_cast<std::size_t>(j) * width + i)] / 255.0;
        worst = std::max(worst, std::abs(got - (1.0 - clear)));
        ink += 1.0 - clear;
      }
    std::printf("bands at %.1f px: largest difference to the CPU %.4f (ink %.1f px)\n", ppem, worst, ink);
    EXPECT_GT(ink, 10.0);
    EXPECT_LE(worst, 0.5 / 255.0 + 1e-3) << ppem;
  }
}

// The same under maps that turn the axes (rotations, skews, a flip): each
// pixel's footprint is a parallelogram in outline units, and every pixel
// matches gpu::band_footprint_coverage over the same texels, in one pass.
TEST(Bands, RotatedAndSkewedShaderMatchesCpuReference) {
  context();
  if (!gpu::context_instances()) GTEST_SKIP() << "GLES2: text blocks draw through their meshes";
  const Font font = Font::open(test::kDejaVuSans);
  const ShapedLine line = shape_line(font, "Band@gq&%Wj");
  GlyphCache cache;
  Renderer renderer;
  ImageTarget target;
  const FontMetrics& fm = font.metrics();
  const std::vector<std::pair<gpu::GlyphBands, Vec2>> glyphs = line_bands(font, line);
  const struct {
    const char* name;
    Transform map;
    double ppem;
  } cases[] = {{"rotated 30", Transform::rotation(30.0), 16.0},
               {"rotated -72.5", Transform::rotation(-72.5), 9.0},
               {"rotated 90", Transform::rotation(90.0), 33.3},
               {"skewed -15, 5", Transform::skew(-15.0, 5.0), 20.0},
               {"skewed 40, 0", Transform::skew(40.0, 0.0), 120.0},
               {"flipped, rotated 3", Transform{{-1, 0.05, 0, 0.05, 1, 0, 0, 0, 1}}, 27.0}};
  for (const auto& c : cases) {
    const DrawBatch batch = DrawBatch::from_text(cache, font, line, c.ppem);
    ASSERT_TRUE(DrawBatchAccess::impl(batch).banded) << c.name;
    const double scale = c.ppem / fm.units_per_em;
    // The block's box under the map, moved into the image with a margin.
    Placement placement{scale, 0.0, 0.0, c.map};
    const Transform local{{scale, 0.0, 0.0, 0.0, -scale, 0.0, 0.0, 0.0, 1.0}};
    Box image;
    for (double x : {0.0, line.advance})
      for (double y : {static_cast<double>(fm.descender), static_cast<double>(fm.ascender)})
        image.add((c.map * local).apply({x, y}));
    // The origin moves the block by its image under the map.
    const Vec2 origin = gpu::inverse(c.map).apply(Vec2{4.37 - image.min.x, 3.61 - image.min.y} + c.map.apply({0, 0}));
    placement.origin_x = origin.x;
    placement.origin_y = origin.y;
    const Transform to_origin{{1.0, 0.0, placement.origin_x, 0.0, 1.0, placement.origin_y, 0.0, 0.0, 1.0}};
    const Transform full = c.map * to_origin * local;
    const Transform inv = gpu::inverse(full);
    const int width = static_cast<int>(std::ceil(image.max.x - image.min.x + 9));
    const int height = static_cast<int>(std::ceil(image.max.y - image.min.y + 8));
    target.begin(width, height, Color{1, 1, 1, 1});
    const std::size_t passes = renderer.offscreen_passes();
    renderer.draw(batch, placement, DrawOptions(Color{0, 0, 0, 1}, AntiAliasing::Full));
    EXPECT_EQ(renderer.offscreen_passes(), passes) << c.name;
    const Image drawn = target.read_pixels();
    // The inverse's linear part: the pixel's axes in outline units.
    const gpu::Footprint f{{inv.m[0], inv.m[3]}, {inv.m[1], inv.m[4]}};
    double worst = 0.0, ink = 0.0;
    for (int j = 0; j < height; ++j)
      for (int i = 0; i < width; ++i) {
        const Vec2 centre = inv.apply({i + 0.5, j + 0.5});
        double clear = 1.0;
        for (const auto& [bands, at] : glyphs)
          clear *= 1.0 - std::clamp(gpu::band_footprint_coverage(bands, centre - at, f), 0.0, 1.0);
        const double got = 1.0 - drawn.rgba[4 * (static_cast<std::size_t>(j) * width + i)] / 255.0;
        worst = std::max(worst, std::abs(got - (1.0 - clear)));
        ink += 1.0 - clear;
      }
    std::printf("bands %s at %.1f px: largest difference to the CPU %.4f (ink %.1f px)\n", c.name, c.ppem, worst, ink);
    EXPECT_GT(ink, 10.0) << c.name;
    EXPECT_LE(worst, 0.5 / 255.0 + 1e-3) << c.name;
  }
  // Under perspective too (first order: tests/transform_test.cpp holds it
  // against exact coverage).
  const DrawBatch batch = DrawBatch::from_text(cache, font, line, 24.0);
  target.begin(300, 80, Color{1, 1, 1, 1});
  const std::size_t passes = renderer.offscreen_passes();
  renderer.draw(batch, Placement{24.0 / fm.units_per_em, 10, 50, Transform::perspective(50.0, 400.0)},
                DrawOptions(Color{0, 0, 0, 1}, AntiAliasing::Full));
  EXPECT_EQ(renderer.offscreen_passes(), passes);
}

// `auto` is full wherever the renderer draws a text block from its curve
// bands (at or below vbaa's edge error, no offscreen pass), else vbaa up to
// kAutoVbaaMaxPx: a small line drawn with auto is then full's image, pixel
// for pixel, and costs no offscreen pass; where the block has no bands (a
// GLES 2 context) auto is vbaa's.
TEST(Bands, AutoIsFullWhereBandsDraw) {
  context();
  const Font font = Font::open(test::kDejaVuSans);
  GlyphCache cache;
  Renderer renderer;
  const DrawBatch batch = DrawBatch::from_text(cache, font, shape_line(font, "auto"), 14.0);
  const double scale = 14.0 / font.metrics().units_per_em;
  for (const Placement& placement :
       {Placement{scale, 2.0, 14.0}, Placement{scale, 2.0, 14.0, Transform::rotation(10.0)}}) {
    const bool bands = renderer.draws_from_bands(batch, placement);
    EXPECT_EQ(resolve_antialiasing(AntiAliasing::Auto, 14.0, renderer, batch, placement),
              bands ? AntiAliasing::Full : AntiAliasing::Vbaa);
    EXPECT_EQ(resolve_antialiasing(AntiAliasing::Curves, 14.0, renderer, batch, placement), AntiAliasing::Curves);
  }
  const bool banded = gpu::context_instances() || gpu::es2_band_context();
  EXPECT_EQ(renderer.draws_from_bands(batch, Placement{scale, 2.0, 14.0}), banded);

  TextImageOptions options;
  options.size_px = 14.0;
  options.margin_px = 3.0;
  const TextImageLayout layout = layout_text_image(font, "Auto, 14 px", options);
  options.antialiasing = AntiAliasing::Full;
  const Image full = render_text_image(renderer, cache, font, layout, options);
  options.antialiasing = AntiAliasing::Vbaa;
  const Image vbaa = render_text_image(renderer, cache, font, layout, options);
  options.antialiasing = AntiAliasing::Auto;
  const std::size_t passes = renderer.offscreen_passes();
  const Image automatic = render_text_image(renderer, cache, font, layout, options);
  ASSERT_NE(full.rgba, vbaa.rgba);  // else the comparison below could not tell them apart
  if (banded) {
    EXPECT_EQ(automatic.rgba, full.rgba);
    EXPECT_EQ(renderer.offscreen_passes(), passes);
  } else {
    EXPECT_EQ(automatic.rgba, vbaa.rgba);
  }
}

// Turns the GLES 2 band path off for one scope.
struct Es2BandsOff {
  Es2BandsOff() { gpu::set_es2_bands_allowed(false); }
  ~Es2BandsOff() { gpu::set_es2_bands_allowed(true); }
  Es2BandsOff(const Es2BandsOff&) = delete;
  Es2BandsOff& operator=(const Es2BandsOff&) = delete;
};

// Draws `batch` black on white in full and returns 1 - red / 255 per pixel,
// and how many offscreen passes the draw took.
std::pair<Coverage, std::size_t> draw_full(Renderer& renderer, const DrawBatch& batch, const Placement& placement) {
  ImageTarget target;
  target.begin(kW * 4, kH, Color{1, 1, 1, 1});
  const std::size_t before = renderer.offscreen_passes();
  renderer.draw(batch, placement, DrawOptions(Color{0, 0, 0, 1}, AntiAliasing::Full));
  const Image image = target.read_pixels();
  Coverage cov(static_cast<std::size_t>(kW) * 4 * kH);
  for (std::size_t i = 0; i < cov.size(); ++i) cov[i] = 1.0 - image.rgba[4 * i] / 255.0;
  return {cov, renderer.offscreen_passes() - before};
}

// On a GLES 2 context whose fragment shaders have highp floats (and float
// textures), full text draws through the GLES 2 band program in one pass;
// switched off, or with a glyph whose bands exceed the program's loop bound
// (tolerance::kEs2BandEntryCap), the block takes the mesh path and its
// offscreen pass, and draws the same coverage (both exact; they differ only
// where two glyphs share a pixel: source-over against a sum).
TEST(Bands, Es2TextBlockDrawsInOnePassOrFallsBack) {
  context();
  if (gpu::context_instances() || !gpu::es2_band_context())
    GTEST_SKIP() << "not a GLES 2 context with highp fragment shaders";
  const Font font = Font::open(test::kDejaVuSans);
  const ShapedLine line = shape_line(font, "Band@gq&%Wj");
  GlyphCache cache;
  Renderer renderer;
  const double ppem = 20.0, scale = ppem / font.metrics().units_per_em;
  const Placement placement{scale, 2.37, 4.61 + font.metrics().ascender * scale};
  const DrawBatch banded = DrawBatch::from_text(cache, font, line, ppem);
  ASSERT_TRUE(DrawBatchAccess::impl(banded).banded && DrawBatchAccess::impl(banded).band_quads);
  const auto [one_pass, passes] = draw_full(renderer, banded, placement);
  EXPECT_EQ(passes, 0u);
  Coverage mesh;
  {
    const Es2BandsOff off;
    const DrawBatch fallback = DrawBatch::from_text(cache, font, line, ppem);
    EXPECT_FALSE(DrawBatchAccess::impl(fallback).banded);
    std::size_t mesh_passes = 0;
    std::tie(mesh, mesh_passes) = draw_full(renderer, fallback, placement);
    EXPECT_EQ(mesh_passes, 1u);
  }
  double worst = 0.0, sum = 0.0, ink = 0.0;
  for (std::size_t i = 0; i < mesh.size(); ++i) {
    worst = std::max(worst, std::abs(one_pass[i] - mesh[i]));
    sum += std::abs(one_pass[i] - mesh[i]);
    ink += mesh[i];
  }
  std::printf("GLES 2 bands against the mesh path: largest difference %.4f, mean %.5f (ink %.1f px)\n", worst,
              sum / static_cast<double>(mesh.size()), ink);
  EXPECT_GT(ink, 50.0);
  EXPECT_LE(worst, 0.1);
  EXPECT_LE(sum / static_cast<double>(mesh.size()), 0.002);

  // A glyph whose bands list more pieces than the loop reaches.
  gpu::BandScratch scratch;
  gpu::GlyphBands bands;
  std::uint32_t long_glyph = 0;
  for (std::uint32_t g = 1; g < font.glyph_count() && long_glyph == 0; ++g) {
    const Outline outline = font.glyph_outline(g);
    if (outline.empty()) continue;
    gpu::build_bands(build_mesh(outline), bands, scratch);
    if (!bands.empty() && gpu::most_band_entries(bands) > tolerance::kEs2BandEntryCap) long_glyph = g;
  }
  ASSERT_NE(long_glyph, 0u);
  std::vector<PlacedGlyph> placed{{line.glyphs[0].glyph_id, 0.0, 0.0}, {long_glyph, 1500.0, 0.0}};
  const DrawBatch capped = DrawBatch::from_glyphs(cache, font, placed, ppem);
  EXPECT_FALSE(DrawBatchAccess::impl(capped).banded) << long_glyph;
  EXPECT_EQ(draw_full(renderer, capped, placement).second, 1u);
}

// A GLES 2 block past one draw's 16-bit indices (gpu::kBandQuadsPerDraw
// glyphs) is drawn in several: every glyph shows, as the mesh path draws it.
TEST(Bands, Es2BlockPastOneDrawsIndicesDrawsEveryGlyph) {
  context();
  if (gpu::context_instances() || !gpu::es2_band_context())
    GTEST_SKIP() << "not a GLES 2 context with highp fragment shaders";
  const Font font = Font::open(test::kDejaVuSans);
  const std::uint32_t stem = shape_line(font, "l").glyphs[0].glyph_id;
  const double ppem = 6.0, scale = ppem / font.metrics().units_per_em;
  constexpr int kColumns = 160, kRows = 110;  // 17,600 glyphs, apart by 2 px and by 6 (no pixel shared)
  static_assert(kColumns * kRows > gpu::kBandQuadsPerDraw);
  std::vector<PlacedGlyph> placed;
  for (int j = 0; j < kRows; ++j)
    for (int i = 0; i < kColumns; ++i) placed.push_back({stem, 2.0 * i / scale, -6.0 * j / scale});
  GlyphCache cache;
  Renderer renderer;
  const auto draw = [&](const DrawBatch& batch) {
    ImageTarget target;
    target.begin(2 * kColumns + 4, 6 * kRows + 4, Color{1, 1, 1, 1});
    renderer.draw(batch, Placement{scale, 1.3, 7.4}, DrawOptions(Color{0, 0, 0, 1}, AntiAliasing::Full));
    return target.read_pixels();
  };
  const DrawBatch banded = DrawBatch::from_glyphs(cache, font, placed, ppem);
  ASSERT_TRUE(DrawBatchAccess::impl(banded).band_quads);
  const Image one_pass = draw(banded);
  const Es2BandsOff off;
  const Image mesh = draw(DrawBatch::from_glyphs(cache, font, placed, ppem));
  // The last row: past the first draw.
  double last_row_ink = 0.0, worst = 0.0;
  for (int y = 0; y < one_pass.height; ++y)
    for (int x = 0; x < one_pass.width; ++x) {
      const double a = 1.0 - one_pass.pixel(x, y)[0] / 255.0, b = 1.0 - mesh.pixel(x, y)[0] / 255.0;
      worst = std::max(worst, std::abs(a - b));
      if (y >= one_pass.height - 8) last_row_ink += a;
    }
  std::printf("%zu glyphs: largest difference to the mesh path %.4f, last row's ink %.1f px\n", placed.size(), worst,
              last_row_ink);
  EXPECT_GT(last_row_ink, 0.5 * kColumns * 0.2);
  EXPECT_LE(worst, 0.02);
}

// A block of N placed glyphs uploads bytes in proportion to N: instanced, 40
// per placed glyph (the meshes are uploaded once, into the cache); expanded
// (the GLES2 path), each placement's mesh. The same text repeated k times
// uploads k times the bytes, and the instanced block adds nothing to the
// cache's GPU bytes after the first.
TEST(Text, BlockUploadsBytesInProportionToItsGlyphs) {
  context();
  const Font font = Font::open(test::kDejaVuSans);
  const ShapedLine line = shape_line(font, "The quick brown fox jumps over the lazy dog, 0123456789.");
  std::size_t inked = 0, vertices = 0, indices = 0;  // of one copy of the line
  GlyphCache cache;
  for (const ShapedGlyph& g : line.glyphs) {
    const gpu::PackedMesh& mesh = GlyphCacheAccess::impl(cache).get(font, g.glyph_id, 16.0)->packed;
    inked += mesh.empty() ? 0 : 1;
    vertices += mesh.vertices.size();
    indices += mesh.indices.size();
  }
  ASSERT_GT(inked, 40u);
  std::vector<PlacedGlyph> placed;
  std::vector<std::size_t> instanced_bytes, expanded_bytes, cache_gpu_bytes;
  for (int copies = 1; copies <= 64; copies *= 4) {
    placed.clear();
    for (int c = 0; c < copies; ++c) {
      double pen = 0.0;
      for (const ShapedGlyph& g : line.glyphs) {
        placed.push_back(PlacedGlyph{g.glyph_id, pen + g.x_offset, -2400.0 * c});
        pen += g.x_advance;
      }
    }
    const DrawBatch instanced = DrawBatchAccess::make(
        gpu::text_block(GlyphCacheAccess::impl(cache), font, placed, 16.0, gpu::BlockPath::Instanced));
    const DrawBatch expanded = DrawBatchAccess::make(
        gpu::text_block(GlyphCacheAccess::impl(cache), font, placed, 16.0, gpu::BlockPath::Expanded));
    cache_gpu_bytes.push_back(cache.stats().gpu_bytes);  // on GLES 2 with highp, the bands' texels too
    ASSERT_TRUE(instanced.instanced());
    ASSERT_FALSE(expanded.instanced());
    instanced_bytes.push_back(instanced.gpu_bytes());
    expanded_bytes.push_back(expanded.gpu_bytes());
    const auto n = static_cast<std::size_t>(copies);
    // An offset, and where the context has float textures the band quad's data (above).
    const std::size_t per_glyph = DrawBatchAccess::impl(instanced).banded ? 40u : 8u;
    EXPECT_EQ(instanced_bytes.back(), per_glyph * inked * n) << copies << " copies";
    const std::size_t index_bytes = n * vertices <= gpu::kMaxShortIndexedVertices ? 2 : 4;
    // Where the GLES 2 band path draws it, each glyph's quad: 4 vertices of 10 floats.
    const std::size_t quad_bytes = DrawBatchAccess::impl(expanded).band_quads ? 160u : 0u;
    EXPECT_EQ(expanded_bytes.back(), n * (vertices * sizeof(gpu::Vertex) + indices * index_bytes + quad_bytes * inked))
        << copies << " copies";
  }
  for (std::size_t i = 1; i < cache_gpu_bytes.size(); ++i)
    EXPECT_EQ(cache_gpu_bytes[i], cache_gpu_bytes[0]) << "glyph meshes uploaded again";
  EXPECT_GT(cache_gpu_bytes[0], 0u);
  // Per placed glyph, the instanced block is two orders of magnitude smaller.
  EXPECT_LT(100 * instanced_bytes.back(), expanded_bytes.back());
}

TEST(Text, CacheEvictsWithinBudget) {
  context();
  const Font font = Font::open(test::kDejaVuSans);
  const ShapedLine line = shape_line(font, "abcdefghijklmnopqrstuvwxyz");
  // A glyph with its mesh and curve bands costs about 10 KB (draw_bench's bytes table).
  GlyphCache cache(32 * 1024);
  DrawBatch batch = DrawBatch::from_text(cache, font, line, 16.0);
  EXPECT_LE(cache.stats().bytes, 32u * 1024u);
  EXPECT_LT(cache.stats().glyphs, line.glyphs.size());
  EXPECT_GT(batch.vertex_count(), 0u);
}

TEST(Renderer, SizeAboveGlMaximumIsInvalidArgument) {
  context();
  Renderer renderer;
  ImageTarget target;
  try {
    target.begin(1 << 20, 4, Color{1, 1, 1, 1});
    FAIL() << "expected InvalidArgument";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::InvalidArgument) << e.what();
  }
  try {
    target.begin(0, 4, Color{1, 1, 1, 1});
    FAIL() << "expected InvalidArgument";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::InvalidArgument) << e.what();
  }
  // Still usable afterwards.
  target.begin(8, 8, Color{1, 0, 0, 0.5f});
  Image img = target.read_pixels();
  EXPECT_EQ(img.pixel(3, 3)[0], 255);
  EXPECT_NEAR(img.pixel(3, 3)[3], 128, 1);
}

// Packing writes one point per corner of each triangle, two at a corner
// sharp enough for a bevel (the vertex shader grows them; the growth itself
// is checked end to end by render_test's FullAntialiasingGrowth): each point
// starts at its corner and carries the edge to the next corner, the edge to
// the previous one in that edge's frame (whose second coordinate times |a|^2
// is the doubled signed area), the corner, side and point kind in its code,
// and the curve's weight; the fan's indices are numbered past what `out`
// holds.
TEST(Packing, CornersEdgesAndCodes) {
  Mesh m;
  // A right triangle (three miters), a needle of about 6 degrees at (10, 20)
  // (its sharp corner bevelled: two points), clockwise.
  m.points = {{0, 0}, {4, 0}, {0, 4}, {10, 20}, {40, 23}, {40, 20}};
  m.triangles = {{0, 1, 2}, {3, 4, 5}};
  m.curves = {CurvedTriangle{0, 2, 1, 0.7, false}};
  const gpu::PackedMesh packed = gpu::pack_mesh(m);
  ASSERT_EQ(packed.vertices.size(), 3u + 4u + 3u);
  ASSERT_EQ(packed.indices.size(), 3u * (1 + 2 + 1));
  struct Expected {
    std::array<std::uint32_t, 3> corners;
    int side;
    float weight;
    std::size_t first;
  };
  const Expected expected[] = {{m.triangles[0], gpu::kInterior, 0.0f, 0},
                               {m.triangles[1], gpu::kInterior, 0.0f, 3},
                               {{0, 2, 1}, gpu::kConcaveCurve, 0.7f, 7}};
  for (const Expected& t : expected) {
    const std::size_t count = t.first == 3 ? 4 : 3;
    int previous_corner = -1;
    for (std::size_t i = t.first; i < t.first + count; ++i) {
      const gpu::Vertex& v = packed.vertices[i];
      const int code = static_cast<int>(v.info[2]);
      ASSERT_EQ(v.info[2], static_cast<float>(code)) << "vertex " << i;
      const int point = code / gpu::kPointStride, side = code % gpu::kPointStride / gpu::kSideStride;
      const int corner = code % gpu::kSideStride;
      EXPECT_EQ(side, t.side) << "vertex " << i;
      EXPECT_GE(corner, previous_corner) << "points in corner order";
      // The needle's corner at (10, 20) (corner 0) is bevelled, the others not.
      const bool bevel = t.first == 3 && corner == 0;
      EXPECT_EQ(point, bevel ? (i == 3 ? gpu::kBevelArriving : gpu::kBevelLeaving) : gpu::kMiter) << "vertex " << i;
      previous_corner = corner;
      const Vec2 own = m.points[t.corners[static_cast<std::size_t>(corner)]];
      const Vec2 next = m.points[t.corners[static_cast<std::size_t>((corner + 1) % 3)]];
      const Vec2 prev = m.points[t.corners[static_cast<std::size_t>((corner + 2) % 3)]];
      EXPECT_EQ(v.pos[0], static_cast<float>(own.x)) << "vertex " << i;
      EXPECT_EQ(v.pos[1], static_cast<float>(own.y)) << "vertex " << i;
      EXPECT_EQ(v.pos[2], static_cast<float>(next.x - own.x)) << "vertex " << i;
      EXPECT_EQ(v.pos[3], static_cast<float>(next.y - own.y)) << "vertex " << i;
      const Vec2 a = next - own, b = prev - own;
      EXPECT_EQ(v.info[0], static_cast<float>(dot(a, b) / dot(a, a))) << "vertex " << i;
      EXPECT_EQ(v.info[1], static_cast<float>(cross(a, b) / dot(a, a))) << "vertex " << i;
      // Rebuilt as the shader does, b is the edge to the previous corner.
      const Vec2 rebuilt = a * v.info[0] + Vec2{-a.y, a.x} * v.info[1];
      EXPECT_NEAR(rebuilt.x, b.x, 1e-5 * length(b)) << "vertex " << i;
      EXPECT_NEAR(rebuilt.y, b.y, 1e-5 * length(b)) << "vertex " << i;
      EXPECT_EQ(v.info[3], t.weight) << "vertex " << i;
    }
  }
  // Fans: (first, first + 1, first + 2), (first, first + 2, first + 3), ...
  const std::uint32_t fans[] = {0, 1, 2, 3, 4, 5, 3, 5, 6, 7, 8, 9};
  for (std::size_t i = 0; i < packed.indices.size(); ++i) EXPECT_EQ(packed.indices[i], fans[i]) << i;

  // The two interior triangles' indices come ahead of the curved one's.
  EXPECT_EQ(packed.interior_indices, 3u * (1 + 2));

  // Appended, the copy's interior indices go after the first's interior ones
  // and its curved indices at the end: [interior, interior', curved, curved'].
  gpu::PackedMesh both = packed;
  gpu::append_translated(packed, Vec2{100, 0}, both);
  ASSERT_EQ(both.vertices.size(), 2 * packed.vertices.size());
  ASSERT_EQ(both.indices.size(), 2 * packed.indices.size());
  ASSERT_EQ(both.interior_indices, 2 * packed.interior_indices);
  const std::size_t interior = packed.interior_indices, curved = packed.indices.size() - interior;
  for (std::size_t i = 0; i < packed.indices.size(); ++i) {
    const bool is_interior = i < interior;
    const std::size_t original = is_interior ? i : interior + i;  // where `i`'s own copy sits in `both`
    const std::size_t copy = is_interior ? interior + i : 2 * interior + curved + (i - interior);
    EXPECT_EQ(both.indices[original], packed.indices[i]) << i;
    EXPECT_EQ(both.indices[copy], packed.indices[i] + packed.vertices.size()) << i;
    const gpu::Vertex& a = packed.vertices[packed.indices[i]];
    const gpu::Vertex& b = both.vertices[both.indices[copy]];
    EXPECT_EQ(b.pos[0], a.pos[0] + 100.0f);  // the corner moves; its edges do not
    EXPECT_EQ(b.pos[2], a.pos[2]);
    EXPECT_EQ(b.info[0], a.info[0]);
    EXPECT_EQ(b.info[2], a.info[2]);
  }
}

// A flat triangle covers nothing and packs to nothing.
TEST(Packing, FlatTrianglesAreLeftOut) {
  Mesh m;
  m.points = {{0, 0}, {4, 0}, {8, 0}, {2, 3}};
  m.triangles = {{0, 1, 2}, {0, 1, 3}};
  const gpu::PackedMesh packed = gpu::pack_mesh(m);
  EXPECT_EQ(packed.vertices.size(), 3u);
  EXPECT_EQ(packed.indices.size(), 3u);
}

// The three ways a batch's indices reach the GPU (16-bit, 32-bit, expanded
// arrays) draw the same pixels, and gpu_bytes counts what was uploaded.
TEST(DrawBatchUpload, SixteenBitThirtyTwoBitAndArraysDrawTheSame) {
  context();
  const Font font = Font::open(test::kDejaVuSans);
  const ShapedLine line = shape_line(font, "Quag@8");
  GlyphCache cache;
  gpu::PackedMesh packed;
  double pen = 0;
  for (const ShapedGlyph& g : line.glyphs) {
    gpu::append_translated(GlyphCacheAccess::impl(cache).get(font, g.glyph_id, 30.0)->packed,
                           Vec2{pen + g.x_offset, g.y_offset}, packed);
    pen += g.x_advance;
  }
  ASSERT_FALSE(packed.empty());
  const double scale = 30.0 / font.metrics().units_per_em;
  const Placement placement{scale, 3.25, 30.5};
  Renderer renderer;
  ImageTarget target;
  std::vector<Image> images;
  for (gpu::IndexUpload how : {gpu::IndexUpload::Bits16, gpu::IndexUpload::Bits32, gpu::IndexUpload::Arrays}) {
    DrawBatch batch = DrawBatchAccess::make(gpu::upload(packed, how));
    const std::size_t expected =
        how == gpu::IndexUpload::Bits16   ? packed.vertices.size() * 32 + packed.indices.size() * 2
        : how == gpu::IndexUpload::Bits32 ? packed.vertices.size() * 32 + packed.indices.size() * 4
                                          : packed.indices.size() * 32;
    EXPECT_EQ(batch.gpu_bytes(), expected);
    for (AntiAliasing aa : {AntiAliasing::Full, AntiAliasing::Curves}) {
      target.begin(160, 44, Color{1, 1, 1, 1});
      renderer.draw(batch, placement, DrawOptions(Color{0, 0, 0, 1}, aa));
      images.push_back(target.read_pixels());
    }
  }
  for (std::size_t i = 2; i < images.size(); ++i) {
    const Image& a = images[i % 2];
    const Image& b = images[i];
    ASSERT_EQ(a.rgba, b.rgba) << "upload way " << i / 2 << ", mode " << i % 2 << " differs from 16-bit";
  }
  // Some ink was drawn.
  std::size_t dark = 0;
  for (std::size_t i = 0; i < images[0].rgba.size(); i += 4) dark += images[0].rgba[i] < 128;
  EXPECT_GT(dark, 100u);

  gpu::PackedMesh too_many;
  too_many.vertices.resize(65537);
  too_many.indices = {0, 1, 65536};
  EXPECT_THROW(gpu::upload(too_many, gpu::IndexUpload::Bits16), Error);
}

TEST(Png, RoundTrip) {
  Image img(7, 5);
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      std::uint8_t* p = img.pixel(x, y);
      p[0] = static_cast<std::uint8_t>(x * 30);
      p[1] = static_cast<std::uint8_t>(y * 50);
      p[2] = static_cast<std::uint8_t>(x * y);
      p[3] = static_cast<std::uint8_t>(255 - x);
    }
  std::filesystem::create_directories(CURVETEXT_TEST_OUTPUT_DIR);
  const std::string path = std::string(CURVETEXT_TEST_OUTPUT_DIR) + "/gpu_png_roundtrip.png";
  write_png(img, path);
  const Image back = read_png(path);
  EXPECT_EQ(back.width, img.width);
  EXPECT_EQ(back.height, img.height);
  EXPECT_EQ(back.rgba, img.rgba);
}

TEST(Png, ErrorsNameThePath) {
  try {
    read_png("/nonexistent/dir/x.png");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::Io);
    EXPECT_NE(std::string(e.what()).find("/nonexistent/dir/x.png"), std::string::npos);
  }
  try {
    write_png(Image(2, 2), "/nonexistent/dir/y.png");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::Io);
    EXPECT_NE(std::string(e.what()).find("/nonexistent/dir/y.png"), std::string::npos);
  }
}

TEST(Parse, Colors) {
  const Color c = parse_color("#ff8000");
  EXPECT_FLOAT_EQ(c.r, 1.0f);
  EXPECT_NEAR(c.g, 128 / 255.0f, 1e-6);
  EXPECT_FLOAT_EQ(c.b, 0.0f);
  EXPECT_FLOAT_EQ(c.a, 1.0f);
  EXPECT_NEAR(parse_color("#0f0").g, 1.0f, 1e-6);
  EXPECT_NEAR(parse_color("#00000080").a, 128 / 255.0f, 1e-6);
  EXPECT_FLOAT_EQ(parse_color("transparent").a, 0.0f);
  EXPECT_FLOAT_EQ(parse_color("white").b, 1.0f);
  for (const char* bad : {"", "#", "#12", "#12345", "#gggggg", "purple", "ff0000", "#1234567"}) {
    try {
      parse_color(bad);
      FAIL() << bad;
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), ErrorCode::InvalidArgument) << bad;
    }
  }
}

}  // namespace
}  // namespace curvetext
