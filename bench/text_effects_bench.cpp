// Text effects (text_effects.hpp): what an outline costs to build, beside the
// plain glyph meshes of the same line (a fresh glyph cache each time, so every
// glyph is built), and what a frame with a shadow costs beside one without.
//   build/bench/text_effects_bench --benchmark_counters_tabular=true
// Figures: docs/strokes.md ("Text effects", "Measured").
#include <benchmark/benchmark.h>

#include <string>

#include "curvetext/font.hpp"
#include "curvetext/headless.hpp"
#include "curvetext/image_target.hpp"
#include "curvetext/shaping.hpp"
#include "curvetext/text_effects.hpp"

namespace {

using namespace curvetext;

constexpr const char* kFont = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
constexpr const char* kText = "The quick brown fox jumps over the lazy dog";

struct Gl {
  HeadlessContext context = HeadlessContext::create(ContextKind::Gles3);
  Renderer renderer;
  Font font = Font::open(kFont);
  ShapedLine line = shape_line(font, kText);
};
Gl& gl() {
  static Gl g;
  return g;
}

// Arg 0: outline width in px at 32 px/em (0: the glyph meshes alone).
void BM_BuildLine(benchmark::State& state) {
  Gl& g = gl();
  TextEffects e;
  e.outline_width = static_cast<double>(state.range(0)) / 2.0;
  for (auto _ : state) {
    GlyphCache cache;
    const EffectBatch batch = EffectBatch::from_text(cache, g.font, g.line, 32.0, e);
    benchmark::DoNotOptimize(batch.glyphs().vertex_count());
  }
  state.counters["outline_px"] = e.outline_width;
  state.counters["us_per_glyph"] =
      benchmark::Counter(static_cast<double>(g.line.glyphs.size()),
                         benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_BuildLine)->Arg(0)->Arg(2)->Arg(6)->Arg(12)->Unit(benchmark::kMillisecond);

// Arg 0: shadow blur radius in px (-1: no shadow); the line at 32 px/em in full.
void BM_DrawFrame(benchmark::State& state) {
  Gl& g = gl();
  GlyphCache cache;
  TextEffects e;
  e.outline_width = 2.0;
  if (state.range(0) >= 0) e.shadow = TextShadow{2.0, 2.0, static_cast<double>(state.range(0)), Color{0, 0, 0, 0.6f}};
  const EffectBatch batch = EffectBatch::from_text(cache, g.font, g.line, 32.0, e);
  ImageTarget target;
  target.begin(720, 64, Color{1, 1, 1, 1});
  const Placement at(32.0 / g.font.metrics().units_per_em, 16.0, 44.0);
  for (auto _ : state) {
    batch.draw(g.renderer, at, DrawOptions{});
    (void)target.read_pixels();  // waits for the frame
  }
  state.counters["blur_px"] = static_cast<double>(state.range(0));
}
BENCHMARK(BM_DrawFrame)->Arg(-1)->Arg(0)->Arg(4)->Arg(16)->Unit(benchmark::kMillisecond);

}  // namespace
BENCHMARK_MAIN();
