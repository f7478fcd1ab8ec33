// Paragraph layout (see layout.hpp for the pipeline).

#include "curvetext/layout.hpp"

#include <hb.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>
#include <limits>
#include <map>
#include <span>
#include <string>

#include "curvetext/error.hpp"
#include "curvetext/line_break.hpp"
#include "curvetext/tolerances.hpp"
#include "font/face_queries.hpp"
#include "font/shaper.hpp"
#include "font/utf8.hpp"
#include "layout/cluster_limit.hpp"
#include "layout/emoji.hpp"
#include "core/format.hpp"

namespace curvetext {

namespace {

constexpr double kEpsilon = 1e-6;

bool is_paragraph_separator(char32_t c) {
  return c == U'\n' || c == U'\r' || c == 0x2029 || c == 0x85 || (c >= 0x1C && c <= 0x1E);
}

hb_unicode_funcs_t* unicode_funcs() {
  static hb_unicode_funcs_t* const funcs = hb_unicode_funcs_get_default();
  return funcs;
}

// The character tests below run several times per character; ASCII, most of
// the text in many paragraphs, is answered without a Unicode table lookup.
bool is_space(char32_t c) {
  if (c < 0x80) return c == U' ';
  return hb_unicode_general_category(unicode_funcs(), c) == HB_UNICODE_GENERAL_CATEGORY_SPACE_SEPARATOR;
}

bool is_whitespace(char32_t c) {
  if (c < 0x80) return c == U' ' || c == U'\t' || c == U'\n' || c == U'\r' || (c >= 0x1C && c <= 0x1E);
  return is_space(c) || c == 0x2028 || is_paragraph_separator(c);
}

// Characters that need no glyph of their own when choosing a font.
bool ignorable_for_coverage(char32_t c) {
  return c < 0x20 || c == 0x7F || c == 0xAD || (c >= 0x200B && c <= 0x200F) || (c >= 0x2028 && c <= 0x202E) ||
         (c >= 0x2060 && c <= 0x206F) || c == 0xFEFF || (c >= 0xFE00 && c <= 0xFE0F) ||
         (c >= 0xE0000 && c <= 0xE0FFF) || c == 0x034F;
}

hb_script_t script_of(char32_t c) {
  if (c < 0x80) return ((c | 0x20) >= U'a' && (c | 0x20) <= U'z') ? HB_SCRIPT_LATIN : HB_SCRIPT_COMMON;
  return hb_unicode_script(unicode_funcs(), c);
}

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

// A piece of a line: a slice of an item, or a synthetic glyph run (ellipsis,
// hyphen) with start == end.
struct Piece {
  std::size_t start = 0, end = 0;
  std::uint8_t level = 0;
  std::shared_ptr<const Font> font;
  std::size_t style = 0;
  std::vector<Glyph> glyphs;
  bool synthetic = false;
};

struct Metrics {
  double ascent = 0, descent = 0, gap = 0;
};

// The weight and italic a face is drawn in: its own, or bold and slanted
// where synthesised.
float drawn_weight(const Font& font) {
  const float weight = detail::style_value(font, HB_STYLE_TAG_WEIGHT);
  return font.synthesis().embolden_em > 0.0 ? std::max(weight, 700.0f) : weight;
}

bool drawn_italic(const Font& font) {
  return detail::style_value(font, HB_STYLE_TAG_ITALIC) > 0 || font.synthesis().slant != 0.0;
}

Metrics font_metrics(const Font& font, double size_px) {
  const FontMetrics m = font.metrics();
  const double s = size_px / m.units_per_em;
  return {m.ascender * s, -m.descender * s, m.line_gap * s};
}

}  // namespace

// Does the work of Paragraph::layout; a friend of Paragraph.
struct ParagraphBuilder {
  FontCollection& fonts;
  const ParagraphStyle& pstyle;
  Paragraph& out;
  std::u32string cps;              // whole text
  std::vector<std::size_t> bytes;  // byte offset of each code point, plus the end
  std::vector<std::size_t> style_of;
  std::deque<ResolvedStyle> resolved_storage;
  std::vector<const ResolvedStyle*> resolved;  // per style
  std::size_t lines_left = std::numeric_limits<std::size_t>::max();
  bool stop = false;

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
  double y = 0.0;
  // Scratch: one HarfBuzz buffer for every run shaped in this layout.
  mutable detail::Shaper shaper;

  ParagraphBuilder(FontCollection& f, const ParagraphStyle& s, Paragraph& o) : fonts(f), pstyle(s), out(o) {}

