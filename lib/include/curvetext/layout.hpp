// Paragraph layout: UTF-8 text with styled spans -> lines of positioned glyph
// runs, line metrics, bounds, carets, hit testing and selection rectangles.
//
// Pipeline (lib/layout/, one file per stage: paragraph_builder.hpp): paragraphs split at paragraph separators;
// per paragraph the bidi levels (bidi.hpp), script runs (HarfBuzz's Unicode
// data; Common and Inherited characters join their neighbours), a font per
// grapheme cluster (font_collection.hpp: the span's fonts, then fontconfig),
// then items of one level, script, font and style are shaped once with
// HarfBuzz with their paragraph context. Lines are filled greedily at UAX #14
// opportunities (line_break.hpp); a word wider than the line breaks between
// grapheme clusters. A line is cut out of the shaped items by slicing their
// glyphs, and re-shaped only at a cut HarfBuzz marks unsafe to break
// (HB_GLYPH_FLAG_UNSAFE_TO_BREAK). Lines are then reordered visually (L1-L2).
//
// Coordinates: pixels, y down; the layout box's top-left is (0, 0); glyph
// positions are pen positions of the glyph origin on its baseline. Lines
// advance by A - D + line gap of the tallest font on the line (docs/design.md
// section 6), times ParagraphStyle::line_height when set.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "curvetext/bidi.hpp"
#include "curvetext/color.hpp"
#include "curvetext/text_effect_style.hpp"
#include "curvetext/export.hpp"
#include "curvetext/font.hpp"
#include "curvetext/font_collection.hpp"
#include "curvetext/shaping.hpp"

namespace curvetext {

struct TextStyle {
  // Font files or fontconfig family names ("Noto Sans", "DejaVu Serif:bold"),
  // first choice first; the rest and then fontconfig are the fallback. Empty:
  // the default font (DejaVu Sans).
  std::vector<std::string> fonts;
  double size_px = 16.0;
  Color color{0, 0, 0, 1};
  std::vector<Feature> features;
  std::vector<Variation> variations;
  std::string language;         // BCP 47; empty: the paragraph's
  double letter_spacing = 0.0;  // px added after every grapheme cluster
  double word_spacing = 0.0;    // px added to every space
  bool underline = false;
  bool strikethrough = false;
  Color background{0, 0, 0, 0};  // drawn behind the style's runs, line high; transparent: none
  // Outline, centred stroke and shadow of the style's glyphs (drawn by
  // TextBlock; text_effect_style.hpp). Widths in px at size_px.
  TextEffects effects;
};

// A style for the UTF-8 byte range [start, end). Later spans win where spans
// overlap; text outside every span has ParagraphStyle::default_style.
struct TextSpan {
  std::size_t start = 0;
  std::size_t end = 0;
  TextStyle style;
};

enum class Align { Left, Right, Center, Justify, Start, End };
enum class Ellipsis { None, Start, Middle, End };

struct ParagraphStyle {
  TextStyle default_style;
  double width = 0.0;  // px; 0: no wrapping (one line per paragraph)
  Align align = Align::Start;
  BaseDirection direction = BaseDirection::Auto;
  std::string language;         // BCP 47: line breaking tailoring and shaping
  double line_height = 0.0;     // multiple of A - D + gap; 0 is 1
  double line_height_px = 0.0;  // a fixed line advance in px; wins when > 0
  // px; negative: a hanging indent (the first line at the edge, the others that far in)
  double first_line_indent = 0.0;
  std::vector<double> tab_stops;       // px from the line start, increasing
  double tab_interval = 0.0;           // px between default stops after the last; 0: 8 spaces
  int max_lines = 0;                   // 0: unlimited
  Ellipsis ellipsis = Ellipsis::None;  // applies to the last line kept (needs width or max_lines)
};

struct PositionedGlyph {
  std::uint32_t id = 0;
  std::uint32_t cluster = 0;  // UTF-8 byte offset into the paragraph text
  double x = 0.0;             // px, the glyph origin
  double y = 0.0;             // px, the glyph origin (baseline + offset)
  double advance = 0.0;       // px along the line
};

// Glyphs of one font, direction and style on one line, left to right.
struct GlyphRun {
  std::shared_ptr<const Font> font;
  double size_px = 16.0;
  bool rtl = false;
  std::size_t style = 0;           // index into Paragraph::styles()
  std::size_t start = 0, end = 0;  // UTF-8 byte range of the text (the ellipsis run: empty at the cut)
  double x = 0.0, width = 0.0;     // px, the run's pen extent
  std::vector<PositionedGlyph> glyphs;
};

struct Rect {
  double x = 0.0, y = 0.0, width = 0.0, height = 0.0;  // px, layout box coordinates
};

struct LayoutLine {
  std::size_t start = 0, end = 0;                 // UTF-8 byte range; lines tile the text
  double top = 0.0;                               // px
  double baseline = 0.0;                          // px
  double ascent = 0.0, descent = 0.0, gap = 0.0;  // px, descent positive below the baseline
  double height = 0.0;                            // the line advance
  double x = 0.0, width = 0.0;                    // px, the content's extent (trailing spaces excluded)
  int paragraph_level = 0;                        // 1 for a right-to-left paragraph
  bool ellipsized = false;
  bool hyphenated = false;     // ends at a soft hyphen drawn as a hyphen
  std::vector<GlyphRun> runs;  // visual order
};

// Which line a caret position at a soft line break belongs to: the index
// that ends one line also starts the next. Downstream (default): with the
// character after it, at the start of the next line; Upstream: with the
// character before it, at the end of the line it ends (a click past that
// line's end).
enum class CaretAffinity { Downstream, Upstream };

struct CaretPosition {
  std::size_t index = 0;  // UTF-8 offset, a grapheme boundary
  CaretAffinity affinity = CaretAffinity::Downstream;
};

// A caret at a text position: where a character inserted there would go.
// At a bidi boundary the two directions disagree, and there are two carets,
// placed as Pango places them: `strong` where a character of the paragraph's
// direction would go, `weak` where one of the other direction would. With c
// the grapheme before the position and d the one after it: strong is at c's
// trailing edge when c has the paragraph's direction and d has not or is
// embedded deeper (bidi level), else at d's leading edge; weak at the other
// (at a line's ends the line's edge stands in for the missing grapheme).
// They are equal elsewhere.
struct Caret {
  std::size_t line = 0;                 // index into Paragraph::lines()
  double strong_x = 0.0, weak_x = 0.0;  // px
  bool strong_rtl = false, weak_rtl = false;
  double top = 0.0, bottom = 0.0;  // px, the line's
};

struct HitResult {
  std::size_t index = 0;  // UTF-8 offset of the nearest caret position (a grapheme boundary)
  std::size_t line = 0;
  bool inside = false;  // the point is over a grapheme of the text
  // Upstream for a point past the end of a line that wraps softly into the
  // next, so that caret(index, affinity) stays on the line clicked.
  CaretAffinity affinity = CaretAffinity::Downstream;
};

// A laid-out paragraph: an immutable value (copyable) that keeps its own copy
// of the text and, through its runs, the fonts it uses alive; it does not
// refer to the FontCollection after layout. Its const functions may be used
// from several threads at once.
class CURVETEXT_API Paragraph {
 public:
  // Uses `fonts` during the call only (not thread-safe: see
  // font_collection.hpp). Throws Error(InvalidText) for invalid UTF-8, a
  // text over tolerance::kMaxTextBytes or a grapheme cluster over
  // tolerance::kMaxClusterCodePoints (an empty text lays out as one empty
  // line), Error(InvalidArgument) for bad sizes, widths, spans or styles or
  // more than tolerance::kMaxSpans spans, and the font errors of
  // FontCollection. Time and memory are linear in the text (docs/limits.md).
  static Paragraph layout(FontCollection& fonts, std::string_view text, const std::vector<TextSpan>& spans,
                          const ParagraphStyle& style);

