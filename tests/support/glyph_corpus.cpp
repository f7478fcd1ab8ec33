#include "support/glyph_corpus.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>

#include "curvetext/curves.hpp"
#include "curvetext/error.hpp"
#include "curvetext/lod.hpp"
#include "gpu/bands_es2.hpp"
#include "gpu/batch_impl.hpp"
#include "support/coverage.hpp"
#include "support/union_coverage.hpp"

namespace curvetext::test {
namespace {

// Empty pixels around each glyph's box in its cell: more than the 0.71 px
// growth of full antialiasing's triangles, so neighbouring cells never touch.
constexpr int kCellMarginPx = 2;
// Side of a page made for one glyph too large for a shared page; a glyph
// larger than this at the test size is drawn smaller (px).
constexpr int kMaxSinglePagePx = 4096;

using Clock = std::chrono::steady_clock;

std::int64_t now_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now().time_since_epoch()).count();
}

struct Prepared {
  std::uint32_t glyph = 0;
  Mesh mesh;
  Outline quadratic;  // what the mesh was built from, in font units
  Box box;            // its control box, font units
  // Placement in the page: font units + (dx, dy), then the page's scale.
  double dx = 0.0, dy = 0.0;
  int cell_x = 0, cell_y = 0, cell_w = 0, cell_h = 0;
};

struct Page {
  double scale = 0.0;  // px per font unit
  int width = 0, height = 0;
  std::vector<Prepared> glyphs;
};

void note(CorpusProgress* progress, std::int64_t glyph, int stage) {
  if (!progress) return;
  progress->since_ns.store(now_ns());
  progress->stage.store(stage);
  progress->glyph.store(glyph);
}

// Pseudo-random sub-pixel phase per glyph (golden-ratio sequence), so edges
// fall at every fraction of a pixel across the corpus, not only at whole ones.
double phase(std::uint32_t glyph, double k) {
  const double v = static_cast<double>(glyph) * k;
  return v - std::floor(v);
}

Mesh merge_page(const Page& page, bool drop_a_triangle) {
  Mesh all;
  for (const Prepared& g : page.glyphs) {
    const auto base = static_cast<std::uint32_t>(all.points.size());
    for (const Vec2 p : g.mesh.points) all.points.push_back(Vec2{p.x + g.dx, p.y + g.dy});
    // The deliberately broken mesh loses its largest interior triangle.
    std::size_t skip = g.mesh.triangles.size();
    if (drop_a_triangle && !g.mesh.triangles.empty()) {
      double best = -1.0;
      for (std::size_t i = 0; i < g.mesh.triangles.size(); ++i) {
        const auto& t = g.mesh.triangles[i];
        const double a =
            std::abs(cross(g.mesh.points[t[1]] - g.mesh.points[t[0]], g.mesh.points[t[2]] - g.mesh.points[t[0]]));
        if (a > best) {
          best = a;
          skip = i;
        }
      }
    }
    for (std::size_t i = 0; i < g.mesh.triangles.size(); ++i) {
      if (i == skip) continue;
      const auto& t = g.mesh.triangles[i];
      all.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
    }
    for (CurvedTriangle c : g.mesh.curves) {
      c.p0 += base;
      c.control += base;
      c.p2 += base;
      all.curves.push_back(c);
    }
    for (const auto& l : g.mesh.boundary_lines) all.boundary_lines.push_back({l[0] + base, l[1] + base});
  }
  return all;
}

Coverage crop(const Coverage& image, int x0, int y0, int w, int h) {
  Coverage out(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) out.at(x, y) = image.at(x0 + x, y0 + y);
  return out;
}

// Largest |mean of the signed error over a 3x3 window|.
double blurred_error(const Coverage& result, const Coverage& reference) {
  double worst = 0.0;
  for (int y = 0; y < result.height; ++y)
    for (int x = 0; x < result.width; ++x) {
      double sum = 0.0;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int xx = x + dx, yy = y + dy;
          if (xx < 0 || yy < 0 || xx >= result.width || yy >= result.height) continue;
          sum += static_cast<double>(result.at(xx, yy)) - reference.at(xx, yy);
        }
      worst = std::max(worst, std::abs(sum) / 9.0);
    }
  return worst;
}

