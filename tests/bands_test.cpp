// The exact pixel-box area over curve bands (lib/gpu/bands.hpp, docs/design.md
// section 9) on the CPU: the conic segment area and the per-piece integral
// against an independent reference (the boundary flattened finely and
// clipped to the box as a polygon), and over whole fonts (the pixels' coverages add up to the
// glyph's area; each pixel against the union sweep of tests/support).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "curvetext/font.hpp"
#include "curvetext/mesh.hpp"
#include "gpu/bands.hpp"
#include "support/fonts.hpp"
#include "support/union_coverage.hpp"

namespace curvetext {
namespace {

using gpu::BandPiece;

Vec2 eval(const BandPiece& p, double t) {
  const double a = 1.0 - t, b0 = a * a, b1 = 2.0 * t * a * p.w, b2 = t * t;
  return (b0 * p.p0 + b1 * p.c + b2 * p.p2) / (b0 + b1 + b2);
}

// The reference: the region's boundary flattened into a polygon of
// kFlatSteps chords per piece (evenly in the parameter: the area it misses
// falls as 1 / kFlatSteps^2, below 1e-9 of a pixel here), clipped to the box
// by Sutherland-Hodgman, its area by the shoelace formula. Signed by the
// boundary's orientation.
constexpr int kFlatSteps = 40000;

std::vector<Vec2> flatten(const std::vector<BandPiece>& pieces) {
  std::vector<Vec2> poly;
  for (const BandPiece& p : pieces)
    for (int i = 0; i < kFlatSteps; ++i) poly.push_back(eval(p, static_cast<double>(i) / kFlatSteps));
  return poly;
}

double polygon_area(const std::vector<Vec2>& poly) {
  double a = 0.0;
  for (std::size_t i = 0; i < poly.size(); ++i) a += cross(poly[(i + poly.size() - 1) % poly.size()], poly[i]);
  return 0.5 * a;
}

// Keeps the part of `poly` where s * (coordinate axis) <= 1/2.
std::vector<Vec2> clip(const std::vector<Vec2>& poly, int axis, double s) {
  const auto d = [&](Vec2 p) { return s * (axis == 0 ? p.x : p.y) - 0.5; };
  std::vector<Vec2> out;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Vec2 p = poly[(i + poly.size() - 1) % poly.size()], q = poly[i];
    const double dp = d(p), dq = d(q);
    if ((dp <= 0.0) != (dq <= 0.0)) out.push_back(p + (q - p) * (dp / (dp - dq)));
    if (dq <= 0.0) out.push_back(q);
  }
  return out;
}

double reference_coverage(const std::vector<BandPiece>& pieces) {
  std::vector<Vec2> poly = flatten(pieces);
  for (int axis = 0; axis < 2; ++axis)
    for (double s : {-1.0, 1.0}) poly = clip(poly, axis, s);
  return polygon_area(poly);
}

// The region between a conic arc and its chord, closed by the chord, with
// the box's coverage through the general integral and through the monotone
// pieces the shader reads.
struct Closed {
  std::vector<BandPiece> pieces;
  double general() const {
    double s = 0.0;
    for (const BandPiece& p : pieces) s += gpu::piece_box_integral(p);
    return s;
  }
  double monotone() const {
    std::vector<BandPiece> split;
    for (const BandPiece& p : pieces) gpu::split_monotone(p, split);
    double s = 0.0;
    for (const BandPiece& p : split) s += gpu::monotone_piece_box_integral(p);
    return s;
  }
};

BandPiece line(Vec2 a, Vec2 b) { return {a, 0.5 * (a + b), b, 1.0}; }

Closed conic_region(Vec2 p0, Vec2 c, Vec2 p2, double w) {
  // Counter-clockwise: the arc, then back along the chord.
  if (cross(c - p0, p2 - p0) < 0.0) std::swap(p0, p2);
  return {{{p0, c, p2, w}, line(p2, p0)}};
}

Closed polygon(std::initializer_list<Vec2> pts) {
  Closed r;
  const std::vector<Vec2> v(pts);
  for (std::size_t i = 0; i < v.size(); ++i) r.pieces.push_back(line(v[i], v[(i + 1) % v.size()]));
  return r;
}

void expect_exact(const Closed& r, const char* what, double tol = 1e-8) {
  const double ref = reference_coverage(r.pieces);
  EXPECT_NEAR(r.general(), ref, tol) << what;
  EXPECT_NEAR(r.monotone(), ref, tol) << what << " (monotone pieces)";
}

TEST(BandArea, SegmentRatioMatchesFlattening) {
  for (double w : {0.01, 0.1, 0.5, 0.7071, 0.979, 0.981, 0.999, 1.0, 1.001, 1.019, 1.021, 2.0, 10.0, 1000.0}) {
    // An arc over the chord (0,0)-(1,0) with control (0.5, 1), closed by the
    // chord: its area over the control triangle's 0.5.
    const BandPiece arc{{1, 0}, {0.5, 1.0}, {0, 0}, w};
    const double area = polygon_area(flatten({arc, line({0, 0}, {1, 0})}));
    EXPECT_NEAR(gpu::conic_segment_ratio(w), area / 0.5, 1e-8) << "w = " << w;
  }
}

TEST(BandArea, LinesThroughCornersAlongSidesAndAxes) {
  expect_exact(polygon({{-2, -2}, {2, -2}, {2, 2}, {-2, 2}}), "box inside a square");
  expect_exact(polygon({{-0.5, -0.5}, {0.5, -0.5}, {0.5, 0.5}, {-0.5, 0.5}}), "the box itself");
  expect_exact(polygon({{-0.5, -0.5}, {0.5, 0.5}, {-2, 3}}), "an edge through two corners");
  expect_exact(polygon({{0.5, -3}, {0.5, 3}, {-3, 0}}), "a vertical edge along the right side");
  expect_exact(polygon({{0.1, -3}, {0.1, 3}, {-3, 0}}), "a vertical edge inside");
  expect_exact(polygon({{-3, 0.2}, {3, 0.2}, {0, 3}}), "a horizontal edge inside");
  expect_exact(polygon({{-3, -0.5}, {3, -0.5}, {0, 3}}), "a horizontal edge along the bottom");
  expect_exact(polygon({{-1, -0.5}, {0.5, 1}, {-1, 1}}), "an edge touching a corner");
  expect_exact(polygon({{0.1, 0.1}, {0.3, 0.1}, {0.2, 0.3}}), "a triangle inside the box");
  expect_exact(polygon({{0.1, 0.1}, {0.1 + 1e-7, 0.1}, {0.1, 0.1 + 1e-7}}), "a triangle of 1e-7 px");
  expect_exact(polygon({{-3, -3}, {0.3, 0.3}, {0.3 + 1e-7, 0.3 + 2e-7}, {-3, 3}}), "an edge of 1e-7 px");
  expect_exact(polygon({{-3, -3}, {3, -3}, {-0.5, 3}}), "one end on the left side's line");
}

TEST(BandArea, ConicsOfAllWeights) {
  std::mt19937 rng(36);
  std::uniform_real_distribution<double> u(-1.5, 1.5);
  for (double w : {0.01, 0.1, 0.5, 0.7071067811865476, 0.99, 1.0, 1.01, 3.0, 30.0, 1000.0}) {
    for (int i = 0; i < 40; ++i) {
      const Vec2 p0{u(rng), u(rng)}, c{u(rng), u(rng)}, p2{u(rng), u(rng)};
      if (std::abs(cross(p2 - p0, c - p0)) < 1e-3) continue;
      char what[96];
      std::snprintf(what, sizeof what, "w %g, case %d", w, i);
      expect_exact(conic_region(p0, c, p2, w), what);
    }
  }
}

TEST(BandArea, ConicsTangentToSidesAndThroughCorners) {
  // A parabola whose apex touches the box's right side (tangent there).
  expect_exact(conic_region({0.0, -2.0}, {1.0, 0.0}, {0.0, 2.0}, 1.0), "apex on x = 1/2");
  // A circle's quarter (w = cos 45) through the box's corners (-1/2, 1/2) and (1/2, -1/2)?
  expect_exact(conic_region({-0.5, 0.5}, {0.5, 0.5}, {0.5, -0.5}, std::sqrt(0.5)), "ends on two corners");
  // Tangent to the top side from inside and to the bottom side from outside.
  expect_exact(conic_region({-2.0, 0.0}, {0.0, 1.0}, {2.0, 0.0}, 1.0), "apex on y = 1/2");
  expect_exact(conic_region({-2.0, -1.0}, {0.0, 0.0}, {2.0, -1.0}, 1.0), "apex on y = -1/2");
  // A heavy hyperbola hugging its control polygon through a corner.
  expect_exact(conic_region({-1.5, 0.5}, {0.5, 0.5}, {0.5, -1.5}, 1000.0), "w 1000 through a corner");
  // A tiny arc, 1e-7 px long.
  expect_exact(conic_region({0.2, 0.2}, {0.2 + 5e-8, 0.2 + 1e-7}, {0.2 + 1e-7, 0.2}, 0.5), "arc of 1e-7 px");
}

// Each of the first `glyphs` glyphs of `font` without cubics that has bands:
// visit(id, outline, mesh, its boundary pieces, its bands).
template <class Visit>
void for_each_banded_glyph(const Font& font, std::uint32_t glyphs, Visit&& visit) {
  gpu::BandScratch scratch;
  gpu::GlyphBands bands;
  Mesh mesh;
  std::vector<BandPiece> pieces;
  for (std::uint32_t id = 0; id < std::min(font.glyph_count(), glyphs); ++id) {
    const Outline outline = font.glyph_outline(id);
    if (outline.empty() || outline.has_cubics()) continue;
    build_mesh(outline, {}, mesh);
    gpu::boundary_pieces(mesh, pieces);
    gpu::build_bands(mesh, bands, scratch);
    if (!bands.empty()) visit(id, outline, mesh, pieces, bands);
  }
}

// The worst figures over a font's glyphs: the pixels' sum against the
// glyph's area (relative), a pixel against the union sweep's exact coverage
// and against the general per-piece integral; printed, and held to their bounds.
struct Worst {
  double area = 0.0, pixel = 0.0, general = 0.0;
  void expect(const std::string& what, bool per_pixel) const {
    std::printf("%s: worst relative area %.3g, pixel vs union sweep %.4f, vs double %.3g\n", what.c_str(), area, pixel,
                general);
    EXPECT_LT(area, 2e-5) << what;
    if (per_pixel) {
      EXPECT_LT(pixel, 0.004) << what;   // the sweep's own bound is 0.003
      EXPECT_LT(general, 1e-4) << what;  // float texels against double pieces
    }
  }
};

// A mesh's boundary pieces enclose its area, and every pixel of a grid over
// each glyph of DejaVu Sans and Noto Sans (overlapping contours: Inter
// variable) adds up to it through the packed bands; at 24 px each pixel of
// the first 400 glyphs is within the union sweep's 0.003 of its exact
// coverage.
void check_font(const char* path, double px_per_em, bool per_pixel, std::uint32_t glyphs = 1u << 30) {
  const Font font = Font::open(path);
  const double scale = px_per_em / font.metrics().units_per_em;
  Worst worst;
  for_each_banded_glyph(
      font, glyphs,
      [&](std::uint32_t id, const Outline& outline, const Mesh& mesh, const std::vector<BandPiece>& pieces,
          const gpu::GlyphBands& bands) {
        double green = 0.0;
        for (const BandPiece& p : pieces) green += gpu::arc_x_dy(p, 0.0, 1.0);
        const double area = mesh_area(mesh);
        EXPECT_NEAR(green, area, 1e-9 * std::max(std::abs(area), 1.0)) << path << " glyph " << id;
        // Pixel (i, j) of a grid over the glyph's box, one pixel of margin.
        const Vec2 half{0.5 / scale, 0.5 / scale};
        const Box& b = bands.box;
        const int w = static_cast<int>((b.max.x - b.min.x) * scale) + 3,
                  h = static_cast<int>((b.max.y - b.min.y) * scale) + 3;
        Outline px = outline;
        for (Contour& c : px.contours())
          for (Segment& s : c.segments)
            for (Vec2& p : s.p) p = Vec2{scale * (p.x - b.min.x) + 1.0, scale * (b.max.y - p.y) + 1.0};
        const test::Coverage exact = per_pixel ? test::union_coverage(px, w, h) : test::Coverage{};
        double sum = 0.0;
        for (int j = 0; j < h; ++j)
          for (int i = 0; i < w; ++i) {
            const Vec2 centre{b.min.x + (i - 0.5) / scale, b.max.y - (j - 0.5) / scale};
            const double c = gpu::band_box_coverage(bands, centre, half);
            sum += c;
            if (per_pixel) {
              worst.pixel = std::max(worst.pixel, std::abs(c - exact.at(i, j)));
              worst.general = std::max(worst.general, std::abs(c - gpu::box_coverage(pieces, centre, half)));
            }
          }
        worst.area = std::max(worst.area, std::abs(sum / (scale * scale) - area) / std::max(area, 1.0));
      });
  worst.expect(std::string(path) + " at " + std::to_string(px_per_em) + " px", per_pixel);
}

TEST(BandArea, EveryGlyphOfDejaVuSans) { check_font(test::kDejaVuSans, 13.0, false); }
TEST(BandArea, DejaVuSansPixelsAgainstUnionSweep) { check_font(test::kDejaVuSans, 24.0, true, 400); }
TEST(BandArea, OverlappingContoursOfInter) { check_font(test::kInterVariable, 17.0, false); }

// Each block of 2 x 2 cells of each grid marked wholly inside (1) or outside
// (0) is so: the exact area of the block inside the glyph (through every
// piece) is the block's area or nothing; every `step`th glyph of DejaVu Sans
// and of Inter (overlapping contours), and both kinds occur.
void check_cells(const char* path, std::uint32_t step) {
  const Font font = Font::open(path);
  gpu::BandScratch scratch;
  gpu::GlyphBands bands;
  Mesh mesh;
  std::vector<BandPiece> pieces;
  double worst = 0.0;
  std::size_t counts[3] = {0, 0, 0};
  for (std::uint32_t id = 0; id < font.glyph_count(); id += step) {
    const Outline outline = font.glyph_outline(id);
    if (outline.empty() || outline.has_cubics()) continue;
    build_mesh(outline, {}, mesh);
    gpu::boundary_pieces(mesh, pieces);
    gpu::build_bands(mesh, bands, scratch);
    if (bands.empty()) continue;
    const Box& b = bands.box;
    const double side = std::max(b.max.x - b.min.x, b.max.y - b.min.y);  // the grids' square
    for (int g = gpu::kGridMinLog2; g <= gpu::kGridMaxLog2; ++g) {
      const int n = 1 << g;
      const Vec2 half{side / n, side / n};  // a block of 2 x 2 cells
      for (int r = 0; r <= n; ++r)
        for (int c = 0; c <= n; ++c) {
          const int state = gpu::block_state(bands, g, c, r);
          ASSERT_LE(state, 2) << path << " glyph " << id;
          ++counts[state];
          if (state == 2) continue;
          const Vec2 centre{b.min.x + c * half.x, b.min.y + r * half.y};
          worst = std::max(worst, std::abs(gpu::box_coverage(pieces, centre, half) - state));
        }
    }
  }
  std::printf("%s: blocks outside %zu, inside %zu, edge %zu; worst |area - state| %.3g\n", path, counts[0], counts[1],
              counts[2], worst);
  EXPECT_LT(worst, 1e-9) << path;
  EXPECT_GT(counts[0], 0u);
  EXPECT_GT(counts[1], 0u);
}

TEST(BandCells, InsideAndOutsideCellsOfDejaVuSans) { check_cells(test::kDejaVuSans, 7); }
TEST(BandCells, InsideAndOutsideCellsOfInter) { check_cells(test::kInterVariable, 3); }

// Under a map that turns the axes the pixel's footprint is a parallelogram
// (gpu::Footprint): the same reference, clipped to its four edges.
std::vector<Vec2> clip_half_plane(const std::vector<Vec2>& poly, Vec2 a, Vec2 d) {
  const auto side = [&](Vec2 p) { return -cross(d, p - a); };  // <= 0: left of the edge, kept
  std::vector<Vec2> out;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Vec2 p = poly[(i + poly.size() - 1) % poly.size()], q = poly[i];
    const double dp = side(p), dq = side(q);
    if ((dp <= 0.0) != (dq <= 0.0)) out.push_back(p + (q - p) * (dp / (dp - dq)));
    if (dq <= 0.0) out.push_back(q);
  }
  return out;
}