  const TextStyle& style(std::size_t i) const { return out.styles_[i]; }

  // Styles that differ only in what font lookup and shaping features do not
  // depend on (colour, size, decorations) share one resolution: many spans
  // cost one lookup.
  void resolve_styles() {
    std::map<std::string, const ResolvedStyle*> by_key;
    resolved.resize(out.styles_.size());
    for (std::size_t i = 0; i < out.styles_.size(); ++i) {
      const TextStyle& s = out.styles_[i];
      std::string key = s.language + "|" + (s.letter_spacing != 0.0 ? "spaced|" : "|");
      for (const std::string& f : s.fonts) key += f + "\n";
      for (const Variation& v : s.variations) key += v.tag + "=" + detail::format_number_exact(v.value) + ",";
      key += "|";
      for (const Feature& f : s.features) key += f.tag + "=" + std::to_string(f.value) + ",";
      auto [it, added] = by_key.try_emplace(std::move(key), nullptr);
      if (added) it->second = &resolved_storage.emplace_back(resolve_style(s));
      resolved[i] = it->second;
    }
  }

  ResolvedStyle resolve_style(const TextStyle& s) {
    ResolvedStyle r;
    if (s.fonts.empty()) {
      auto f = fonts.default_font();
      if (!s.variations.empty()) f = fonts.resolve(f->path(), s.variations);
      r.chain.push_back(f);
    }
    for (std::size_t k = 0; k < s.fonts.size(); ++k) {
      // The first font must take the variations; later ones may lack the axes.
      if (k == 0) {
        r.chain.push_back(fonts.resolve(s.fonts[k], s.variations));
      } else {
        try {
          r.chain.push_back(fonts.resolve(s.fonts[k], s.variations));
        } catch (const Error& e) {
          if (e.code() != ErrorCode::FontInvalid) throw;
          r.chain.push_back(fonts.resolve(s.fonts[k]));
        }
      }
    }
    r.language_tag = s.language.empty() ? pstyle.language : s.language;
    if (!r.language_tag.empty()) {
      r.language = hb_language_from_string(r.language_tag.c_str(), -1);
      if (r.language == HB_LANGUAGE_INVALID)
        throw Error(ErrorCode::InvalidArgument, "bad BCP 47 language tag '" + r.language_tag + "'");
    }
    for (const Feature& f : s.features) {
      if (f.tag.empty() || f.tag.size() > 4) throw Error(ErrorCode::InvalidArgument, "bad feature tag '" + f.tag + "'");
      r.features.push_back({hb_tag_from_string(f.tag.c_str(), static_cast<int>(f.tag.size())), f.value,
                            HB_FEATURE_GLOBAL_START, HB_FEATURE_GLOBAL_END});
    }
    // Letter spacing would pull ligatures apart: turn them off (as Pango does).
    if (s.letter_spacing != 0.0)
      for (const char* tag : {"liga", "clig", "dlig", "hlig"})
        r.features.push_back({hb_tag_from_string(tag, 4), 0, HB_FEATURE_GLOBAL_START, HB_FEATURE_GLOBAL_END});
    return r;
  }

  // Shapes paragraph code points [a, b) as one run; the whole paragraph is
  // context (Arabic joining across items), clusters are paragraph code point
  // indices.
  std::vector<Glyph> shape(std::size_t a, std::size_t b, std::uint8_t level, hb_script_t script, const Font& font,
                           std::size_t style_index) const {
    const ResolvedStyle& r = *resolved[style_index];
    detail::ShapeSettings settings;
    settings.direction = level % 2 ? HB_DIRECTION_RTL : HB_DIRECTION_LTR;
    settings.script = script;
    settings.language = r.language;
    settings.features = r.features;
    settings.beginning_of_text = a == 0;
    settings.end_of_text = b == para.size();
    return to_pixels(shaper.shape(font, shaped_text, a, b - a, settings), font, style_index);
  }

  // Glyphs for a single character string (ellipsis, hyphen) in `font`.
  std::vector<Glyph> shape_string(const std::u32string& s, const Font& font, std::size_t style_index,
                                  std::uint8_t level) const {
    detail::ShapeSettings settings;
    settings.direction = level % 2 ? HB_DIRECTION_RTL : HB_DIRECTION_LTR;
    settings.guess_unset = true;
    std::vector<Glyph> glyphs = to_pixels(shaper.shape(font, s, 0, s.size(), settings), font, style_index);
    for (Glyph& g : glyphs) {
      g.cluster = 0;
      g.unsafe = false;
    }
    return glyphs;
  }

