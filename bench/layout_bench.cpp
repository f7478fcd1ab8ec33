// Paragraph layout speed against Pango (pangoft2) on the same texts, font
// file, size and width, in one run; and, with --check-breaks, a comparison of
// where the two break lines (run by CTest as layout_pango_breaks).
//
//   build/bench/layout_bench                 paragraphs/s for both, and the ratio
//   build/bench/layout_bench --check-breaks  line starts, ours vs Pango's
//
// Both lay out from scratch each time (text set, itemised, shaped, broken);
// both keep their font caches warm (a FontCollection / a PangoFontMap), as an
// application would.
#include <pango/pangoft2.h>

#include <algorithm>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "curvetext/layout.hpp"

namespace {

constexpr const char* kFontFile = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
constexpr const char* kFontFamily = "DejaVu Sans";  // fontconfig resolves it to kFontFile
constexpr double kSize = 16.0;
constexpr double kWidth = 420.0;

const std::vector<std::string>& english() {
  static const std::vector<std::string> t = {
      "It was the best of times, it was the worst of times, it was the age of wisdom, it was the age of foolishness, "
      "it was the epoch of belief, it was the epoch of incredulity, it was the season of Light, it was the season of "
      "Darkness, it was the spring of hope, it was the winter of despair.",
      "A text layout engine takes a paragraph and a width and returns positioned glyphs: it itemises the text by "
      "direction, script and font, shapes each item, finds the line break opportunities of UAX #14, and fills lines "
      "greedily, re-shaping only where a break falls inside a shaping context (e.g. a ligature or a kerning pair).",
      "The quick brown fox jumps over the lazy dog; pack my box with five dozen liquor jugs! How vexingly quick daft "
      "zebras jump - sphinx of black quartz, judge my vow. 1,234.56 dollars (about 1.2e3) were paid on 2023-05-04 at "
      "10:30 a.m.; see https://example.com/some/long/path?query=value&other=thing for details.",
      "Well-known, state-of-the-art, user-friendly tools \"quote\" their sources [1], (2) and {3}; others don't. "
      "Mr. Smith's well-being - and his co-workers' - was, in a word, non-negotiable.",
  };
  return t;
}

const std::vector<std::string>& german() {
  static const std::vector<std::string> t = {
      "Die Donaudampfschifffahrtsgesellschaftskapitänsmütze liegt auf dem Tisch, während draußen die "
      "Straßenbahn über die Brücke fährt und die Kinder im Schnee spielen.",
      "Überall dieselbe alte Leier: Das Wetter ist schlecht, die Bahn ist verspätet, und der Kaffee ist kalt. "
      "Trotzdem gehen wir jeden Morgen um halb acht ins Büro – zumindest die meisten von uns.",
      "Sprachwissenschaftlerinnen untersuchen Zusammensetzungen wie „Rechtsschutzversicherungsgesellschaften“ "
      "oder „Grundstücksverkehrsgenehmigungszuständigkeitsübertragungsverordnung“, die in Wörterbüchern fehlen.",
      "Er sagte: „Wir treffen uns am 3. Oktober um 14:00 Uhr vor dem Rathaus (Eingang B), bringt bitte 20 € mit!“",
  };
  return t;
}

struct PangoSetup {
  PangoFontMap* map = pango_ft2_font_map_new();
  PangoContext* context = nullptr;
  PangoFontDescription* desc = pango_font_description_from_string(kFontFamily);
  PangoSetup() {
    context = pango_font_map_create_context(map);
    // Unrounded positions, as curvetext keeps them.
    pango_context_set_round_glyph_positions(context, FALSE);
    pango_font_description_set_absolute_size(desc, kSize * PANGO_SCALE);
  }
  ~PangoSetup() {
    pango_font_description_free(desc);
    g_object_unref(context);
    g_object_unref(map);
  }
  std::vector<std::size_t> line_starts(const std::string& text, int* lines_out = nullptr) {
    PangoLayout* layout = pango_layout_new(context);
    pango_layout_set_font_description(layout, desc);
    pango_layout_set_width(layout, static_cast<int>(kWidth * PANGO_SCALE));
    pango_layout_set_wrap(layout, PANGO_WRAP_WORD_CHAR);
    pango_layout_set_text(layout, text.data(), static_cast<int>(text.size()));
    std::vector<std::size_t> starts;
    const int n = pango_layout_get_line_count(layout);
    if (lines_out) *lines_out = n;
    if (!lines_out)
      for (int i = 0; i < n; ++i)
        starts.push_back(static_cast<std::size_t>(pango_layout_get_line_readonly(layout, i)->start_index));
    g_object_unref(layout);
    return starts;
  }
};

curvetext::ParagraphStyle style() {
  curvetext::ParagraphStyle s;
  s.default_style.fonts = {kFontFile};
  s.default_style.size_px = kSize;
  s.width = kWidth;
  return s;
}

std::vector<std::size_t> our_starts(curvetext::FontCollection& fonts, const std::string& text) {
  std::vector<std::size_t> starts;
  const curvetext::Paragraph p = curvetext::Paragraph::layout(fonts, text, {}, style());
  for (const auto& l : p.lines()) starts.push_back(l.start);
  return starts;
}

// CPU time of this thread: the machine may be shared, and other processes'
// load should not count against either side.
double thread_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

// Paragraphs per CPU second of one round (at least 0.3 s) of lay_out over texts.
template <typename F>
double round_rate(const std::vector<std::string>& texts, F&& lay_out) {
  std::size_t count = 0;
  const double t0 = thread_seconds();
  double elapsed = 0;
  do {
    for (const std::string& t : texts) lay_out(t);
    count += texts.size();
    elapsed = thread_seconds() - t0;
  } while (elapsed < 0.3);
  return static_cast<double>(count) / elapsed;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}
int check_breaks() {
  curvetext::FontCollection fonts;
  PangoSetup pango;
  int differ = 0, total = 0;
  for (const auto* set : {&english(), &german()})
    for (const std::string& text : *set) {
      ++total;
      const auto ours = our_starts(fonts, text);
      const auto theirs = pango.line_starts(text);
      if (ours == theirs) continue;
      ++differ;
      std::printf("differs: \"%.40s...\"\n", text.c_str());
      auto show = [&](const char* who, const std::vector<std::size_t>& s) {
        std::printf("  %s:", who);
        for (std::size_t k = 1; k < s.size(); ++k) {
          const std::size_t a = s[k] >= 12 ? s[k] - 12 : 0;
          std::printf(" [%zu]...%s|", s[k], text.substr(a, s[k] - a).c_str());
        }
        std::printf("\n");
      };
      show("curvetext", ours);
      show("pango    ", theirs);
    }
  std::printf("line breaks: %d of %d paragraphs identical to Pango's\n", total - differ, total);
  return differ == 0 ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && std::strcmp(argv[1], "--check-breaks") == 0) return check_breaks();
  std::vector<std::string> texts = english();
  texts.insert(texts.end(), german().begin(), german().end());
  curvetext::FontCollection fonts;
  PangoSetup pango;
  std::size_t sink = 0;
  // --profile N: N rounds of curvetext only (for callgrind / perf).
  if (argc > 2 && std::strcmp(argv[1], "--profile") == 0) {
    for (int k = std::atoi(argv[2]); k > 0; --k)
      for (const std::string& t : texts) sink += curvetext::Paragraph::layout(fonts, t, {}, style()).lines().size();
    std::printf("[%zu]\n", sink);
    return 0;
  }
  // Rounds alternate between the two so that a change in machine load hits
  // both alike; each figure is the median of 7 rounds.
  std::vector<double> ours, theirs;
  for (int round = 0; round < 7; ++round) {
    ours.push_back(round_rate(texts, [&](const std::string& t) {
      sink += curvetext::Paragraph::layout(fonts, t, {}, style()).lines().size();
    }));
    theirs.push_back(round_rate(texts, [&](const std::string& t) {
      int n = 0;
      pango.line_starts(t, &n);
      sink += static_cast<std::size_t>(n);
    }));
  }
  const double a = median(ours), b = median(theirs);
  std::printf("layout of %zu paragraphs (%s %.0f px, width %.0f px), per CPU second, median of 7 alternating rounds\n",
              texts.size(), kFontFile, kSize, kWidth);
  std::printf("  curvetext: %10.0f paragraphs/s\n", a);
  std::printf("  pango    : %10.0f paragraphs/s (pangoft2)\n", b);
  std::printf("  ratio    : %.2fx (target >= 2x)   [%zu]\n", a / b, sink % 10);
  return 0;
}
