// Private interface of font/ for the stages after it: strict UTF-8 decoding
// (RFC 3629), shared by validation and by any stage that needs code points
// (layout, line breaking).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace curvetext::detail {

struct Utf8Problem {
  std::size_t offset = 0;  // byte offset of the first byte of the bad sequence
  const char* reason = "";
};

// Decodes the sequence starting at `offset`: on success stores the code point
// and returns its length in bytes (1-4); on failure returns 0 and fills
// `problem`. Rejects overlong forms, surrogates, values above U+10FFFF, stray
// continuation bytes and truncated sequences.
std::size_t decode_utf8_at(std::string_view text, std::size_t offset, char32_t& codepoint, Utf8Problem& problem);

// The first problem in `text`, or nullopt when it is valid UTF-8.
std::optional<Utf8Problem> find_utf8_problem(std::string_view text);

// Decodes valid UTF-8; throws Error(InvalidText) otherwise.
std::u32string decode_utf8(std::string_view text);

}  // namespace curvetext::detail