// Largest under-coverage along a short line: -(mean of the signed error over
// 5 pixels in a row, column or diagonal), the most negative over the image.
// A crack (a missing sliver triangle) is a line of pixels drawn too light;
// antialiasing errs along lines mostly the other way (sub-pixel strokes and
// narrow gaps drawn too dark) and too light only at points (concave cusps).
double line_deficit(const Coverage& result, const Coverage& reference) {
  constexpr int kSteps[4][2] = {{1, 0}, {0, 1}, {1, 1}, {1, -1}};
  constexpr int kHalf = 2;  // 5 pixels
  double worst = 0.0;
  for (int y = 0; y < result.height; ++y)
    for (int x = 0; x < result.width; ++x)
      for (const auto& d : kSteps) {
        double sum = 0.0;
        for (int k = -kHalf; k <= kHalf; ++k) {
          const int xx = x + k * d[0], yy = y + k * d[1];
          if (xx < 0 || yy < 0 || xx >= result.width || yy >= result.height) continue;
          sum += static_cast<double>(reference.at(xx, yy)) - result.at(xx, yy);
        }
        worst = std::max(worst, sum / (2 * kHalf + 1));
      }
  return worst;
}

// Largest error on "core" pixels: those whose 3x3 neighbourhood is entirely
// outside or entirely inside the reference (no outline within a pixel), where
// antialiasing has nothing to approximate and a right mesh is exact.
double core_error(const Coverage& result, const Coverage& reference) {
  constexpr float kExact = 1e-6f;  // reference values this close to 0 or 1 are 0 or 1
  double worst = 0.0;
  for (int y = 0; y < result.height; ++y)
    for (int x = 0; x < result.width; ++x) {
      bool all_in = true, all_out = true;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int xx = x + dx, yy = y + dy;
          const float r = (xx < 0 || yy < 0 || xx >= result.width || yy >= result.height) ? 0.0f : reference.at(xx, yy);
          all_in = all_in && r >= 1.0f - kExact;
          all_out = all_out && r <= kExact;
        }
      if (all_in || all_out)
        worst = std::max(worst, std::abs(static_cast<double>(result.at(x, y)) - reference.at(x, y)));
    }
  return worst;
}

class Checker {
 public:
  Checker(Renderer& renderer, const Font* font, double units_per_em, const CorpusOptions& options, CorpusResult& result)
      : renderer_(renderer), font_(font), options_(options), result_(result), upem_(units_per_em) {
    scale_ = options.size_px / upem_;
    // The level of detail the glyph cache would use at the test size.
    cubic_tolerance_ = cubic_tolerance_for_lod(lod_for_scale(scale_, upem_), upem_);
  }

  void add(std::uint32_t glyph) {
    ++result_.glyphs;
    note(options_.progress, glyph, 0);
    Prepared g;
    g.glyph = glyph;
    Outline outline;
    try {
      outline = font_->glyph_outline(glyph);
    } catch (const std::exception& e) {
      fail(glyph, std::string("outline: ") + e.what());
      return;
    }
    if (outline.empty()) {
      ++result_.empty;
      return;
    }
    const auto t0 = Clock::now();
    try {
      g.mesh = build_mesh(outline, MeshOptions{cubic_tolerance_});
      g.quadratic = to_quadratic_outline(outline, cubic_tolerance_);
      const MeshCheck check = check_mesh(g.mesh, g.quadratic);
      result_.max_area_error = std::max(result_.max_area_error, check.area_rel_error);
      if (!check.ok()) {
        char numbers[160];
        std::snprintf(numbers, sizeof numbers, " (%zu problems; area mesh %.9g outline %.9g rel error %.3g)",
                      check.problems.size(), check.area_mesh, check.area_outline, check.area_rel_error);
        fail(glyph, "mesh check: " + check.problems.front() + numbers);
      }
    } catch (const std::exception& e) {
      fail(glyph, std::string("build_mesh threw: ") + e.what());
      return;
    }
    const double seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    result_.seconds_mesh += seconds;
    if (seconds > result_.slowest_glyph_seconds) {
      result_.slowest_glyph_seconds = seconds;
      result_.slowest_glyph = glyph;
    }
    if (seconds > options_.max_glyph_seconds) {
      char text[96];
      std::snprintf(text, sizeof text, "mesh build + check took %.2f s (limit %.2f s)", seconds,
                    options_.max_glyph_seconds);
      fail(glyph, text);
    }
    g.box = g.quadratic.control_box();
    if (g.box.empty()) return;
    place(std::move(g));
  }

