#include "json.hpp"

#include <charconv>
#include <cstdio>
#include <cmath>
#include <cstdint>

#include "curvetext/error.hpp"

namespace curvetext::json {

Value::Value() = default;
Value::Value(const Value&) = default;
Value::Value(Value&&) noexcept = default;
Value& Value::operator=(const Value&) = default;
Value& Value::operator=(Value&&) noexcept = default;
Value::~Value() = default;

const Value* Value::find(std::string_view key) const {
  for (const auto& [k, v] : object)
    if (k == key) return &v;
  return nullptr;
}

std::string Value::where() const { return "line " + std::to_string(line) + ", column " + std::to_string(column); }

const char* type_name(Value::Type type) {
  switch (type) {
    case Value::Type::Null:
      return "null";
    case Value::Type::Bool:
      return "a boolean";
    case Value::Type::Number:
      return "a number";
    case Value::Type::String:
      return "a string";
    case Value::Type::Array:
      return "an array";
    case Value::Type::Object:
      return "an object";
  }
  return "?";
}

namespace {

class Parser {
 public:
  explicit Parser(std::string_view text) : s_(text) {
    // A UTF-8 byte order mark is not JSON but editors write it; skip it.
    if (s_.substr(0, 3) == "\xEF\xBB\xBF") pos_ = 3;
  }

  Value document() {
    skip_space();
    Value v = value(0);
    skip_space();
    if (pos_ < s_.size()) fail("unexpected '" + shown(s_[pos_]) + "' after the end of the document");
    return v;
  }

 private:
  std::string_view s_;
  std::size_t pos_ = 0;
  int line_ = 1;
  std::size_t line_start_ = 0;

  int column() const { return static_cast<int>(pos_ - line_start_) + 1; }

  [[noreturn]] void fail(const std::string& message) const {
    throw Error(ErrorCode::InvalidArgument,
                "JSON line " + std::to_string(line_) + ", column " + std::to_string(column()) + ": " + message);
  }

