// Line break opportunities (UAX #14) through libunibreak, and grapheme cluster
// boundaries (UAX #29, simplified; see grapheme_boundaries) for caret movement.
//
// Debian 12 ships libunibreak 1.1 (2012, Unicode 6.x tables and rules). The
// layer below corrects what it gets wrong against Unicode 15 where the fix is
// local (see line_break.cpp); what is left is listed, with reasons, in
// tests/fixtures/layout/linebreak_skips.txt and checked by
// tests/line_break_conformance_test.cpp.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

namespace curvetext {

enum class BreakAction : std::uint8_t {
  Mandatory,  // a line must end after this character (LB4-LB6; and the end of the text, LB3)
  Allowed,    // a line may end after this character
  None,       // no break after this character
};

// One action per code point: whether a line may end after it. `language` (BCP
// 47, may be empty) selects libunibreak's tailorings (e.g. "de", "zh", "ja").
std::vector<BreakAction> line_breaks(std::u32string_view text, std::string_view language = {});

// One flag per code point: true where a grapheme cluster starts. Covers the
// rules that matter for carets: CR LF, combining marks and spacing marks,
// ZWJ, variation selectors, emoji modifiers, regional indicator pairs and
// Hangul syllable sequences.
std::vector<bool> grapheme_starts(std::u32string_view text);

}  // namespace curvetext
