// Unicode's BidiCharacterTest.txt (Unicode 15.0, from Debian's unicode-data)
// through curvetext's bidi layer: paragraph level, resolved levels after L1,
// and visual order. Cases that cannot pass are listed, with reasons, in
// tests/fixtures/layout/bidi_skips.txt; a listed case that passes fails the
// test too, so the list cannot go stale.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>

#include "curvetext/bidi.hpp"
#include "support/layout_support.hpp"

namespace curvetext {
namespace {

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::string item;
  std::istringstream in(s);
  while (std::getline(in, item, sep)) out.push_back(item);
  if (!s.empty() && s.back() == sep) out.emplace_back();
  return out;
}

std::vector<std::string> words(const std::string& s) {
  std::vector<std::string> out;
  std::istringstream in(s);
  std::string w;
  while (in >> w) out.push_back(w);
  return out;
}

TEST(BidiConformance, BidiCharacterTest) {
  std::ifstream in(test::kBidiCharacterTest);
  ASSERT_TRUE(in) << "missing " << test::kBidiCharacterTest << " (Debian package unicode-data)";
  const auto skips = test::read_skip_list(test::layout_fixture("bidi_skips.txt"));
  std::string line;
  int number = 0, passed = 0, skipped = 0, failed = 0;
  while (std::getline(in, line)) {
    ++number;
    if (line.empty() || line[0] == '#') continue;
    const std::vector<std::string> f = split(line, ';');
    ASSERT_GE(f.size(), 5u) << "line " << number;
    std::u32string text;
    for (const std::string& h : words(f[0])) text.push_back(static_cast<char32_t>(std::stoul(h, nullptr, 16)));
    const int dir = std::stoi(f[1]);
    const BaseDirection base = dir == 0 ? BaseDirection::Ltr : dir == 1 ? BaseDirection::Rtl : BaseDirection::Auto;
    const int expected_level = std::stoi(f[2]);
    const std::vector<std::string> expected_levels = words(f[3]);
    const std::vector<std::string> expected_order = words(f[4]);

    const BidiParagraph bidi = resolve_bidi(text, base);
    const std::vector<std::uint8_t> levels = line_levels(text, bidi, 0, text.size());
    const std::vector<std::size_t> order = visual_order(text, bidi, 0, text.size());
    std::string why;
    if (bidi.paragraph_level != expected_level) why = "paragraph level";
    for (std::size_t i = 0; why.empty() && i < text.size(); ++i) {
      if (expected_levels[i] == "x") continue;
      if (levels[i] != std::stoi(expected_levels[i])) why = "level of character " + std::to_string(i);
    }
    if (why.empty()) {
      std::string got;
      for (std::size_t k : order) got += (got.empty() ? "" : " ") + std::to_string(k);
      std::string want;
      for (const std::string& k : expected_order) want += (want.empty() ? "" : " ") + k;
      if (got != want) why = "order " + got + " want " + want;
    }
    const auto skip = skips.find(number);
    if (skip != skips.end()) {
      ++skipped;
      EXPECT_FALSE(why.empty()) << "line " << number << " is in bidi_skips.txt but passes: remove it";
      continue;
    }
    if (why.empty()) {
      ++passed;
    } else {
      ++failed;
      if (failed <= 20) ADD_FAILURE() << "BidiCharacterTest line " << number << ": " << why << "\n  " << line;
    }
  }
  std::printf("BidiCharacterTest: %d passed, %d skipped (listed), %d failed\n", passed, skipped, failed);
  EXPECT_EQ(failed, 0);
  EXPECT_GT(passed, 90000);
}

}  // namespace
}  // namespace curvetext
