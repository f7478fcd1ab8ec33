// Paragraph layout, style resolution and shaping: each distinct style's font
// chain, language and OpenType features, and runs of the paragraph shaped
// into glyphs in pixels (paragraph_builder.hpp).

#include <hb.h>

#include <map>
#include <string>

#include "curvetext/error.hpp"
#include "core/format.hpp"
#include "font/face_queries.hpp"
#include "layout/paragraph_builder.hpp"

namespace curvetext {

// Styles that differ only in what font lookup and shaping features do not
// depend on (colour, size, decorations) share one resolution: many spans
// cost one lookup.
void ParagraphBuilder::resolve_styles() {
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

ParagraphBuilder::ResolvedStyle ParagraphBuilder::resolve_style(const TextStyle& s) {
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
std::vector<ParagraphBuilder::Glyph> ParagraphBuilder::shape(std::size_t a, std::size_t b, std::uint8_t level,
                                                             hb_script_t script, const Font& font,
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
std::vector<ParagraphBuilder::Glyph> ParagraphBuilder::shape_string(const std::u32string& s, const Font& font,
                                                                    std::size_t style_index, std::uint8_t level) const {
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

std::vector<ParagraphBuilder::Glyph> ParagraphBuilder::to_pixels(std::span<const detail::UnitGlyph> units,
                                                                 const Font& font, std::size_t style_index) const {
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

std::vector<ParagraphBuilder::Glyph> ParagraphBuilder::hyphen_glyphs(const Item& it) const {
  const std::u32string h = it.font->glyph_for_codepoint(0x2010) ? U"\u2010" : U"-";
  return shape_string(h, *it.font, it.style, it.level);
}

std::vector<ParagraphBuilder::Glyph> ParagraphBuilder::ellipsis_glyphs(const Item& near) const {
  const std::u32string e = near.font->glyph_for_codepoint(0x2026) ? U"\u2026" : U"...";
  return shape_string(e, *near.font, near.style, static_cast<std::uint8_t>(bidi.paragraph_level));
}

double ParagraphBuilder::space_width(std::size_t style_index) const {
  const Font& f = *resolved[style_index]->chain.front();
  const std::uint32_t g = f.glyph_for_codepoint(U' ');
  const double s = style(style_index).size_px / f.metrics().units_per_em;
  return g ? detail::glyph_h_advance(f, g) * s : style(style_index).size_px / 3.0;
}

}  // namespace curvetext
