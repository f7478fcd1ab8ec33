// Markup for styled paragraphs: a small, Pango-like language read into the
// plain text and the TextSpans of Paragraph::layout. docs/markup.md describes
// it in full:
//
//   <b> <i> <u> <s>                     bold, italic, underline, strikethrough
//   <color=C> <size=PX> <font=NAME>     colour, size, first font
//   <span font_family=".." size=".." weight=".." style=".." foreground=".."
//         background=".." underline=".." strikethrough=".." letter_spacing=".."
//         font_features=".." lang="..">
//   &lt; &gt; &amp; &quot; &apos; &#NNNN; &#xHHHH;
//
// Elements nest as a tree: text takes every style of the elements around it,
// the innermost deciding where two set the same property.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "curvetext/export.hpp"
#include "curvetext/layout.hpp"

namespace curvetext {

struct MarkupText {
  std::string text;             // the plain text
  std::vector<TextSpan> spans;  // disjoint, in text order, each with the full style in effect
};

// Reads `markup` with `base` as the style outside every element (its first
// font, or DejaVu Sans when it has none, is the family, or the font file,
// that <b> and <i> ask for in bold or italic: "Family:weight=bold",
// "file.ttf:weight=bold"; FontCollection::resolve finds that face or
// synthesises it).
// Throws Error(InvalidText) "markup, byte N: ..." naming the byte offset of
// the problem in `markup`: invalid UTF-8, a malformed, unknown or unclosed
// element, an unknown attribute or entity, a bad value; also for markup over
// tolerance::kMaxTextBytes, elements nested deeper than
// tolerance::kMaxMarkupDepth, or more than tolerance::kMaxSpans spans.
// Opens no files.
CURVETEXT_API MarkupText parse_markup(std::string_view markup, const TextStyle& base);

}  // namespace curvetext
