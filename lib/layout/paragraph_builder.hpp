// Private: the state and stages of Paragraph::layout (a friend of Paragraph),
// one file per stage of its pipeline:
//   layout.cpp         the text, its spans and paragraphs; validation
//   style_shaping.cpp  styles -> font chains, languages, features; shaping
//                      runs into pixel glyphs (font/shaper.hpp)
//   itemize.cpp        script runs, a font per grapheme cluster, items,
//                      advances per code point
//   line_fill.cpp      greedy line filling, broken words, ellipsis
//   line_build.cpp     a line's pieces: slicing items, spacing, tabs,
//                      justification, metrics, runs, cluster boxes; alignment
//   queries.cpp        bounds, grapheme boundaries, selection rectangles
#pragma once

#include <hb.h>

#include <cstddef>
#include <cstdint>
#include <deque>
#include <limits>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "curvetext/bidi.hpp"
#include "curvetext/font_collection.hpp"
#include "curvetext/layout.hpp"
#include "curvetext/line_break.hpp"
#include "font/shaper.hpp"

namespace curvetext {

struct ParagraphBuilder {
  // Widths closer than this (px) count as equal when fitting text.
  static constexpr double kEpsilon = 1e-6;

  // One shaped glyph, paragraph-relative cluster (code point index), px.
  struct Glyph {
    std::uint32_t id = 0;
    std::uint32_t cluster = 0;
    double advance = 0.0, x_offset = 0.0, y_offset = 0.0;
    bool unsafe = false;  // HB_GLYPH_FLAG_UNSAFE_TO_BREAK: re-shape if the text is cut before this cluster
  };

  struct ResolvedStyle {
    std::vector<std::shared_ptr<const Font>> chain;
    hb_language_t language = HB_LANGUAGE_INVALID;
    std::string language_tag;
    std::vector<hb_feature_t> features;
  };

  struct Item {
    std::size_t start = 0, end = 0;  // paragraph code points
    std::uint8_t level = 0;
    hb_script_t script = HB_SCRIPT_COMMON;
    std::shared_ptr<const Font> font;
    std::size_t style = 0;
    std::vector<Glyph> glyphs;  // HarfBuzz order (visual within the item)
  };

  // A piece of a line: a slice of an item, or a synthetic glyph run
  // (ellipsis, hyphen) with start == end.
  struct Piece {
    std::size_t start = 0, end = 0;
    std::uint8_t level = 0;
    std::shared_ptr<const Font> font;
    std::size_t style = 0;
    std::vector<Glyph> glyphs;
    bool synthetic = false;
  };

  // px
  struct LineMetrics {
    double ascent = 0, descent = 0, gap = 0;
  };

  // Fonts by index (a few per paragraph), not a shared_ptr per code point.
  struct UsedFonts {
    std::vector<std::shared_ptr<const Font>> fonts;
    std::size_t index_of(const std::shared_ptr<const Font>& f);
  };
  static constexpr std::size_t kNoFont = static_cast<std::size_t>(-1);

  // Widths of pieces of [a, e) in O(1) each: pen positions from `a` (a tab
  // measured from `a`, where every piece of an ellipsized line is measured
  // from), and per end the last visible code point before it.
  struct PenWidths {
    std::size_t a = 0;
    std::vector<double> pen;               // before code point a + k
    std::vector<std::size_t> visible_end;  // per end a + k: one past the last non-whitespace before it, or a
    // Width of [s, t), trailing whitespace excluded.
    double of(std::size_t s, std::size_t t) const {
      const std::size_t v = s < t ? visible_end[t - a] : a;
      return v > s ? pen[v - a] - pen[s - a] : 0.0;
    }
  };

  // Where a line ends: one past its last code point, and whether a
  // mandatory break ends it.
  struct LineEnd {
    std::size_t end = 0;
    bool mandatory = false;
  };

  FontCollection& fonts;
  const ParagraphStyle& pstyle;
  Paragraph& out;
  std::u32string cps;              // whole text
  std::vector<std::size_t> bytes;  // byte offset of each code point, plus the end
  std::vector<std::size_t> style_of;
  std::deque<ResolvedStyle> resolved_storage;
  std::vector<const ResolvedStyle*> resolved;                    // per style
  std::map<std::string, std::shared_ptr<const Font>> restyled_;  // fontconfig pattern -> face (null: none)
  std::size_t lines_left = std::numeric_limits<std::size_t>::max();
  bool stop = false;
  bool last_paragraph_ = false;
  std::vector<double> line_indent_;  // per line
  double y = 0.0;                    // top of the next line
  // Scratch: one HarfBuzz buffer for every run shaped in this layout.
  mutable detail::Shaper shaper;

  // Per paragraph state.
  std::size_t p0 = 0;  // paragraph start in cps
  std::u32string para, shaped_text;
  BidiParagraph bidi;
  std::vector<bool> grapheme;
  std::vector<BreakAction> breaks;
  std::vector<bool> dictionary_done;  // per code point: Thai dictionary breaks added (lazily)
  std::vector<Item> items;
  std::vector<std::size_t> item_of;
  std::vector<double> advance;  // px per code point in logical order (incl. spacing)