  std::vector<Glyph> to_pixels(std::span<const detail::UnitGlyph> units, const Font& font,
                               std::size_t style_index) const {
    const double s = style(style_index).size_px / font.metrics().units_per_em;
    std::vector<Glyph> glyphs(units.size());
    for (std::size_t i = 0; i < units.size(); ++i) {
      glyphs[i].id = units[i].id;
      glyphs[i].cluster = units[i].cluster;
      glyphs[i].advance = units[i].x_advance * s;
      glyphs[i].x_offset = units[i].x_offset * s;
      glyphs[i].y_offset = units[i].y_offset * s;
      glyphs[i].unsafe = units[i].unsafe_to_break;
    }
    return glyphs;
  }

  bool covers(const Font& font, std::size_t a, std::size_t b) const {
    for (std::size_t i = a; i < b; ++i)
      if (!ignorable_for_coverage(para[i]) && !fonts.has_glyph(font, para[i])) return false;
    return true;
  }

  // A colour face (COLR or bitmaps) that covers [a, b): the style's first,
  // else fontconfig's; -1 when none.
  template <typename IndexOf>
  std::size_t color_face(std::size_t a, std::size_t b, const ResolvedStyle& r, IndexOf& index_of) {
    for (const auto& f : r.chain)
      if (f->color_format() != ColorFormat::None && covers(*f, a, b)) return index_of(f);
    if (auto f = fonts.color_fallback(para[a], r.language_tag); f && covers(*f, a, b)) return index_of(f);
    return static_cast<std::size_t>(-1);
  }
  // A fallback face in the weight and slant of the style's first font (bold
  // or italic text stays bold or italic in Hebrew or Arabic): the same
  // family's face for them where fontconfig has one that covers [a, b) (a
  // Regular-only family's face comes synthesised), else `f` synthesised.
  std::shared_ptr<const Font> styled_like(const std::shared_ptr<const Font>& f, const Font& first, std::size_t a,
                                          std::size_t b) {
    const float weight = drawn_weight(first);
    const bool italic = drawn_italic(first);
    const bool has_italic = drawn_italic(*f);
    const float has_weight = drawn_weight(*f);
    if (std::abs(weight - has_weight) < 100 && italic == has_italic) return f;
    const std::string family = f->family_name();
    if (family.empty() || family.find_first_of(":,-\\") != std::string::npos)
      return fonts.synthesised(f, weight, italic);
    static const char* const names[] = {"thin",     "extralight", "light",     "regular", "medium",
                                        "semibold", "bold",       "extrabold", "black"};
    const int k = std::clamp(static_cast<int>(std::lround(weight / 100.0f)) - 1, 0, 8);
    const std::string pattern = family + ":weight=" + names[k] + (italic ? ":slant=italic" : "");
    auto [it, added] = restyled_.try_emplace(pattern, nullptr);
    if (added) {
      try {
        it->second = fonts.resolve(pattern);
      } catch (const Error&) {
        // No such face: the fallback face as it is.
      }
    }
    const std::shared_ptr<const Font>& g = it->second;
    if (!g || !covers(*g, a, b)) return fonts.synthesised(f, weight, italic);
    const bool closer = std::abs(drawn_weight(*g) - weight) < std::abs(has_weight - weight);
    const bool slant_fixed = drawn_italic(*g) == italic && has_italic != italic;
    return closer || slant_fixed ? g : fonts.synthesised(f, weight, italic);
  }
  std::map<std::string, std::shared_ptr<const Font>> restyled_;  // fontconfig pattern -> face (null: none)