double reference_footprint(const std::vector<BandPiece>& pieces, const gpu::Footprint& f) {
  std::vector<Vec2> poly = flatten(pieces);
  const bool ccw = cross(f.u, f.v) >= 0.0;
  const Vec2 u = ccw ? f.u : f.v, v = ccw ? f.v : f.u;
  const Vec2 c[4] = {-0.5 * (u + v), 0.5 * (u - v), 0.5 * (u + v), 0.5 * (v - u)};
  for (int e = 0; e < 4; ++e) poly = clip_half_plane(poly, c[e], c[(e + 1) % 4] - c[e]);
  return polygon_area(poly);
}

struct NamedFootprint {
  const char* name;
  gpu::Footprint f;
};

// Rotations (a hair off the axes, 30 degrees, a quarter turn), skews both
// ways, a flip, and shears so strong that two edges are all but level.
std::vector<NamedFootprint> footprints() {
  const auto rotation = [](double a, double s) {
    return gpu::Footprint{{s * std::cos(a), s * std::sin(a)}, {-s * std::sin(a), s * std::cos(a)}};
  };
  return {{"box", {{1, 0}, {0, 1}}},
          {"rotated 1e-4 rad", rotation(1e-4, 1.0)},
          {"rotated 30 degrees", rotation(0.5235987755982988, 1.3)},
          {"rotated 90 degrees", rotation(1.5707963267948966, 0.8)},
          {"skewed in x", {{1, 0}, {0.7, 1}}},
          {"skewed in y", {{1, -0.4}, {0, 1}}},
          {"flipped and rotated", {{0.9, 0.3}, {0.3, -0.9}}},
          {"near-level edges", {{1.6, 1e-5}, {0.3, 0.6}}},
          {"thin and long", {{2.5, 1.9}, {-0.05, 0.07}}}};
}

