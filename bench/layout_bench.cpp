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
#include "curvetext/line_break.hpp"

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
      "Prices rose 12% (from $3.50 to $3.92) in Q3/2023 \u2014 see pp. 12\u201314, e.g. \u201cTable 2\u201d \u2013 and "
      "the and/or clause; 50\u00a0km/h limits apply to long-distance lorries on the A1/A7 interchange.",
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
      "Die E-Mail-Adresse, die Ein- und Ausgänge sowie die Haupt- und Nebenstraßen (vgl. S. 4–7, Nr. 12/13) "
      "wurden am 1.\u00a0Januar 2024 im Rahmen des Bund-Länder-Programms „Soziale Stadt“ neu geordnet.",
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
  std::vector<std::size_t> line_starts(const std::string& text, int* lines_out = nullptr, double width = kWidth,
                                       bool hyphens = true) {
    PangoLayout* layout = pango_layout_new(context);
    if (!hyphens) {
      // Pango (>= 1.44) draws a hyphen where it breaks inside a word; off,
      // its emergency breaks follow the same rule as ours.
      PangoAttrList* attrs = pango_attr_list_new();
      pango_attr_list_insert(attrs, pango_attr_insert_hyphens_new(FALSE));
      pango_layout_set_attributes(layout, attrs);
      pango_attr_list_unref(attrs);
    }
    pango_layout_set_font_description(layout, desc);
    pango_layout_set_width(layout, static_cast<int>(width * PANGO_SCALE));
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

curvetext::ParagraphStyle style(double width = kWidth) {
  curvetext::ParagraphStyle s;
  s.default_style.fonts = {kFontFile};
  s.default_style.size_px = kSize;
  s.width = width;
  return s;
}

std::vector<std::size_t> our_starts(curvetext::FontCollection& fonts, const std::string& text, double width) {
  std::vector<std::size_t> starts;
  const curvetext::Paragraph p = curvetext::Paragraph::layout(fonts, text, {}, style(width));
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
// Every paragraph at several widths (more line ends to compare than one
// width gives), against Pango with and without its inserted hyphens.
//  * Hyphens off: every line start must be Pango's.
//  * Hyphens on (Pango's default): differences are allowed only where Pango
//    breaks inside a word too long for the line (not a UAX #14 opportunity):
//    Pango then draws a hyphen and so breaks one character earlier, while
//    curvetext breaks such words without a hyphen (CSS overflow-wrap:
//    break-word). Each such difference is printed.
int check_breaks() {
  curvetext::FontCollection fonts;
  PangoSetup pango;
  int total = 0, breaks = 0, differ_plain = 0, differ_hyphen = 0, unexplained = 0;
  auto show = [](const std::string& text, const char* who, const std::vector<std::size_t>& s) {
    std::printf("  %s:", who);
    for (std::size_t k = 1; k < s.size(); ++k) {
      const std::size_t a = s[k] >= 12 ? s[k] - 12 : 0;
      std::printf(" [%zu]...%s|", s[k], text.substr(a, s[k] - a).c_str());
    }
    std::printf("\n");
  };
  for (const double width : {160.0, 240.0, 330.0, 420.0, 560.0})
    for (const auto* set : {&english(), &german()})
      for (const std::string& text : *set) {
        ++total;
        const auto ours = our_starts(fonts, text, width);
        const auto plain = pango.line_starts(text, nullptr, width, false);
        const auto hyphenated = pango.line_starts(text, nullptr, width, true);
        breaks += static_cast<int>(plain.size()) - 1;
        if (ours != plain) {
          ++differ_plain;
          std::printf("DIFFERS (Pango without hyphens) at width %.0f: \"%.40s...\"\n", width, text.c_str());
          show(text, "curvetext", ours);
          show(text, "pango    ", plain);
        }
        if (ours == hyphenated) continue;
        ++differ_hyphen;
        // The first line start that differs must be a break inside a word.
        std::size_t k = 0;
        while (k < ours.size() && k < hyphenated.size() && ours[k] == hyphenated[k]) ++k;
        bool inside_word = false;
        if (k < hyphenated.size()) {
          gchar* head = g_strndup(text.data(), hyphenated[k]);
          glong n = 0;
          gunichar* cps = g_utf8_to_ucs4_fast(text.c_str(), -1, &n);
          const std::size_t at = static_cast<std::size_t>(g_utf8_strlen(head, -1));
          const std::vector<curvetext::BreakAction> opportunities =
              curvetext::line_breaks(std::u32string(reinterpret_cast<const char32_t*>(cps), static_cast<std::size_t>(n)));
          inside_word = at > 0 && opportunities[at - 1] == curvetext::BreakAction::None;
          g_free(cps);
          g_free(head);
        }
        if (!inside_word) ++unexplained;
        std::printf("%s (Pango's default, hyphen at a break inside a word) at width %.0f: \"%.40s...\"\n",
                    inside_word ? "differs" : "DIFFERS, NOT EXPLAINED", width, text.c_str());
        show(text, "curvetext", ours);
        show(text, "pango    ", hyphenated);
      }
  std::printf("line breaks (widths 160, 240, 330, 420, 560 px; %d Pango line breaks):\n", breaks);
  std::printf("  %d of %d paragraph layouts identical to Pango's with insert-hyphens off\n", total - differ_plain, total);
  std::printf("  %d of %d identical to Pango's default (insert-hyphens on); %d differ only where Pango hyphenates "
              "a word longer than the line, %d unexplained\n",
              total - differ_hyphen, total, differ_hyphen - unexplained, unexplained);
  return differ_plain == 0 && unexplained == 0 ? 0 : 1;
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
