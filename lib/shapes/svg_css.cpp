// A small CSS reader and selector matcher for SVG style sheets (see
// docs/svg.md for why no library: Debian packages libcroco, which is
// unmaintained, and full browser engines; SVG icons need type, class, id,
// attribute, descendant and child selectors with specificity, a few hundred
// lines here).
#include <algorithm>
#include <string>

#include "curvetext/error.hpp"
#include "svg_css.hpp"

namespace curvetext::svg {

namespace {

// Compound tests all matching of a document may make (descendant
// combinators walk up to the root and backtrack: ".a .b" against deep
// markup), so hostile sheets stop in bounded time.
constexpr std::size_t kMaxMatchSteps = 20000000;

// The text with /* comments */ replaced by a space.
std::string strip_comments(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text.substr(i, 2) == "/*") {
      const std::size_t end = text.find("*/", i + 2);
      if (end == std::string_view::npos) break;
      i = end + 1;
      out += ' ';
    } else {
      out += text[i];
    }
  }
  return out;
}

[[noreturn]] void fail(const std::string& where, const std::string& message) {
  throw Error(ErrorCode::InvalidArgument, "SVG: " + where + message);
}

bool name_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_' ||
         static_cast<unsigned char>(c) >= 0x80;
}

// An identifier at `s[i]` (advancing i).
std::string identifier(std::string_view s, std::size_t& i) {
  const std::size_t start = i;
  while (i < s.size() && (name_char(s[i]) || s[i] == '\\')) i += s[i] == '\\' ? 2 : 1;
  return std::string(s.substr(start, std::min(i, s.size()) - start));
}

// "[name]" or "[name=value]" at s[i] == '['.
void attribute_test(std::string_view s, std::size_t& i, Compound& c, const std::string& where) {
  const std::size_t close = s.find(']', i);
  if (close == std::string_view::npos) fail(where, "unclosed '[' in selector '" + std::string(s) + "'");
  const std::string inside = trim(s.substr(i + 1, close - i - 1));
  i = close + 1;
  const std::size_t eq = inside.find('=');
  if (eq == std::string::npos) {
    c.attributes.emplace_back(inside, std::nullopt);
    return;
  }
  if (eq > 0 && std::string("~|^$*").find(inside[eq - 1]) != std::string::npos)
    fail(where, "attribute selector '[" + inside + "]' is not supported (only [name] and [name=value])");
  std::string value = trim(std::string_view(inside).substr(eq + 1));
  if (value.size() >= 2 && (value.front() == '"' || value.front() == '\'') && value.back() == value.front())
    value = value.substr(1, value.size() - 2);
  c.attributes.emplace_back(trim(std::string_view(inside).substr(0, eq)), value);
}

Compound compound(std::string_view s, std::size_t& i, const std::string& where, int& specificity) {
  Compound c;
  if (i < s.size() && s[i] == '*') {
    c.type = "*";
    ++i;
  } else if (i < s.size() && name_char(s[i])) {
    c.type = identifier(s, i);
    specificity += 1;
  }
  while (i < s.size()) {
    const char k = s[i];
    if (k == '.') {
      ++i;
      c.classes.push_back(identifier(s, i));
      specificity += 100;
    } else if (k == '#') {
      ++i;
      c.id = identifier(s, i);
      specificity += 10000;
    } else if (k == '[') {
      attribute_test(s, i, c, where);
      specificity += 100;
    } else if (k == ':') {
      fail(where, "pseudo-class in selector '" + std::string(s) + "' is not supported");
    } else {
      break;
    }
  }
  if (c.type.empty() && c.id.empty() && c.classes.empty() && c.attributes.empty())
    fail(where, "selector '" + std::string(s) + "' is not supported");
  return c;
}

Selector selector(std::string_view s, const std::string& where) {
  Selector sel;
  std::size_t i = 0;
  for (;;) {
    while (i < s.size() && (s[i] == ' ' || s[i] == '\t' || s[i] == '\n' || s[i] == '\r')) ++i;
    if (i >= s.size()) break;
    if (!sel.compounds.empty()) {
      char combinator = ' ';
      if (s[i] == '>' || s[i] == '+' || s[i] == '~') {
        combinator = s[i++];
        while (i < s.size() && (s[i] == ' ' || s[i] == '\t' || s[i] == '\n' || s[i] == '\r')) ++i;
      }
      if (combinator != ' ' && combinator != '>')
        fail(where,
             "combinator '" + std::string(1, combinator) + "' in selector '" + std::string(s) + "' is not supported");
      sel.combinators.push_back(combinator);
    }
    sel.compounds.push_back(compound(s, i, where, sel.specificity));
  }
  if (sel.compounds.empty()) fail(where, "empty selector");
  return sel;
}

