// Paragraph layout of UTF-8 text (bidi, fallback, line breaking, ellipsis,
// tabs) and, when the first byte says so, the CLI's span markup first
// (tools/curvetext/layout.cpp); then carets, hit tests, selection and
// grapheme boundaries over the result, with the invariants layout.hpp states.
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "curvetext/layout.hpp"
#include "fuzz_support.hpp"

// The markup reader: the library's where it has one, else the CLI's.
#if __has_include("curvetext/markup.hpp")
#include "curvetext/markup.hpp"
#define CURVETEXT_FUZZ_LIBRARY_MARKUP 1
#else
#include "cli.hpp"
#include "layout_options.hpp"
#endif

namespace {

using namespace curvetext;

// The plain text; the spans into `spans`.
std::string read_markup(const std::string& markup, const TextStyle& base, std::vector<TextSpan>& spans) {
#ifdef CURVETEXT_FUZZ_LIBRARY_MARKUP
  MarkupText read = parse_markup(markup, base);
  spans = std::move(read.spans);
  return std::move(read.text);
#else
  try {
    return cli::parse_markup(markup, base, spans);
  } catch (const cli::UsageError& e) {  // <size=...> not a number
    throw Error(ErrorCode::InvalidArgument, e.message);
  }
#endif
}

// Six bytes of options, then the text.
ParagraphStyle style_from(fuzz::Input& in, bool& markup) {
  static const char* const kLanguages[] = {"", "en", "ar", "th", "ja", "zh-Hant", "tr", "x-bad language"};
  ParagraphStyle style;
  const std::uint8_t flags = in.byte();
  markup = flags & 1;
  style.align = static_cast<Align>((flags >> 1) % 6);
  style.ellipsis = static_cast<Ellipsis>((flags >> 4) % 4);
  style.direction = static_cast<BaseDirection>((flags >> 6) % 3);
  const std::uint8_t width = in.byte();
  style.width = width < 8 ? width / 4.0 : width * 2.0;  // 0 (no wrapping), fractions of a px, up to 510 px
  style.default_style.size_px = 1 + in.byte() % 64;
  const std::uint8_t lines = in.byte();
  style.max_lines = lines % 5;
  style.line_height = (lines >> 3) % 4 * 0.5;
  const std::uint8_t spacing = in.byte();
  style.default_style.letter_spacing = static_cast<std::int8_t>(spacing) % 8 * 0.5;
  style.first_line_indent = (spacing >> 4) * 3.0;
  const std::uint8_t language = in.byte();
  style.language = kLanguages[language % 8];
  if (language & 8) style.tab_stops = {10.0, 40.5};
  return style;
}

void check_lines(const Paragraph& p, const ParagraphStyle& style) {
  const auto& lines = p.lines();
  if (lines.empty()) fuzz::fail("no lines");
  // Layout stops after max_lines: the lines then tile a prefix of the text.
  const bool cut = style.max_lines > 0 && lines.size() == static_cast<std::size_t>(style.max_lines);
  if (lines.front().start != 0 || (cut ? lines.back().end > p.text().size() : lines.back().end != p.text().size()))
    fuzz::fail("lines do not tile the text");
  for (std::size_t i = 0; i + 1 < lines.size(); ++i)
    if (lines[i].end != lines[i + 1].start) fuzz::fail("lines do not tile the text");
  for (const LayoutLine& line : lines)
    for (const GlyphRun& run : line.runs)
      for (const PositionedGlyph& g : run.glyphs)
        if (!std::isfinite(g.x) || !std::isfinite(g.y)) fuzz::fail("glyph position not finite");
}

void query(const Paragraph& p) {
  const std::size_t n = p.text().size();
  (void)p.logical_bounds();
  (void)p.ink_bounds();
  for (std::size_t i = 0; i < n;) {
    const std::size_t next = p.next_boundary(i);
    if (next <= i || next > n) fuzz::fail("next_boundary does not advance within the text");
    if (p.previous_boundary(next) != i) fuzz::fail("previous_boundary(next_boundary(i)) != i");
    i = next;
  }
  for (std::size_t i : {std::size_t{0}, n / 3, n / 2, n, n + 5}) {
    const Caret c = p.caret(i);
    if (c.line >= p.lines().size() || !std::isfinite(c.strong_x) || !std::isfinite(c.weak_x))
      fuzz::fail("caret off the lines or not finite");
  }
  const Rect box = p.logical_bounds();
  for (double fx : {-1.0, 0.3, 0.7, 2.0}) {
    const HitResult hit = p.hit_test(box.width * fx, box.height * (1.0 - fx));
    if (hit.index > n || hit.line >= p.lines().size()) fuzz::fail("hit test outside the text");
  }
  (void)p.selection_rects(n / 4, n);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // One collection for the whole run, as an application keeps one: its
  // caches (faces, fallback answers) are bounded by the fonts installed.
  static FontCollection fonts;
  fuzz::Input in(data, size);
  bool markup = false;
  ParagraphStyle style = style_from(in, markup);
  std::string text(in.rest());
  // Markup's <font=...> opens files by path: never device or process files.
  for (const char* dir : {"/dev", "/proc", "/sys"})
    if (text.find(dir) != std::string::npos) return 0;
  try {
    std::vector<TextSpan> spans;
    if (markup) text = read_markup(text, style.default_style, spans);
    const Paragraph p = Paragraph::layout(fonts, text, spans, style);
    check_lines(p, style);
    query(p);
  } catch (const Error&) {
  }
  return 0;
}
