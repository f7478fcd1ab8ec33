// Glyph preparation, side by side with the incumbent in one run (docs/design.md
// section 7): curvetext loads a glyph's outline and builds its GPU-ready mesh
// (size independent, once per glyph); an atlas renderer loads the glyph with
// FreeType and renders a 32 px AA bitmap (once per glyph *and size*).
//
// Two tables, both timed the same way (every glyph timed in each of N rounds,
// its fastest time kept, then the median over glyphs):
//   - Latin glyphs (the cmap's glyphs for U+0020..U+024F) of DejaVu Sans, Noto
//     Sans and Nimbus Roman: the measure of the "under 5 us per Latin glyph"
//     target;
//   - every glyph of the same three fonts, plus the first 5,000 glyphs of Noto
//     Sans CJK (face 0 of the .ttc).
// Next to each: mean triangles and GPU bytes per glyph, and the mean atlas
// cell bytes of the same glyphs at 16, 32, 64 and 128 px, computed from the
// bitmaps FreeType really renders (width x rows, 8 bits per pixel).
//
// Run: build/bench/glyph_prep_bench            (Google Benchmark entries, then the tables)
//      build/bench/glyph_prep_bench --tables-only
//      build/bench/glyph_prep_bench --rounds=N  (default 5)
//      build/bench/glyph_prep_bench --warm      (each glyph's rounds back to back instead of
//                                                the glyphs in turn: trained branch predictors)
//      build/bench/glyph_prep_bench --no-bands  (the mesh side without gpu::build_bands: the
//                                                mesh path's own cost, against which the bands' is set)
//      build/bench/glyph_prep_bench --stages    (where the mesh time goes, stage by stage; needs
//                                                a build configured with -DCURVETEXT_STAGE_TIMING=ON)
#include <benchmark/benchmark.h>

#include <ft2build.h>
#include FT_FREETYPE_H

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "curvetext/font.hpp"
#include "curvetext/lod.hpp"
#include "curvetext/mesh.hpp"
#include "gpu/bands.hpp"
#include "gpu/vertex_format.hpp"
#include "tessellate/stage_timing.hpp"