void expect_footprint_exact(const Closed& r, const NamedFootprint& nf, const char* what, double tol = 1e-8) {
  const double ref = reference_footprint(r.pieces, nf.f);
  double general = 0.0, monotone = 0.0;
  for (const BandPiece& p : r.pieces) general += gpu::piece_footprint_integral(p, nf.f);
  std::vector<BandPiece> split;
  for (const BandPiece& p : r.pieces) gpu::split_monotone(p, split);
  for (const BandPiece& p : split) monotone += gpu::monotone_piece_footprint_integral(p, nf.f);
  EXPECT_NEAR(general, ref, tol) << what << ", " << nf.name;
  EXPECT_NEAR(monotone, ref, tol) << what << ", " << nf.name << " (monotone pieces)";
}

TEST(BandFootprint, LinesThroughCornersAlongEdgesAndAxes) {
  for (const NamedFootprint& nf : footprints()) {
    const std::array<Vec2, 4> c = {-0.5 * (nf.f.u + nf.f.v), 0.5 * (nf.f.u - nf.f.v), 0.5 * (nf.f.u + nf.f.v),
                                   0.5 * (nf.f.v - nf.f.u)};
    const double r = 3.0 * std::max(nf.f.half().x, nf.f.half().y);
    expect_footprint_exact(polygon({{-r, -r}, {r, -r}, {r, r}, {-r, r}}), nf, "inside a square");
    expect_footprint_exact(polygon({{-r, -r}, {r, -r}, {-r, r}}), nf, "a diagonal through the centre");
    expect_footprint_exact(polygon({c[0], c[2], c[0] + 3.0 * (c[3] - c[0])}), nf, "an edge through two corners");
    expect_footprint_exact(polygon({c[1] - 2.0 * (c[2] - c[1]), c[2] + 2.0 * (c[2] - c[1]), {-r, 0.0}}), nf,
                           "an edge along a side");
    expect_footprint_exact(polygon({{-r, 0.2 * r}, {r, 0.2 * r}, {0, r}}), nf, "a level edge");
    expect_footprint_exact(polygon({{0.1 * r, -r}, {0.1 * r, r}, {-r, 0}}), nf, "an upright edge");
    expect_footprint_exact(polygon({c[1], c[1] + Vec2{1e-7, 0}, c[1] + Vec2{0, 1e-7}}), nf, "1e-7 at a corner");
    expect_footprint_exact(polygon({{0.01, 0.02}, {0.01 + 1e-7, 0.02}, {0.01, 0.02 + 1e-7}}), nf, "1e-7 inside");
    expect_footprint_exact(polygon({{-r, -r}, {0.03, 0.03}, {0.03 + 1e-7, 0.03 + 2e-7}, {-r, r}}), nf,
                           "an edge of 1e-7");
  }
}

