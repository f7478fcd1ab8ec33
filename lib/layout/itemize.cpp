// Paragraph layout, itemisation: script runs, a font per grapheme cluster,
// items of one level, script, font and style shaped once, and the advance of
// every code point (paragraph_builder.hpp).

#include <hb.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "curvetext/error.hpp"
#include "font/face_queries.hpp"
#include "layout/emoji.hpp"
#include "layout/paragraph_builder.hpp"
#include "layout/text_classes.hpp"

namespace curvetext {

namespace {

// The weight and italic a face is drawn in: its own, or bold and slanted
// where synthesised.
float drawn_weight(const Font& font) {
  const float weight = detail::style_value(font, HB_STYLE_TAG_WEIGHT);
  return font.synthesis().embolden_em > 0.0 ? std::max(weight, 700.0f) : weight;
}

bool drawn_italic(const Font& font) {
  return detail::style_value(font, HB_STYLE_TAG_ITALIC) > 0 || font.synthesis().slant != 0.0;
}

}  // namespace

std::size_t ParagraphBuilder::UsedFonts::index_of(const std::shared_ptr<const Font>& f) {
  std::size_t index = 0;
  while (index < fonts.size() && fonts[index] != f) ++index;
  if (index == fonts.size()) fonts.push_back(f);
  return index;
}

void ParagraphBuilder::itemize() {
  std::vector<bool> neutral;
  const std::vector<hb_script_t> script = script_runs(neutral);
  UsedFonts used;
  const std::vector<std::uint32_t> font_of = choose_fonts(neutral, used);
  build_items(script, font_of, used);
  add_advances();
}

// Script runs: Common and Inherited take the script of the text around them.
// `neutral` gets, per code point, whether it is Common or Inherited itself
// (for the font choice).
std::vector<hb_script_t> ParagraphBuilder::script_runs(std::vector<bool>& neutral) const {
  const std::size_t n = para.size();
  std::vector<hb_script_t> script(n, HB_SCRIPT_COMMON);
  neutral.assign(n, false);
  hb_script_t last = HB_SCRIPT_COMMON;
  for (std::size_t i = 0; i < n; ++i) {
    const hb_script_t s = detail::script_of(para[i]);
    neutral[i] = s == HB_SCRIPT_COMMON || s == HB_SCRIPT_INHERITED;
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
  return script;
}

// A font per grapheme cluster, as an index into `used` per code point (the
// loop passes raw pointers, no reference counting per cluster).
std::vector<std::uint32_t> ParagraphBuilder::choose_fonts(const std::vector<bool>& neutral, UsedFonts& used) {
  const std::size_t n = para.size();
  std::vector<std::uint32_t> font_of(n, 0);
  std::size_t previous = kNoFont;  // index into used
  std::size_t previous_style = kNoFont;
  bool previous_emoji = false;  // the previous cluster took a colour face for emoji presentation
  for (std::size_t a = 0; a < n;) {
    std::size_t b = a + 1;
    while (b < n && !grapheme[b]) ++b;
    const bool neutral_cluster = neutral[a] || detail::ignorable_for_coverage(para[a]);
    const std::size_t chosen = choose_font(a, b, neutral_cluster, used, previous, previous_style, previous_emoji);
    for (std::size_t i = a; i < b; ++i) font_of[i] = static_cast<std::uint32_t>(chosen);
    a = b;
  }
  return font_of;
}

// The font of cluster [a, b); updates the previous cluster's choice.
std::size_t ParagraphBuilder::choose_font(std::size_t a, std::size_t b, bool neutral, UsedFonts& used,
                                          std::size_t& previous, std::size_t& previous_style, bool& previous_emoji) {
  const std::size_t si = style_of[p0 + a];
  const ResolvedStyle& r = *resolved[si];
  std::size_t chosen = kNoFont;
  // Emoji presentation: a colour face first, the style's or fontconfig's,
  // as Pango does.
  const bool emoji = detail::emoji_presentation(std::u32string_view(para).substr(a, b - a));
  if (emoji) chosen = color_face(a, b, r, used);
  // Spaces, digits and punctuation stay with the font before them when it
  // has them (not with an emoji's), so a run of Arabic words is not cut
  // at every space.
  if (chosen == kNoFont && neutral && !previous_emoji && previous < used.fonts.size() && previous_style == si &&
      covers(*used.fonts[previous], a, b))
    chosen = previous;
  previous_emoji = emoji && chosen != kNoFont;
  for (std::size_t k = 0; chosen == kNoFont && k < r.chain.size(); ++k)
    if (covers(*r.chain[k], a, b)) chosen = used.index_of(r.chain[k]);
  if (chosen == kNoFont) {
    std::size_t c = a;
    while (c + 1 < b && detail::ignorable_for_coverage(para[c])) ++c;
    auto f = fonts.fallback(para[c], r.language_tag, style(si).variations);
    if (f && style(si).variations.empty()) f = styled_like(f, *r.chain.front(), a, b);
    chosen = used.index_of(f ? f : r.chain.front());
  }
  previous = chosen;
  previous_style = si;
  return chosen;
}

// Items: maximal runs of one bidi level, script, font and style, each shaped
// once.
void ParagraphBuilder::build_items(const std::vector<hb_script_t>& script, const std::vector<std::uint32_t>& font_of,
                                   const UsedFonts& used) {
  const std::size_t n = para.size();
  items.clear();
  item_of.assign(n, 0);
  for (std::size_t a = 0; a < n;) {
    std::size_t b = a + 1;
    while (b < n && bidi.levels[b] == bidi.levels[a] && script[b] == script[a] && font_of[b] == font_of[a] &&
           style_of[p0 + b] == style_of[p0 + a])
      ++b;
    Item it;
    it.start = a;
    it.end = b;
    it.level = bidi.levels[a];
    it.script = script[a];
    it.font = used.fonts[font_of[a]];
    it.style = style_of[p0 + a];
    it.glyphs = shape(a, b, it.level, it.script, *it.font, it.style);
    for (std::size_t i = a; i < b; ++i) item_of[i] = items.size();
    items.push_back(std::move(it));
    a = b;
  }
}

// Advances per code point (the glyphs of a cluster count on its first code
// point), plus letter and word spacing.
void ParagraphBuilder::add_advances() {
  const std::size_t n = para.size();
  advance.assign(n, 0.0);
  for (const Item& it : items)
    for (const Glyph& g : it.glyphs) advance[g.cluster] += g.advance;
  for (std::size_t i = 0; i < n; ++i) {
    const TextStyle& s = style(style_of[p0 + i]);
    if (s.letter_spacing != 0.0 && (i + 1 == n || grapheme[i + 1])) advance[i] += s.letter_spacing;
    if (s.word_spacing != 0.0 && detail::is_space(para[i])) advance[i] += s.word_spacing;
  }
}

bool ParagraphBuilder::covers(const Font& font, std::size_t a, std::size_t b) const {
  for (std::size_t i = a; i < b; ++i)
    if (!detail::ignorable_for_coverage(para[i]) && !fonts.has_glyph(font, para[i])) return false;
  return true;
}

// A colour face (COLR or bitmaps) that covers [a, b): the style's first,
// else fontconfig's; kNoFont when none.
std::size_t ParagraphBuilder::color_face(std::size_t a, std::size_t b, const ResolvedStyle& r, UsedFonts& used) {
  for (const auto& f : r.chain)
    if (f->color_format() != ColorFormat::None && covers(*f, a, b)) return used.index_of(f);
  if (auto f = fonts.color_fallback(para[a], r.language_tag); f && covers(*f, a, b)) return used.index_of(f);
  return kNoFont;
}

// A fallback face in the weight and slant of the style's first font (bold
// or italic text stays bold or italic in Hebrew or Arabic): the same
// family's face for them where fontconfig has one that covers [a, b) (a
// Regular-only family's face comes synthesised), else `f` synthesised.
std::shared_ptr<const Font> ParagraphBuilder::styled_like(const std::shared_ptr<const Font>& f, const Font& first,
                                                          std::size_t a, std::size_t b) {
  const float weight = drawn_weight(first);
  const bool italic = drawn_italic(first);
  const bool has_italic = drawn_italic(*f);
  const float has_weight = drawn_weight(*f);
  if (std::abs(weight - has_weight) < 100 && italic == has_italic) return f;
  const std::string family = f->family_name();
  if (family.empty() || family.find_first_of(":,-\\") != std::string::npos) return fonts.synthesised(f, weight, italic);
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

}  // namespace curvetext
