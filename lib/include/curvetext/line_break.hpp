// Line break opportunities (UAX #14, Unicode 15.0: classes generated at build
// time from Debian's unicode-data, libunibreak's language tailorings), and
// grapheme cluster boundaries (UAX #29, simplified; see grapheme_boundaries)
// for caret movement.
//
// tests/line_break_conformance_test.cpp runs LineBreakTest.txt (Unicode 15.0);
// cases still wrong would be listed, with reasons, in
// tests/fixtures/layout/linebreak_skips.txt (none are).
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include "curvetext/export.hpp"

namespace curvetext {

enum class BreakAction : std::uint8_t {
  Mandatory,  // a line must end after this character (LB4-LB6; and the end of the text, LB3)
  Allowed,    // a line may end after this character
  None,       // no break after this character
};

// One action per code point: whether a line may end after it. `language` (BCP
// 47, may be empty) selects libunibreak's class tailorings (e.g. "de", "zh", "ja").
CURVETEXT_API std::vector<BreakAction> line_breaks(std::u32string_view text, std::string_view language = {});

// Adds, as Allowed where `breaks` (line_breaks() of the same text) has None,
// the word boundaries inside runs of Thai letters that libthai's dictionary
// finds. UAX #14 leaves breaks inside class SA (Thai, Lao, Khmer, Myanmar...)
// to a dictionary and resolves SA to AL without one, which is what
// line_breaks() does (and what LineBreakTest expects). Only Thai has a
// dictionary here; the other SA scripts still break at spaces only.
CURVETEXT_API void add_dictionary_breaks(std::u32string_view text, std::vector<BreakAction>& breaks);

// The same for the Thai runs that reach into [from, to) only, skipping those
// already marked in `done` (one flag per code point; the runs handled here are
// marked). Returns true when a break was added. Line filling calls it only for
// the text between the last break that fits and the first that does not: a
// run lying wholly inside a line needs no word breaks, and the dictionary
// lookup is most of the time spent on Thai text.
CURVETEXT_API bool add_dictionary_breaks(std::u32string_view text, std::vector<BreakAction>& breaks, std::size_t from,
                                         std::size_t to, std::vector<bool>& done);

// One flag per code point: true where a grapheme cluster starts. Covers the
// rules that matter for carets: CR LF, combining marks and spacing marks,
// ZWJ, variation selectors, emoji modifiers, regional indicator pairs and
// Hangul syllable sequences.
CURVETEXT_API std::vector<bool> grapheme_starts(std::u32string_view text);

}  // namespace curvetext
