// Test support: the glyph corpus check shared by tests/corpus_coverage_test
// (a representative subset under CTest) and tests/corpus/corpus_run (every
// glyph, driven by scripts/corpus.sh). For each glyph:
//  (a) area identity and the other mesh invariants (check_mesh), with the
//      mesh built for the level of detail of the test size, as drawn;
//  (b) coverage: the glyphs are laid out in a grid, drawn with the real
//      renderer (one DrawBatch::from_mesh per page, `full` antialiasing,
//      exact curves) and compared per pixel, cell by cell, with the exact
//      nonzero-union coverage of the outline the mesh was built from
//      (union_coverage.hpp);
//  (c) time: building and checking one glyph's mesh must stay under a bound.
#pragma once

#include <atomic>
#include <cstdio>
#include <cstdint>
#include <string>
#include <vector>

#include "curvetext/font.hpp"
#include "curvetext/mesh.hpp"
#include "curvetext/renderer.hpp"

namespace curvetext::test {

// --- Stated tolerances of the coverage comparison ------------------------------
// Test size in pixels per em: large enough that stems and counters span
// several pixels (a missing triangle or a filled hole is then a block of
// wrong pixels), small enough that a page holds hundreds of glyphs.
inline constexpr double kCorpusSizePx = 32.0;
// Mean absolute coverage error over a glyph's edge band (pixels where either
// image has 0.02 < c < 0.98, dilated by one). `full` antialiasing measures
// 0.004-0.013 at 12-48 px on text (render_test); per glyph over the corpus
// the median is 0.0037 and p99.9 0.025 (sub-pixel hairlines, acute spikes); a
// glyph whose fill is wrong along an edge (a missing sliver, a stroke left
// out) adds errors near 1 over a run of band pixels.
inline constexpr double kCorpusEdgeMeanLimit = 0.05;
// Largest |3x3 box mean of the signed error| (coverage units). Antialiasing
// errors lie along the outline and are at most about half a pixel, so a 3x3
// window holds at most a line of them: measured at most 0.28 over the
// whole corpus, p99.9 0.15 (a hairline drawn fully dark crossing the window
// gives about 3 x 0.5 / 9 = 0.17). A wrong region of 2x2 pixels or more (a missing
// triangle, a filled hole, an overlap left empty) gives 0.44 to 1.
inline constexpr double kCorpusBlurredErrorLimit = 0.3;
// Largest under-coverage along a line of 5 pixels (row, column or diagonal):
// -(mean signed error). A crack (a missing sliver triangle) or a stroke drawn
// too light is a line of pixels too light; antialiasing errs along lines the
// other way (sub-pixel strokes and narrow gaps too dark) and too light only
// at points (concave cusps). Measured at most 0.22 on DejaVu Sans (p99.9
// 0.24 over the whole corpus); dropping a sliver triangle gives 0.3 to 1.
inline constexpr double kCorpusCrackLimit = 0.3;
// Reported, not limited: the ink difference sum(result) - sum(reference) in
// px^2 and the largest error on pixels with no outline within one pixel
// ("core"). Full AA sums exact per-triangle areas, so what remains comes
// from the arcs' tangent-polygon approximation within a pixel and the
// coverage buffer's 8-bit steps, not from the mesh.
// Bound on building plus checking one glyph's mesh, in seconds (the same as
// `curvetext check`); slower glyphs are reported as failures.
inline constexpr double kCorpusMaxGlyphSeconds = 1.0;

// The glyph being worked on, for a watchdog on another thread.
struct CorpusProgress {
  std::atomic<std::int64_t> glyph{-1};
  std::atomic<std::int64_t> since_ns{0};  // steady_clock, when work on it began
  std::atomic<int> stage{0};              // 0 mesh, 1 render, 2 reference + compare
};

struct CorpusOptions {
  double size_px = kCorpusSizePx;
  double max_glyph_seconds = kCorpusMaxGlyphSeconds;
  int page_width = 1024;   // px
  int page_height = 1024;  // px
  // Images (result, reference, diff) written for at most this many failing
  // glyphs, named <label>-g<id>, in build/test-output.
  int max_images = 20;
  bool images_of_passing_glyphs = false;  // for looking at glyphs that pass
  std::string label;                      // names the font in messages and image names
  CorpusProgress* progress = nullptr;
  // Drop one interior triangle of every mesh before drawing: a deliberately
  // broken mesh, to show that the comparison catches it.
  bool drop_a_triangle = false;
  // When set, one line per compared glyph: id, edge mean, 3x3 error, ink,
  // reference ink, max pixel error (for studying the limits).
  std::FILE* stats = nullptr;
};

struct GlyphFailure {
  std::uint32_t glyph = 0;
  std::string reason;
};

struct CorpusResult {
  std::size_t glyphs = 0;              // examined
  std::size_t empty = 0;               // without contours
  std::size_t compared = 0;            // drawn and compared
  std::vector<GlyphFailure> failures;  // one entry per reason
  std::size_t failed_glyphs = 0;
  double max_area_error = 0.0;  // relative, from check_mesh
  // Worst per-glyph figures and where they occur.
  double worst_edge_mean = 0.0;
  std::uint32_t worst_edge_glyph = 0;
  double worst_blurred = 0.0;
  std::uint32_t worst_blurred_glyph = 0;
  double worst_pixel = 0.0;  // largest single-pixel error (reported, not limited)
  std::uint32_t worst_pixel_glyph = 0;
  double worst_ink = 0.0;  // |ink difference|, px^2
  std::uint32_t worst_ink_glyph = 0;
  double worst_crack = 0.0;
  std::uint32_t worst_crack_glyph = 0;
  double worst_core = 0.0;  // largest error more than a pixel away from the outline
  std::uint32_t worst_core_glyph = 0;
  double sum_edge_mean = 0.0;  // for the mean over glyphs
  double slowest_glyph_seconds = 0.0;
  std::uint32_t slowest_glyph = 0;
  double seconds_mesh = 0.0, seconds_render = 0.0, seconds_reference = 0.0;
};

// Checks `glyphs` of `font` (at its current variations). Needs a current GL
// context (HeadlessContext) behind `renderer`. Never throws for a bad glyph:
// a glyph whose outline, mesh or check throws is a failure.
CorpusResult check_corpus(Renderer& renderer, const Font& font, const std::vector<std::uint32_t>& glyphs,
                          const CorpusOptions& options);

// A mesh to draw and the outline whose exact coverage it must match, both in
// font units (to test the comparison itself with deliberately wrong meshes).
struct MeshCase {
  std::uint32_t id = 0;
  Mesh mesh;
  Outline reference;
};

// Draws the meshes at options.size_px / units_per_em px per unit and compares
// each with its reference (step (b) only).
CorpusResult compare_meshes(Renderer& renderer, double units_per_em, const std::vector<MeshCase>& cases,
                            const CorpusOptions& options);

// Every `stride`-th glyph id from `first`.
std::vector<std::uint32_t> every_nth_glyph(const Font& font, std::uint32_t stride, std::uint32_t first = 0);

}  // namespace curvetext::test
