// Private interface of shapes/ (the SVG reader's parts): an XML document read
// by expat into a small element tree, with namespaces resolved the way the
// SVG reader needs them.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace curvetext::svg {

// One element. `name` is the local name for elements in the SVG namespace
// (or in none), and "{uri}local" for any other namespace, which the reader
// skips. Attributes: local names for those in no namespace, "xlink:href" for
// XLink's href, "{uri}local" for others. `text` holds the character data of
// <style> elements only (the only text the reader uses).
struct XmlElement {
  std::string name;
  std::vector<std::pair<std::string, std::string>> attributes;
  std::vector<std::size_t> children;  // indices into XmlDocument::elements
  std::size_t parent = 0;             // the root is its own parent
  int line = 0;
  int column = 0;
  std::string text;
  const std::string* find(std::string_view key) const {
    for (const auto& [k, v] : attributes)
      if (k == key) return &v;
    return nullptr;
  }
};

struct XmlDocument {
  std::vector<XmlElement> elements;  // elements[0] is the root
};

// Limits for hostile input: nesting depth and element count (each refused by
// name), entity declarations (refused: SVG files need none beyond XML's
// predefined ones and character references; this also rules out "billion
// laughs" expansion), and expat's own amplification guard as a second wall.
inline constexpr int kMaxXmlDepth = 256;
inline constexpr std::size_t kMaxXmlElements = 200000;

// Parses `text`. Throws Error(InvalidArgument) "SVG: line L, column C: ..."
// for malformed XML, an entity declaration, or a limit reached.
XmlDocument parse_xml(std::string_view text);

// "line L, column C: " for an element, the prefix of the reader's errors.
std::string position(const XmlElement& e);

}  // namespace curvetext::svg
