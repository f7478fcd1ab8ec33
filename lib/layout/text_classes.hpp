// Private: the character classes paragraph layout tests several times per
// character (ASCII, most of the text in many paragraphs, is answered without
// a Unicode table lookup), from HarfBuzz's Unicode data.
#pragma once

#include <hb.h>

namespace curvetext::detail {

inline bool is_paragraph_separator(char32_t c) {
  return c == U'\n' || c == U'\r' || c == 0x2029 || c == 0x85 || (c >= 0x1C && c <= 0x1E);
}

inline hb_unicode_funcs_t* unicode_funcs() {
  static hb_unicode_funcs_t* const funcs = hb_unicode_funcs_get_default();
  return funcs;
}

inline bool is_space(char32_t c) {
  if (c < 0x80) return c == U' ';
  return hb_unicode_general_category(unicode_funcs(), c) == HB_UNICODE_GENERAL_CATEGORY_SPACE_SEPARATOR;
}

inline bool is_whitespace(char32_t c) {
  if (c < 0x80) return c == U' ' || c == U'\t' || c == U'\n' || c == U'\r' || (c >= 0x1C && c <= 0x1E);
  return is_space(c) || c == 0x2028 || is_paragraph_separator(c);
}

// Characters that need no glyph of their own when choosing a font.
inline bool ignorable_for_coverage(char32_t c) {
  return c < 0x20 || c == 0x7F || c == 0xAD || (c >= 0x200B && c <= 0x200F) || (c >= 0x2028 && c <= 0x202E) ||
         (c >= 0x2060 && c <= 0x206F) || c == 0xFEFF || (c >= 0xFE00 && c <= 0xFE0F) ||
         (c >= 0xE0000 && c <= 0xE0FFF) || c == 0x034F;
}

inline hb_script_t script_of(char32_t c) {
  if (c < 0x80) return ((c | 0x20) >= U'a' && (c | 0x20) <= U'z') ? HB_SCRIPT_LATIN : HB_SCRIPT_COMMON;
  return hb_unicode_script(unicode_funcs(), c);
}

}  // namespace curvetext::detail
