// Unicode's LineBreakTest.txt (Unicode 15.0) through curvetext's line
// breaking (lib/layout/line_break.cpp: Unicode 15 classes generated from
// unicode-data, UAX #14 rules in one pass). Every case passes
// or is listed with its reason in tests/fixtures/layout/linebreak_skips.txt;
// a listed case that passes fails the test, so the list cannot go stale.
// CURVETEXT_WRITE_LINEBREAK_SKIPS=FILE regenerates the list (reasons from the
// rule numbers in the test file's comments).
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>

#include "curvetext/line_break.hpp"
#include "support/layout_support.hpp"

namespace curvetext {
namespace {

// What each UAX #14 rule is about (for the reasons in the skip list), keyed by
// the rule number LineBreakTest.txt cites. Many name what libunibreak 1.1
// (Unicode 6.x), which curvetext's breaks came from before, lacked.
const std::map<std::string, std::string>& rule_names() {
  static const std::map<std::string, std::string> names = {
      {"8.1", "LB8a: no break after ZWJ (Unicode 9)"},
      {"9.0", "LB9: combining marks and ZWJ attach to the base (ZWJ is class CM only since Unicode 9)"},
      {"10.0", "LB10: lone combining mark/ZWJ treated as AL"},
      {"11.01", "LB11: word joiner"},
      {"12.0", "LB12: glue after GL"},
      {"12.1", "LB12a: glue before GL"},
      {"13.0", "LB13: no break before ] ) ! ? / (Unicode 15 keeps CL/CP/EX/IS/SY here)"},
      {"14.0", "LB14: OP SP* x"},
      {"15.0", "LB15: QU SP* x OP"},
      {"16.0", "LB16: (CL|CP) SP* x NS"},
      {"17.0", "LB17: B2 SP* x B2"},
      {"18.0", "LB18: break after spaces"},
      {"19.0", "LB19: quotation marks"},
      {"20.0", "LB20: break around CB"},
      {"21.0", "LB21: no break before BA, HY, NS; after BB"},
      {"21.01", "LB21a: Hebrew letter followed by hyphen (Unicode 6.3)"},
      {"21.02", "LB21b: SY x HL (Unicode 6.3)"},
      {"22.0", "LB22: inseparable characters (Unicode 13 dropped the left context)"},
      {"23.0", "LB23: letters and numbers"},
      {"23.01", "LB23a: numeric prefixes and postfixes with ideographs/emoji (Unicode 9)"},
      {"24.0", "LB24: prefix/postfix with letters"},
      {"25.0", "LB25: numeric expressions (Unicode 15 uses the regex form)"},
      {"26.0", "LB26: Korean syllable blocks"},
      {"27.0", "LB27: Korean syllables with PR/PO"},
      {"28.0", "LB28: letters"},
      {"28.1", "LB28a: Brahmic orthographic syllables (Aksara, new in Unicode 15)"},
      {"29.0", "LB29: IS x (AL|HL)"},
      {"30.0", "LB30: letters/numbers with parentheses (East Asian width restriction since Unicode 8)"},
      {"30.1", "LB30a: regional indicator pairs (Unicode 6.2+)"},
      {"30.11", "LB30a: regional indicator pairs (Unicode 6.2+)"},
      {"30.12", "LB30a: regional indicator pairs (Unicode 6.2+)"},
      {"30.13", "LB30a: regional indicator pairs (Unicode 6.2+)"},
      {"30.2", "LB30b: emoji base x emoji modifier (Unicode 9, extended to unassigned pictographs in 11)"},
      {"999.0", "LB31: break everywhere else (libunibreak 1.1 keeps an older rule or old class data)"},
      {"4.0", "LB4: break after BK"},
      {"5.01", "LB5: CR LF"},
      {"5.02", "LB5: break after CR"},
      {"5.03", "LB5: break after LF"},
      {"5.04", "LB5: break after NL"},
      {"6.0", "LB6: no break before hard line breaks"},
      {"7.01", "LB7: no break before spaces"},
      {"7.02", "LB7: no break before ZW"},
      {"8.0", "LB8: break after ZW SP*"},
  };
  return names;
}

struct Case {
  std::u32string text;
  std::vector<bool> breaks;        // break after code point i
  std::vector<std::string> rules;  // rule cited after code point i
};

Case parse(const std::string& line) {
  Case c;
  const std::size_t hash = line.find('#');
  std::istringstream in(line.substr(0, hash));
  std::string token;
  in >> token;  // the mark before the first character (start of text)
  while (in >> token) {
    c.text.push_back(static_cast<char32_t>(std::stoul(token, nullptr, 16)));
    in >> token;
    c.breaks.push_back(token == "\xC3\xB7");  // "÷"
  }
  // Comments cite one rule per position: "[0.3]" at the start, then one after
  // each character.
  const std::string comment = hash == std::string::npos ? "" : line.substr(hash);
  std::size_t pos = 0;
  bool first = true;
  while ((pos = comment.find('[', pos)) != std::string::npos) {
    const std::size_t close = comment.find(']', pos);
    if (!first) c.rules.push_back(comment.substr(pos + 1, close - pos - 1));
    first = false;
    pos = close;
  }
  return c;
}

TEST(LineBreakConformance, LineBreakTest) {
  std::ifstream in(test::kLineBreakTest);
  ASSERT_TRUE(in) << "missing " << test::kLineBreakTest << " (Debian package unicode-data)";
  const auto skips = test::read_skip_list(test::layout_fixture("linebreak_skips.txt"));
  const char* write_path = std::getenv("CURVETEXT_WRITE_LINEBREAK_SKIPS");
  std::ofstream out;
  if (write_path) {
    out.open(write_path);
    out << "# LineBreakTest.txt (Unicode 15.0) cases that curvetext's line breaking (lib/layout/line_break.cpp)\n"
           "# gets wrong, with the first UAX #14 rule where the answer differs. <line>\\t<reason>\n";
  }
  std::map<std::string, int> by_rule;
  std::string line;
  int number = 0, passed = 0, skipped = 0, failed = 0;
  while (std::getline(in, line)) {
    ++number;
    if (line.empty() || line[0] == '#') continue;
    const Case c = parse(line);
    const std::vector<BreakAction> got = line_breaks(c.text);
    std::string why;
    for (std::size_t i = 0; why.empty() && i < c.text.size(); ++i) {
      const bool brk = got[i] != BreakAction::None;
      if (brk != c.breaks[i]) {
        const std::string rule = i < c.rules.size() ? c.rules[i] : "?";
        auto name = rule_names().find(rule);
        // Sub-rules the table does not name (24.03, 21.04) take their rule's name.
        if (name == rule_names().end()) name = rule_names().find(rule.substr(0, rule.find('.')) + ".0");
        why = std::string(brk ? "breaks" : "does not break") + " after character " + std::to_string(i) + ", rule " +
              rule + (name != rule_names().end() ? " (" + name->second + ")" : "");
      }
    }
    if (!why.empty()) {
      by_rule[why.substr(why.find(", rule ") + 7)]++;
      if (out) out << number << '\t' << why << '\n';
    }
    const auto skip = skips.find(number);
    if (skip != skips.end()) {
      ++skipped;
      EXPECT_FALSE(why.empty()) << "line " << number << " is in linebreak_skips.txt but passes: remove it";
      continue;
    }
    if (why.empty()) {
      ++passed;
    } else {
      ++failed;
      if (failed <= 20) ADD_FAILURE() << "LineBreakTest line " << number << ": " << why << "\n  " << line;
    }
  }
  std::printf("LineBreakTest: %d passed, %d skipped (listed), %d failed\n", passed, skipped, failed);
  for (const auto& [rule, count] : by_rule) std::printf("  %5d wrong at rule %s\n", count, rule.c_str());
  EXPECT_EQ(failed, 0);
  EXPECT_GT(passed, 5000);
}

// libunibreak's language tailorings apply over the Unicode 15 classes: in
// Chinese, U+201C/U+201D are opening/closing punctuation (breaks allowed
// before and after the pair), where Unicode's default class QU glues them.
TEST(LineBreakConformance, LanguageTailoring) {
  const std::u32string text = U"\u4E2D\u201C\u6587\u201D\u5B57";
  const auto plain = line_breaks(text);
  EXPECT_EQ(plain[0], BreakAction::None);
  EXPECT_EQ(plain[3], BreakAction::None);
  const auto zh = line_breaks(text, "zh");
  EXPECT_EQ(zh[0], BreakAction::Allowed);
  EXPECT_EQ(zh[1], BreakAction::None);
  EXPECT_EQ(zh[2], BreakAction::None);
  EXPECT_EQ(zh[3], BreakAction::Allowed);
  EXPECT_EQ(zh[4], BreakAction::Mandatory);
  EXPECT_EQ(line_breaks(text, "xx"), plain);
}

}  // namespace
}  // namespace curvetext
