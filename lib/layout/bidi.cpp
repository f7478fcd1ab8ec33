// UAX #9 through FriBiDi. Levels come from fribidi_get_par_embedding_levels_ex
// (rules P2-I2 with bracket pairs, N0); the line rules L1 and L2 are done here
// because they work on a line of a paragraph and FriBiDi's reorder_line also
// applies optional rules (L3 reordering of marks) that layout does not want.

#include "curvetext/bidi.hpp"

#include <fribidi.h>

#include <algorithm>
#include <climits>
#include <string>

#include "curvetext/error.hpp"

namespace curvetext {

namespace {

std::vector<FriBidiCharType> bidi_types(std::u32string_view text) {
  std::vector<FriBidiCharType> types(text.size());
  fribidi_get_bidi_types(reinterpret_cast<const FriBidiChar*>(text.data()), static_cast<FriBidiStrIndex>(text.size()),
                         types.data());
  return types;
}

}  // namespace

bool bidi_removed(char32_t c) {
  const FriBidiCharType t = fribidi_get_bidi_type(static_cast<FriBidiChar>(c));
  return FRIBIDI_IS_EXPLICIT_OR_BN(t) != 0;
}

char32_t bidi_mirror(char32_t c) {
  FriBidiChar mirrored = 0;
  return fribidi_get_mirror_char(static_cast<FriBidiChar>(c), &mirrored) ? static_cast<char32_t>(mirrored) : c;
}

BidiParagraph resolve_bidi(std::u32string_view paragraph, BaseDirection direction) {
  if (paragraph.size() > static_cast<std::size_t>(INT_MAX / 2))
    throw Error(ErrorCode::InvalidText, "paragraph too long for the bidi algorithm");
  BidiParagraph result;
  const auto n = static_cast<FriBidiStrIndex>(paragraph.size());
  if (n == 0) {
    result.paragraph_level = direction == BaseDirection::Rtl ? 1 : 0;
    return result;
  }
  // Fast path: a paragraph that is not forced right-to-left and has no
  // R, AL, AN or explicit embedding/isolate is all at level 0 (P2-P3 give
  // level 0; W7 turns EN into L after sos L; neutrals between L and sos/eos L
  // resolve to L). Most text is like this, and FriBiDi's full pass is a large
  // part of laying out a Latin paragraph.
  if (direction != BaseDirection::Rtl) {
    bool simple = true;
    for (const char32_t c : paragraph) {
      if (c < 0x80) continue;  // ASCII is L, EN, ES, ET, CS, B, S, WS, ON or BN
      const FriBidiCharType t = fribidi_get_bidi_type(static_cast<FriBidiChar>(c));
      if (FRIBIDI_IS_RTL(t) || t == FRIBIDI_TYPE_AN || FRIBIDI_IS_EXPLICIT(t) || FRIBIDI_IS_ISOLATE(t)) {
        simple = false;
        break;
      }
    }
    if (simple) {
      result.paragraph_level = 0;
      result.levels.assign(paragraph.size(), 0);
      return result;
    }
  }
  const std::vector<FriBidiCharType> types = bidi_types(paragraph);
  std::vector<FriBidiBracketType> brackets(paragraph.size());
  fribidi_get_bracket_types(reinterpret_cast<const FriBidiChar*>(paragraph.data()), n, types.data(), brackets.data());
  FriBidiParType base = direction == BaseDirection::Ltr   ? FRIBIDI_PAR_LTR
                        : direction == BaseDirection::Rtl ? FRIBIDI_PAR_RTL
                                                          : FRIBIDI_PAR_ON;
  std::vector<FriBidiLevel> levels(paragraph.size());
  if (fribidi_get_par_embedding_levels_ex(types.data(), brackets.data(), n, &base, levels.data()) == 0)
    throw Error(ErrorCode::InvalidText, "the bidi algorithm failed on this paragraph");
  result.paragraph_level = FRIBIDI_IS_RTL(base) ? 1 : 0;
  result.levels.resize(paragraph.size());
  for (std::size_t i = 0; i < paragraph.size(); ++i) {
    // X9-removed characters: FriBiDi gives them a level, but the UBA does not;
    // use the previous character's so that they never split a shaping run.
    if (FRIBIDI_IS_EXPLICIT_OR_BN(types[i]))
      result.levels[i] = static_cast<std::uint8_t>(i > 0 ? result.levels[i - 1] : result.paragraph_level);
    else
      result.levels[i] = static_cast<std::uint8_t>(levels[i]);
  }
  // Removed characters at the start take the next kept character's level.
  std::size_t first = 0;
  while (first < paragraph.size() && FRIBIDI_IS_EXPLICIT_OR_BN(types[first])) ++first;
  for (std::size_t i = 0; i < first && first < paragraph.size(); ++i) result.levels[i] = result.levels[first];
  return result;
}

std::vector<std::uint8_t> line_levels(std::u32string_view paragraph, const BidiParagraph& bidi, std::size_t start,
                                      std::size_t end) {
  end = std::min(end, paragraph.size());
  start = std::min(start, end);
  std::vector<std::uint8_t> levels(bidi.levels.begin() + static_cast<std::ptrdiff_t>(start),
                                   bidi.levels.begin() + static_cast<std::ptrdiff_t>(end));
  // L1 only moves characters to the paragraph level: nothing to do when the
  // paragraph and every level on the line are 0.
  if (bidi.paragraph_level == 0 && std::all_of(levels.begin(), levels.end(), [](std::uint8_t l) { return l == 0; }))
    return levels;
  const std::vector<FriBidiCharType> types = bidi_types(paragraph.substr(start, end - start));
  const auto para = static_cast<std::uint8_t>(bidi.paragraph_level);
  // L1, scanning backwards: `trailing` is true while every character since
  // the line end or the last separator is whitespace, an isolate control or
  // removed by X9.
  bool trailing = true;
  for (std::size_t k = levels.size(); k-- > 0;) {
    const FriBidiCharType t = types[k];
    if (t == FRIBIDI_TYPE_SS || t == FRIBIDI_TYPE_BS) {
      levels[k] = para;
      trailing = true;
    } else if (trailing && (t == FRIBIDI_TYPE_WS || FRIBIDI_IS_ISOLATE(t) || FRIBIDI_IS_EXPLICIT_OR_BN(t))) {
      levels[k] = para;
    } else {
      trailing = false;
    }
  }
  return levels;
}

std::vector<std::size_t> reorder_levels(const std::vector<std::uint8_t>& levels) {
  std::vector<std::size_t> order(levels.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  if (levels.empty()) return order;
  const std::uint8_t highest = *std::max_element(levels.begin(), levels.end());
  std::uint8_t lowest_odd = 255;
  for (std::uint8_t l : levels)
    if (l % 2 == 1) lowest_odd = std::min(lowest_odd, l);
  // L2: from the highest level down to the lowest odd level, reverse every
  // maximal sequence at that level or higher. Levels travel with the items.
  std::vector<std::uint8_t> lv = levels;
  for (int level = highest; level >= lowest_odd && level > 0; --level) {
    std::size_t i = 0;
    while (i < lv.size()) {
      if (lv[i] < level) {
        ++i;
        continue;
      }
      std::size_t j = i;
      while (j < lv.size() && lv[j] >= level) ++j;
      std::reverse(order.begin() + static_cast<std::ptrdiff_t>(i), order.begin() + static_cast<std::ptrdiff_t>(j));
      std::reverse(lv.begin() + static_cast<std::ptrdiff_t>(i), lv.begin() + static_cast<std::ptrdiff_t>(j));
      i = j;
    }
  }
  return order;
}

std::vector<std::size_t> visual_order(std::u32string_view paragraph, const BidiParagraph& bidi, std::size_t start,
                                      std::size_t end) {
  const std::vector<std::uint8_t> levels = line_levels(paragraph, bidi, start, end);
  std::vector<std::size_t> order = reorder_levels(levels);
  std::vector<std::size_t> result;
  result.reserve(order.size());
  for (std::size_t k : order)
    if (!bidi_removed(paragraph[start + k])) result.push_back(start + k);
  return result;
}

}  // namespace curvetext
