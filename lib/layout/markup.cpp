// Markup reader (markup.hpp): a stack of open elements, each holding the
// style in effect inside it; text between two tags becomes one span with the
// innermost element's style, so nesting keeps every enclosing style and the
// work is linear in the markup (each element copies one style, depth is
// bounded).

#include "curvetext/markup.hpp"

#include <charconv>
#include <cmath>
#include <map>

#include "curvetext/color.hpp"
#include "curvetext/error.hpp"
#include "curvetext/shaping.hpp"
#include "curvetext/tolerances.hpp"
#include "font/utf8.hpp"

namespace curvetext {

namespace {

[[noreturn]] void fail(std::size_t at, const std::string& message) {
  throw Error(ErrorCode::InvalidText, "markup, byte " + std::to_string(at) + ": " + message);
}

void append_utf8(std::string& out, char32_t c) {
  if (c < 0x80) {
    out += static_cast<char>(c);
  } else if (c < 0x800) {
    out += static_cast<char>(0xC0 | (c >> 6));
    out += static_cast<char>(0x80 | (c & 0x3F));
  } else if (c < 0x10000) {
    out += static_cast<char>(0xE0 | (c >> 12));
    out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (c & 0x3F));
  } else {
    out += static_cast<char>(0xF0 | (c >> 18));
    out += static_cast<char>(0x80 | ((c >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (c & 0x3F));
  }
}

// The character of entity `name` (between '&' and ';'), or 0 when unknown.
char32_t entity_value(std::string_view name) {
  if (name == "lt") return U'<';
  if (name == "gt") return U'>';
  if (name == "amp") return U'&';
  if (name == "quot") return U'"';
  if (name == "apos") return U'\'';
  if (name.size() < 2 || name[0] != '#') return 0;
  const bool hex = name[1] == 'x' || name[1] == 'X';
  const std::string_view digits = name.substr(hex ? 2 : 1);
  std::uint32_t c = 0;
  const auto [end, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), c, hex ? 16 : 10);
  if (digits.empty() || ec != std::errc() || end != digits.data() + digits.size()) return 0;
  if (c == 0 || c > 0x10FFFF || (c >= 0xD800 && c <= 0xDFFF)) return 0;
  return c;
}

// Appends the entity at markup[at] == '&' to `out`; returns the position after its ';'.
std::size_t read_entity(std::string_view markup, std::size_t at, std::string& out) {
  constexpr std::size_t kLongestEntity = 10;  // "&#x10FFFF;" less the '&'
  const std::size_t semi = markup.find(';', at);
  if (semi == std::string_view::npos || semi - at > kLongestEntity)
    fail(at, "'&' does not start an entity (write &amp; for '&')");
  const char32_t c = entity_value(markup.substr(at + 1, semi - at - 1));
  if (c == 0)
    fail(at, "unknown entity " + std::string(markup.substr(at, semi - at + 1)) +
                 " (known: &lt; &gt; &amp; &quot; &apos; &#NNNN; &#xHHHH; for a character up to U+10FFFF)");
  append_utf8(out, c);
  return semi + 1;
}

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r'; }
bool is_name_char(char c) { return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_' || c == '-'; }

double pixels(std::size_t at, const std::string& what, std::string value, double lo, double hi) {
  if (value.size() > 2 && value.ends_with("px")) value.resize(value.size() - 2);
  double v = 0.0;
  const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), v);
  if (value.empty() || ec != std::errc() || end != value.data() + value.size() || !std::isfinite(v) || v < lo || v > hi)
    fail(at, what + " needs a number of pixels from " + std::to_string(static_cast<int>(lo)) + " to " +
                 std::to_string(static_cast<int>(hi)) + ", got '" + value + "'");
  return v;
}

bool boolean(std::size_t at, const std::string& what, const std::string& value) {
  if (value == "true") return true;
  if (value == "false") return false;
  fail(at, what + " needs true or false, got '" + value + "'");
}

// CSS / Pango weights as fontconfig names ("" is the font's own weight;
// fontconfig 2.14 has no name above black).
std::string weight_name(std::size_t at, const std::string& value) {
  static const std::map<std::string, std::string> kNames = {{"thin", "thin"},     {"ultralight", "extralight"},
                                                            {"light", "light"},   {"semilight", "semilight"},
                                                            {"book", "book"},     {"normal", ""},
                                                            {"medium", "medium"}, {"semibold", "semibold"},
                                                            {"bold", "bold"},     {"ultrabold", "extrabold"},
                                                            {"heavy", "black"},   {"ultraheavy", "black"}};
  if (auto it = kNames.find(value); it != kNames.end()) return it->second;
  int n = 0;
  const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), n);
  if (ec == std::errc() && end == value.data() + value.size() && n >= 100 && n <= 1000) {
    static const char* const kByHundred[] = {"thin",     "extralight", "light",     "",      "medium",
                                             "semibold", "bold",       "extrabold", "black", "black"};
    return kByHundred[(n + 50) / 100 - 1];
  }
  fail(at,
       "weight needs normal, bold, thin, ultralight, light, semilight, book, medium, semibold, ultrabold, heavy, "
       "ultraheavy or a number from 100 to 1000, got '" +
           value + "'");
}