namespace {

struct FontCase {
  const char* name;
  const char* path;
  int face_index = 0;
  unsigned max_glyphs = 0;  // 0: every glyph
  bool latin = true;        // part of the Latin table
};
const FontCase kFonts[] = {
    {"DejaVuSans", "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"},
    {"NotoSans", "/usr/share/fonts/truetype/noto/NotoSans-Regular.ttf"},
    {"NimbusRoman", "/usr/share/fonts/opentype/urw-base35/NimbusRoman-Regular.otf"},
    {"NotoSansCJK", "/usr/share/fonts/opentype/noto/NotoSansCJK-Regular.ttc", 0, 5000, false},
};
constexpr int kAtlasSizes[] = {16, 32, 64, 128};
constexpr int kAtlasSizeCount = sizeof(kAtlasSizes) / sizeof(kAtlasSizes[0]);

// Latin glyphs: those the cmap gives for U+0020..U+024F.
std::vector<unsigned> latin_glyphs(const curvetext::Font& font) {
  std::vector<unsigned> ids;
  for (char32_t c = 0x20; c <= 0x24F; ++c)
    if (unsigned g = font.glyph_for_codepoint(c)) ids.push_back(g);
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  return ids;
}

std::vector<unsigned> all_glyphs(const curvetext::Font& font, unsigned max_glyphs) {
  unsigned n = font.glyph_count();
  if (max_glyphs != 0) n = std::min(n, max_glyphs);
  std::vector<unsigned> ids(n);
  for (unsigned g = 0; g < n; ++g) ids[g] = g;
  return ids;
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

// The stage columns: outline loading, build_mesh's stages, packing.
constexpr int kStageColumns = 2 + curvetext::detail::kMeshStageCount;

struct PrepResult {
  std::size_t glyphs = 0, empty = 0, mesh_faster = 0, ft_errors = 0;
  double mesh_us_median = 0, ft_us_median = 0;
  double mesh_us_mean = 0, ft_us_mean = 0;  // the tail (glyphs with overlapping contours) shows here
  double mean_triangles = 0, mean_gpu_bytes = 0;
  double atlas_bytes[kAtlasSizeCount] = {};         // mean width x rows, 1 byte per pixel
  double atlas_bytes_padded[kAtlasSizeCount] = {};  // the same with 1 px of padding on each side
  double seconds = 0;                               // wall time of the measurement
  // With CURVETEXT_STAGE_TIMING: per stage (outline load, build_mesh's stages,
  // packing) the median over glyphs of each glyph's fastest time, us; and the
  // median of the glyphs' summed stages (timed with the clock reads inside).
  double stage_us[kStageColumns] = {};
  double stage_total_us = 0;
};

struct FtFace {
  FT_Library lib = nullptr;
  FT_Face face = nullptr;
  FtFace(const char* path, int face_index) {
    if (FT_Init_FreeType(&lib) != 0 || FT_New_Face(lib, path, face_index, &face) != 0) {
      std::fprintf(stderr, "glyph_prep_bench: FreeType cannot open %s (face %d)\n", path, face_index);
      std::exit(1);
    }
  }
  ~FtFace() {
    FT_Done_Face(face);
    FT_Done_FreeType(lib);
  }
  FtFace(const FtFace&) = delete;
  FtFace& operator=(const FtFace&) = delete;
};

// Times every glyph `rounds` times and keeps each glyph's fastest time, so the
// median is of per-glyph costs without scheduler noise. The mesh side is what
// the glyph cache pays on a miss: outline load + build_mesh (into a reused
// scratch outline and mesh, as the cache does) + gpu::pack_mesh into a new
// vector + gpu::build_bands (where the context draws full from bands),
// with the cubic tolerance of the 32 px level of detail. The FreeType side is
// what an atlas renderer pays: FT_Load_Glyph + FT_Render_Glyph (AA, 32 px).
// With `warm`, each glyph's rounds run back to back instead (the predictors
// and caches trained on that glyph): the cost of the work itself.
PrepResult measure(const FontCase& fc, const std::vector<unsigned>& glyphs, int rounds, bool warm, bool bands_too) {
  namespace detail = curvetext::detail;
  using clock = std::chrono::steady_clock;
  const auto start = clock::now();
  curvetext::Font font = curvetext::Font::open(fc.path, fc.face_index);
  const double upem = font.metrics().units_per_em;
  const double tolerance = curvetext::cubic_tolerance_for_lod(curvetext::lod_for_scale(32.0 / upem, upem), upem);

  FtFace ft(fc.path, fc.face_index);
  FT_Set_Pixel_Sizes(ft.face, 0, 32);

  std::vector<double> mesh_us(glyphs.size(), 1e300), ft_us(glyphs.size(), 1e300);
  PrepResult r;
  r.glyphs = glyphs.size();
  double triangles = 0, bytes = 0;
  curvetext::Outline outline;  // reused, as GlyphCache reuses its scratch outline
  curvetext::Mesh mesh;        // and mesh
  curvetext::gpu::PackScratch pack_scratch;
  curvetext::gpu::GlyphBands bands;  // the cache copies them into its band page
  curvetext::gpu::BandScratch band_scratch;
  const std::size_t n = glyphs.size();
  // (Only filled with CURVETEXT_STAGE_TIMING: ticks per glyph and stage.)
  std::vector<double> stage_ticks(detail::kStageTiming ? n * kStageColumns : 0, 1e300);
  std::vector<double> stage_total_ticks(detail::kStageTiming ? n : 0, 1e300);
  std::uint64_t first_tick = 0;
  if constexpr (detail::kStageTiming) first_tick = detail::stage_clock();
  for (std::size_t step = 0; step < n * static_cast<std::size_t>(rounds); ++step) {
    const std::size_t i = warm ? step / static_cast<std::size_t>(rounds) : step % n;
    const bool first_visit = warm ? step % static_cast<std::size_t>(rounds) == 0 : step < n;
    // (The clock reads and the stage bookkeeping exist only in stage-timing
    // builds; elsewhere stage_tick() is a constant 0 and this is the plain
    // sequence.)
    auto stage_tick = [] { return detail::kStageTiming ? detail::stage_clock() : std::uint64_t{0}; };
    std::uint64_t s0 = 0, s1 = 0, s2 = 0, s3 = 0;
    std::size_t packed_bytes = 0;
    auto t0 = clock::now();
    {
      s0 = stage_tick();
      font.glyph_outline(glyphs[i], outline);
      s1 = stage_tick();
      if constexpr (detail::kStageTiming) detail::mesh_stage_ticks() = {};
      curvetext::build_mesh(outline, {tolerance}, mesh);
      s2 = stage_tick();
      curvetext::gpu::PackedMesh packed;  // new, as the cache stores each glyph's own
      curvetext::gpu::pack_mesh(mesh, packed, pack_scratch);
      benchmark::DoNotOptimize(packed.vertices.data());
      benchmark::DoNotOptimize(packed.indices.data());
      packed_bytes = packed.gpu_bytes();
      // The curve bands full draws text from in one pass (GLES 3 / GL 3.3).
      if (bands_too) {
        curvetext::gpu::build_bands(mesh, bands, band_scratch);
        benchmark::DoNotOptimize(bands.texels.data());
      }
      s3 = stage_tick();
    }  // (freed inside the timed span, as the cache would free a replaced mesh)
    auto t1 = clock::now();
    if constexpr (detail::kStageTiming) {
      double* row = stage_ticks.data() + i * kStageColumns;
      row[0] = std::min(row[0], static_cast<double>(s1 - s0));
      for (int k = 0; k < detail::kMeshStageCount; ++k)
        row[1 + k] = std::min(row[1 + k], static_cast<double>(detail::mesh_stage_ticks().ticks[k]));
      row[kStageColumns - 1] = std::min(row[kStageColumns - 1], static_cast<double>(s3 - s2));
      stage_total_ticks[i] = std::min(stage_total_ticks[i], static_cast<double>(s3 - s0));
    }
    const FT_Error load_error = FT_Load_Glyph(ft.face, glyphs[i], FT_LOAD_DEFAULT);
    const FT_Error render_error = load_error ? load_error : FT_Render_Glyph(ft.face->glyph, FT_RENDER_MODE_NORMAL);
    benchmark::DoNotOptimize(ft.face->glyph->bitmap.buffer);
    auto t2 = clock::now();
    mesh_us[i] = std::min(mesh_us[i], std::chrono::duration<double, std::micro>(t1 - t0).count());
    ft_us[i] = std::min(ft_us[i], std::chrono::duration<double, std::micro>(t2 - t1).count());
    if (first_visit) {
      if (render_error) ++r.ft_errors;
      if (outline.empty()) ++r.empty;
      triangles += static_cast<double>(mesh.triangles.size() + mesh.curves.size());
      bytes += static_cast<double>(packed_bytes);
    }
  }
  for (std::size_t i = 0; i < glyphs.size(); ++i)
    if (mesh_us[i] < ft_us[i]) ++r.mesh_faster;

  // Atlas cells: the bitmaps FreeType renders for the same glyphs (not timed).
  for (int s = 0; s < kAtlasSizeCount; ++s) {
    FT_Set_Pixel_Sizes(ft.face, 0, static_cast<FT_UInt>(kAtlasSizes[s]));
    double raw = 0, padded = 0;
    for (unsigned g : glyphs) {
      if (FT_Load_Glyph(ft.face, g, FT_LOAD_DEFAULT) != 0 ||
          FT_Render_Glyph(ft.face->glyph, FT_RENDER_MODE_NORMAL) != 0)
        continue;
      const double w = ft.face->glyph->bitmap.width, h = ft.face->glyph->bitmap.rows;
      raw += w * h;
      if (w > 0 && h > 0) padded += (w + 2) * (h + 2);
    }
    r.atlas_bytes[s] = raw / static_cast<double>(glyphs.size());
    r.atlas_bytes_padded[s] = padded / static_cast<double>(glyphs.size());
  }

  if constexpr (detail::kStageTiming) {
    // Ticks to microseconds against steady_clock over the whole measurement.
    const double elapsed_us = std::chrono::duration<double, std::micro>(clock::now() - start).count();
    const double ticks_per_us = static_cast<double>(detail::stage_clock() - first_tick) / elapsed_us;
    std::vector<double> column(n);
    for (int k = 0; k < kStageColumns; ++k) {
      for (std::size_t i = 0; i < n; ++i) column[i] = stage_ticks[i * kStageColumns + k] / ticks_per_us;
      r.stage_us[k] = median(column);
    }
    for (std::size_t i = 0; i < n; ++i) column[i] = stage_total_ticks[i] / ticks_per_us;
    r.stage_total_us = median(column);
  }
  r.mesh_us_median = median(mesh_us);
  r.ft_us_median = median(ft_us);
  for (std::size_t i = 0; i < glyphs.size(); ++i) {
    r.mesh_us_mean += mesh_us[i] / static_cast<double>(glyphs.size());
    r.ft_us_mean += ft_us[i] / static_cast<double>(glyphs.size());
  }
  r.mean_triangles = triangles / static_cast<double>(glyphs.size());
  r.mean_gpu_bytes = bytes / static_cast<double>(glyphs.size());
  r.seconds = std::chrono::duration<double>(clock::now() - start).count();
  return r;
}

void print_header() {
  std::printf("%-12s %6s %5s %9s %10s %6s %7s %9s %9s | %7s %7s %7s %7s\n", "font", "glyphs", "empty", "mesh us",
              "FT32 us", "ratio", "faster", "triangles", "GPU bytes", "atl16", "atl32", "atl64", "atl128");
}

void print_row(const char* name, const PrepResult& r) {
  std::printf("%-12s %6zu %5zu %9.2f %10.2f %6.3f %6.1f%% %9.1f %9.0f | %7.0f %7.0f %7.0f %7.0f\n", name, r.glyphs,
              r.empty, r.mesh_us_median, r.ft_us_median, r.ft_us_median / r.mesh_us_median,
              100.0 * static_cast<double>(r.mesh_faster) / static_cast<double>(r.glyphs), r.mean_triangles,
              r.mean_gpu_bytes, r.atlas_bytes[0], r.atlas_bytes[1], r.atlas_bytes[2], r.atlas_bytes[3]);
}

void print_notes(const std::vector<std::pair<const FontCase*, PrepResult>>& rows) {
  std::size_t faster = 0, total = 0;
  for (const auto& [fc, r] : rows) {
    faster += r.mesh_faster;
    total += r.glyphs;
  }
  std::printf("mesh faster than FreeType 32 px on %zu of %zu glyphs (%.1f%%)\n", faster, total,
              total ? 100.0 * static_cast<double>(faster) / static_cast<double>(total) : 0.0);
  std::printf("means over glyphs, us (mesh / FT32; glyphs with overlapping contours weigh on the mesh side):");
  for (const auto& [fc, r] : rows) std::printf(" %s %.2f / %.2f;", fc->name, r.mesh_us_mean, r.ft_us_mean);
  std::printf("\n");
  std::printf("atlas cells with 1 px padding per side (mean bytes, 16/32/64/128 px):");
  for (const auto& [fc, r] : rows)
    std::printf(" %s %.0f/%.0f/%.0f/%.0f;", fc->name, r.atlas_bytes_padded[0], r.atlas_bytes_padded[1],
                r.atlas_bytes_padded[2], r.atlas_bytes_padded[3]);
  std::printf("\n");
  for (const auto& [fc, r] : rows)
    if (r.ft_errors) std::printf("note: FreeType failed to load or render %zu glyphs of %s\n", r.ft_errors, fc->name);
}

// Where the mesh side's time goes (CURVETEXT_STAGE_TIMING builds).
void print_stages(const std::vector<std::pair<const FontCase*, PrepResult>>& rows) {
  std::printf(
      "mesh time by stage, us per glyph (median over glyphs of each glyph's fastest time per stage; the\n"
      "clock reads inside add a little to the mesh column above; sum = sum of the stage medians,\n"
      "total = median of the glyphs' summed stages):\n");
  std::printf("%-12s %9s", "font", "outline");
  for (const char* name : curvetext::detail::kMeshStageNames) std::printf(" %9s", name);
  std::printf(" %9s %9s %9s\n", "pack", "sum", "total");
  for (const auto& [fc, r] : rows) {
    std::printf("%-12s", fc->name);
    double sum = 0;
    for (const double us : r.stage_us) {
      std::printf(" %9.2f", us);
      sum += us;
    }
    std::printf(" %9.2f %9.2f\n", sum, r.stage_total_us);
  }
}

// Google Benchmark entries for the same work (Latin glyphs), for its usual statistics.
void BM_CurvetextMesh(benchmark::State& state, const FontCase* fc) {
  curvetext::Font font = curvetext::Font::open(fc->path, fc->face_index);
  const std::vector<unsigned> glyphs = latin_glyphs(font);
  const double upem = font.metrics().units_per_em;
  const double tolerance = curvetext::cubic_tolerance_for_lod(curvetext::lod_for_scale(32.0 / upem, upem), upem);
  curvetext::Outline outline;
  curvetext::Mesh mesh;
  curvetext::gpu::PackScratch pack_scratch;
  std::size_t i = 0;
  for (auto _ : state) {
    font.glyph_outline(glyphs[i++ % glyphs.size()], outline);
    curvetext::build_mesh(outline, {tolerance}, mesh);
    curvetext::gpu::PackedMesh packed;
    curvetext::gpu::pack_mesh(mesh, packed, pack_scratch);
    benchmark::DoNotOptimize(packed.vertices.data());
    benchmark::DoNotOptimize(packed.indices.data());
  }
  state.SetItemsProcessed(state.iterations());
}

void BM_FreeTypeBitmap32(benchmark::State& state, const FontCase* fc) {
  curvetext::Font font = curvetext::Font::open(fc->path, fc->face_index);
  const std::vector<unsigned> glyphs = latin_glyphs(font);
  FtFace ft(fc->path, fc->face_index);
  FT_Set_Pixel_Sizes(ft.face, 0, 32);
  std::size_t i = 0;
  for (auto _ : state) {
    FT_Load_Glyph(ft.face, glyphs[i++ % glyphs.size()], FT_LOAD_DEFAULT);
    FT_Render_Glyph(ft.face->glyph, FT_RENDER_MODE_NORMAL);
    benchmark::DoNotOptimize(ft.face->glyph->bitmap.buffer);
  }
  state.SetItemsProcessed(state.iterations());
}

}  // namespace

int main(int argc, char** argv) {
  bool tables_only = false, warm = false, stages = false, bands_too = true;
  int rounds = 5;
  std::vector<char*> args;
  for (int i = 0; i < argc; ++i) {
    if (std::strcmp(argv[i], "--tables-only") == 0) {
      tables_only = true;
    } else if (std::strcmp(argv[i], "--warm") == 0) {
      warm = true;
    } else if (std::strcmp(argv[i], "--no-bands") == 0) {
      bands_too = false;
    } else if (std::strcmp(argv[i], "--stages") == 0) {
      stages = true;
    } else if (std::strncmp(argv[i], "--rounds=", 9) == 0) {
      rounds = std::max(1, std::atoi(argv[i] + 9));
    } else {
      args.push_back(argv[i]);
    }
  }
  if (stages && !curvetext::detail::kStageTiming) {
    std::fprintf(stderr,
                 "glyph_prep_bench: --stages needs a build configured with -DCURVETEXT_STAGE_TIMING=ON, e.g.\n"
                 "  cmake -S . -B build-stages -DCURVETEXT_STAGE_TIMING=ON -DCURVETEXT_BUILD_TESTS=OFF &&\n"
                 "  cmake --build build-stages -j2 --target glyph_prep_bench &&\n"
                 "  build-stages/bench/glyph_prep_bench --tables-only --stages\n");
    return 2;
  }
  std::vector<const FontCase*> fonts;
  for (const FontCase& fc : kFonts) {
    if (std::filesystem::exists(fc.path)) {
      fonts.push_back(&fc);
    } else {
      std::printf("skipped %s: %s not installed\n", fc.name, fc.path);
    }
  }

  if (!tables_only) {
    for (const FontCase* fc : fonts) {
      if (!fc->latin) continue;
      benchmark::RegisterBenchmark((std::string("curvetext_mesh/") + fc->name).c_str(), BM_CurvetextMesh, fc);
      benchmark::RegisterBenchmark((std::string("freetype_bitmap32/") + fc->name).c_str(), BM_FreeTypeBitmap32, fc);
    }
    int bench_argc = static_cast<int>(args.size());
    benchmark::Initialize(&bench_argc, args.data());
    benchmark::RunSpecifiedBenchmarks();
  }

  std::printf(
      "\nmesh = outline load + build_mesh + gpu::pack_mesh + gpu::build_bands (cubic tolerance of the 32 px level of "
      "detail);\n"
      "FT32 = FT_Load_Glyph + FT_Render_Glyph, AA, 32 px. Fastest of %d rounds per glyph, median over glyphs;\n"
      "ratio = FT32 / mesh (>= 1: the mesh is prepared at least as fast); faster = share of glyphs whose\n"
      "mesh is faster than their bitmap; triangles, GPU bytes (%zu-byte vertices and 16-bit indices) and\n"
      "atlas cells (atlN: mean FreeType bitmap width x rows at N px, 1 byte per pixel, no padding) are\n"
      "means over all glyphs of the row, empty ones included.%s%s\n",
      rounds, sizeof(curvetext::gpu::Vertex),
      warm ? "\n--warm: each glyph's rounds back to back (predictors and caches trained on it)." : "",
      bands_too ? "" : "\n--no-bands: mesh without gpu::build_bands.");

  std::printf("\nLatin glyphs (U+0020..U+024F)  [target: ratio >= 1.0 and mesh < 5 us]\n");
  print_header();
  std::vector<std::pair<const FontCase*, PrepResult>> latin_rows;
  for (const FontCase* fc : fonts) {
    if (!fc->latin) continue;
    curvetext::Font font = curvetext::Font::open(fc->path, fc->face_index);
    latin_rows.emplace_back(fc, measure(*fc, latin_glyphs(font), rounds, warm, bands_too));
    print_row(fc->name, latin_rows.back().second);
    std::fflush(stdout);
  }
  print_notes(latin_rows);
  if (stages) print_stages(latin_rows);

  std::printf("\nAll glyphs (Noto Sans CJK: face 0, first 5,000 glyphs)  [target: ratio >= 1.0]\n");
  print_header();
  std::vector<std::pair<const FontCase*, PrepResult>> all_rows;
  double seconds = 0;
  for (const FontCase* fc : fonts) {
    curvetext::Font font = curvetext::Font::open(fc->path, fc->face_index);
    all_rows.emplace_back(fc, measure(*fc, all_glyphs(font, fc->max_glyphs), rounds, warm, bands_too));
    print_row(fc->name, all_rows.back().second);
    seconds += all_rows.back().second.seconds;
    std::fflush(stdout);
  }
  print_notes(all_rows);
  if (stages) print_stages(all_rows);
  std::printf("(all-glyphs table measured in %.1f s)\n", seconds);
  return 0;
}