  void add_case(const MeshCase& c) {
    ++result_.glyphs;
    Prepared g;
    g.glyph = c.id;
    g.mesh = c.mesh;
    g.quadratic = to_quadratic_outline(c.reference, cubic_tolerance_);
    g.box = g.quadratic.control_box();
    if (g.box.empty()) {
      ++result_.empty;
      return;
    }
    place(std::move(g));
  }

  void finish() {
    flush(shared_);
    shared_ = Page{};
  }

 private:
  void fail(std::uint32_t glyph, std::string reason) {
    if (result_.failures.empty() || result_.failures.back().glyph != glyph) ++result_.failed_glyphs;
    result_.failures.push_back({glyph, std::move(reason)});
  }

  // Shelf packing: glyphs left to right in rows; a new page when full.
  void place(Prepared g) {
    const double bw = (g.box.max.x - g.box.min.x) * scale_, bh = (g.box.max.y - g.box.min.y) * scale_;
    const int w = static_cast<int>(std::ceil(bw)) + 2 * kCellMarginPx + 1;
    const int h = static_cast<int>(std::ceil(bh)) + 2 * kCellMarginPx + 1;
    if (w > options_.page_width || h > options_.page_height) {
      // Alone on a page of its own size (drawn smaller if absurdly large).
      Page single;
      const double shrink = std::min(1.0, static_cast<double>(kMaxSinglePagePx) / std::max(w, h));
      single.scale = scale_ * shrink;
      single.width = std::max(1, static_cast<int>(std::ceil(w * shrink)) + 1);
      single.height = std::max(1, static_cast<int>(std::ceil(h * shrink)) + 1);
      position(g, single.scale, 0, 0, single.width, single.height);
      single.glyphs.push_back(std::move(g));
      flush(single);
      return;
    }
    if (shared_.glyphs.empty()) {
      shared_.scale = scale_;
      shared_.width = options_.page_width;
      shared_.height = options_.page_height;
      pen_x_ = pen_y_ = shelf_h_ = 0;
    }
    if (pen_x_ + w > shared_.width) {
      pen_x_ = 0;
      pen_y_ += shelf_h_;
      shelf_h_ = 0;
    }
    if (pen_y_ + h > shared_.height) {
      flush(shared_);
      shared_.glyphs.clear();
      pen_x_ = pen_y_ = shelf_h_ = 0;
    }
    position(g, scale_, pen_x_, pen_y_, w, h);
    pen_x_ += w;
    shelf_h_ = std::max(shelf_h_, h);
    shared_.glyphs.push_back(std::move(g));
  }

  // Offsets in whole font units (exact for integer outlines) putting the
  // glyph's box at the cell's margin plus a sub-pixel phase.
  static void position(Prepared& g, double scale, int x, int y, int w, int h) {
    g.cell_x = x;
    g.cell_y = y;
    g.cell_w = w;
    g.cell_h = h;
    const double left = x + kCellMarginPx + phase(g.glyph, 0.6180339887);
    const double top = y + kCellMarginPx + phase(g.glyph, 0.4142135624);
    // x_px = scale * (x + dx), y_px = -scale * (y + dy) (placement origin 0, 0).
    g.dx = std::round(left / scale - g.box.min.x);
    g.dy = std::round(-top / scale - g.box.max.y);
  }

