// Glyph preparation, side by side with the incumbent in one run (DESIGN.md
// section 7): curvetext loads a glyph's outline and builds its GPU-ready mesh
// (size independent, once per glyph); an atlas renderer loads the glyph with
// FreeType and renders a 32 px AA bitmap (once per glyph *and size*).
// Prints per-glyph medians, the ratio, and GPU bytes per glyph next to atlas
// cell bytes. Run: build/bench/glyph_prep_bench
#include <benchmark/benchmark.h>

#include <ft2build.h>
#include FT_FREETYPE_H

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include "curvetext/font.hpp"
#include "curvetext/lod.hpp"
#include "curvetext/mesh.hpp"
#include "gpu/vertex_format.hpp"

namespace {

struct FontCase {
  const char* name;
  const char* path;
};
const FontCase kFonts[] = {
    {"DejaVuSans", "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"},
    {"NotoSans", "/usr/share/fonts/truetype/noto/NotoSans-Regular.ttf"},
    {"NimbusRoman", "/usr/share/fonts/opentype/urw-base35/NimbusRoman-Regular.otf"},
};

// Latin glyphs: those the cmap gives for U+0020..U+024F.
std::vector<unsigned> latin_glyphs(const curvetext::Font& font) {
  std::vector<unsigned> ids;
  for (char32_t c = 0x20; c <= 0x24F; ++c)
    if (unsigned g = font.glyph_for_codepoint(c)) ids.push_back(g);
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  return ids;
}

double median(std::vector<double> v) {
  if (v.empty()) return 0;
  std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
  return v[v.size() / 2];
}

struct PrepResult {
  double mesh_us_median = 0, ft_us_median = 0;
  double mean_triangles = 0, mean_gpu_bytes = 0;
  std::size_t glyphs = 0;
};

// Times every glyph `rounds` times and keeps each glyph's fastest time, so
// the median is of per-glyph costs without scheduler noise.
PrepResult measure(const FontCase& fc, const std::vector<unsigned>& glyphs, int rounds) {
  using clock = std::chrono::steady_clock;
  curvetext::Font font = curvetext::Font::open(fc.path);
  const double upem = font.metrics().units_per_em;
  const double tolerance = curvetext::cubic_tolerance_for_lod(curvetext::lod_for_scale(32.0 / upem, upem), upem);

  FT_Library lib;
  FT_Init_FreeType(&lib);
  FT_Face face;
  FT_New_Face(lib, fc.path, 0, &face);
  FT_Set_Pixel_Sizes(face, 0, 32);

  std::vector<double> mesh_us(glyphs.size(), 1e300), ft_us(glyphs.size(), 1e300);
  PrepResult r;
  r.glyphs = glyphs.size();
  double triangles = 0, bytes = 0;
  std::vector<curvetext::gpu::Vertex> packed;
  for (int round = 0; round < rounds; ++round) {
    for (std::size_t i = 0; i < glyphs.size(); ++i) {
      auto t0 = clock::now();
      const curvetext::Outline outline = font.glyph_outline(glyphs[i]);
      const curvetext::Mesh mesh = curvetext::build_mesh(outline, {tolerance});
      packed.clear();
      curvetext::gpu::pack_mesh(mesh, packed);
      benchmark::DoNotOptimize(packed.data());
      auto t1 = clock::now();
      FT_Load_Glyph(face, glyphs[i], FT_LOAD_DEFAULT);
      FT_Render_Glyph(face->glyph, FT_RENDER_MODE_NORMAL);
      benchmark::DoNotOptimize(face->glyph->bitmap.buffer);
      auto t2 = clock::now();
      mesh_us[i] = std::min(mesh_us[i], std::chrono::duration<double, std::micro>(t1 - t0).count());
      ft_us[i] = std::min(ft_us[i], std::chrono::duration<double, std::micro>(t2 - t1).count());
      if (round == 0) {
        triangles += static_cast<double>(mesh.triangles.size() + mesh.curves.size());
        bytes += static_cast<double>(packed.size() * sizeof(curvetext::gpu::Vertex));
      }
    }
  }
  FT_Done_Face(face);
  FT_Done_FreeType(lib);
  r.mesh_us_median = median(mesh_us);
  r.ft_us_median = median(ft_us);
  r.mean_triangles = triangles / static_cast<double>(glyphs.size());
  r.mean_gpu_bytes = bytes / static_cast<double>(glyphs.size());
  return r;
}

// Google Benchmark entries for the same work, for its usual statistics.
void BM_CurvetextMesh(benchmark::State& state, const FontCase* fc) {
  curvetext::Font font = curvetext::Font::open(fc->path);
  const std::vector<unsigned> glyphs = latin_glyphs(font);
  const double upem = font.metrics().units_per_em;
  const double tolerance = curvetext::cubic_tolerance_for_lod(5, upem);
  std::vector<curvetext::gpu::Vertex> packed;
  std::size_t i = 0;
  for (auto _ : state) {
    const curvetext::Mesh mesh = curvetext::build_mesh(font.glyph_outline(glyphs[i++ % glyphs.size()]), {tolerance});
    packed.clear();
    curvetext::gpu::pack_mesh(mesh, packed);
    benchmark::DoNotOptimize(packed.data());
  }
  state.SetItemsProcessed(state.iterations());
}

void BM_FreeTypeBitmap32(benchmark::State& state, const FontCase* fc) {
  curvetext::Font font = curvetext::Font::open(fc->path);
  const std::vector<unsigned> glyphs = latin_glyphs(font);
  FT_Library lib;
  FT_Init_FreeType(&lib);
  FT_Face face;
  FT_New_Face(lib, fc->path, 0, &face);
  FT_Set_Pixel_Sizes(face, 0, 32);
  std::size_t i = 0;
  for (auto _ : state) {
    FT_Load_Glyph(face, glyphs[i++ % glyphs.size()], FT_LOAD_DEFAULT);
    FT_Render_Glyph(face->glyph, FT_RENDER_MODE_NORMAL);
    benchmark::DoNotOptimize(face->glyph->bitmap.buffer);
  }
  state.SetItemsProcessed(state.iterations());
  FT_Done_Face(face);
  FT_Done_FreeType(lib);
}

}  // namespace