  void itemize() {
    const std::size_t n = para.size();
    // Script runs: Common and Inherited take the script of the text around them.
    std::vector<hb_script_t> script(n, HB_SCRIPT_COMMON);
    std::vector<bool> neutral_script(n, false);  // Common or Inherited, for the font choice below
    hb_script_t last = HB_SCRIPT_COMMON;
    for (std::size_t i = 0; i < n; ++i) {
      const hb_script_t s = script_of(para[i]);
      neutral_script[i] = s == HB_SCRIPT_COMMON || s == HB_SCRIPT_INHERITED;
      if (s != HB_SCRIPT_COMMON && s != HB_SCRIPT_INHERITED && s != HB_SCRIPT_UNKNOWN) last = s;
      script[i] = (s == HB_SCRIPT_COMMON || s == HB_SCRIPT_INHERITED || s == HB_SCRIPT_UNKNOWN) ? last : s;
    }
    hb_script_t next = HB_SCRIPT_COMMON;
    for (std::size_t i = n; i-- > 0;) {
      if (script[i] != HB_SCRIPT_COMMON)
        next = script[i];
      else
        script[i] = next;
    }
    // A font per grapheme cluster.
    // Fonts by index (a few per paragraph), not a shared_ptr per code point;
    // the loop passes raw pointers (no reference counting per cluster), the
    // shared_ptrs live in `used`.
    std::vector<std::shared_ptr<const Font>> used;
    std::vector<std::uint32_t> keep(n, 0);
    std::size_t previous = static_cast<std::size_t>(-1);  // index into used
    std::size_t previous_style = static_cast<std::size_t>(-1);
    bool previous_emoji = false;  // the previous cluster took a colour face for emoji presentation
    auto index_of = [&](const std::shared_ptr<const Font>& f) {
      std::size_t index = 0;
      while (index < used.size() && used[index] != f) ++index;
      if (index == used.size()) used.push_back(f);
      return index;
    };
    for (std::size_t a = 0; a < n;) {
      std::size_t b = a + 1;
      while (b < n && !grapheme[b]) ++b;
      const std::size_t si = style_of[p0 + a];
      const ResolvedStyle& r = *resolved[si];
      std::size_t chosen = static_cast<std::size_t>(-1);
      const bool neutral = neutral_script[a] || ignorable_for_coverage(para[a]);
      // Emoji presentation: a colour face first, the style's or fontconfig's,
      // as Pango does.
      const bool emoji = detail::emoji_presentation(std::u32string_view(para).substr(a, b - a));
      if (emoji) chosen = color_face(a, b, r, index_of);
      // Spaces, digits and punctuation stay with the font before them when it
      // has them (not with an emoji's), so a run of Arabic words is not cut
      // at every space.
      if (chosen == static_cast<std::size_t>(-1) && neutral && !previous_emoji && previous < used.size() &&
          previous_style == si && covers(*used[previous], a, b))
        chosen = previous;
      previous_emoji = emoji && chosen != static_cast<std::size_t>(-1);
      for (std::size_t k = 0; chosen == static_cast<std::size_t>(-1) && k < r.chain.size(); ++k)
        if (covers(*r.chain[k], a, b)) chosen = index_of(r.chain[k]);
      if (chosen == static_cast<std::size_t>(-1)) {
        std::size_t c = a;
        while (c + 1 < b && ignorable_for_coverage(para[c])) ++c;
        auto f = fonts.fallback(para[c], r.language_tag, style(si).variations);
        if (f && style(si).variations.empty()) f = styled_like(f, *r.chain.front(), a, b);
        chosen = index_of(f ? f : r.chain.front());
      }
      for (std::size_t i = a; i < b; ++i) keep[i] = static_cast<std::uint32_t>(chosen);
      previous = chosen;
      previous_style = si;
      a = b;
    }
    items.clear();
    item_of.assign(n, 0);
    for (std::size_t a = 0; a < n;) {
      std::size_t b = a + 1;
      while (b < n && bidi.levels[b] == bidi.levels[a] && script[b] == script[a] && keep[b] == keep[a] &&
             style_of[p0 + b] == style_of[p0 + a])
        ++b;
      Item it;
      it.start = a;
      it.end = b;
      it.level = bidi.levels[a];
      it.script = script[a];
      it.font = used[keep[a]];
      it.style = style_of[p0 + a];
      it.glyphs = shape(a, b, it.level, it.script, *it.font, it.style);
      for (std::size_t i = a; i < b; ++i) item_of[i] = items.size();
      items.push_back(std::move(it));
      a = b;
    }
    // Advances per code point (the glyphs of a cluster count on its first
    // code point), plus letter and word spacing.
    advance.assign(n, 0.0);
    for (const Item& it : items)
      for (const Glyph& g : it.glyphs) advance[g.cluster] += g.advance;
    for (std::size_t i = 0; i < n; ++i) {
      const TextStyle& s = style(style_of[p0 + i]);
      if (s.letter_spacing != 0.0 && (i + 1 == n || grapheme[i + 1])) advance[i] += s.letter_spacing;
      if (s.word_spacing != 0.0 && is_space(para[i])) advance[i] += s.word_spacing;
    }
  }

  // A negative first-line indent hangs: the first line starts at the edge,
  // the others that far in (nothing is drawn outside the box).
  double line_indent(bool first) const {
    const double i = pstyle.first_line_indent;
    if (i >= 0) return first ? i : 0.0;
    return first ? 0.0 : -i;
  }

