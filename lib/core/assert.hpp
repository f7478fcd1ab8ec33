// Private interface of core/ for every stage: CURVETEXT_ASSERT(condition)
// states an invariant of the code itself (never of its input: bad input is an
// Error). It is checked in debug, sanitizer and fuzz builds
// (CURVETEXT_ASSERTIONS, set by the top-level CMakeLists.txt), where a failure
// prints the condition and aborts; in release builds the condition is not
// evaluated.
#pragma once

#if defined(CURVETEXT_ASSERTIONS) && CURVETEXT_ASSERTIONS
#include <cstdio>
#include <cstdlib>

namespace curvetext::detail {

[[noreturn]] inline void assertion_failed(const char* condition, const char* file, int line) {
  std::fprintf(stderr, "%s:%d: CURVETEXT_ASSERT(%s) failed\n", file, line, condition);
  std::abort();
}

}  // namespace curvetext::detail

#define CURVETEXT_ASSERT(condition) \
  ((condition) ? static_cast<void>(0) : ::curvetext::detail::assertion_failed(#condition, __FILE__, __LINE__))
#else
// (sizeof: the names in the condition count as used, nothing is evaluated.)
#define CURVETEXT_ASSERT(condition) static_cast<void>(sizeof(!(condition)))
#endif
