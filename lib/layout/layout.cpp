// Paragraph layout (see layout.hpp for the pipeline, paragraph_builder.hpp
// for where each stage lives): the text decoded, its spans, its paragraphs.

#include "curvetext/layout.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "curvetext/error.hpp"
#include "curvetext/line_break.hpp"
#include "curvetext/tolerances.hpp"
#include "core/format.hpp"
#include "font/utf8.hpp"
#include "layout/paragraph_builder.hpp"
#include "layout/text_classes.hpp"

namespace curvetext {

namespace {

void check_finite(double v, double lo, double hi, const char* what) {
  if (!std::isfinite(v) || v < lo || v > hi)
    throw Error(ErrorCode::InvalidArgument, std::string(what) + " must be between " + detail::format_number(lo) +
                                                " and " + detail::format_number(hi) + ", got " +
                                                detail::format_number(v));
}

void validate_style(const TextStyle& s) {
  if (!std::isfinite(s.size_px) || s.size_px <= 0.0)
    throw Error(ErrorCode::InvalidArgument,
                "size must be a positive number of pixels, got " + detail::format_number(s.size_px));
  check_finite(s.size_px, 0.0, tolerance::kMaxPixelsPerEm, "size (px)");
  check_finite(s.letter_spacing, -1e4, 1e4, "letter spacing (px)");
  check_finite(s.word_spacing, -1e4, 1e4, "word spacing (px)");
}
}  // namespace

void ParagraphBuilder::run(std::string_view text, const std::vector<TextSpan>& spans) {
  decode(text);
  apply_spans(text, spans);
  resolve_styles();
  if (pstyle.max_lines > 0) lines_left = static_cast<std::size_t>(pstyle.max_lines);
  const std::vector<std::pair<std::size_t, std::size_t>> paragraphs = paragraph_ranges();
  for (std::size_t k = 0; k < paragraphs.size() && !stop; ++k) {
    last_paragraph_ = k + 1 == paragraphs.size();
    layout_paragraph(paragraphs[k].first, paragraphs[k].second);
  }
  finish();
  // Grapheme boundaries over the whole text, for carets.
  const std::vector<bool> g = grapheme_starts(cps);
  for (std::size_t i = 0; i < cps.size(); ++i)
    if (g[i]) out.boundaries_.push_back(bytes[i]);
  out.boundaries_.push_back(text.size());
}

// Code points and their byte offsets.
void ParagraphBuilder::decode(std::string_view text) {
  std::size_t off = 0;
  cps.reserve(text.size());
  bytes.reserve(text.size() + 1);
  detail::Utf8Problem problem;
  while (off < text.size()) {
    char32_t c = static_cast<unsigned char>(text[off]);
    if (c < 0x80) {  // ASCII without the decoder's bookkeeping
      cps.push_back(c);
      bytes.push_back(off++);
      continue;
    }
    const std::size_t len = detail::decode_utf8_at(text, off, c, problem);
    if (len == 0)
      throw Error(ErrorCode::InvalidText,
                  "invalid UTF-8 at byte " + std::to_string(problem.offset) + ": " + problem.reason);
    cps.push_back(c);
    bytes.push_back(off);
    off += len;
  }
  bytes.push_back(text.size());
}

// Styles per code point: later spans win.
void ParagraphBuilder::apply_spans(std::string_view text, const std::vector<TextSpan>& spans) {
  style_of.assign(cps.size(), 0);
  for (const TextSpan& span : spans) {
    if (span.start > span.end || span.end > text.size())
      throw Error(ErrorCode::InvalidArgument, "span [" + std::to_string(span.start) + ", " + std::to_string(span.end) +
                                                  ") is outside the text (" + std::to_string(text.size()) + " bytes)");
    const auto at = [&](std::size_t b) { return std::lower_bound(bytes.begin(), bytes.end(), b); };
    const auto s = at(span.start), e = at(span.end);
    if (*s != span.start || *e != span.end)
      throw Error(ErrorCode::InvalidArgument,
                  "span [" + std::to_string(span.start) + ", " + std::to_string(span.end) + ") cuts a UTF-8 sequence");
    validate_style(span.style);
    out.styles_.push_back(span.style);
    for (auto i = s - bytes.begin(); i < e - bytes.begin(); ++i)
      style_of[static_cast<std::size_t>(i)] = out.styles_.size() - 1;
  }
}

// Paragraphs end after a paragraph separator (CR LF counts as one).
std::vector<std::pair<std::size_t, std::size_t>> ParagraphBuilder::paragraph_ranges() const {
  std::vector<std::pair<std::size_t, std::size_t>> paragraphs;
  std::size_t start = 0;
  for (std::size_t i = 0; i < cps.size(); ++i) {
    if (!detail::is_paragraph_separator(cps[i])) continue;
    if (cps[i] == U'\r' && i + 1 < cps.size() && cps[i + 1] == U'\n') ++i;
    paragraphs.push_back({start, i + 1});
    start = i + 1;
  }
  if (start < cps.size() || paragraphs.empty() || (!cps.empty() && detail::is_paragraph_separator(cps.back())))
    paragraphs.push_back({start, cps.size()});
  return paragraphs;
}

Paragraph Paragraph::layout(FontCollection& fonts, std::string_view text, const std::vector<TextSpan>& spans,
                            const ParagraphStyle& style) {
  validate_style(style.default_style);
  check_finite(style.width, 0.0, tolerance::kMaxImageSidePx * 64.0, "width (px)");
  check_finite(style.line_height, 0.0, 100.0, "line height (multiple)");
  check_finite(style.line_height_px, 0.0, 1e6, "line height (px)");
  check_finite(style.first_line_indent, -1e6, 1e6, "first line indent (px)");
  check_finite(style.tab_interval, 0.0, 1e6, "tab interval (px)");
  if (style.max_lines < 0) throw Error(ErrorCode::InvalidArgument, "max lines must be 0 (no limit) or more");
  for (std::size_t i = 0; i < style.tab_stops.size(); ++i) {
    check_finite(style.tab_stops[i], 0.0, 1e6, "tab stop (px)");
    if (i > 0 && style.tab_stops[i] <= style.tab_stops[i - 1])
      throw Error(ErrorCode::InvalidArgument, "tab stops must increase");
  }
  if (text.size() > tolerance::kMaxTextBytes)
    throw Error(ErrorCode::InvalidText, "text of " + std::to_string(text.size()) + " bytes is over the limit of " +
                                            std::to_string(tolerance::kMaxTextBytes) + " bytes");
  if (spans.size() > tolerance::kMaxSpans)
    throw Error(ErrorCode::InvalidArgument,
                std::to_string(spans.size()) + " spans are over the limit of " + std::to_string(tolerance::kMaxSpans));
  Paragraph p;
  p.text_ = std::string(text);
  p.styles_.push_back(style.default_style);
  ParagraphBuilder builder(fonts, style, p);
  builder.run(p.text_, spans);
  return p;
}
}  // namespace curvetext