  double space_width(std::size_t style_index) const {
    const Font& f = *resolved[style_index]->chain.front();
    const std::uint32_t g = f.glyph_for_codepoint(U' ');
    const double s = style(style_index).size_px / f.metrics().units_per_em;
    return g ? detail::glyph_h_advance(f, g) * s : style(style_index).size_px / 3.0;
  }

  // Pen advance of a tab at pen position x (from the line start).
  double tab_advance(double x, std::size_t style_index) const {
    for (double tab_stop : pstyle.tab_stops)
      if (tab_stop > x + kEpsilon) return tab_stop - x;
    const double last = pstyle.tab_stops.empty() ? 0.0 : pstyle.tab_stops.back();
    double interval = pstyle.tab_interval > 0 ? pstyle.tab_interval : 8.0 * space_width(style_index);
    if (interval <= 0) interval = 1.0;
    const double k = std::floor((x - last) / interval + kEpsilon) + 1.0;
    return last + k * interval - x;
  }

  double hyphen_width(std::size_t i) const {
    const Item& it = items[item_of[i]];
    double w = 0;
    for (const Glyph& g : hyphen_glyphs(it)) w += g.advance;
    return w;
  }

  std::vector<Glyph> hyphen_glyphs(const Item& it) const {
    const std::u32string h = it.font->glyph_for_codepoint(0x2010) ? U"\u2010" : U"-";
    return shape_string(h, *it.font, it.style, it.level);
  }

  // Width of [a, b) laid out from pen x0 (tabs depend on it), trailing
  // whitespace excluded.
  double range_width(std::size_t a, std::size_t b, double x0 = 0.0) const {
    double x = x0, visible = x0;
    for (std::size_t i = a; i < b; ++i) {
      x += para[i] == U'\t' ? tab_advance(x, style_of[p0 + i]) : advance[i];
      if (!is_whitespace(para[i])) visible = x;
    }
    return visible - x0;
  }

  std::size_t paragraph_content_end() const {
    std::size_t e = para.size();
    if (e > 0 && is_paragraph_separator(para[e - 1])) --e;
    if (e > 0 && para[e - 1] == U'\r' && para.size() - e == 1) --e;  // CR LF
    return e;
  }

  // --- Line assembly -----------------------------------------------------------