// What an open element sets: the style, and the face's family, weight and
// slant, from which <b> / <i> / weight / style build a fontconfig pattern.
struct State {
  TextStyle style;     // fonts without the weighted or slanted face
  std::string family;  // empty: the family (or font file) of style.fonts.front()
  std::string weight;  // fontconfig weight name; empty: the font's own
  std::string slant;   // "italic", "oblique"; empty: the font's own
  std::string tag;     // element name, matched by its closing tag
  std::size_t opened = 0;
  TextStyle effective;  // style with the weighted or slanted face first
};

class MarkupParser {
 public:
  MarkupParser(std::string_view markup, const TextStyle& base) : s_(markup) { root_.style = base; }

  MarkupText run() {
    while (pos_ < s_.size()) {
      const std::size_t next = s_.find_first_of("<&", pos_);
      out_.text.append(s_.substr(pos_, next == std::string_view::npos ? std::string_view::npos : next - pos_));
      if (next == std::string_view::npos) break;
      pos_ = next;
      if (s_[pos_] == '&') {
        pos_ = read_entity(s_, pos_, out_.text);
      } else {
        flush();
        element();
      }
    }
    flush();
    if (!stack_.empty()) fail(stack_.back().opened, "<" + stack_.back().tag + "> is not closed");
    return std::move(out_);
  }

 private:
  std::string_view s_;
  std::size_t pos_ = 0;
  MarkupText out_;
  State root_;
  std::vector<State> stack_;
  std::size_t segment_ = 0;  // start of the text not yet in a span

  // The text since the last tag becomes a span of the innermost element.
  void flush() {
    if (!stack_.empty() && segment_ < out_.text.size()) {
      if (out_.spans.size() == tolerance::kMaxSpans)
        fail(pos_, "more than " + std::to_string(tolerance::kMaxSpans) + " styled spans");
      out_.spans.push_back({segment_, out_.text.size(), stack_.back().effective});
    }
    segment_ = out_.text.size();
  }

  const State& top() const { return stack_.empty() ? root_ : stack_.back(); }

  void skip_spaces() {
    while (pos_ < s_.size() && is_space(s_[pos_])) ++pos_;
  }

  std::string name() {
    const std::size_t start = pos_;
    while (pos_ < s_.size() && is_name_char(s_[pos_])) ++pos_;
    return std::string(s_.substr(start, pos_ - start));
  }

  void expect_close(std::size_t opened) {
    skip_spaces();
    if (pos_ >= s_.size()) fail(opened, "'<' without a closing '>'");
    if (s_[pos_] != '>') fail(pos_, "unexpected '" + std::string(1, s_[pos_]) + "' in a tag");
    ++pos_;
  }

