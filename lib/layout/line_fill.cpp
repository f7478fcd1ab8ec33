// Paragraph layout, filling lines: greedy at line break opportunities (Thai
// dictionary breaks added where a line must end), a word wider than the line
// broken between grapheme clusters, soft hyphens, tabs, and the last line
// allowed cut with an ellipsis at its start, middle or end
// (paragraph_builder.hpp).

#include <cmath>
#include <limits>
#include <string>

#include "layout/cluster_limit.hpp"
#include "layout/paragraph_builder.hpp"
#include "layout/text_classes.hpp"

namespace curvetext {

void ParagraphBuilder::layout_paragraph(std::size_t start, std::size_t end) {
  if (!prepare_paragraph(start, end)) return;
  const std::size_t n = para.size();
  const std::size_t content_end = paragraph_content_end();
  const bool wrap = pstyle.width > 0;
  const bool one_line_ellipsis = pstyle.ellipsis != Ellipsis::None && wrap && pstyle.max_lines == 0;
  std::size_t a = 0;
  bool first = true;
  while (a < content_end && !stop) {
    const double indent = line_indent(first);
    const double avail = wrap ? pstyle.width - indent : std::numeric_limits<double>::infinity();
    const LineEnd line = fill_line(a, content_end, indent, avail);
    // Lines left: the last one allowed takes the rest of the paragraph (and
    // gets the ellipsis).
    const bool more_after = line.end < content_end || !last_paragraph_;
    const bool last_allowed = lines_left == 1 && more_after;
    if (one_line_ellipsis || last_allowed) {
      if (pstyle.ellipsis != Ellipsis::None) {
        ellipsize_line(a, content_end, n, first, avail, !(line.end < content_end) && last_allowed);
      } else {
        emit_simple(a, line.end, first, line.mandatory, n);
      }
      consume_line();
      if (last_allowed) stop = true;
      break;
    }
    emit_simple(a, line.end, first, line.mandatory, n);
    consume_line();
    first = false;
    a = line.end;
    // Spaces after a mandatory break belong to the next line.
  }
}

// The paragraph's code points [start, end) of the text, their bidi levels,
// grapheme clusters, break opportunities and items. An empty paragraph is
// one empty line, emitted here: returns false then.
bool ParagraphBuilder::prepare_paragraph(std::size_t start, std::size_t end) {
  p0 = start;
  para = cps.substr(start, end - start);
  const std::size_t n = para.size();
  // HarfBuzz sees tabs as spaces (their width is set per line) and control
  // characters as zero width spaces, so neither draws a missing glyph.
  shaped_text = para;
  for (char32_t& c : shaped_text) {
    if (c == U'\t')
      c = U' ';
    else if (c < 0x20 || c == 0x7F || c == 0x85 || c == 0x2028 || c == 0x2029)
      c = 0x200B;
  }
  bidi = resolve_bidi(para, pstyle.direction);
  grapheme = grapheme_starts(para);
  if (const detail::LongCluster c = detail::find_long_cluster(grapheme); c.length > 0)
    detail::throw_long_cluster(c.length, out_bytes(c.start));
  const std::string& lang = resolved[n ? style_of[p0] : 0]->language_tag;
  breaks = line_breaks(para, lang);
  // Thai word breaks are added lazily, where a line must end (see fill_line).
  dictionary_done.assign(n, false);
  if (paragraph_content_end() == 0) {
    items.clear();
    emit_line({}, 0, n, true, true, true, false, false);
    consume_line();
    return false;
  }
  itemize();
  return true;
}

// Greedy: the last opportunity from `a` where the line still fits. The line
// ends somewhere in (best, overflow]; Thai runs there get their dictionary
// word breaks, and the line is measured again. Nothing fits: the first word
// broken.
ParagraphBuilder::LineEnd ParagraphBuilder::fill_line(std::size_t a, std::size_t content_end, double indent,
                                                      double avail) {
  const bool wrap = pstyle.width > 0;
  std::size_t best = 0;
  bool best_mandatory = false;
  for (bool measure = true; measure;) {
    best = 0;
    best_mandatory = false;
    std::size_t overflow = content_end;  // where the line stopped fitting
    double x = indent, visible = indent;
    for (std::size_t i = a; i < content_end; ++i) {
      x += para[i] == U'\t' ? tab_advance(x, style_of[p0 + i]) : advance[i];
      if (!detail::is_whitespace(para[i])) visible = x;
      const bool at_end = i + 1 == content_end;
      const BreakAction action = at_end ? BreakAction::Mandatory : breaks[i];
      // Nothing fits and the word already overflows: it is broken below,
      // its end is not needed (a long word costs one pass, not one per line).
      if (best == 0 && visible - indent > avail + kEpsilon) {
        overflow = i;
        break;
      }
      if (action == BreakAction::None) continue;
      double w = visible - indent;
      if (para[i] == 0xAD && !at_end) w += hyphen_width(i);
      // A line that does not fit ends in (best, i]: that range gets its
      // dictionary breaks, even where the only break left is the
      // mandatory one at the paragraph's end.
      if (w > avail + kEpsilon) {
        overflow = i;
        break;
      }
      best = i + 1;
      best_mandatory = action == BreakAction::Mandatory;
      if (best_mandatory) break;
    }
    measure = wrap && overflow < content_end &&
              add_dictionary_breaks(para, breaks, best > a ? best : a, overflow + 1, dictionary_done);
  }
  if (best == 0) {
    best = break_word(a, content_end, indent, avail);
    best_mandatory = breaks[best - 1] == BreakAction::Mandatory;
  }
  return {best, best_mandatory};
}

// Nothing fits on the line from `a`: the end of the first word broken
// between grapheme clusters (overflow-wrap: break-word), at least one
// cluster; in one pass, the width growing cluster by cluster.
std::size_t ParagraphBuilder::break_word(std::size_t a, std::size_t content_end, double indent, double avail) const {
  std::size_t best = a + 1;
  while (best < content_end && !grapheme[best]) ++best;
  double x = indent, visible = indent;
  for (std::size_t i = a; i < content_end; ++i) {
    x += para[i] == U'\t' ? tab_advance(x, style_of[p0 + i]) : advance[i];
    if (!detail::is_whitespace(para[i])) visible = x;
    const std::size_t cut = i + 1;
    if (cut < content_end && !grapheme[cut]) continue;
    if (cut <= best) continue;
    if (visible - indent > avail + kEpsilon) break;
    best = cut;
    if (breaks[i] != BreakAction::None) break;
  }
  return best;
}

void ParagraphBuilder::consume_line() {
  if (lines_left != std::numeric_limits<std::size_t>::max()) --lines_left;
  if (lines_left == 0) stop = true;
}

void ParagraphBuilder::emit_simple(std::size_t a, std::size_t b, bool first, bool mandatory, std::size_t n) {
  const std::size_t content_end = paragraph_content_end();
  const bool last = b >= content_end;
  const std::size_t text_end = last ? n : b;
  std::vector<std::uint8_t> lv = line_levels(para, bidi, a, text_end);
  std::vector<Piece> pieces;
  add_pieces(pieces, a, b, lv, a);
  bool hyphen = false;
  if (!last && b > a && para[b - 1] == 0xAD) {
    const Item& it = items[item_of[b - 1]];
    pieces.push_back(synthetic(hyphen_glyphs(it), it, it.level, b));
    hyphen = true;
  }
  emit_line(std::move(pieces), a, text_end, first, last, mandatory || last, false, hyphen);
}

ParagraphBuilder::PenWidths ParagraphBuilder::pen_widths(std::size_t a, std::size_t e) const {
  PenWidths w;
  w.a = a;
  w.pen.assign(e - a + 1, 0.0);
  w.visible_end.assign(e - a + 1, a);
  for (std::size_t i = a; i < e; ++i) {
    const double x = w.pen[i - a];
    w.pen[i - a + 1] = x + (para[i] == U'\t' ? tab_advance(x, style_of[p0 + i]) : advance[i]);
    w.visible_end[i - a + 1] = detail::is_whitespace(para[i]) ? w.visible_end[i - a] : i + 1;
  }
  return w;
}

// The last line: the rest of the paragraph [a, e) cut to fit `avail` with
// an ellipsis at the start, middle or end. `force` adds an ellipsis even
// when the text fits (text after it was dropped).
void ParagraphBuilder::ellipsize_line(std::size_t a, std::size_t e, std::size_t n, bool first, double avail,
                                      bool force) {
  const std::vector<std::uint8_t> lv = line_levels(para, bidi, a, e);
  const double full = range_width(a, e);
  std::vector<Piece> pieces;
  if (full <= avail + kEpsilon && !force) {
    add_pieces(pieces, a, e, lv, a);
    emit_line(std::move(pieces), a, n, first, true, true, false, false);
    return;
  }
  std::vector<std::size_t> bounds;  // grapheme boundaries in [a, e]
  for (std::size_t i = a; i < e; ++i)
    if (grapheme[i] || i == a) bounds.push_back(i);
  bounds.push_back(e);
  const PenWidths widths = pen_widths(a, e);
  auto width_of = [&](std::size_t s, std::size_t t) { return widths.of(s, t); };
  const Item& near_start = items[item_of[a]];
  const Item& near_end = items[item_of[e - 1]];
  const std::uint8_t para_level = static_cast<std::uint8_t>(bidi.paragraph_level);
  if (pstyle.ellipsis == Ellipsis::End || (force && pstyle.ellipsis != Ellipsis::Start)) {
    std::vector<Glyph> eg = ellipsis_glyphs(near_end);
    const double room = avail - glyphs_width(eg);
    std::size_t keep = a;
    for (std::size_t k : bounds)
      if (width_of(a, k) <= room + kEpsilon) keep = k;
    if (force && full <= room + kEpsilon) keep = e;
    add_pieces(pieces, a, keep, lv, a);
    pieces.push_back(synthetic(std::move(eg), keep > a ? items[item_of[keep - 1]] : near_end, para_level, keep));
  } else if (pstyle.ellipsis == Ellipsis::Start) {
    std::vector<Glyph> eg = ellipsis_glyphs(near_start);
    const double room = avail - glyphs_width(eg);
    std::size_t keep = e;
    for (std::size_t k = bounds.size(); k-- > 0;)
      if (width_of(bounds[k], e) <= room + kEpsilon) keep = bounds[k];
    pieces.push_back(synthetic(std::move(eg), keep < e ? items[item_of[keep]] : near_start, para_level, keep));
    add_pieces(pieces, keep, e, lv, a);
  } else {
    std::vector<Glyph> eg = ellipsis_glyphs(near_start);
    const double room = avail - glyphs_width(eg);
    // Grow the head and the tail in turn while both fit.
    std::size_t h = 0, t = bounds.size() - 1;  // indices into bounds: head [a, bounds[h]), tail [bounds[t], e)
    bool grew = true, head_turn = true;
    while (grew && h < t) {
      grew = false;
      for (int attempt = 0; attempt < 2 && !grew; ++attempt, head_turn = !head_turn) {
        const std::size_t nh = head_turn ? h + 1 : h, nt = head_turn ? t : t - 1;
        if (nh > nt) continue;
        if (width_of(a, bounds[nh]) + width_of(bounds[nt], e) <= room + kEpsilon) {
          h = nh;
          t = nt;
          grew = true;
        }
      }
    }
    add_pieces(pieces, a, bounds[h], lv, a);
    pieces.push_back(synthetic(std::move(eg), near_start, para_level, bounds[h]));
    add_pieces(pieces, bounds[t], e, lv, a);
  }
  emit_line(std::move(pieces), a, n, first, true, true, true, false);
}

// A negative first-line indent hangs: the first line starts at the edge,
// the others that far in (nothing is drawn outside the box).
double ParagraphBuilder::line_indent(bool first) const {
  const double i = pstyle.first_line_indent;
  if (i >= 0) return first ? i : 0.0;
  return first ? 0.0 : -i;
}

// Pen advance of a tab at pen position x (from the line start).
double ParagraphBuilder::tab_advance(double x, std::size_t style_index) const {
  for (double tab_stop : pstyle.tab_stops)
    if (tab_stop > x + kEpsilon) return tab_stop - x;
  const double last = pstyle.tab_stops.empty() ? 0.0 : pstyle.tab_stops.back();
  double interval = pstyle.tab_interval > 0 ? pstyle.tab_interval : 8.0 * space_width(style_index);
  if (interval <= 0) interval = 1.0;
  const double k = std::floor((x - last) / interval + kEpsilon) + 1.0;
  return last + k * interval - x;
}

double ParagraphBuilder::hyphen_width(std::size_t i) const {
  const Item& it = items[item_of[i]];
  double w = 0;
  for (const Glyph& g : hyphen_glyphs(it)) w += g.advance;
  return w;
}

// Width of [a, b) laid out from pen x0 (tabs depend on it), trailing
// whitespace excluded.
double ParagraphBuilder::range_width(std::size_t a, std::size_t b, double x0) const {
  double x = x0, visible = x0;
  for (std::size_t i = a; i < b; ++i) {
    x += para[i] == U'\t' ? tab_advance(x, style_of[p0 + i]) : advance[i];
    if (!detail::is_whitespace(para[i])) visible = x;
  }
  return visible - x0;
}

std::size_t ParagraphBuilder::paragraph_content_end() const {
  std::size_t e = para.size();
  if (e > 0 && detail::is_paragraph_separator(para[e - 1])) --e;
  if (e > 0 && para[e - 1] == U'\r' && para.size() - e == 1) --e;  // CR LF
  return e;
}

}  // namespace curvetext
