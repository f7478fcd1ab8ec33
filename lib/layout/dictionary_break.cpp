// Word breaks inside runs of Thai letters from libthai's dictionary. UAX #14
// puts Thai in class SA (complex context): the standard leaves its breaks to
// a dictionary and resolves SA to AL without one, so line_breaks() alone lets
// a line end only at spaces. libthai is what Pango uses for Thai, so the two
// break Thai text alike.
#include "curvetext/line_break.hpp"

#include <thai/thbrk.h>
#include <thai/thwbrk.h>

#include <algorithm>
#include <cstddef>
#include <memory>
#include <vector>

namespace curvetext {
namespace {

// U+0E01..U+0E5B: the Thai block's letters, vowels, tone marks and digits.
bool is_thai(char32_t c) { return c >= 0x0E01 && c <= 0x0E5B; }

struct ThBrkDeleter {
  void operator()(ThBrk* b) const { th_brk_delete(b); }
};

// One breaker per thread (libthai does not promise that one may be shared),
// kept for the thread's life: it holds the loaded dictionary, not scratch,
// and th_brk_new takes tens of milliseconds to load it, more than laying out
// a paragraph. Null when the dictionary cannot be loaded, and then nothing is
// added.
ThBrk* breaker() {
  thread_local std::unique_ptr<ThBrk, ThBrkDeleter> brk(th_brk_new(nullptr));
  return brk.get();
}

}  // namespace

bool add_dictionary_breaks(std::u32string_view text, std::vector<BreakAction>& breaks, std::size_t from, std::size_t to,
                           std::vector<bool>& done) {
  if (breaks.size() != text.size() || done.size() != text.size()) return false;
  to = std::min(to, text.size());
  // Back to the start of a run that reaches into [from, to).
  std::size_t i = std::min(from, to);
  while (i > 0 && i < text.size() && is_thai(text[i]) && is_thai(text[i - 1])) --i;
  bool added = false;
  std::vector<wchar_t> run;
  std::vector<int> positions;
  while (i < to) {
    if (!is_thai(text[i])) {
      ++i;
      continue;
    }
    std::size_t end = i;
    while (end < text.size() && is_thai(text[end])) ++end;
    ThBrk* brk = !done[i] && end - i > 1 ? breaker() : nullptr;
    for (std::size_t k = i; k < end; ++k) done[k] = true;
    if (brk) {
      run.assign(text.begin() + static_cast<std::ptrdiff_t>(i), text.begin() + static_cast<std::ptrdiff_t>(end));
      run.push_back(L'\0');
      positions.resize(end - i);
      const int n = th_brk_wc_find_breaks(brk, run.data(), positions.data(), positions.size());
      // positions[k]: a word starts at that index of the run, so a line may
      // end after the character before it.
      for (int k = 0; k < n; ++k) {
        const auto p = static_cast<std::size_t>(positions[static_cast<std::size_t>(k)]);
        if (p == 0 || p >= end - i) continue;
        BreakAction& b = breaks[i + p - 1];
        if (b == BreakAction::None) {
          b = BreakAction::Allowed;
          added = true;
        }
      }
    }
    i = end;
  }
  return added;
}

void add_dictionary_breaks(std::u32string_view text, std::vector<BreakAction>& breaks) {
  std::vector<bool> done(text.size(), false);
  add_dictionary_breaks(text, breaks, 0, text.size(), done);
}

}  // namespace curvetext
