// Every glyph of real fonts through build_mesh + check_mesh: DejaVu Sans,
// Noto Sans, Nimbus Roman and the Inter variable font at three weights (whose
// glyphs overlap their own contours all the time). Every glyph, crossing or
// not, must pass all the invariants of docs/design.md section 4; the classifier
// below only reports how many glyphs have crossing contours.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <cstdio>
#include <string>
#include <vector>

#include "curvetext/curves.hpp"
#include "curvetext/error.hpp"
#include "curvetext/font.hpp"
#include "curvetext/mesh.hpp"
#include "support/fonts.hpp"
#include "tessellate/predicates.hpp"

namespace curvetext {
namespace {

struct Piece {
  Vec2 a, b;
  std::size_t contour;
  std::size_t index;  // position along the contour's flattened pieces
  Box box;
};

enum class Contact { None, Touch, Cross };

// Collinear segments sharing a piece of positive length.
bool collinear_overlap(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  if (detail::orient2d(a, b, c) != 0 || detail::orient2d(a, b, d) != 0) return false;
  const Vec2 dir = b - a;
  const double t0 = 0.0, t1 = dot(dir, dir);
  const double u0 = dot(c - a, dir), u1 = dot(d - a, dir);
  return std::min(t1, std::max(u0, u1)) > std::max(t0, std::min(u0, u1));
}

// Whether any two contours of the (quadratic) outline meet, or a contour meets
// itself away from consecutive pieces: Cross for a proper crossing or a
// folding back or a shared stretch of edge, Touch when they only touch. Conics are flattened finely; this
// classifies glyphs for the test, it is not part of the library.
Contact contours_cross_or_touch(const Outline& quadratic) {
  constexpr int kStepsPerConic = 32;
  std::vector<Piece> pieces;
  std::vector<std::size_t> contour_sizes;
  for (std::size_t c = 0; c < quadratic.contours().size(); ++c) {
    std::size_t index = 0;
    for (const Segment& s : quadratic.contours()[c].segments) {
      const int steps = s.kind == Segment::Kind::Line ? 1 : kStepsPerConic;
      Vec2 prev = s.p[0];
      for (int i = 1; i <= steps; ++i) {
        const Vec2 p = i == steps ? s.end() : evaluate(s, static_cast<double>(i) / steps);
        if (p == prev) continue;
        Piece piece{prev, p, c, index++, {}};
        piece.box.add(prev);
        piece.box.add(p);
        pieces.push_back(piece);
        prev = p;
      }
    }
    contour_sizes.push_back(index);
  }
  std::sort(pieces.begin(), pieces.end(), [](const Piece& x, const Piece& y) { return x.box.min.x < y.box.min.x; });
  bool touching = false;
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const Piece& p = pieces[i];
    for (std::size_t j = i + 1; j < pieces.size() && pieces[j].box.min.x <= p.box.max.x; ++j) {
      const Piece& q = pieces[j];
      if (!detail::boxes_overlap(p.box, q.box)) continue;
      if (p.contour == q.contour) {
        const std::size_t n = contour_sizes[p.contour];
        const std::size_t lo = std::min(p.index, q.index), hi = std::max(p.index, q.index);
        const bool adjacent = hi == lo + 1 || (lo == 0 && hi == n - 1);
        if (adjacent) {
          // Consecutive pieces share one end; folding back over each other counts.
          const Vec2 shared = (p.b == q.a) ? p.b : p.a;
          const Vec2 pf = (p.a == shared) ? p.b : p.a, qf = (q.a == shared) ? q.b : q.a;
          if (detail::point_on_segment(shared, pf, qf) || detail::point_on_segment(shared, qf, pf))
            return Contact::Cross;
          continue;
        }
      }
      if (detail::segments_cross_properly(p.a, p.b, q.a, q.b)) return Contact::Cross;
      if (collinear_overlap(p.a, p.b, q.a, q.b)) return Contact::Cross;  // contours overlap along an edge
      if (detail::segments_intersect(p.a, p.b, q.a, q.b)) touching = true;
    }
  }
  return touching ? Contact::Touch : Contact::None;
}

struct CorpusFont {
  const char* name;
  const char* path;
  double cubic_tolerance_per_em;        // cubic tolerance as a fraction of units per em
  float wght = 0.0f;                    // variable fonts: the weight instance (0: default)
  const char* fallback_path = nullptr;  // where Debian's package puts it otherwise
};

// Debian's fonts-inter package installs the variable font here.
constexpr const char* kInterFallback = "/usr/share/fonts/truetype/inter-vf/Inter.var.ttf";

class MeshCorpus : public ::testing::TestWithParam<CorpusFont> {};

TEST_P(MeshCorpus, EveryGlyphPassesTheMeshInvariants) {
  const CorpusFont& spec = GetParam();
  std::string path = spec.path;
  if (!std::filesystem::exists(path) && spec.fallback_path && std::filesystem::exists(spec.fallback_path)) {
    path = spec.fallback_path;
  }
  if (!std::filesystem::exists(path)) GTEST_SKIP() << spec.name << ": font file " << spec.path << " not installed";
  Font font = Font::open(path);
  if (spec.wght > 0.0f) font.set_variations({{"wght", spec.wght}});
  const double tolerance = spec.cubic_tolerance_per_em * font.metrics().units_per_em;
  const MeshOptions options{tolerance};
  constexpr double kMaxSecondsPerGlyph = 1.0;

  std::size_t touching = 0;  // checked like the others: touching is not crossing
  std::size_t glyphs = 0, empty = 0, crossing = 0, crossing_clean = 0, failures = 0, triangles = 0, meshed = 0;
  double max_area_error = 0.0, slowest = 0.0;
  std::vector<double> build_seconds;
  std::vector<std::string> failure_lines;
  const auto start = std::chrono::steady_clock::now();
  for (std::uint32_t gid = 0; gid < font.glyph_count(); ++gid) {
    ++glyphs;
    const Outline outline = font.glyph_outline(gid);
    const Outline quadratic = to_quadratic_outline(outline, tolerance);
    const Contact contact = contours_cross_or_touch(quadratic);
    const bool crosses = contact == Contact::Cross;
    if (contact == Contact::Touch && !outline.empty()) ++touching;
    const auto t0 = std::chrono::steady_clock::now();
    Mesh mesh;
    std::string error;
    try {
      mesh = build_mesh(outline, options);
    } catch (const Error& e) {
      error = e.what();
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    slowest = std::max(slowest, seconds);
    if (!outline.empty()) build_seconds.push_back(seconds);
    if (seconds > kMaxSecondsPerGlyph) {
      ADD_FAILURE() << spec.name << " glyph " << gid << " took " << seconds << " s";
    }
    if (outline.empty()) {
      ++empty;
      continue;
    }
    const MeshCheck check = check_mesh(mesh, quadratic);
    if (crosses) {
      ++crossing;
      if (check.ok() && error.empty()) ++crossing_clean;
    }
    ++meshed;
    triangles += mesh.triangles.size();
    max_area_error = std::max(max_area_error, check.area_rel_error);
    if (!error.empty() || !check.ok()) {
      ++failures;
      if (failure_lines.size() < 25) {
        failure_lines.push_back("glyph " + std::to_string(gid) + ": " +
                                (error.empty() ? check.problems.front() : "threw: " + error) + " (" +
                                std::to_string(check.problems.size()) + " problems)");
      }
    }
  }
  const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::sort(build_seconds.begin(), build_seconds.end());
  const double median = build_seconds.empty() ? 0.0 : build_seconds[build_seconds.size() / 2];
  std::printf(
      "[corpus] %s: %zu glyphs (%zu empty), %zu with crossing/overlapping contours (%zu of them clean), "
      "%zu with touching contours, %zu failures of %zu checked, max area error %.3g, mean triangles %.1f, "
      "build time median %.1f us slowest %.2f ms, total (incl. checks) %.2f s\n",
      spec.name, glyphs, empty, crossing, crossing_clean, touching, failures, meshed, max_area_error,
      meshed ? static_cast<double>(triangles) / static_cast<double>(meshed) : 0.0, median * 1e6, slowest * 1e3, total);
  for (const std::string& line : failure_lines) std::printf("[corpus]   %s\n", line.c_str());
  RecordProperty("glyphs", static_cast<int>(glyphs));
  RecordProperty("crossing", static_cast<int>(crossing));
  RecordProperty("failures", static_cast<int>(failures));
  EXPECT_EQ(failures, 0u);
}

INSTANTIATE_TEST_SUITE_P(
    Fonts, MeshCorpus,
    ::testing::Values(CorpusFont{"DejaVuSans", test::kDejaVuSans, 1.0 / 1000.0},
                      CorpusFont{"NotoSans", test::kNotoSans, 1.0 / 1000.0},
                      CorpusFont{"NimbusRoman", test::kNimbusRoman, 1.0 / 1000.0},
                      CorpusFont{"InterWght100", test::kInterVariable, 1.0 / 1000.0, 100.0f, kInterFallback},
                      CorpusFont{"InterWght400", test::kInterVariable, 1.0 / 1000.0, 400.0f, kInterFallback},
                      CorpusFont{"InterWght900", test::kInterVariable, 1.0 / 1000.0, 900.0f, kInterFallback}),
    [](const ::testing::TestParamInfo<CorpusFont>& param_info) { return std::string(param_info.param.name); });

}  // namespace
}  // namespace curvetext
