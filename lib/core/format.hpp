// Private interface of core/ for every stage: numbers in error messages.
#pragma once

#include <cstdio>
#include <string>

namespace curvetext::detail {

// Short ("%g"): exact for the integers and round values users type.
inline std::string format_number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

// Every digit ("%.17g"): for coordinates read from a file, so the message
// names the exact value.
inline std::string format_number_exact(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

}  // namespace curvetext::detail
