// Private: numbers in error messages ("%g": short, and exact for the
// integers and round values users type).
#pragma once

#include <cstdio>
#include <string>

namespace curvetext::detail {

inline std::string format_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

}  // namespace curvetext::detail
