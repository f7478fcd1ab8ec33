// XML through expat, namespace-aware: elements become an index-linked tree.
// Entity declarations stop the parse (see svg_xml.hpp), as do the depth and
// element-count limits, so memory and time stay proportional to the input.
#include "svg_xml.hpp"

// Debian's expat is built with XML_DTD; its header declares the amplification
// guard only when the including code defines it too.
#ifndef XML_DTD
#define XML_DTD
#endif
#include <expat.h>

#include <limits>
#include <string>

#include "curvetext/error.hpp"

namespace curvetext::svg {

namespace {

constexpr std::string_view kSvgNs = "http://www.w3.org/2000/svg";
constexpr std::string_view kXlinkNs = "http://www.w3.org/1999/xlink";
// Expat's guard against expansion: output may be at most this many times the
// input once it passes the threshold (bytes).
constexpr float kMaxAmplification = 4.0f;
constexpr unsigned long long kAmplificationThreshold = 1 << 20;

// expat reports "uri|local" (the separator set below) or "local".
std::string element_name(std::string_view raw) {
  const std::size_t bar = raw.rfind('|');
  if (bar == std::string_view::npos) return std::string(raw);
  const std::string_view uri = raw.substr(0, bar), local = raw.substr(bar + 1);
  if (uri == kSvgNs) return std::string(local);
  return "{" + std::string(uri) + "}" + std::string(local);
}

std::string attribute_name(std::string_view raw) {
  const std::size_t bar = raw.rfind('|');
  if (bar == std::string_view::npos) return std::string(raw);
  const std::string_view uri = raw.substr(0, bar), local = raw.substr(bar + 1);
  if (uri == kXlinkNs) return "xlink:" + std::string(local);
  return "{" + std::string(uri) + "}" + std::string(local);
}

struct Builder {
  XML_Parser parser = nullptr;
  XmlDocument doc;
  std::vector<std::size_t> open;  // the open elements, innermost last
  std::string error;              // set when a handler stopped the parse

  void stop(std::string message) {
    if (error.empty()) error = std::move(message);
    XML_StopParser(parser, XML_FALSE);
  }
};

void XMLCALL on_start(void* data, const XML_Char* name, const XML_Char** attributes) {
  auto& b = *static_cast<Builder*>(data);
  if (!b.error.empty()) return;
  if (b.open.size() >= static_cast<std::size_t>(kMaxXmlDepth))
    return b.stop("elements nested deeper than " + std::to_string(kMaxXmlDepth));
  if (b.doc.elements.size() >= kMaxXmlElements)
    return b.stop("more than " + std::to_string(kMaxXmlElements) + " elements");
  XmlElement e;
  e.name = element_name(name);
  e.line = static_cast<int>(XML_GetCurrentLineNumber(b.parser));
  e.column = static_cast<int>(XML_GetCurrentColumnNumber(b.parser)) + 1;
  for (const XML_Char** a = attributes; *a; a += 2) e.attributes.emplace_back(attribute_name(a[0]), a[1]);
  const std::size_t index = b.doc.elements.size();
  if (!b.open.empty()) {
    e.parent = b.open.back();
    b.doc.elements[e.parent].children.push_back(index);
  }
  b.doc.elements.push_back(std::move(e));
  b.open.push_back(index);
}

void XMLCALL on_end(void* data, const XML_Char*) {
  auto& b = *static_cast<Builder*>(data);
  if (!b.open.empty()) b.open.pop_back();
}

void XMLCALL on_text(void* data, const XML_Char* s, int length) {
  auto& b = *static_cast<Builder*>(data);
  if (b.open.empty() || !b.error.empty()) return;
  XmlElement& e = b.doc.elements[b.open.back()];
  if (e.name == "style") e.text.append(s, static_cast<std::size_t>(length));
}

void XMLCALL on_entity_declaration(void* data, const XML_Char* name, int, const XML_Char*, int, const XML_Char*,
                                   const XML_Char*, const XML_Char*, const XML_Char*) {
  auto& b = *static_cast<Builder*>(data);
  b.stop(std::string("entity declarations are not supported (<!ENTITY ") + name + ">)");
}

[[noreturn]] void fail_at(XML_Parser parser, const std::string& message) {
  throw Error(ErrorCode::InvalidArgument, "SVG: line " + std::to_string(XML_GetCurrentLineNumber(parser)) +
                                              ", column " + std::to_string(XML_GetCurrentColumnNumber(parser) + 1) +
                                              ": " + message);
}

}  // namespace

XmlDocument parse_xml(std::string_view text) {
  if (text.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()))
    throw Error(ErrorCode::InvalidArgument, "SVG: the document is too large");
  Builder b;
  b.parser = XML_ParserCreateNS(nullptr, '|');
  if (!b.parser) throw Error(ErrorCode::InvalidArgument, "SVG: cannot create an XML parser");
  struct Free {
    XML_Parser p;
    ~Free() { XML_ParserFree(p); }
  } free_parser{b.parser};
  XML_SetUserData(b.parser, &b);
  XML_SetElementHandler(b.parser, on_start, on_end);
  XML_SetCharacterDataHandler(b.parser, on_text);
  XML_SetEntityDeclHandler(b.parser, on_entity_declaration);
  XML_SetParamEntityParsing(b.parser, XML_PARAM_ENTITY_PARSING_NEVER);
  XML_SetBillionLaughsAttackProtectionMaximumAmplification(b.parser, kMaxAmplification);
  XML_SetBillionLaughsAttackProtectionActivationThreshold(b.parser, kAmplificationThreshold);
  const XML_Status status = XML_Parse(b.parser, text.data(), static_cast<int>(text.size()), XML_TRUE);
  if (!b.error.empty()) fail_at(b.parser, b.error);
  if (status != XML_STATUS_OK) fail_at(b.parser, XML_ErrorString(XML_GetErrorCode(b.parser)));
  if (b.doc.elements.empty()) throw Error(ErrorCode::InvalidArgument, "SVG: no root element");
  return std::move(b.doc);
}

std::string position(const XmlElement& e) {
  return "line " + std::to_string(e.line) + ", column " + std::to_string(e.column) + ": ";
}

}  // namespace curvetext::svg