std::vector<std::string> classes_of(const XmlElement& e) {
  std::vector<std::string> out;
  const std::string* cls = e.find("class");
  if (!cls) return out;
  std::size_t i = 0;
  const std::string& s = *cls;
  while (i < s.size()) {
    while (i < s.size() && (s[i] == ' ' || s[i] == '\t' || s[i] == '\n' || s[i] == '\r')) ++i;
    std::size_t j = i;
    while (j < s.size() && !(s[j] == ' ' || s[j] == '\t' || s[j] == '\n' || s[j] == '\r')) ++j;
    if (j > i) out.push_back(s.substr(i, j - i));
    i = j;
  }
  return out;
}

bool matches_compound(const Compound& c, const XmlElement& e) {
  if (!c.type.empty() && c.type != "*" && c.type != e.name) return false;
  if (!c.id.empty()) {
    const std::string* id = e.find("id");
    if (!id || *id != c.id) return false;
  }
  if (!c.classes.empty()) {
    const std::vector<std::string> have = classes_of(e);
    for (const std::string& want : c.classes)
      if (std::find(have.begin(), have.end(), want) == have.end()) return false;
  }
  for (const auto& [name, value] : c.attributes) {
    const std::string* v = e.find(name);
    if (!v || (value && *v != *value)) return false;
  }
  return true;
}

// Whether compounds [0, k] match with compound k at `index`.
// `steps` bounds the backtracking of descendant combinators.
bool matches_from(const Selector& s, std::size_t k, const XmlDocument& doc, std::size_t index, std::size_t& steps) {
  if (++steps > kMaxMatchSteps)
    throw Error(ErrorCode::InvalidArgument, "SVG: matching the style sheet's selectors takes too long (more than " +
                                                std::to_string(kMaxMatchSteps) + " tests)");
  if (!matches_compound(s.compounds[k], doc.elements[index])) return false;
  if (k == 0) return true;
  const bool child = s.combinators[k - 1] == '>';
  for (std::size_t up = index; up != 0;) {
    up = doc.elements[up].parent;
    if (matches_from(s, k - 1, doc, up, steps)) return true;
    if (child || up == 0) break;
  }
  return false;
}

}  // namespace

std::vector<Declaration> parse_declarations(std::string_view text) {
  std::vector<Declaration> out;
  const std::string s = strip_comments(text);
  std::size_t i = 0;
  while (i < s.size()) {
    std::size_t semi = s.find(';', i);
    if (semi == std::string::npos) semi = s.size();
    const std::string_view decl = std::string_view(s).substr(i, semi - i);
    i = semi + 1;
    const std::size_t colon = decl.find(':');
    if (colon == std::string_view::npos) continue;
    Declaration d{lower(trim(decl.substr(0, colon))), trim(decl.substr(colon + 1)), false};
    if (d.property.empty()) continue;
    const std::size_t bang = d.value.rfind('!');
    if (bang != std::string::npos && lower(trim(std::string_view(d.value).substr(bang + 1))) == "important") {
      d.important = true;
      d.value = trim(std::string_view(d.value).substr(0, bang));
    }
    out.push_back(std::move(d));
  }
  return out;
}

void parse_style_sheet(std::string_view text, const std::string& where, std::vector<Rule>& rules) {
  std::string s = strip_comments(text);
  // CDO/CDC, which old files wrap sheets in, are no tokens of a rule.
  for (const std::string_view mark : {std::string_view("<!--"), std::string_view("-->")})
    for (std::size_t p = s.find(mark); p != std::string::npos; p = s.find(mark, p))
      std::fill_n(s.begin() + static_cast<std::ptrdiff_t>(p), mark.size(), ' ');
  std::size_t i = 0;
  while (i < s.size()) {
    const std::size_t open = s.find('{', i);
    if (open == std::string::npos) {
      if (!trim(std::string_view(s).substr(i)).empty()) fail(where, "style sheet text outside a rule");
      break;
    }
    const std::string prelude = trim(std::string_view(s).substr(i, open - i));
    if (!prelude.empty() && prelude[0] == '@') fail(where, "at-rule " + prelude + " is not supported");
    const std::size_t close = s.find('}', open);
    if (close == std::string::npos) fail(where, "unclosed rule for '" + prelude + "'");
    const std::vector<Declaration> declarations =
        parse_declarations(std::string_view(s).substr(open + 1, close - open - 1));
    std::size_t start = 0;
    for (;;) {
      const std::size_t comma = prelude.find(',', start);
      const std::string one = trim(std::string_view(prelude).substr(start, comma - start));
      rules.push_back({selector(one, where), declarations, rules.size()});
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
    i = close + 1;
  }
}

bool matches(const Selector& selector, const XmlDocument& doc, std::size_t index, std::size_t& steps) {
  return matches_from(selector, selector.compounds.size() - 1, doc, index, steps);
}

}  // namespace curvetext::svg
