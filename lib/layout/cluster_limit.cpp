#include "layout/cluster_limit.hpp"

#include <string>

#include "curvetext/error.hpp"
#include "curvetext/line_break.hpp"
#include "curvetext/tolerances.hpp"
#include "font/utf8.hpp"

namespace curvetext::detail {

LongCluster find_long_cluster(const std::vector<bool>& starts) {
  std::size_t start = 0;
  for (std::size_t i = 1; i <= starts.size(); ++i) {
    if (i < starts.size() && !starts[i]) continue;
    if (i - start > tolerance::kMaxClusterCodePoints) return {start, i - start};
    start = i;
  }
  return {};
}

void throw_long_cluster(std::size_t length, std::size_t byte) {
  throw Error(ErrorCode::InvalidText, "a grapheme cluster of " + std::to_string(length) +
                                          " code points (a character and its combining marks) at byte " +
                                          std::to_string(byte) + " is over the limit of " +
                                          std::to_string(tolerance::kMaxClusterCodePoints));
}

void check_cluster_lengths(std::string_view text) {
  const std::u32string cps = decode_utf8(text);
  const LongCluster c = find_long_cluster(grapheme_starts(cps));
  if (c.length == 0) return;
  std::size_t byte = 0;
  for (std::size_t k = 0; k < c.start; ++k) do
      ++byte;
    while (byte < text.size() && (static_cast<unsigned char>(text[byte]) & 0xC0) == 0x80);
  throw_long_cluster(c.length, byte);
}

}  // namespace curvetext::detail