TEST(BandFootprint, ConicsOfAllWeights) {
  std::mt19937 rng(3636);
  std::uniform_real_distribution<double> u(-1.8, 1.8);
  for (const NamedFootprint& nf : footprints())
    for (double w : {0.01, 0.1, 0.7071067811865476, 1.0, 1.01, 3.0, 1000.0})
      for (int i = 0; i < 8; ++i) {
        const Vec2 p0{u(rng), u(rng)}, c{u(rng), u(rng)}, p2{u(rng), u(rng)};
        if (std::abs(cross(p2 - p0, c - p0)) < 1e-3) continue;
        char what[96];
        std::snprintf(what, sizeof what, "w %g, case %d", w, i);
        expect_footprint_exact(conic_region(p0, c, p2, w), nf, what);
      }
}

TEST(BandFootprint, ConicsTangentToEdgesAndThroughCorners) {
  for (const NamedFootprint& nf : footprints()) {
    const Vec2 u = nf.f.u, v = nf.f.v;
    const Vec2 c0 = -0.5 * (u + v), c1 = 0.5 * (u - v), c2 = 0.5 * (u + v);
    // A parabola whose apex touches the edge c1 -> c2 (its control point
    // beyond the edge's midpoint: the apex lies halfway to it).
    const Vec2 m = 0.5 * (c1 + c2), out = 0.5 * u;
    expect_footprint_exact(conic_region(m - 2.0 * v, m + out, m + 2.0 * v, 1.0), nf, "apex on an edge");
    // A quarter circle's image and a heavy hyperbola through two corners.
    expect_footprint_exact(conic_region(c0, c1, c2, std::sqrt(0.5)), nf, "ends on two corners");
    expect_footprint_exact(conic_region(c0 - u, c1, c2 + v, 1000.0), nf, "w 1000 through a corner");
    expect_footprint_exact(conic_region(c1, c1 + 5e-8 * (u + v), c1 + 1e-7 * u, 0.5), nf, "arc of 1e-7 at a corner");
  }
}