  void flush(Page& page) {
    if (page.glyphs.empty()) return;
    note(options_.progress, page.glyphs.front().glyph, 1);
    const auto t0 = Clock::now();
    Coverage drawn;
    try {
      const Mesh merged = merge_page(page, options_.drop_a_triangle);
      auto impl = gpu::upload(gpu::pack_mesh(merged));
      // full in one pass from each glyph's curve bands where the context
      // has the band program (as text blocks draw: GLES 3, GL 3.3, GLES 2
      // with highp); the broken mesh through its triangles.
      if (!options_.drop_a_triangle && (gpu::context_instances() || gpu::es2_band_context())) {
        std::vector<const Mesh*> meshes;
        std::vector<Vec2> offsets;
        for (const Prepared& g : page.glyphs) {
          meshes.push_back(&g.mesh);
          offsets.push_back(Vec2{g.dx, g.dy});
        }
        gpu::add_mesh_bands(*impl, meshes, offsets);
      }
      DrawBatch batch = DrawBatchAccess::make(std::move(impl));
      target_.begin(page.width, page.height, Color{1, 1, 1, 1});
      DrawOptions draw;
      draw.antialiasing = AntiAliasing::Full;
      draw.curve_mode = CurveMode::Exact;
      renderer_.draw(batch, Placement{page.scale, 0.0, 0.0}, draw);
      drawn = coverage_from_black_on_white(target_.read_pixels());
    } catch (const std::exception& e) {
      for (const Prepared& g : page.glyphs) fail(g.glyph, std::string("drawing the page threw: ") + e.what());
      return;
    }
    const auto t1 = Clock::now();
    result_.seconds_render += std::chrono::duration<double>(t1 - t0).count();

    Coverage reference(page.width, page.height);
    for (const Prepared& g : page.glyphs) {
      note(options_.progress, g.glyph, 2);
      Outline px = g.quadratic;
      for (Contour& c : px.contours())
        for (Segment& s : c.segments)
          for (Vec2& p : s.p) p = Vec2{page.scale * (p.x + g.dx), -page.scale * (p.y + g.dy)};
      add_union_coverage(px, reference);
      compare_cell(g, drawn, reference);
    }
    result_.seconds_reference += std::chrono::duration<double>(Clock::now() - t1).count();
  }

