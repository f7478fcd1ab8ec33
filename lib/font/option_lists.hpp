// Parsing the comma-separated option lists users type ("wght=700, wdth=85",
// "kern,-liga"), shared by variations and features.
#pragma once

#include <cctype>
#include <string_view>
#include <vector>

namespace curvetext::detail {

inline std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

// Trimmed items between commas. A blank text has no items; an empty item
// ("a,,b", "a,") is kept so the caller can reject it by name.
inline std::vector<std::string_view> split_comma_list(std::string_view text) {
  std::vector<std::string_view> items;
  if (trim(text).empty()) return items;
  std::size_t start = 0;
  while (start <= text.size()) {
    std::size_t comma = text.find(',', start);
    if (comma == std::string_view::npos) comma = text.size();
    items.push_back(trim(text.substr(start, comma - start)));
    start = comma + 1;
  }
  return items;
}

}  // namespace curvetext::detail