  void element() {
    const std::size_t opened = pos_++;
    if (pos_ < s_.size() && s_[pos_] == '/') {
      ++pos_;
      const std::string tag = name();
      expect_close(opened);
      close(opened, tag);
      return;
    }
    const std::string tag = name();
    if (tag.empty()) fail(opened, "'<' does not start a tag (write &lt; for '<')");
    if (stack_.size() == tolerance::kMaxMarkupDepth)
      fail(opened, "elements nested deeper than " + std::to_string(tolerance::kMaxMarkupDepth));
    State state = top();
    state.tag = tag;
    state.opened = opened;
    if (tag == "span") {
      span_attributes(state, opened);
    } else {
      simple_tag(state, tag, opened);
      expect_close(opened);
    }
    finish(state);
    stack_.push_back(std::move(state));
  }

  void close(std::size_t at, const std::string& tag) {
    if (stack_.empty()) fail(at, "</" + tag + "> closes no open element");
    if (stack_.back().tag != tag)
      fail(at, "</" + tag + "> does not close <" + stack_.back().tag + "> (opened at byte " +
                   std::to_string(stack_.back().opened) + ")");
    stack_.pop_back();
  }

  // <b> <i> <u> <s> and the short forms <color=C> <size=PX> <font=NAME>.
  void simple_tag(State& state, const std::string& tag, std::size_t at) {
    std::string value;
    const bool has_value = pos_ < s_.size() && s_[pos_] == '=';
    if (has_value) {
      const std::size_t end = s_.find('>', ++pos_);
      if (end == std::string_view::npos) fail(at, "'<' without a closing '>'");
      value = std::string(s_.substr(pos_, end - pos_));
      pos_ = end;
    }
    const bool wants_value = tag == "color" || tag == "size" || tag == "font";
    if (has_value != wants_value)
      fail(at, "<" + tag + (wants_value ? "> needs a value (<" + tag + "=...>)" : "> takes no value"));
    if (tag == "b")
      state.weight = "bold";
    else if (tag == "i")
      state.slant = "italic";
    else if (tag == "u")
      state.style.underline = true;
    else if (tag == "s")
      state.style.strikethrough = true;
    else if (tag == "color" || tag == "size" || tag == "font")
      attribute(state, tag == "color" ? "foreground" : tag == "size" ? "size" : "font_family", value, at);
    else
      fail(at, "unknown tag <" + tag + "> (known: b, i, u, s, color=, size=, font=, span)");
  }

  void span_attributes(State& state, std::size_t opened) {
    for (;;) {
      skip_spaces();
      if (pos_ < s_.size() && s_[pos_] == '>') break;
      const std::size_t at = pos_;
      const std::string key = name();
      if (pos_ >= s_.size()) fail(opened, "'<' without a closing '>'");
      if (key.empty()) fail(pos_, "unexpected '" + std::string(1, s_[pos_]) + "' in a tag");
      skip_spaces();
      if (pos_ >= s_.size() || s_[pos_] != '=') fail(at, "span attribute " + key + " needs a value");
      ++pos_;
      skip_spaces();
      if (pos_ >= s_.size() || (s_[pos_] != '"' && s_[pos_] != '\''))
        fail(pos_, "the value of " + key + " needs quotes");
      const char quote = s_[pos_++];
      const std::size_t end = s_.find(quote, pos_);
      if (end == std::string_view::npos) fail(at, "the value of " + key + " has no closing quote");
      std::string value;
      for (std::size_t i = pos_; i < end;) {
        const std::size_t amp = s_.find('&', i);
        if (amp == std::string_view::npos || amp >= end) {
          value.append(s_.substr(i, end - i));
          break;
        }
        value.append(s_.substr(i, amp - i));
        i = read_entity(s_.substr(0, end), amp, value);
      }
      pos_ = end + 1;
      attribute(state, key, value, at);
    }
    ++pos_;
  }