  const std::string& text() const { return text_; }
  const std::vector<LayoutLine>& lines() const { return lines_; }  // top to bottom, at least one
  // The default style, then each span's, indexed by GlyphRun::style.
  const std::vector<TextStyle>& styles() const { return styles_; }
  // Union of the lines' boxes (x from 0 to the widest line, or the width).
  Rect logical_bounds() const;
  // Union of the glyphs' outline boxes; empty rect when nothing is inked.
  Rect ink_bounds() const;

  // The caret at UTF-8 offset `index`, clamped to the text and moved back to
  // a grapheme boundary; at a soft line break, on the line `affinity` says.
  Caret caret(std::size_t index, CaretAffinity affinity = CaretAffinity::Downstream) const;
  Caret caret(CaretPosition position) const { return caret(position.index, position.affinity); }
  // The caret position nearest the point (px, layout box coordinates); points
  // above or below the text go to the first or last line.
  HitResult hit_test(double x, double y) const;
  // Rectangles (px), one per visually contiguous piece, covering the UTF-8
  // range [start, end) (swapped when start > end).
  std::vector<Rect> selection_rects(std::size_t start, std::size_t end) const;
  // Grapheme boundaries (for caret movement): the previous/next one, as
  // UTF-8 offsets within [0, text().size()].
  std::size_t previous_boundary(std::size_t index) const;
  std::size_t next_boundary(std::size_t index) const;
  // Visual movement, as arrow keys move: the caret position whose strong
  // caret is next on screen to the right (direction > 0) or left (< 0) of
  // `from`'s, on its line; past the line's end in that direction, the next
  // or previous line's first position that way (the following line when
  // moving in the paragraph's direction). At the paragraph's ends `from`
  // comes back. Walking a line from one end to the other visits every
  // caret x once, monotonically.
  CaretPosition move_visually(CaretPosition from, int direction) const;
  // Word movement (ctrl + arrow): visual moves until the caret stands at a
  // word boundary (UAX #29) after crossing something other than white
  // space, or at a line's end; monotonic on screen as move_visually.
  CaretPosition move_word_visually(CaretPosition from, int direction) const;

 private:
  friend struct ParagraphBuilder;  // lib/layout/paragraph_builder.hpp
  // A grapheme cluster's box on a line, for carets, hit testing and selection.
  struct ClusterBox {
    std::size_t start = 0, end = 0;  // UTF-8 range of the grapheme
    double left = 0.0, right = 0.0;
    bool rtl = false;
    int level = 0;  // bidi embedding level
  };
  std::string text_;
  std::vector<TextStyle> styles_;
  std::vector<LayoutLine> lines_;
  std::vector<std::vector<ClusterBox>> boxes_;  // per line, visual order
  std::vector<std::size_t> boundaries_;         // grapheme starts (bytes), plus text size
  std::size_t line_of(std::size_t index, CaretAffinity affinity) const;
  // The carets of `positions` (grapheme boundaries on `line`), in one pass.
  std::vector<Caret> carets_on(std::size_t line, const std::vector<std::size_t>& positions) const;
  double width_ = 0.0;
};

}  // namespace curvetext
