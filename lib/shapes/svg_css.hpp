// Private interface of shapes/ (the SVG reader's parts): CSS as SVG files use
// it. Declarations ("fill: red; opacity: .5"), a style sheet of rules with
// selectors and the cascade's specificity, and colours in every CSS form.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "curvetext/color.hpp"
#include "svg_xml.hpp"

namespace curvetext::svg {

struct Declaration {
  std::string property;  // lower case
  std::string value;     // trimmed, without "!important"
  bool important = false;
};

// "a: b; c: d !important". Comments are skipped; a declaration without a
// colon or with an empty name is dropped (as CSS drops invalid ones).
std::vector<Declaration> parse_declarations(std::string_view text);

// One compound selector: an optional type ("*" or empty: any), an optional
// id, classes, and attribute-presence / attribute-equals tests.
struct Compound {
  std::string type;
  std::string id;
  std::vector<std::string> classes;
  std::vector<std::pair<std::string, std::optional<std::string>>> attributes;
};

// Compounds joined by combinators, left to right: ' ' (descendant), '>'
// (child). Sibling combinators and pseudo-classes are refused when the
// sheet is read (none of the icon themes use them).
struct Selector {
  std::vector<Compound> compounds;
  std::vector<char> combinators;  // compounds.size() - 1 entries
  int specificity = 0;            // ids * 10000 + classes/attributes * 100 + types
};

struct Rule {
  Selector selector;
  std::vector<Declaration> declarations;
  std::size_t order = 0;  // position in the document's sheets
};

// The rules of a <style> element's text appended to `rules`. Throws
// Error(InvalidArgument) naming an at-rule or a selector that is not
// supported, or a rule that is not closed; `where` prefixes the message.
void parse_style_sheet(std::string_view text, const std::string& where, std::vector<Rule>& rules);

// Whether `selector` matches element `index` of `doc`. `steps` counts the
// compound tests made, across calls; Error(InvalidArgument) past the limit.
bool matches(const Selector& selector, const XmlDocument& doc, std::size_t index, std::size_t& steps);

// A CSS colour: #rgb, #rgba, #rrggbb, #rrggbbaa, rgb()/rgba() with numbers or
// percentages (commas or spaces, "/ alpha"), hsl()/hsla(), the 147 named
// colours and "transparent". nullopt when the text is none of those
// ("currentColor", "none" and url() are the caller's).
std::optional<Color> parse_css_color(std::string_view text);

std::string trim(std::string_view s);
std::string lower(std::string_view s);

}  // namespace curvetext::svg