  void compare_cell(const Prepared& g, const Coverage& drawn, const Coverage& reference) {
    const Coverage got = crop(drawn, g.cell_x, g.cell_y, g.cell_w, g.cell_h);
    const Coverage want = crop(reference, g.cell_x, g.cell_y, g.cell_w, g.cell_h);
    const CoverageStats s = compare(got, want);
    const double blurred = blurred_error(got, want);
    const double core = core_error(got, want);
    const double crack = line_deficit(got, want);
    double ink = 0.0, ink_ref = 0.0;
    for (std::size_t i = 0; i < got.value.size(); ++i) {
      ink += got.value[i];
      ink_ref += want.value[i];
    }
    const double ink_diff = std::abs(ink - ink_ref);
    ++result_.compared;
    result_.sum_edge_mean += s.edge_mean_abs;
    auto worst = [&](double v, double& slot, std::uint32_t& where) {
      if (v > slot) {
        slot = v;
        where = g.glyph;
      }
    };
    worst(s.edge_mean_abs, result_.worst_edge_mean, result_.worst_edge_glyph);
    worst(blurred, result_.worst_blurred, result_.worst_blurred_glyph);
    worst(s.max_abs, result_.worst_pixel, result_.worst_pixel_glyph);
    worst(ink_diff, result_.worst_ink, result_.worst_ink_glyph);
    worst(core, result_.worst_core, result_.worst_core_glyph);
    worst(crack, result_.worst_crack, result_.worst_crack_glyph);
    if (options_.stats)
      std::fprintf(options_.stats, "%u %.5f %.4f %.3f %.3f %.4f %.4f %.4f\n", g.glyph, s.edge_mean_abs, blurred, ink,
                   ink_ref, s.max_abs, core, crack);
    const bool edge_bad = s.edge_mean_abs > kCorpusEdgeMeanLimit, region_bad = blurred > kCorpusBlurredErrorLimit,
               crack_bad = crack > kCorpusCrackLimit;
    const bool failed = edge_bad || region_bad || crack_bad;
    if (!failed && options_.images_of_passing_glyphs) {
      write_comparison((options_.label.empty() ? "corpus" : options_.label) + "-g" + std::to_string(g.glyph), got,
                       want);
    }
    if (failed) {
      char text[320];
      std::snprintf(text, sizeof text,
                    "coverage at %.0f px/em: edge mean %.4f (limit %.3f), 3x3 error %.3f (limit %.2f), "
                    "line deficit %.3f (limit %.2f); ink %.2f vs %.2f px^2, max pixel %.3f, core %.3f",
                    options_.size_px, s.edge_mean_abs, kCorpusEdgeMeanLimit, blurred, kCorpusBlurredErrorLimit, crack,
                    kCorpusCrackLimit, ink, ink_ref, s.max_abs, core);
      // A first guess at the kind of fault, for whoever reads the list.
      const char* kind = region_bad      ? " [a region filled wrongly]"
                         : crack_bad     ? " [a line of pixels too light: crack or faded thin stroke]"
                         : ink > ink_ref ? " [edges too dark: sub-pixel strokes?]"
                                         : " [edges too light]";
      std::string reason = std::string(text) + kind;
      if (images_written_ < options_.max_images) {
        ++images_written_;
        const std::string name = (options_.label.empty() ? "corpus" : options_.label) + "-g" + std::to_string(g.glyph);
        reason += "; images " + write_comparison(name, got, want) + "/" + name + "-*.png";
      }
      fail(g.glyph, reason);
    }
  }

  Renderer& renderer_;
  ImageTarget target_;
  const Font* font_;
  const CorpusOptions& options_;
  CorpusResult& result_;
  double upem_ = 0.0, scale_ = 0.0, cubic_tolerance_ = 0.0;
  Page shared_;
  int pen_x_ = 0, pen_y_ = 0, shelf_h_ = 0;
  int images_written_ = 0;
};

// Failures in glyph order (coverage failures are found a page later), and
// the count of distinct failing glyphs.
void sort_failures(CorpusResult& result) {
  std::stable_sort(result.failures.begin(), result.failures.end(),
                   [](const GlyphFailure& a, const GlyphFailure& b) { return a.glyph < b.glyph; });
  result.failed_glyphs = 0;
  for (std::size_t i = 0; i < result.failures.size(); ++i)
    if (i == 0 || result.failures[i].glyph != result.failures[i - 1].glyph) ++result.failed_glyphs;
}

}  // namespace

CorpusResult check_corpus(Renderer& renderer, const Font& font, const std::vector<std::uint32_t>& glyphs,
                          const CorpusOptions& options) {
  CorpusResult result;
  Checker checker(renderer, &font, font.metrics().units_per_em, options, result);
  for (const std::uint32_t g : glyphs) checker.add(g);
  checker.finish();
  sort_failures(result);
  return result;
}

CorpusResult compare_meshes(Renderer& renderer, double units_per_em, const std::vector<MeshCase>& cases,
                            const CorpusOptions& options) {
  CorpusResult result;
  Checker checker(renderer, nullptr, units_per_em, options, result);
  for (const MeshCase& c : cases) checker.add_case(c);
  checker.finish();
  sort_failures(result);
  return result;
}
std::vector<std::uint32_t> every_nth_glyph(const Font& font, std::uint32_t stride, std::uint32_t first) {
  std::vector<std::uint32_t> ids;
  if (stride == 0) stride = 1;
  for (std::uint32_t g = first; g < font.glyph_count(); g += stride) ids.push_back(g);
  return ids;
}

}  // namespace curvetext::test
