// The Unicode Bidirectional Algorithm (UAX #9) for one paragraph, through
// FriBiDi: resolved embedding levels per code point, the paragraph direction
// (explicit or found from the first strong character, rules P2-P3), and the
// visual order of a line (rules L1-L2). Mirroring of brackets in right-to-left
// runs (L4) is done by HarfBuzz when it shapes an RTL run; mirror() exposes the
// same mapping for callers that draw without shaping.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

#include "curvetext/export.hpp"

namespace curvetext {

enum class BaseDirection {
  Auto,  // from the first strong character (P2-P3); left-to-right when there is none
  Ltr,
  Rtl,
};

struct BidiParagraph {
  int paragraph_level = 0;           // 0 left-to-right, 1 right-to-left
  std::vector<std::uint8_t> levels;  // one per code point, after rules W1-I2 (not L1)
};

// Levels for one paragraph of text (it should hold no paragraph separator but
// its last character). Characters that rule X9 removes (embedding controls,
// boundary neutrals) get the level of the character before them, so they stay
// inside their neighbours' runs when shaped. Throws Error(InvalidText) for a
// paragraph over INT_MAX / 2 code points or one FriBiDi cannot resolve.
CURVETEXT_API BidiParagraph resolve_bidi(std::u32string_view paragraph, BaseDirection direction);

// True for characters rule X9 removes (LRE, RLE, LRO, RLO, PDF and class BN):
// they have no level of their own and no place in the visual order.
CURVETEXT_API bool bidi_removed(char32_t c);

// Levels of the line [start, end) after rule L1 (segment separators, and
// whitespace and isolate controls before them or at the end of the line, go
// to the paragraph level), indexed from `start`. [start, end) are code point
// indices into `paragraph`, whose resolve_bidi result `bidi` is.
CURVETEXT_API std::vector<std::uint8_t> line_levels(std::u32string_view paragraph, const BidiParagraph& bidi,
                                                    std::size_t start, std::size_t end);

// Visual order of the line: result[k] is the index (into the paragraph) of the
// code point shown k-th from the left (rule L2 on line_levels). Characters
// removed by X9 are left out.
CURVETEXT_API std::vector<std::size_t> visual_order(std::u32string_view paragraph, const BidiParagraph& bidi,
                                                    std::size_t start, std::size_t end);

// Rule L2 on arbitrary levels: the visual order of items 0..levels.size()-1.
CURVETEXT_API std::vector<std::size_t> reorder_levels(const std::vector<std::uint8_t>& levels);

// The Bidi_Mirroring_Glyph of c, or c when it has none.
CURVETEXT_API char32_t bidi_mirror(char32_t c);

}  // namespace curvetext
