// Private interface of layout/ for the stages after it: the limit on grapheme
// cluster length (tolerance::kMaxClusterCodePoints) shared by paragraph layout
// and single-line text images (compose/). Shaping a cluster costs the square
// of its length (HarfBuzz attaches each mark by looking back over the marks
// before it), so long ones are refused before shaping.
#pragma once

#include <cstddef>
#include <string_view>
#include <vector>

namespace curvetext::detail {

// The first cluster longer than the limit in `starts` (grapheme_starts of
// some code points): its first code point and its length; length 0 if none.
struct LongCluster {
  std::size_t start = 0, length = 0;
};
LongCluster find_long_cluster(const std::vector<bool>& starts);

// Error(InvalidText) naming the cluster's length and byte offset.
[[noreturn]] void throw_long_cluster(std::size_t length, std::size_t byte);

// The check for valid UTF-8 text.
void check_cluster_lengths(std::string_view text);

}  // namespace curvetext::detail
