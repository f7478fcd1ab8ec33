// Strict UTF-8 validation. HarfBuzz would replace bad bytes with U+FFFD and
// carry on; we refuse them instead so that bad input is reported with its byte
// offset rather than drawn as boxes.

#include "font/utf8.hpp"

#include <cstdint>

#include "curvetext/error.hpp"
#include "curvetext/shaping.hpp"

namespace curvetext {

namespace detail {

std::size_t decode_utf8_at(std::string_view text, std::size_t offset, char32_t& codepoint, Utf8Problem& problem) {
  const auto byte = [&](std::size_t i) { return static_cast<std::uint8_t>(text[i]); };
  const std::uint8_t lead = byte(offset);
  problem.offset = offset;
  if (lead < 0x80) {
    codepoint = lead;
    return 1;
  }
  std::size_t length = 0;
  char32_t value = 0;
  // Range of the second byte: narrower than 80..BF exactly where the lead
  // byte alone would allow an overlong form, a surrogate or > U+10FFFF.
  std::uint8_t second_min = 0x80, second_max = 0xBF;
  const char* second_reason = "";
  if (lead < 0xC0) {
    problem.reason = "unexpected continuation byte";
    return 0;
  } else if (lead < 0xC2) {
    problem.reason = "overlong encoding";
    return 0;
  } else if (lead < 0xE0) {
    length = 2;
    value = lead & 0x1Fu;
  } else if (lead < 0xF0) {
    length = 3;
    value = lead & 0x0Fu;
    if (lead == 0xE0) second_min = 0xA0, second_reason = "overlong encoding";
    if (lead == 0xED) second_max = 0x9F, second_reason = "surrogate code point (U+D800..U+DFFF)";
  } else if (lead < 0xF5) {
    length = 4;
    value = lead & 0x07u;
    if (lead == 0xF0) second_min = 0x90, second_reason = "overlong encoding";
    if (lead == 0xF4) second_max = 0x8F, second_reason = "code point above U+10FFFF";
  } else {
    problem.reason = "code point above U+10FFFF (lead byte 0xF5..0xFF)";
    return 0;
  }
  for (std::size_t k = 1; k < length; ++k) {
    if (offset + k >= text.size()) {
      problem.reason = "truncated sequence at end of text";
      return 0;
    }
    const std::uint8_t b = byte(offset + k);
    if (b < 0x80 || b > 0xBF) {
      problem.reason = "truncated sequence (missing continuation byte)";
      return 0;
    }
    if (k == 1 && (b < second_min || b > second_max)) {
      problem.reason = second_reason;
      return 0;
    }
    value = (value << 6) | (b & 0x3Fu);
  }
  codepoint = value;
  return length;
}

std::optional<Utf8Problem> find_utf8_problem(std::string_view text) {
  std::size_t i = 0;
  while (i < text.size()) {
    // Fast path for ASCII runs.
    if (static_cast<std::uint8_t>(text[i]) < 0x80) {
      ++i;
      continue;
    }
    char32_t cp = 0;
    Utf8Problem problem;
    const std::size_t n = decode_utf8_at(text, i, cp, problem);
    if (n == 0) return problem;
    i += n;
  }
  return std::nullopt;
}

namespace {
[[noreturn]] void throw_problem(const Utf8Problem& problem) {
  throw Error(ErrorCode::InvalidText,
              "invalid UTF-8 at byte offset " + std::to_string(problem.offset) + ": " + problem.reason);
}
}  // namespace

std::u32string decode_utf8(std::string_view text) {
  std::u32string out;
  out.reserve(text.size());
  std::size_t i = 0;
  while (i < text.size()) {
    char32_t cp = 0;
    Utf8Problem problem;
    const std::size_t n = decode_utf8_at(text, i, cp, problem);
    if (n == 0) throw_problem(problem);
    out.push_back(cp);
    i += n;
  }
  return out;
}

}  // namespace detail

void validate_utf8(std::string_view text) {
  if (const auto problem = detail::find_utf8_problem(text)) detail::throw_problem(*problem);
}

}  // namespace curvetext