  static std::string shown(char c) {
    if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) >= 0x7f) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", static_cast<unsigned char>(c));
      return buf;
    }
    return std::string(1, c);
  }

  void skip_space() {
    while (pos_ < s_.size()) {
      const char c = s_[pos_];
      if (c == '\n') {
        ++pos_;
        ++line_;
        line_start_ = pos_;
      } else if (c == ' ' || c == '\t' || c == '\r') {
        ++pos_;
      } else {
        break;
      }
    }
  }

  void expect_word(std::string_view word) {
    if (s_.substr(pos_, word.size()) != word) fail("invalid literal (expected " + std::string(word) + ")");
    pos_ += word.size();
  }

  Value value(int depth) {
    if (depth > kMaxJsonDepth) fail("nesting deeper than " + std::to_string(kMaxJsonDepth) + " levels");
    if (pos_ >= s_.size()) fail("unexpected end of the document (a value was expected)");
    Value v;
    v.line = line_;
    v.column = column();
    const char c = s_[pos_];
    if (c == '{') {
      object(v, depth);
    } else if (c == '[') {
      array(v, depth);
    } else {
      scalar(v, c);
    }
    return v;
  }

  // Whether the next character (after spaces) is `c`; if so, past it.
  bool take(char c) {
    skip_space();
    if (pos_ >= s_.size() || s_[pos_] != c) return false;
    ++pos_;
    return true;
  }

  void object(Value& v, int depth) {
    v.type = Value::Type::Object;
    ++pos_;
    if (take('}')) return;
    for (;;) {
      skip_space();
      if (pos_ >= s_.size() || s_[pos_] != '"') fail("expected a string key in an object");
      const int key_line = line_, key_column = column();
      std::string key = string();
      if (v.find(key))
        throw Error(ErrorCode::InvalidArgument, "JSON line " + std::to_string(key_line) + ", column " +
                                                    std::to_string(key_column) + ": duplicate key \"" + key + "\"");
      if (!take(':')) fail("expected ':' after an object key");
      skip_space();
      Value member = value(depth + 1);
      v.object.emplace_back(std::move(key), std::move(member));
      if (take(',')) continue;
      if (take('}')) return;
      fail("expected ',' or '}' in an object");
    }
  }

  void array(Value& v, int depth) {
    v.type = Value::Type::Array;
    ++pos_;
    if (take(']')) return;
    for (;;) {
      skip_space();
      v.array.push_back(value(depth + 1));
      if (take(',')) continue;
      if (take(']')) return;
      fail("expected ',' or ']' in an array");
    }
  }

  // A string, true, false, null or a number starting with `c`.
  void scalar(Value& v, char c) {
    if (c == '"') {
      v.type = Value::Type::String;
      v.string = string();
    } else if (c == 't') {
      expect_word("true");
      v.type = Value::Type::Bool;
      v.boolean = true;
    } else if (c == 'f') {
      expect_word("false");
      v.type = Value::Type::Bool;
    } else if (c == 'n') {
      expect_word("null");
    } else if (c == '-' || (c >= '0' && c <= '9')) {
      v.type = Value::Type::Number;
      v.number = number();
    } else {
      fail("unexpected '" + shown(c) + "' (a value was expected)");
    }
  }

  static bool digit(char c) { return c >= '0' && c <= '9'; }

  // -?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)?
  double number() {
    const std::size_t start = pos_;
    auto at = [&](std::size_t i) { return i < s_.size() ? s_[i] : '\0'; };
    if (at(pos_) == '-') ++pos_;
    if (at(pos_) == '0') {
      ++pos_;
      if (digit(at(pos_))) fail("a number may not have leading zeros");
    } else if (digit(at(pos_))) {
      while (digit(at(pos_))) ++pos_;
    } else {
      fail("invalid number (a digit must follow '-')");
    }
    if (at(pos_) == '.') {
      ++pos_;
      if (!digit(at(pos_))) fail("invalid number (a digit must follow '.')");
      while (digit(at(pos_))) ++pos_;
    }
    if (at(pos_) == 'e' || at(pos_) == 'E') {
      ++pos_;
      if (at(pos_) == '+' || at(pos_) == '-') ++pos_;
      if (!digit(at(pos_))) fail("invalid number (a digit must follow the exponent)");
      while (digit(at(pos_))) ++pos_;
    }
    double value = 0.0;
    const auto [ptr, ec] = std::from_chars(s_.data() + start, s_.data() + pos_, value);
    if (ec == std::errc::result_out_of_range) {
      // Underflow to zero is harmless; overflow is not a number we can use.
      const std::string_view text = s_.substr(start, pos_ - start);
      const std::size_t e = text.find_first_of("eE");
      if (e != std::string_view::npos && text.substr(e + 1).starts_with('-')) return 0.0;
      pos_ = start;
      fail("number " + std::string(text) + " is out of range");
    }
    if (ec != std::errc() || ptr != s_.data() + pos_) {
      pos_ = start;
      fail("invalid number");
    }
    return value;
  }

  unsigned hex4() {
    unsigned v = 0;
    for (int i = 0; i < 4; ++i) {
      if (pos_ >= s_.size()) fail("unexpected end in a \\u escape");
      const char c = s_[pos_++];
      v <<= 4;
      if (c >= '0' && c <= '9')
        v |= static_cast<unsigned>(c - '0');
      else if (c >= 'a' && c <= 'f')
        v |= static_cast<unsigned>(c - 'a' + 10);
      else if (c >= 'A' && c <= 'F')
        v |= static_cast<unsigned>(c - 'A' + 10);
      else
        fail("invalid \\u escape (4 hex digits expected)");
    }
    return v;
  }

  static void append_utf8(std::string& out, unsigned cp) {
    if (cp < 0x80) {
      out += static_cast<char>(cp);
    } else if (cp < 0x800) {
      out += static_cast<char>(0xC0 | (cp >> 6));
      out += static_cast<char>(0x80 | (cp & 0x3F));
    } else if (cp < 0x10000) {
      out += static_cast<char>(0xE0 | (cp >> 12));
      out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (cp & 0x3F));
    } else {
      out += static_cast<char>(0xF0 | (cp >> 18));
      out += static_cast<char>(0x80 | ((cp >> 12) & 0x3F));
      out += static_cast<char>(0x80 | ((cp >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (cp & 0x3F));
    }
  }

  std::string string() {
    ++pos_;  // opening quote
    std::string out;
    for (;;) {
      if (pos_ >= s_.size()) fail("unterminated string");
      const char c = s_[pos_];
      if (c == '"') {
        ++pos_;
        return out;
      }
      if (static_cast<unsigned char>(c) < 0x20) fail("control character in a string (escape it)");
      if (c != '\\') {
        out += c;
        ++pos_;
        continue;
      }
      ++pos_;
      if (pos_ >= s_.size()) fail("unterminated string");
      const char e = s_[pos_++];
      switch (e) {
        case '"':
          out += '"';
          break;
        case '\\':
          out += '\\';
          break;
        case '/':
          out += '/';
          break;
        case 'b':
          out += '\b';
          break;
        case 'f':
          out += '\f';
          break;
        case 'n':
          out += '\n';
          break;
        case 'r':
          out += '\r';
          break;
        case 't':
          out += '\t';
          break;
        case 'u': {
          unsigned cp = hex4();
          if (cp >= 0xD800 && cp < 0xDC00) {
            if (s_.substr(pos_, 2) != "\\u") fail("a high surrogate must be followed by a low surrogate");
            pos_ += 2;
            const unsigned lo = hex4();
            if (lo < 0xDC00 || lo >= 0xE000) fail("a high surrogate must be followed by a low surrogate");
            cp = 0x10000 + ((cp - 0xD800) << 10) + (lo - 0xDC00);
          } else if (cp >= 0xDC00 && cp < 0xE000) {
            fail("lone low surrogate in a \\u escape");
          }
          append_utf8(out, cp);
          break;
        }
        default:
          --pos_;
          fail("invalid escape '\\" + shown(e) + "'");
      }
    }
  }
};

}  // namespace

Value parse(std::string_view text) { return Parser(text).document(); }

}  // namespace curvetext::json
