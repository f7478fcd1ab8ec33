// Line breaking with libunibreak, corrected towards Unicode 15 (see the
// header), and a compact grapheme cluster segmentation.

#include "curvetext/line_break.hpp"

#include <hb.h>
#include <linebreak.h>

#include <mutex>
#include <string>

namespace curvetext {

namespace {

void init_once() {
  static std::once_flag flag;
  std::call_once(flag, [] { init_linebreak(); });
}

hb_unicode_general_category_t category(char32_t c) {
  return hb_unicode_general_category(hb_unicode_funcs_get_default(), static_cast<hb_codepoint_t>(c));
}

bool is_mark(char32_t c) {
  const auto g = category(c);
  return g == HB_UNICODE_GENERAL_CATEGORY_NON_SPACING_MARK || g == HB_UNICODE_GENERAL_CATEGORY_SPACING_MARK ||
         g == HB_UNICODE_GENERAL_CATEGORY_ENCLOSING_MARK;
}

// Grapheme_Cluster_Break=Control, approximately: C0/C1 controls and the line
// and paragraph separators (so a paragraph never starts inside a cluster).
bool is_control(char32_t c) { return c < 0x20 || (c >= 0x7F && c <= 0x9F) || c == 0x2028 || c == 0x2029; }
bool is_regional_indicator(char32_t c) { return c >= 0x1F1E6 && c <= 0x1F1FF; }
bool is_emoji_modifier(char32_t c) { return c >= 0x1F3FB && c <= 0x1F3FF; }
bool is_variation_selector(char32_t c) {
  return (c >= 0xFE00 && c <= 0xFE0F) || (c >= 0xE0100 && c <= 0xE01EF) || (c >= 0x180B && c <= 0x180D);
}
// Extended_Pictographic, approximately: the emoji and pictograph blocks.
bool is_pictographic(char32_t c) {
  return (c >= 0x1F000 && c <= 0x1FAFF) || (c >= 0x2600 && c <= 0x27BF) || (c >= 0x2300 && c <= 0x23FF) ||
         c == 0x00A9 || c == 0x00AE || c == 0x203C || c == 0x2049 || c == 0x2122 || (c >= 0x2B00 && c <= 0x2BFF);
}

enum class Hangul { None, L, V, T, LV, LVT };
Hangul hangul(char32_t c) {
  if ((c >= 0x1100 && c <= 0x115F) || (c >= 0xA960 && c <= 0xA97C)) return Hangul::L;
  if ((c >= 0x1160 && c <= 0x11A7) || (c >= 0xD7B0 && c <= 0xD7C6)) return Hangul::V;
  if ((c >= 0x11A8 && c <= 0x11FF) || (c >= 0xD7CB && c <= 0xD7FB)) return Hangul::T;
  if (c >= 0xAC00 && c <= 0xD7A3) return (c - 0xAC00) % 28 == 0 ? Hangul::LV : Hangul::LVT;
  return Hangul::None;
}

}  // namespace

std::vector<BreakAction> line_breaks(std::u32string_view text, std::string_view language) {
  init_once();
  std::vector<BreakAction> result(text.size(), BreakAction::None);
  if (text.empty()) return result;
  std::vector<char> brks(text.size());
  const std::string lang(language);
  // libunibreak 1.1 has class RI in its data but not in its pair table, and
  // asserts (aborting the process) on any regional indicator. Give it an
  // ideograph instead, which breaks on both sides like RI (LB31), and apply
  // LB30a (pairs stay together) below.
  std::u32string input(text);
  bool has_ri = false;
  for (char32_t& c : input)
    if (c >= 0x1F1E6 && c <= 0x1F1FF) {
      c = 0x4E00;
      has_ri = true;
    }
  set_linebreaks_utf32(reinterpret_cast<const utf32_t*>(input.data()), input.size(),
                       lang.empty() ? nullptr : lang.c_str(), brks.data());
  // LB8a (Unicode 9): no break after ZERO WIDTH JOINER, which 1.1 classes as
  // CM with a break opportunity after it in some contexts.
  for (std::size_t i = 0; i + 1 < text.size(); ++i)
    if (text[i] == 0x200D && brks[i] == LINEBREAK_ALLOWBREAK) brks[i] = LINEBREAK_NOBREAK;
  if (has_ri) {
    std::size_t run = 0;
    for (std::size_t i = 0; i + 1 < text.size(); ++i) {
      run = is_regional_indicator(text[i]) ? run + 1 : 0;
      // LB30a: RI x RI when an odd number of RIs precede the break.
      if (run % 2 == 1 && is_regional_indicator(text[i + 1])) brks[i] = LINEBREAK_NOBREAK;
    }
  }
  for (std::size_t i = 0; i < text.size(); ++i)
    result[i] = brks[i] == LINEBREAK_MUSTBREAK    ? BreakAction::Mandatory
                : brks[i] == LINEBREAK_ALLOWBREAK ? BreakAction::Allowed
                                                  : BreakAction::None;
  return result;
}

std::vector<bool> grapheme_starts(std::u32string_view text) {
  std::vector<bool> starts(text.size(), true);
  std::size_t ri_run = 0;  // regional indicators in a row before the current one
  for (std::size_t i = 1; i < text.size(); ++i) {
    const char32_t a = text[i - 1];
    const char32_t b = text[i];
    ri_run = is_regional_indicator(a) ? ri_run + 1 : 0;
    // Fast path: below U+0300 nothing extends, joins or is Hangul, so only CR
    // LF and GB11 (ZWJ before a pictograph such as U+00A9) can join.
    if (b < 0x300 && a != 0x200D) {
      starts[i] = !(a == U'\r' && b == U'\n');
      continue;
    }
    bool join = false;
    if (a == U'\r' && b == U'\n') join = true;                                       // GB3
    else if (is_control(a) || is_control(b)) join = false;                           // GB4-5
    else if (is_mark(b) || b == 0x200D || is_variation_selector(b) || is_emoji_modifier(b)) join = true;  // GB9, 9a
    else if (a == 0x200D && is_pictographic(b)) join = true;                         // GB11
    else if (is_regional_indicator(a) && is_regional_indicator(b)) join = ri_run % 2 == 1;  // GB12-13
    else {
      const Hangul ha = hangul(a), hb = hangul(b);  // GB6-8
      join = (ha == Hangul::L && hb != Hangul::None && hb != Hangul::T) ||
             ((ha == Hangul::LV || ha == Hangul::V) && (hb == Hangul::V || hb == Hangul::T)) ||
             ((ha == Hangul::LVT || ha == Hangul::T) && hb == Hangul::T);
    }
    starts[i] = !join;
  }
  return starts;
}

}  // namespace curvetext