  // Glyphs of item `it` for [a, b) (inside the item), sliced or re-shaped.
  // Index of the first glyph (in HarfBuzz order) whose cluster is logically
  // at or after code point c. HarfBuzz's default cluster level keeps clusters
  // monotonic: increasing for LTR, decreasing for RTL; so the glyphs of any
  // code point range are contiguous and found by binary search, not by a
  // scan of the whole item per line.
  static std::size_t glyph_bound(const Item& it, std::size_t c) {
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
  static bool safe_cut(const Item& it, std::size_t c) {
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

  std::vector<Glyph> slice(const Item& it, std::size_t a, std::size_t b, std::uint8_t level) const {
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
  void add_pieces(std::vector<Piece>& pieces, std::size_t a, std::size_t b, const std::vector<std::uint8_t>& lv,
                  std::size_t lv_base) const {
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

  Piece synthetic(std::vector<Glyph> glyphs, const Item& near, std::uint8_t level, std::size_t at) const {
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

  std::vector<Glyph> ellipsis_glyphs(const Item& near) const {
    const std::u32string e = near.font->glyph_for_codepoint(0x2026) ? U"\u2026" : U"...";
    return shape_string(e, *near.font, near.style, static_cast<std::uint8_t>(bidi.paragraph_level));
  }

  double glyphs_width(const std::vector<Glyph>& g) const {
    double w = 0;
    for (const Glyph& x : g) w += x.advance;
    return w;
  }

  // Emits one line made of `pieces` (logical order) covering paragraph code
  // points [a, b) for the line's text range.
  void emit_line(std::vector<Piece> pieces, std::size_t a, std::size_t b, bool first, bool last_of_paragraph,
                 bool mandatory, bool ellipsized, bool hyphenated) {
    LayoutLine line;
    line.start = out_bytes(a);
    line.end = out_bytes(b);
    line.paragraph_level = bidi.paragraph_level;
    line.ellipsized = ellipsized;
    line.hyphenated = hyphenated;
    const bool rtl_para = bidi.paragraph_level % 2 == 1;
    const double indent = line_indent(first);

    // Spacing, tabs (logical order, pen from the line start) and the content width.
    double x = indent, visible = indent;
    for (Piece& p : pieces) {
      if (!p.synthetic) {
        // Add each code point's extra advance (spacing, tabs) to the last
        // glyph of its cluster in logical order.
        // Per code point of the piece: its glyphs' advance and the last glyph
        // of its cluster (one pass, not one per code point).
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
          if (s.word_spacing != 0.0 && is_space(para[i])) extra += s.word_spacing;
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
          if (!is_whitespace(para[i])) visible = x;
        }
      } else {
        x += glyphs_width(p.glyphs);
        visible = x;
      }
    }
    double content = visible - indent;
    const double box = pstyle.width > 0 ? pstyle.width : 0.0;

    // Visual order of the pieces (L2 on their levels).
    std::vector<std::uint8_t> levels;
    for (const Piece& p : pieces) levels.push_back(p.level);
    const std::vector<std::size_t> order = reorder_levels(levels);

    // Justification of a full line (not the paragraph's last line, nor one
    // ended by a mandatory break).
    if (pstyle.align == Align::Justify && box > 0 && !last_of_paragraph && !mandatory && !ellipsized)
      content += justify(pieces, order, a, b, box - indent - content);

    // Metrics: the tallest font on the line (the default style's first font
    // for an empty line).
    Metrics m{};
    bool any = false;
    for (const Piece& p : pieces) {
      if (p.glyphs.empty() && !p.synthetic && p.end - p.start == 0) continue;
      const Metrics f = font_metrics(*p.font, style(p.style).size_px);
      m.ascent = std::max(m.ascent, f.ascent);
      m.descent = std::max(m.descent, f.descent);
      m.gap = std::max(m.gap, f.gap);
      any = true;
    }
    if (!any) {
      const std::size_t si = a < para.size() ? style_of[p0 + a] : 0;
      m = font_metrics(*resolved[si]->chain.front(), style(si).size_px);
    }
    const double natural = m.ascent + m.descent + m.gap;
    line.ascent = m.ascent;
    line.descent = m.descent;
    line.gap = m.gap;
    line.height = pstyle.line_height_px > 0 ? pstyle.line_height_px
                                            : natural * (pstyle.line_height > 0 ? pstyle.line_height : 1.0);
    line.top = y;
    // Extra leading is shared above and below, as in CSS.
    line.baseline = y + m.ascent + (line.height - natural) / 2.0;
    line.width = content;
    // Provisional x: content starts at the indent on the start side; the
    // alignment pass (finish) moves it.
    line.x = rtl_para ? -content - indent : indent;  // relative to the start edge, fixed in finish()

    double pen = 0.0;
    std::vector<Paragraph::ClusterBox> boxes;
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
    // Shift everything so that x = 0 is the line's visual left end; finish()
    // applies the alignment offset.
    out.lines_.push_back(std::move(line));
    out.boxes_.push_back(std::move(boxes));
    line_indent_.push_back(indent);
    y += out.lines_.back().height;
  }

  // Spreads `extra` px over the line's spaces; a line without spaces (CJK,
  // Thai) gets it between its clusters instead, except inside runs of a
  // joining script (Arabic keeps its joins). Returns the width added.
  double justify(std::vector<Piece>& pieces, const std::vector<std::size_t>& order, std::size_t a, std::size_t b,
                 double extra) const {
    if (!(extra > 0)) return 0.0;
    std::size_t last_visible = a;
    for (std::size_t i = a; i < b; ++i)
      if (!is_whitespace(para[i])) last_visible = i;
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
            if (g.cluster <= last_visible && !ignorable_for_coverage(para[g.cluster])) seq.push_back(&g);
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
  bool joins(std::size_t i) const {
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

  void add_boxes(std::vector<Paragraph::ClusterBox>& boxes, const Piece& p,
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

  std::size_t out_bytes(std::size_t para_index) const { return bytes[p0 + para_index]; }

  std::vector<double> line_indent_;

  // --- Line breaking -----------------------------------------------------------

  void layout_paragraph(std::size_t start, std::size_t end) {
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
    // Thai word breaks are added lazily, where a line must end (see below).
    dictionary_done.assign(n, false);
    const std::size_t content_end = paragraph_content_end();
    if (content_end == 0) {
      // An empty paragraph is one empty line.
      items.clear();
      emit_line({}, 0, n, true, true, true, false, false);
      consume_line();
      return;
    }
    itemize();

    const bool wrap = pstyle.width > 0;
    const bool one_line_ellipsis = pstyle.ellipsis != Ellipsis::None && wrap && pstyle.max_lines == 0;
    std::size_t a = 0;
    bool first = true;
    while (a < content_end && !stop) {
      const double indent = line_indent(first);
      const double avail = wrap ? pstyle.width - indent : std::numeric_limits<double>::infinity();
      // Greedy: the last opportunity where the line still fits. The line
      // ends somewhere in (best, overflow]; Thai runs there get their
      // dictionary word breaks, and the line is measured again.
      std::size_t best = 0;
      bool best_mandatory = false;
      for (bool measure = true; measure;) {
        best = 0;
        best_mandatory = false;
        std::size_t overflow = content_end;  // where the line stopped fitting
        double x = indent, visible = indent;
        for (std::size_t i = a; i < content_end; ++i) {
          x += para[i] == U'\t' ? tab_advance(x, style_of[p0 + i]) : advance[i];
          if (!is_whitespace(para[i])) visible = x;
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
      // Lines left: the last one allowed takes the rest of the paragraph (and
      // gets the ellipsis).
      const bool more_after = best < content_end || !last_paragraph_;
      const bool last_allowed = lines_left == 1 && more_after;
      if (one_line_ellipsis || last_allowed) {
        if (pstyle.ellipsis != Ellipsis::None) {
          ellipsize_line(a, content_end, n, first, avail, !(best < content_end) && last_allowed);
        } else {
          emit_simple(a, best, first, best_mandatory, n);
        }
        consume_line();
        if (last_allowed) stop = true;
        break;
      }
      emit_simple(a, best, first, best_mandatory, n);
      consume_line();
      first = false;
      a = best;
      // Spaces after a mandatory break belong to the next line.
    }
  }

  // Nothing fits on the line from `a`: the end of the first word broken
  // between grapheme clusters (overflow-wrap: break-word), at least one
  // cluster; in one pass, the width growing cluster by cluster.
  std::size_t break_word(std::size_t a, std::size_t content_end, double indent, double avail) const {
    std::size_t best = a + 1;
    while (best < content_end && !grapheme[best]) ++best;
    double x = indent, visible = indent;
    for (std::size_t i = a; i < content_end; ++i) {
      x += para[i] == U'\t' ? tab_advance(x, style_of[p0 + i]) : advance[i];
      if (!is_whitespace(para[i])) visible = x;
      const std::size_t cut = i + 1;
      if (cut < content_end && !grapheme[cut]) continue;
      if (cut <= best) continue;
      if (visible - indent > avail + kEpsilon) break;
      best = cut;
      if (breaks[i] != BreakAction::None) break;
    }
    return best;
  }

  bool last_paragraph_ = false;

  void consume_line() {
    if (lines_left != std::numeric_limits<std::size_t>::max()) --lines_left;
    if (lines_left == 0) stop = true;
  }

  void emit_simple(std::size_t a, std::size_t b, bool first, bool mandatory, std::size_t n) {
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

  PenWidths pen_widths(std::size_t a, std::size_t e) const {
    PenWidths w;
    w.a = a;
    w.pen.assign(e - a + 1, 0.0);
    w.visible_end.assign(e - a + 1, a);
    for (std::size_t i = a; i < e; ++i) {
      const double x = w.pen[i - a];
      w.pen[i - a + 1] = x + (para[i] == U'\t' ? tab_advance(x, style_of[p0 + i]) : advance[i]);
      w.visible_end[i - a + 1] = is_whitespace(para[i]) ? w.visible_end[i - a] : i + 1;
    }
    return w;
  }

  // The last line: the rest of the paragraph [a, e) cut to fit `avail` with
  // an ellipsis at the start, middle or end. `force` adds an ellipsis even
  // when the text fits (text after it was dropped).
  void ellipsize_line(std::size_t a, std::size_t e, std::size_t n, bool first, double avail, bool force) {
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

  // Alignment, once every line is known (without a width the box is the
  // widest line).
  void finish() {
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

  void run(std::string_view text, const std::vector<TextSpan>& spans) {
    // Code points and their byte offsets.
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
    // Styles per code point: later spans win.
    style_of.assign(cps.size(), 0);
    for (const TextSpan& span : spans) {
      if (span.start > span.end || span.end > text.size())
        throw Error(ErrorCode::InvalidArgument, "span [" + std::to_string(span.start) + ", " +
                                                    std::to_string(span.end) + ") is outside the text (" +
                                                    std::to_string(text.size()) + " bytes)");
      const auto at = [&](std::size_t b) { return std::lower_bound(bytes.begin(), bytes.end(), b); };
      const auto s = at(span.start), e = at(span.end);
      if (*s != span.start || *e != span.end)
        throw Error(ErrorCode::InvalidArgument, "span [" + std::to_string(span.start) + ", " +
                                                    std::to_string(span.end) + ") cuts a UTF-8 sequence");
      validate_style(span.style);
      out.styles_.push_back(span.style);
      for (auto i = s - bytes.begin(); i < e - bytes.begin(); ++i)
        style_of[static_cast<std::size_t>(i)] = out.styles_.size() - 1;
    }
    resolve_styles();
    if (pstyle.max_lines > 0) lines_left = static_cast<std::size_t>(pstyle.max_lines);

    // Paragraphs end after a paragraph separator (CR LF counts as one).
    std::vector<std::pair<std::size_t, std::size_t>> paragraphs;
    std::size_t start = 0;
    for (std::size_t i = 0; i < cps.size(); ++i) {
      if (!is_paragraph_separator(cps[i])) continue;
      if (cps[i] == U'\r' && i + 1 < cps.size() && cps[i + 1] == U'\n') ++i;
      paragraphs.push_back({start, i + 1});
      start = i + 1;
    }
    if (start < cps.size() || paragraphs.empty() || (!cps.empty() && is_paragraph_separator(cps.back())))
      paragraphs.push_back({start, cps.size()});
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
};

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

// --- Queries -------------------------------------------------------------------

Rect Paragraph::logical_bounds() const {
  Rect r;
  if (lines_.empty()) return r;
  double left = 0.0, right = width_;
  for (const LayoutLine& l : lines_) {
    left = std::min(left, l.x);
    right = std::max(right, l.x + l.width);
  }
  r.x = left;
  r.y = lines_.front().top;
  r.width = right - left;
  r.height = lines_.back().top + lines_.back().height - r.y;
  return r;
}

Rect Paragraph::ink_bounds() const {
  double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
  for (const LayoutLine& l : lines_)
    for (const GlyphRun& r : l.runs) {
      const double s = r.size_px / r.font->metrics().units_per_em;
      for (const PositionedGlyph& g : r.glyphs) {
        hb_glyph_extents_t e{};
        if (!detail::glyph_extents(*r.font, g.id, e) || e.width == 0 || e.height == 0) continue;
        const double gx0 = g.x + e.x_bearing * s, gx1 = gx0 + e.width * s;
        const double gy0 = g.y - e.y_bearing * s, gy1 = gy0 - e.height * s;
        x0 = std::min({x0, gx0, gx1});
        x1 = std::max({x1, gx0, gx1});
        y0 = std::min({y0, gy0, gy1});
        y1 = std::max({y1, gy0, gy1});
      }
    }
  if (x0 > x1) return {};
  return {x0, y0, x1 - x0, y1 - y0};
}

std::size_t Paragraph::previous_boundary(std::size_t index) const {
  index = std::min(index, text_.size());
  auto it = std::lower_bound(boundaries_.begin(), boundaries_.end(), index);
  if (it != boundaries_.end() && *it == index) {
    return it == boundaries_.begin() ? index : *(it - 1);
  }
  return it == boundaries_.begin() ? 0 : *(it - 1);
}

std::size_t Paragraph::next_boundary(std::size_t index) const {
  auto it = std::upper_bound(boundaries_.begin(), boundaries_.end(), index);
  return it == boundaries_.end() ? text_.size() : *it;
}

std::vector<Rect> Paragraph::selection_rects(std::size_t start, std::size_t end) const {
  std::vector<Rect> rects;
  if (start > end) std::swap(start, end);
  for (std::size_t k = 0; k < lines_.size(); ++k) {
    const LayoutLine& line = lines_[k];
    if (line.end <= start || line.start >= end) continue;
    std::vector<std::pair<double, double>> spans;
    for (const ClusterBox& b : boxes_[k])
      if (b.start < end && b.end > start) spans.push_back({b.left, b.right});
    std::sort(spans.begin(), spans.end());
    for (const auto& [l, r] : spans) {
      if (!rects.empty() && rects.back().y == line.top && std::abs(rects.back().x + rects.back().width - l) < 1e-6) {
        rects.back().width = r - rects.back().x;
      } else {
        rects.push_back({l, line.top, r - l, line.height});
      }
    }
  }
  return rects;
}

}  // namespace curvetext
