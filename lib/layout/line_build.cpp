// Paragraph layout, building a line: pieces cut out of the shaped items
// (sliced, or re-shaped where a cut is unsafe), spacing and tabs,
// justification, metrics, glyph runs in visual order and cluster boxes for
// hit testing; then the alignment of every line (paragraph_builder.hpp).

#include <hb.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "layout/paragraph_builder.hpp"
#include "layout/text_classes.hpp"

namespace curvetext {

namespace {

// The line metrics of `font` at `size_px`, in px.
ParagraphBuilder::LineMetrics font_line_metrics(const Font& font, double size_px) {
  const FontMetrics m = font.metrics();
  const double s = size_px / m.units_per_em;
  return {m.ascender * s, -m.descender * s, m.line_gap * s};
}

}  // namespace

// Index of the first glyph (in HarfBuzz order) whose cluster is logically
// at or after code point c. HarfBuzz's default cluster level keeps clusters
// monotonic: increasing for LTR, decreasing for RTL; so the glyphs of any
// code point range are contiguous and found by binary search, not by a
// scan of the whole item per line.
std::size_t ParagraphBuilder::glyph_bound(const Item& it, std::size_t c) {
  const auto& g = it.glyphs;
  if (it.level % 2 == 0)
    return static_cast<std::size_t>(
        std::partition_point(g.begin(), g.end(), [c](const Glyph& x) { return x.cluster < c; }) - g.begin());
  // RTL: glyphs of clusters >= c come first; their end bounds [.., c).
  return static_cast<std::size_t>(
      std::partition_point(g.begin(), g.end(), [c](const Glyph& x) { return x.cluster >= c; }) - g.begin());
}

// Is a cut of item `it` before code point c (start < c < end) safe: c starts
// a cluster and HarfBuzz did not flag that cluster unsafe to break.
bool ParagraphBuilder::safe_cut(const Item& it, std::size_t c) {
  const std::size_t k = glyph_bound(it, c);
  const bool rtl = it.level % 2 == 1;
  // The glyphs of cluster c: from k on (LTR) or just before k (RTL).
  bool found = false;
  if (!rtl) {
    for (std::size_t i = k; i < it.glyphs.size() && it.glyphs[i].cluster == c; ++i) {
      found = true;
      if (it.glyphs[i].unsafe) return false;
    }
  } else {
    for (std::size_t i = k; i-- > 0 && it.glyphs[i].cluster == c;) {
      found = true;
      if (it.glyphs[i].unsafe) return false;
    }
  }
  return found;  // no glyph starts at c: the cut falls inside a cluster
}

// Glyphs of item `it` for [a, b) (inside the item), sliced or re-shaped.
std::vector<ParagraphBuilder::Glyph> ParagraphBuilder::slice(const Item& it, std::size_t a, std::size_t b,
                                                             std::uint8_t level) const {
  if (a == it.start && b == it.end && level == it.level) return it.glyphs;
  const bool safe = level == it.level && (a == it.start || safe_cut(it, a)) && (b == it.end || safe_cut(it, b));
  if (!safe) return shape(a, b, level, it.script, *it.font, it.style);
  std::size_t lo = glyph_bound(it, a), hi = glyph_bound(it, b);
  if (lo > hi) std::swap(lo, hi);
  return std::vector<Glyph>(it.glyphs.begin() + static_cast<std::ptrdiff_t>(lo),
                            it.glyphs.begin() + static_cast<std::ptrdiff_t>(hi));
}

// Appends pieces for paragraph code points [a, b) with line levels `lv`
// (indexed from `lv_base`).
void ParagraphBuilder::add_pieces(std::vector<Piece>& pieces, std::size_t a, std::size_t b,
                                  const std::vector<std::uint8_t>& lv, std::size_t lv_base) const {
  std::size_t i = a;
  while (i < b) {
    const Item& it = items[item_of[i]];
    std::size_t j = i + 1;
    const std::uint8_t level = lv[i - lv_base];
    while (j < b && j < it.end && lv[j - lv_base] == level) ++j;
    Piece p;
    p.start = i;
    p.end = j;
    p.level = level;
    p.font = it.font;
    p.style = it.style;
    p.glyphs = slice(it, i, j, level);
    pieces.push_back(std::move(p));
    i = j;
  }
}

ParagraphBuilder::Piece ParagraphBuilder::synthetic(std::vector<Glyph> glyphs, const Item& near, std::uint8_t level,
                                                    std::size_t at) const {
  Piece p;
  p.start = p.end = at;
  p.level = level;
  p.font = near.font;
  p.style = near.style;
  for (Glyph& g : glyphs) g.cluster = static_cast<std::uint32_t>(at);
  p.glyphs = std::move(glyphs);
  p.synthetic = true;
  return p;
}

double ParagraphBuilder::glyphs_width(const std::vector<Glyph>& g) {
  double w = 0;
  for (const Glyph& x : g) w += x.advance;
  return w;
}

// Emits one line made of `pieces` (logical order) covering paragraph code
// points [a, b) for the line's text range.
void ParagraphBuilder::emit_line(std::vector<Piece> pieces, std::size_t a, std::size_t b, bool first,
                                 bool last_of_paragraph, bool mandatory, bool ellipsized, bool hyphenated) {
  LayoutLine line;
  line.start = out_bytes(a);
  line.end = out_bytes(b);
  line.paragraph_level = bidi.paragraph_level;
  line.ellipsized = ellipsized;
  line.hyphenated = hyphenated;
  const bool rtl_para = bidi.paragraph_level % 2 == 1;
  const double indent = line_indent(first);
  double content = apply_spacing(pieces, indent);
  const double box = pstyle.width > 0 ? pstyle.width : 0.0;

  // Visual order of the pieces (L2 on their levels).
  std::vector<std::uint8_t> levels;
  for (const Piece& p : pieces) levels.push_back(p.level);
  const std::vector<std::size_t> order = reorder_levels(levels);

  // Justification of a full line (not the paragraph's last line, nor one
  // ended by a mandatory break).
  if (pstyle.align == Align::Justify && box > 0 && !last_of_paragraph && !mandatory && !ellipsized)
    content += justify(pieces, order, a, b, box - indent - content);

  const LineMetrics m = line_metrics(pieces, a);
  const double natural = m.ascent + m.descent + m.gap;
  line.ascent = m.ascent;
  line.descent = m.descent;
  line.gap = m.gap;
  line.height =
      pstyle.line_height_px > 0 ? pstyle.line_height_px : natural * (pstyle.line_height > 0 ? pstyle.line_height : 1.0);
  line.top = y;
  // Extra leading is shared above and below, as in CSS.
  line.baseline = y + m.ascent + (line.height - natural) / 2.0;
  line.width = content;
  // Provisional x: content starts at the indent on the start side; the
  // alignment pass (finish) moves it.
  line.x = rtl_para ? -content - indent : indent;  // relative to the start edge, fixed in finish()

  std::vector<Paragraph::ClusterBox> boxes;
  place_runs(line, pieces, order, boxes);
  out.lines_.push_back(std::move(line));
  out.boxes_.push_back(std::move(boxes));
  line_indent_.push_back(indent);
  y += out.lines_.back().height;
}

// Spacing and tabs (logical order, pen from the line start) added to the
// pieces' glyphs; returns the content width (trailing whitespace excluded).
double ParagraphBuilder::apply_spacing(std::vector<Piece>& pieces, double indent) const {
  double x = indent, visible = indent;
  for (Piece& p : pieces) {
    if (!p.synthetic) {
      space_piece(p, x, visible);
    } else {
      x += glyphs_width(p.glyphs);
      visible = x;
    }
  }
  return visible - indent;
}

// Adds each code point's extra advance (spacing, tabs) to the last glyph of
// its cluster in logical order, moving the pen `x` and the end of the
// visible text.
void ParagraphBuilder::space_piece(Piece& p, double& x, double& visible) const {
  // Per code point of the piece: its glyphs' advance and the last glyph of
  // its cluster (one pass, not one per code point).
  std::vector<double> shaped_of(p.end - p.start, 0.0);
  std::vector<Glyph*> target_of(p.end - p.start, nullptr);
  for (Glyph& g : p.glyphs) {
    if (g.cluster < p.start || g.cluster >= p.end) continue;
    shaped_of[g.cluster - p.start] += g.advance;
    target_of[g.cluster - p.start] = &g;
  }
  for (std::size_t i = p.start; i < p.end; ++i) {
    double extra = 0.0;
    const TextStyle& s = style(style_of[p0 + i]);
    if (s.letter_spacing != 0.0 && (i + 1 == para.size() || grapheme[i + 1])) extra += s.letter_spacing;
    if (s.word_spacing != 0.0 && detail::is_space(para[i])) extra += s.word_spacing;
    double shaped = shaped_of[i - p.start];
    Glyph* target = target_of[i - p.start];
    if (para[i] == U'\t' && target) {
      const double want = tab_advance(x, style_of[p0 + i]);
      target->advance += want - shaped;
      shaped = want;
    } else if (target) {
      target->advance += extra;
      shaped += extra;
    }
    x += shaped;
    if (!detail::is_whitespace(para[i])) visible = x;
  }
}

// The tallest font on the line (the default style's first font for an empty
// line), in px.
ParagraphBuilder::LineMetrics ParagraphBuilder::line_metrics(const std::vector<Piece>& pieces, std::size_t a) const {
  LineMetrics m{};
  bool any = false;
  for (const Piece& p : pieces) {
    if (p.glyphs.empty() && !p.synthetic && p.end - p.start == 0) continue;
    const LineMetrics f = font_line_metrics(*p.font, style(p.style).size_px);
    m.ascent = std::max(m.ascent, f.ascent);
    m.descent = std::max(m.descent, f.descent);
    m.gap = std::max(m.gap, f.gap);
    any = true;
  }
  if (!any) {
    const std::size_t si = a < para.size() ? style_of[p0 + a] : 0;
    m = font_line_metrics(*resolved[si]->chain.front(), style(si).size_px);
  }
  return m;
}

// Glyph runs of the pieces in visual `order`, placed from pen 0 at the
// line's visual left end (finish() applies the alignment), and their
// cluster boxes.
void ParagraphBuilder::place_runs(LayoutLine& line, const std::vector<Piece>& pieces,
                                  const std::vector<std::size_t>& order,
                                  std::vector<Paragraph::ClusterBox>& boxes) const {
  double pen = 0.0;
  for (std::size_t k : order) {
    const Piece& p = pieces[k];
    GlyphRun run;
    run.font = p.font;
    run.size_px = style(p.style).size_px;
    run.rtl = p.level % 2 == 1;
    run.style = p.style;
    run.start = out_bytes(p.start);
    run.end = out_bytes(p.end);
    run.x = pen;
    // Cluster boxes for hit testing.
    std::vector<std::pair<std::uint32_t, std::pair<double, double>>> clusters;  // cluster -> [left, right)
    clusters.reserve(p.glyphs.size());
    run.glyphs.reserve(p.glyphs.size());
    for (const Glyph& g : p.glyphs) {
      PositionedGlyph pg;
      pg.id = g.id;
      pg.cluster = static_cast<std::uint32_t>(out_bytes(g.cluster));
      pg.x = pen + g.x_offset;
      pg.y = line.baseline - g.y_offset;
      pg.advance = g.advance;
      run.glyphs.push_back(pg);
      if (!p.synthetic) {
        if (!clusters.empty() && clusters.back().first == g.cluster)
          clusters.back().second.second = pen + g.advance;
        else
          clusters.push_back({g.cluster, {pen, pen + g.advance}});
      }
      pen += g.advance;
    }
    run.width = pen - run.x;
    if (!p.synthetic) add_boxes(boxes, p, clusters);
    line.runs.push_back(std::move(run));
  }
}

// Spreads `extra` px over the line's spaces; a line without spaces (CJK,
// Thai) gets it between its clusters instead, except inside runs of a
// joining script (Arabic keeps its joins). Returns the width added.
double ParagraphBuilder::justify(std::vector<Piece>& pieces, const std::vector<std::size_t>& order, std::size_t a,
                                 std::size_t b, double extra) const {
  if (!(extra > 0)) return 0.0;
  std::size_t last_visible = a;
  for (std::size_t i = a; i < b; ++i)
    if (!detail::is_whitespace(para[i])) last_visible = i;
  std::vector<Glyph*> gaps;
  for (Piece& p : pieces)
    for (Glyph& g : p.glyphs)
      if (!p.synthetic && g.cluster < last_visible && para[g.cluster] == U' ') gaps.push_back(&g);
  if (gaps.empty()) {
    // The glyphs before the line's visible end, left to right, without
    // invisible characters (a zero width space is no cluster of its own
    // here); a gap after the last glyph of each cluster but the rightmost.
    std::vector<Glyph*> seq;
    for (std::size_t k : order)
      if (!pieces[k].synthetic)
        for (Glyph& g : pieces[k].glyphs)
          if (g.cluster <= last_visible && !detail::ignorable_for_coverage(para[g.cluster])) seq.push_back(&g);
    for (std::size_t i = 0; i + 1 < seq.size(); ++i)
      if (seq[i]->cluster != seq[i + 1]->cluster && !joins(seq[i]->cluster) && !joins(seq[i + 1]->cluster))
        gaps.push_back(seq[i]);
  }
  if (gaps.empty()) return 0.0;
  for (Glyph* g : gaps) g->advance += extra / static_cast<double>(gaps.size());
  return extra;
}

// Is code point i in a script whose letters join (spacing them out would
// break the joins)?
bool ParagraphBuilder::joins(std::size_t i) const {
  switch (items[item_of[i]].script) {
    case HB_SCRIPT_ARABIC:
    case HB_SCRIPT_SYRIAC:
    case HB_SCRIPT_NKO:
    case HB_SCRIPT_MONGOLIAN:
    case HB_SCRIPT_MANDAIC:
    case HB_SCRIPT_ADLAM:
    case HB_SCRIPT_HANIFI_ROHINGYA:
      return true;
    default:
      return false;
  }
}

void ParagraphBuilder::add_boxes(
    std::vector<Paragraph::ClusterBox>& boxes, const Piece& p,
    const std::vector<std::pair<std::uint32_t, std::pair<double, double>>>& clusters) const {
  const bool rtl = p.level % 2 == 1;
  // Logical extent of each cluster: up to the next cluster start in logical
  // order, which is the next entry (LTR) or the previous one (RTL) because
  // HarfBuzz keeps clusters monotonic in the run's direction.
  for (std::size_t k = 0; k < clusters.size(); ++k) {
    const auto& [cluster, span] = clusters[k];
    const std::size_t end =
        rtl ? (k > 0 ? clusters[k - 1].first : p.end) : (k + 1 < clusters.size() ? clusters[k + 1].first : p.end);
    // Graphemes inside the cluster (a ligature "fi" holds two) share its width.
    std::size_t count = 1;
    for (std::size_t i = cluster + 1; i < end; ++i) count += grapheme[i] ? 1 : 0;
    const double w = (span.second - span.first) / static_cast<double>(count);
    std::size_t nth = 0;
    for (std::size_t g = cluster; g < end; ++nth) {
      std::size_t next = g + 1;
      while (next < end && !grapheme[next]) ++next;
      Paragraph::ClusterBox b;
      b.start = out_bytes(g);
      b.end = out_bytes(next);
      const std::size_t slot = rtl ? count - 1 - nth : nth;
      b.left = span.first + w * static_cast<double>(slot);
      b.right = b.left + w;
      b.rtl = rtl;
      b.level = p.level;
      boxes.push_back(b);
      g = next;
    }
  }
}

// Alignment, once every line is known (without a width the box is the
// widest line).
void ParagraphBuilder::finish() {
  double box = pstyle.width;
  if (box <= 0)
    for (std::size_t k = 0; k < out.lines_.size(); ++k) box = std::max(box, out.lines_[k].width + line_indent_[k]);
  out.width_ = box;
  for (std::size_t k = 0; k < out.lines_.size(); ++k) {
    LayoutLine& line = out.lines_[k];
    const bool rtl = line.paragraph_level % 2 == 1;
    const double indent = line_indent_[k];
    Align align = pstyle.align;
    if (align == Align::Justify) align = Align::Start;
    if (align == Align::Start) align = rtl ? Align::Right : Align::Left;
    if (align == Align::End) align = rtl ? Align::Left : Align::Right;
    // The glyphs were placed from pen 0 at the visual left; content starts
    // at 0 for LTR. For RTL, trailing spaces (visually at the left) lie
    // before the content: find the content's left edge.
    double content_left = 0.0;
    if (rtl) {
      double total = 0.0;
      for (const GlyphRun& r : line.runs) total = std::max(total, r.x + r.width);
      content_left = total - line.width;
    }
    double left = 0.0;
    switch (align) {
      case Align::Left:
        left = rtl ? 0.0 : indent;
        break;
      case Align::Right:
        left = box - line.width - (rtl ? indent : 0.0);
        break;
      case Align::Center:
        left = (box - line.width) / 2.0;
        break;
      default:
        break;
    }
    const double shift = left - content_left;
    line.x = left;
    for (GlyphRun& r : line.runs) {
      r.x += shift;
      for (PositionedGlyph& g : r.glyphs) g.x += shift;
    }
    for (Paragraph::ClusterBox& b : out.boxes_[k]) {
      b.left += shift;
      b.right += shift;
    }
  }
}

}  // namespace curvetext