  ParagraphBuilder(FontCollection& f, const ParagraphStyle& s, Paragraph& o) : fonts(f), pstyle(s), out(o) {}

  const TextStyle& style(std::size_t i) const { return out.styles_[i]; }
  std::size_t out_bytes(std::size_t para_index) const { return bytes[p0 + para_index]; }

  // layout.cpp
  void run(std::string_view text, const std::vector<TextSpan>& spans);
  void decode(std::string_view text);
  void apply_spans(std::string_view text, const std::vector<TextSpan>& spans);
  std::vector<std::pair<std::size_t, std::size_t>> paragraph_ranges() const;

  // style_shaping.cpp
  void resolve_styles();
  ResolvedStyle resolve_style(const TextStyle& s);
  std::vector<Glyph> shape(std::size_t a, std::size_t b, std::uint8_t level, hb_script_t script, const Font& font,
                           std::size_t style_index) const;
  std::vector<Glyph> shape_string(const std::u32string& s, const Font& font, std::size_t style_index,
                                  std::uint8_t level) const;
  std::vector<Glyph> to_pixels(std::span<const detail::UnitGlyph> units, const Font& font,
                               std::size_t style_index) const;
  std::vector<Glyph> hyphen_glyphs(const Item& it) const;
  std::vector<Glyph> ellipsis_glyphs(const Item& near) const;
  double space_width(std::size_t style_index) const;

  // itemize.cpp
  void itemize();
  std::vector<hb_script_t> script_runs(std::vector<bool>& neutral) const;
  std::vector<std::uint32_t> choose_fonts(const std::vector<bool>& neutral, UsedFonts& used);
  std::size_t choose_font(std::size_t a, std::size_t b, bool neutral, UsedFonts& used, std::size_t& previous,
                          std::size_t& previous_style, bool& previous_emoji);
  void build_items(const std::vector<hb_script_t>& script, const std::vector<std::uint32_t>& font_of,
                   const UsedFonts& used);
  void add_advances();
  bool covers(const Font& font, std::size_t a, std::size_t b) const;
  std::size_t color_face(std::size_t a, std::size_t b, const ResolvedStyle& r, UsedFonts& used);
  std::shared_ptr<const Font> styled_like(const std::shared_ptr<const Font>& f, const Font& first, std::size_t a,
                                          std::size_t b);

  // line_fill.cpp
  void layout_paragraph(std::size_t start, std::size_t end);
  bool prepare_paragraph(std::size_t start, std::size_t end);
  LineEnd fill_line(std::size_t a, std::size_t content_end, double indent, double avail);
  std::size_t break_word(std::size_t a, std::size_t content_end, double indent, double avail) const;
  void consume_line();
  void emit_simple(std::size_t a, std::size_t b, bool first, bool mandatory, std::size_t n);
  void ellipsize_line(std::size_t a, std::size_t e, std::size_t n, bool first, double avail, bool force);
  PenWidths pen_widths(std::size_t a, std::size_t e) const;
  double line_indent(bool first) const;
  double tab_advance(double x, std::size_t style_index) const;
  double hyphen_width(std::size_t i) const;
  double range_width(std::size_t a, std::size_t b, double x0 = 0.0) const;
  std::size_t paragraph_content_end() const;

  // line_build.cpp
  static std::size_t glyph_bound(const Item& it, std::size_t c);
  static bool safe_cut(const Item& it, std::size_t c);
  std::vector<Glyph> slice(const Item& it, std::size_t a, std::size_t b, std::uint8_t level) const;
  void add_pieces(std::vector<Piece>& pieces, std::size_t a, std::size_t b, const std::vector<std::uint8_t>& lv,
                  std::size_t lv_base) const;
  Piece synthetic(std::vector<Glyph> glyphs, const Item& near, std::uint8_t level, std::size_t at) const;
  static double glyphs_width(const std::vector<Glyph>& g);
  void emit_line(std::vector<Piece> pieces, std::size_t a, std::size_t b, bool first, bool last_of_paragraph,
                 bool mandatory, bool ellipsized, bool hyphenated);
  double apply_spacing(std::vector<Piece>& pieces, double indent) const;
  void space_piece(Piece& p, double& x, double& visible) const;
  LineMetrics line_metrics(const std::vector<Piece>& pieces, std::size_t a) const;
  void place_runs(LayoutLine& line, const std::vector<Piece>& pieces, const std::vector<std::size_t>& order,
                  std::vector<Paragraph::ClusterBox>& boxes) const;
  double justify(std::vector<Piece>& pieces, const std::vector<std::size_t>& order, std::size_t a, std::size_t b,
                 double extra) const;
  bool joins(std::size_t i) const;
  void add_boxes(std::vector<Paragraph::ClusterBox>& boxes, const Piece& p,
                 const std::vector<std::pair<std::uint32_t, std::pair<double, double>>>& clusters) const;
  void finish();
};

}  // namespace curvetext