int main(int argc, char** argv) {
  for (const FontCase& fc : kFonts) {
    benchmark::RegisterBenchmark((std::string("curvetext_mesh/") + fc.name).c_str(), BM_CurvetextMesh, &fc);
    benchmark::RegisterBenchmark((std::string("freetype_bitmap32/") + fc.name).c_str(), BM_FreeTypeBitmap32, &fc);
  }
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();

  std::printf("\nGlyph preparation, Latin glyphs (U+0020..U+024F), fastest of 5 rounds per glyph, median over glyphs\n");
  std::printf("%-12s %6s %12s %14s %8s %10s %10s | atlas cell bytes (8-bit): 16px %d, 32px %d, 64px %d, 128px %d\n",
              "font", "glyphs", "mesh us", "FT 32px us", "ratio", "triangles", "GPU bytes", 16 * 16, 32 * 32,
              64 * 64, 128 * 128);
  for (const FontCase& fc : kFonts) {
    curvetext::Font font = curvetext::Font::open(fc.path);
    const PrepResult r = measure(fc, latin_glyphs(font), 5);
    std::printf("%-12s %6zu %12.2f %14.2f %8.2f %10.1f %10.0f\n", fc.name, r.glyphs, r.mesh_us_median,
                r.ft_us_median, r.ft_us_median / r.mesh_us_median, r.mean_triangles, r.mean_gpu_bytes);
  }
  std::printf("ratio = FreeType time / curvetext time (above 1: curvetext prepares a glyph faster)\n");
  return 0;
}
