// Private: which grapheme clusters ask for emoji presentation (Unicode
// Technical Standard #51), for the font choice in itemize.cpp.
#pragma once

#include <string_view>

namespace curvetext::detail {

// Whether the code point has Emoji_Presentation=Yes (drawn as an emoji by
// default).
bool emoji_presentation_default(char32_t c);

// Whether a grapheme cluster is drawn as an emoji: it ends its base with
// U+FE0F (emoji variation selector), is an emoji modifier, ZWJ, keycap or
// tag sequence, or a flag (two regional indicators), or its base defaults to
// emoji presentation and no U+FE0E (text variation selector) follows it.
bool emoji_presentation(std::u32string_view cluster);

}  // namespace curvetext::detail
