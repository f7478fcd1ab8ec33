// Line breaking (UAX #14, Unicode 15.0) and a compact grapheme cluster
// segmentation.
//
// Classes come from line_break_table.inc, generated at build time from
// Debian's unicode-data (LineBreak.txt, EastAsianWidth.txt, UnicodeData.txt,
// emoji-data.txt) by tools/gen_line_break_table.cpp, with libunibreak's
// language tailorings on top. The rules LB2-LB31 (LB25 in the regex form of
// UAX #14 example 7, as LineBreakTest.txt uses) are one pass over the class
// sequence. libunibreak 1.1's own pass (Unicode 6 rules and data) is no
// longer run: correcting its result needed every rule anyway, and this pass
// is cheaper than libunibreak's.

#include "curvetext/line_break.hpp"

#include <hb.h>
#include <linebreak.h>
#include <linebreakdef.h>

#include <bitset>
#include <cstdint>
#include <cstring>
#include <iterator>
#include <string>

namespace curvetext {

namespace {

#include "line_break_table.inc"

// UAX #14 Line_Break classes after LB1, in the generator's order
// (tools/gen_line_break_table.cpp).
enum class Lb : std::uint8_t {
  BK,
  CR,
  LF,
  NL,
  SP,
  ZW,
  WJ,
  GL,
  CM,
  ZWJ,
  OP,
  CL,
  CP,
  QU,
  IS,
  SY,
  NS,
  EX,
  BA,
  BB,
  B2,
  HY,
  CB,
  HL,
  AL,
  NU,
  PR,
  PO,
  ID,
  EB,
  EM,
  IN,
  H2,
  H3,
  JL,
  JV,
  JT,
  RI,
  AK,
  AP,
  AS,
  VI,
  VF
};
constexpr std::uint8_t kClassMask = 0x3F;
constexpr std::uint8_t kWide = 0x40;                    // East_Asian_Width F, W or H
constexpr std::uint8_t kPictographicUnassigned = 0x80;  // Extended_Pictographic and Cn

std::uint8_t properties(char32_t c) {
  if (c >= 0x110000) return static_cast<std::uint8_t>(Lb::AL);
  return kLbBlocks[kLbStage1[c >> kLbBlockShift]][c & ((1u << kLbBlockShift) - 1)];
}

// libunibreak's classes, in its enum's order (linebreakdef.h), as ours; its
// classes outside LB1's result are resolved as LB1 does (SA as AL: its
// tailorings contain none).
Lb from_libunibreak(int c) {
  static constexpr Lb map[] = {Lb::AL /*Undefined*/,
                               Lb::OP,
                               Lb::CL,
                               Lb::CP,
                               Lb::QU,
                               Lb::GL,
                               Lb::NS,
                               Lb::EX,
                               Lb::SY,
                               Lb::IS,
                               Lb::PR,
                               Lb::PO,
                               Lb::NU,
                               Lb::AL,
                               Lb::HL,
                               Lb::ID,
                               Lb::IN,
                               Lb::HY,
                               Lb::BA,
                               Lb::BB,
                               Lb::B2,
                               Lb::ZW,
                               Lb::CM,
                               Lb::WJ,
                               Lb::H2,
                               Lb::H3,
                               Lb::JL,
                               Lb::JV,
                               Lb::JT,
                               Lb::RI,
                               Lb::AL /*AI*/,
                               Lb::BK,
                               Lb::CB,
                               Lb::NS /*CJ*/,
                               Lb::CR,
                               Lb::LF,
                               Lb::NL,
                               Lb::AL /*SA*/,
                               Lb::AL /*SG*/,
                               Lb::SP,
                               Lb::AL /*XX*/};
  return c >= 0 && c < static_cast<int>(std::size(map)) ? map[c] : Lb::AL;
}

// The language tailorings of libunibreak (its lb_prop_lang_map: quotation
// marks as opening/closing punctuation in German, French, Chinese, Japanese,
// ...), applied over the Unicode 15 classes.
void apply_tailoring(std::u32string_view text, std::string_view language, std::vector<std::uint8_t>& props) {
  const std::string lang(language);
  const LineBreakProperties* table = nullptr;
  for (const LineBreakPropertiesLang* m = lb_prop_lang_map; m->lang != nullptr; ++m)
    if (std::strncmp(lang.c_str(), m->lang, m->namelen) == 0) {
      table = m->lbp;
      break;
    }
  if (table == nullptr) return;
  for (std::size_t i = 0; i < text.size(); ++i)
    for (const LineBreakProperties* p = table; p->prop != LBP_Undefined; ++p)
      if (text[i] >= p->start && text[i] <= p->end) {
        props[i] =
            static_cast<std::uint8_t>((props[i] & ~kClassMask) | static_cast<std::uint8_t>(from_libunibreak(p->prop)));
        break;
      }
}

hb_unicode_general_category_t category(char32_t c) {
  return hb_unicode_general_category(hb_unicode_funcs_get_default(), static_cast<hb_codepoint_t>(c));
}

bool is_mark_uncached(char32_t c) {
  const auto g = category(c);
  return g == HB_UNICODE_GENERAL_CATEGORY_NON_SPACING_MARK || g == HB_UNICODE_GENERAL_CATEGORY_SPACING_MARK ||
         g == HB_UNICODE_GENERAL_CATEGORY_ENCLOSING_MARK;
}

// General category M for the BMP as a bit set, filled once (65,536 lookups,
// under a millisecond): grapheme_starts asks for every character past U+0300,
// and HarfBuzz's per-call lookup was 9% of laying out a Hebrew paragraph.
bool is_mark(char32_t c) {
  static const std::bitset<0x10000> bmp = [] {
    std::bitset<0x10000> bits;
    for (char32_t u = 0; u < 0x10000; ++u) bits[u] = is_mark_uncached(u);
    return bits;
  }();
  return c < 0x10000 ? bmp[c] : is_mark_uncached(c);
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

// UAX #14 over one text: the rules LB4-LB31 as a pass over the characters,
// with the state after each character (on the sequence after LB9/LB10, where
// a base and the marks it carries count as the base) in members.
class LineBreaker {
 public:
  LineBreaker(std::u32string_view text, std::string_view language) : text_(text), n_(text.size()), props_(n_) {
    for (std::size_t i = 0; i < n_; ++i) props_[i] = properties(text[i]);
    if (!language.empty()) apply_tailoring(text, language, props_);
  }

  std::vector<BreakAction> run();

 private:
  Lb cls(std::size_t i) const { return static_cast<Lb>(props_[i] & kClassMask); }
  // The class of the first character at or after j that is not CM or ZWJ (a
  // look-ahead for LB25 and LB28a, where LB9 lets marks sit in between).
  Lb next_base(std::size_t j) const {
    while (j < n_ && (cls(j) == Lb::CM || cls(j) == Lb::ZWJ)) ++j;
    return j < n_ ? cls(j) : Lb::BK;
  }
  static bool is_aksara(Lb c, char32_t ch) { return c == Lb::AK || c == Lb::AS || ch == 0x25CC; }
  BreakAction action_before(std::size_t i, Lb cb, Lb sp_base, bool& absorbed) const;
  BreakAction pair_action(Lb a, Lb b, std::size_t i, Lb sp_base) const;
  void advance(std::size_t i, Lb cb);

  std::u32string_view text_;
  std::size_t n_;
  std::vector<std::uint8_t> props_;
  // State after character i-1:
  Lb eff = Lb::BK;  // effective class
  std::uint8_t a_props = 0;
  char32_t a_char = 0;
  Lb a_prev = Lb::BK;  // the effective class before eff (sot reads as BK: matches no rule)
  char32_t a_prev_char = 0;
  Lb before_spaces = Lb::BK;  // when eff is SP: the effective class before the spaces
  std::size_t ri_run = 0;
  // LB25 (tailored as in UAX #14 example 7): eff ends NU (NU|SY|IS)*, or that followed by CL/CP.
  bool numeric = false, numeric_close = false;
};

std::vector<BreakAction> LineBreaker::run() {
  std::vector<BreakAction> result(n_, BreakAction::None);
  if (n_ == 0) return result;
  eff = cls(0);
  if (eff == Lb::CM || eff == Lb::ZWJ) eff = Lb::AL;  // LB10
  a_props = props_[0];
  a_char = text_[0];
  ri_run = eff == Lb::RI ? 1 : 0;
  numeric = eff == Lb::NU;
  for (std::size_t i = 1; i < n_; ++i) {
    Lb cb = cls(i);
    bool absorbed = false;
    const Lb sp_base = eff == Lb::SP ? before_spaces : eff;
    result[i - 1] = action_before(i, cb, sp_base, absorbed);
    if (absorbed) continue;
    if (cb == Lb::CM || cb == Lb::ZWJ) cb = Lb::AL;  // LB10
    advance(i, cb);
  }
  result[n_ - 1] = BreakAction::Mandatory;  // LB3
  return result;
}

// LB4-LB10 before character i (class cb); `absorbed`: LB9 attaches it to
// the base before it.
BreakAction LineBreaker::action_before(std::size_t i, Lb cb, Lb sp_base, bool& absorbed) const {
  const Lb raw_a = cls(i - 1);
  if (raw_a == Lb::BK) return BreakAction::Mandatory;             // LB4
  if (raw_a == Lb::CR && cb == Lb::LF) return BreakAction::None;  // LB5
  if (raw_a == Lb::CR || raw_a == Lb::LF || raw_a == Lb::NL) return BreakAction::Mandatory;
  if (cb == Lb::BK || cb == Lb::CR || cb == Lb::LF || cb == Lb::NL) return BreakAction::None;  // LB6
  if (cb == Lb::SP || cb == Lb::ZW) return BreakAction::None;                                  // LB7
  if (sp_base == Lb::ZW) return BreakAction::Allowed;                                          // LB8
  if (raw_a == Lb::ZWJ) return BreakAction::None;                                              // LB8a
  if ((cb == Lb::CM || cb == Lb::ZWJ) && eff != Lb::SP) {
    absorbed = true;
    return BreakAction::None;  // LB9 (eff is never BK, CR, LF, NL or ZW here)
  }
  return pair_action(eff, cb == Lb::CM || cb == Lb::ZWJ ? Lb::AL : cb, i, sp_base);  // LB10
}

// LB11-LB31 between effective classes a and b (b at index i).
BreakAction LineBreaker::pair_action(Lb a, Lb b, std::size_t i, Lb sp_base) const {
  constexpr BreakAction no = BreakAction::None, yes = BreakAction::Allowed;
  if (a == Lb::WJ || b == Lb::WJ) return no;                                               // LB11
  if (a == Lb::GL) return no;                                                              // LB12
  if (b == Lb::GL && a != Lb::SP && a != Lb::BA && a != Lb::HY) return no;                 // LB12a
  if (b == Lb::CL || b == Lb::CP || b == Lb::EX || b == Lb::IS || b == Lb::SY) return no;  // LB13
  if (sp_base == Lb::OP) return no;                                                        // LB14
  if (b == Lb::OP && sp_base == Lb::QU) return no;                                         // LB15
  if (b == Lb::NS && (sp_base == Lb::CL || sp_base == Lb::CP)) return no;                  // LB16
  if (b == Lb::B2 && sp_base == Lb::B2) return no;                                         // LB17
  if (a == Lb::SP) return yes;                                                             // LB18
  if (a == Lb::QU || b == Lb::QU) return no;                                               // LB19
  if (a == Lb::CB || b == Lb::CB) return yes;                                              // LB20
  if (b == Lb::BA || b == Lb::HY || b == Lb::NS || a == Lb::BB) return no;                 // LB21
  if ((a == Lb::HY || a == Lb::BA) && a_prev == Lb::HL) return no;                         // LB21a
  if (a == Lb::SY && b == Lb::HL) return no;                                               // LB21b
  if (b == Lb::IN) return no;                                                              // LB22
  const bool a_letter = a == Lb::AL || a == Lb::HL, b_letter = b == Lb::AL || b == Lb::HL;
  if ((a_letter && b == Lb::NU) || (a == Lb::NU && b_letter)) return no;  // LB23
  const bool b_ideo = b == Lb::ID || b == Lb::EB || b == Lb::EM;
  if ((a == Lb::PR && b_ideo) || ((a == Lb::ID || a == Lb::EB || a == Lb::EM) && b == Lb::PO)) return no;  // LB23a
  const bool a_prpo = a == Lb::PR || a == Lb::PO, b_prpo = b == Lb::PR || b == Lb::PO;
  if ((a_prpo && b_letter) || (a_letter && b_prpo)) return no;                                             // LB24
  if (a_prpo && (b == Lb::NU || ((b == Lb::OP || b == Lb::HY) && next_base(i + 1) == Lb::NU))) return no;  // LB25
  if ((a == Lb::OP || a == Lb::HY) && b == Lb::NU) return no;
  if (numeric && (b == Lb::NU || b == Lb::SY || b == Lb::IS || b == Lb::CL || b == Lb::CP)) return no;
  if ((numeric || numeric_close) && b_prpo) return no;
  if ((a == Lb::JL && (b == Lb::JL || b == Lb::JV || b == Lb::H2 || b == Lb::H3)) ||  // LB26
      ((a == Lb::JV || a == Lb::H2) && (b == Lb::JV || b == Lb::JT)) || ((a == Lb::JT || a == Lb::H3) && b == Lb::JT))
    return no;
  const bool a_korean = a == Lb::JL || a == Lb::JV || a == Lb::JT || a == Lb::H2 || a == Lb::H3;
  const bool b_korean = b == Lb::JL || b == Lb::JV || b == Lb::JT || b == Lb::H2 || b == Lb::H3;
  if ((a_korean && b == Lb::PO) || (a == Lb::PR && b_korean)) return no;          // LB27
  if (a_letter && b_letter) return no;                                            // LB28
  const bool a_aksara = is_aksara(a, a_char), b_aksara = is_aksara(b, text_[i]);  // LB28a
  if (a == Lb::AP && b_aksara) return no;
  if (a_aksara && (b == Lb::VF || b == Lb::VI)) return no;
  if (a == Lb::VI && is_aksara(a_prev, a_prev_char) && (b == Lb::AK || text_[i] == 0x25CC)) return no;
  if (a_aksara && b_aksara && next_base(i + 1) == Lb::VF) return no;
  if (a == Lb::IS && b_letter) return no;                                           // LB29
  if ((a_letter || a == Lb::NU) && b == Lb::OP && !(props_[i] & kWide)) return no;  // LB30
  if (a == Lb::CP && !(a_props & kWide) && (b_letter || b == Lb::NU)) return no;
  if (a == Lb::RI && b == Lb::RI && ri_run % 2 == 1) return no;                        // LB30a
  if (b == Lb::EM && (a == Lb::EB || (a_props & kPictographicUnassigned))) return no;  // LB30b
  return yes;                                                                          // LB31
}

// The state after character i, of effective class cb.
void LineBreaker::advance(std::size_t i, Lb cb) {
  if (cb == Lb::SP && eff != Lb::SP) before_spaces = eff;
  numeric_close = numeric && (cb == Lb::CL || cb == Lb::CP);
  numeric = cb == Lb::NU || (numeric && (cb == Lb::SY || cb == Lb::IS));
  ri_run = cb == Lb::RI ? ri_run + 1 : 0;
  a_prev = eff;
  a_prev_char = a_char;
  eff = cb;
  a_props = props_[i];
  a_char = text_[i];
}

}  // namespace

std::vector<BreakAction> line_breaks(std::u32string_view text, std::string_view language) {
  return LineBreaker(text, language).run();
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
    // Below U+1100 (Latin through Thai, Tibetan, Myanmar) there is no Hangul,
    // regional indicator, emoji modifier or variation selector: only marks
    // extend (GB9), and ZWJ (U+200D) lies above.
    if (a < 0x1100 && b < 0x1100) {
      starts[i] = is_control(a) || is_control(b) || !is_mark(b);
      continue;
    }
    bool join = false;
    if (a == U'\r' && b == U'\n')
      join = true;  // GB3
    else if (is_control(a) || is_control(b))
      join = false;  // GB4-5
    else if (is_mark(b) || b == 0x200D || is_variation_selector(b) || is_emoji_modifier(b))
      join = true;  // GB9, 9a
    else if (a == 0x200D && is_pictographic(b))
      join = true;  // GB11
    else if (is_regional_indicator(a) && is_regional_indicator(b))
      join = ri_run % 2 == 1;  // GB12-13
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