  void attribute(State& state, const std::string& key, const std::string& value, std::size_t at) {
    TextStyle& s = state.style;
    try {
      if (key == "font_family" || key == "face") {
        if (value.empty()) fail(at, key + " needs a family name or font file");
        s.fonts.insert(s.fonts.begin(), value);
        state.family.clear();
      } else if (key == "size" || key == "font_size") {
        s.size_px = pixels(at, key, value, 0.0, tolerance::kMaxPixelsPerEm);
        if (!(s.size_px > 0.0)) fail(at, key + " must be more than 0 px");
      } else if (key == "weight" || key == "font_weight") {
        state.weight = weight_name(at, value);
      } else if (key == "style" || key == "font_style") {
        if (value != "normal" && value != "italic" && value != "oblique")
          fail(at, key + " needs normal, italic or oblique, got '" + value + "'");
        state.slant = value == "normal" ? "" : value;
      } else if (key == "foreground" || key == "fgcolor" || key == "color") {
        s.color = parse_color(value);
      } else if (key == "background" || key == "bgcolor") {
        s.background = parse_color(value);
      } else if (key == "underline") {
        if (value != "none" && value != "single" && value != "true" && value != "false")
          fail(at, "underline needs none or single (double, low and error lines are not drawn), got '" + value + "'");
        s.underline = value == "single" || value == "true";
      } else if (key == "strikethrough") {
        s.strikethrough = boolean(at, key, value);
      } else if (key == "letter_spacing") {
        s.letter_spacing = pixels(at, key, value, -1e4, 1e4);
      } else if (key == "word_spacing") {
        s.word_spacing = pixels(at, key, value, -1e4, 1e4);
      } else if (key == "font_features") {
        const std::vector<Feature> features = parse_features(value);
        s.features.insert(s.features.end(), features.begin(), features.end());
      } else if (key == "lang") {
        s.language = value;
      } else if (key == "outline") {
        parse_outline(value, ' ', s.effects);
      } else if (key == "shadow") {
        s.effects.shadow = parse_shadow(value, ' ');
      } else {
        fail(at, "span attribute " + key +
                     " is not supported (known: font_family, size, weight, style, foreground, background, underline, "
                     "strikethrough, letter_spacing, word_spacing, font_features, lang, outline, shadow)");
      }
    } catch (const Error& e) {
      if (e.code() == ErrorCode::InvalidText) throw;
      fail(at, key + ": " + e.what());
    }
  }

  // The face: the family (or the first font's family, or font file) with the
  // weight and slant asked for, as a fontconfig pattern in front of the other
  // fonts; a face lacking them is synthesised (FontCollection::resolve).
  void finish(State& state) {
    state.effective = state.style;
    if (state.weight.empty() && state.slant.empty()) return;
    std::string pattern = family_of(state);
    if (!state.weight.empty()) pattern += ":weight=" + state.weight;
    if (!state.slant.empty()) pattern += ":slant=" + state.slant;
    state.effective.fonts.insert(state.effective.fonts.begin(), pattern);
  }

  // The first font's family; for a font file the file itself, which
  // FontCollection::resolve reads with the style ("file.ttf:weight=bold": its
  // family's face in that style where fontconfig has one, else the file).
  std::string family_of(State& state) {
    if (!state.family.empty()) return state.family;
    const std::string first = state.style.fonts.empty() ? "DejaVu Sans" : state.style.fonts.front();
    const std::size_t slash = first.rfind('/');
    state.family = first.substr(0, first.find(':', slash == std::string::npos ? 0 : slash + 1));
    return state.family;
  }
};

}  // namespace

MarkupText parse_markup(std::string_view markup, const TextStyle& base) {
  if (markup.size() > tolerance::kMaxTextBytes)
    throw Error(ErrorCode::InvalidText, "markup of " + std::to_string(markup.size()) + " bytes is over the limit of " +
                                            std::to_string(tolerance::kMaxTextBytes) + " bytes");
  if (const auto problem = detail::find_utf8_problem(markup)) fail(problem->offset, problem->reason);
  return MarkupParser(markup, base).run();
}

}  // namespace curvetext