// Glyphs under rotation and skew (pixel units from outline units: `map`,
// affine): through the packed bands, each pixel's parallelogram, the pixels
// add up to the glyph's area times |det map|, and at 20 px each pixel is
// within the union sweep's bound of the exact coverage of the glyph drawn
// under the map, and within float rounding of the general integral.
void check_footprint_font(const char* path, double px_per_em, double angle, double skew, std::uint32_t glyphs,
                          bool per_pixel) {
  const Font font = Font::open(path);
  const double s = px_per_em / font.metrics().units_per_em;
  // map = scale * rotation * skew (x += skew y), y up in both.
  const double ca = std::cos(angle), sa = std::sin(angle);
  const double m00 = s * ca, m01 = s * (ca * skew - sa), m10 = s * sa, m11 = s * (sa * skew + ca);
  const double det = m00 * m11 - m01 * m10;
  const gpu::Footprint f{{m11 / det, -m10 / det}, {-m01 / det, m00 / det}};  // the inverse's columns
  Worst worst;
  for_each_banded_glyph(font, glyphs,
                        [&](std::uint32_t, const Outline& outline, const Mesh& mesh,
                            const std::vector<BandPiece>& pieces, const gpu::GlyphBands& bands) {
                          // The pixels (image y down) over the map of the glyph's box, a pixel of margin.
                          const Box& b = bands.box;
                          Box image;
                          for (Vec2 c : {b.min, b.max, Vec2{b.min.x, b.max.y}, Vec2{b.max.x, b.min.y}})
                            image.add({m00 * c.x + m01 * c.y, m10 * c.x + m11 * c.y});
                          const double x0 = std::floor(image.min.x) - 1.0, y1 = std::ceil(image.max.y) + 1.0;
                          const int w = static_cast<int>(std::ceil(image.max.x) + 1.0 - x0),
                                    h = static_cast<int>(y1 - std::floor(image.min.y) + 1.0);
                          Outline px = outline;
                          for (Contour& c : px.contours())
                            for (Segment& seg : c.segments)
                              for (Vec2& p : seg.p) p = Vec2{m00 * p.x + m01 * p.y - x0, y1 - (m10 * p.x + m11 * p.y)};
                          const test::Coverage exact = per_pixel ? test::union_coverage(px, w, h) : test::Coverage{};
                          double sum = 0.0;
                          for (int j = 0; j < h; ++j)
                            for (int i = 0; i < w; ++i) {
                              const Vec2 q{x0 + i + 0.5, y1 - j - 0.5};  // the pixel's centre, y up
                              const Vec2 centre{(m11 * q.x - m01 * q.y) / det, (m00 * q.y - m10 * q.x) / det};
                              const double c = gpu::band_footprint_coverage(bands, centre, f);
                              sum += c;
                              if (per_pixel) {
                                worst.pixel = std::max(worst.pixel, std::abs(c - exact.at(i, j)));
                                worst.general =
                                    std::max(worst.general, std::abs(c - gpu::footprint_coverage(pieces, centre, f)));
                              }
                            }
                          const double area = mesh_area(mesh);
                          worst.area = std::max(worst.area, std::abs(sum / std::abs(det) - area) / std::max(area, 1.0));
                        });
  worst.expect(std::string(path) + " at " + std::to_string(px_per_em) + " px, rotated " + std::to_string(angle) +
                   " rad, skew " + std::to_string(skew),
               per_pixel);
}

TEST(BandFootprint, RotatedGlyphsOfDejaVuSans) { check_footprint_font(test::kDejaVuSans, 13.0, 0.4, 0.0, 600, false); }
TEST(BandFootprint, SkewedGlyphsOfInter) { check_footprint_font(test::kInterVariable, 15.0, 0.0, 0.35, 300, false); }
TEST(BandFootprint, RotatedSkewedPixelsAgainstUnionSweep) {
  check_footprint_font(test::kDejaVuSans, 20.0, -1.1, 0.25, 120, true);
}

}  // namespace
}  // namespace curvetext
