// Carets against Pango, from data (tests/carets/carets.tsv, written by
// tests/carets/pango_carets.cpp from texts.txt; one bidi paragraph per line):
// strong and weak caret x at every caret position, and visual walks to the
// right and left compared as the places on screen they visit. Then caret
// affinity at a soft wrap, and word movement.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "curvetext/font_collection.hpp"
#include "curvetext/layout.hpp"
#include "support/fonts.hpp"

namespace curvetext {
namespace {

// Pango works in 1/1024 px; both lay out DejaVu Sans with HarfBuzz, unhinted.
constexpr double kToleranceSamePx = 0.01;

struct Case {
  std::string direction, text;
  std::vector<std::size_t> positions;
  std::vector<double> strong, weak;
  std::vector<std::size_t> right_walk, left_walk;
};

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> out;
  std::string part;
  std::istringstream in(s);
  while (std::getline(in, part, sep)) out.push_back(part);
  if (!s.empty() && s.back() == sep) out.push_back("");
  return out;
}

std::vector<std::size_t> indices(const std::string& s) {
  std::vector<std::size_t> out;
  for (const std::string& v : split(s, ' '))
    if (!v.empty()) out.push_back(std::stoul(v));
  return out;
}

std::vector<Case> read_cases() {
  std::ifstream in(std::string(CURVETEXT_SOURCE_DIR) + "/tests/carets/carets.tsv");
  std::vector<Case> cases;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    const std::vector<std::string> f = split(line, '\t');
    if (f.size() != 5) ADD_FAILURE() << "bad line: " << line;
    if (f.size() != 5) continue;
    Case c{f[0], f[1], {}, {}, {}, indices(f[3]), indices(f[4])};
    for (const std::string& item : split(f[2], ' ')) {
      const std::vector<std::string> v = split(item, ':');
      c.positions.push_back(std::stoul(v.at(0)));
      c.strong.push_back(std::stod(v.at(1)));
      c.weak.push_back(std::stod(v.at(2)));
    }
    cases.push_back(c);
  }
  return cases;
}

ParagraphStyle style(const std::string& direction) {
  ParagraphStyle s;
  s.default_style.fonts = {test::kDejaVuSans};
  s.default_style.size_px = 20.0;
  s.direction = direction == "rtl" ? BaseDirection::Rtl : direction == "ltr" ? BaseDirection::Ltr : BaseDirection::Auto;
  return s;
}

// Our walk from the line's left (right) end, as strong caret x.
std::vector<double> walk_x(const Paragraph& p, int direction) {
  const HitResult start = p.hit_test(direction > 0 ? -1e6 : 1e6, 1.0);
  CaretPosition at{start.index, start.affinity};
  std::vector<double> xs{p.caret(at).strong_x};
  for (int guard = 0; guard < 1000; ++guard) {
    const CaretPosition next = p.move_visually(at, direction);
    if (next.index == at.index) break;
    at = next;
    xs.push_back(p.caret(at).strong_x);
  }
  return xs;
}

// Pango's walk as strong caret x, with positions at one place on screen
// visited once (Pango visits one of two positions with equal strong x).
std::vector<double> pango_walk_x(const Case& c, const std::vector<std::size_t>& walk) {
  std::vector<double> xs;
  for (std::size_t index : walk)
    for (std::size_t k = 0; k < c.positions.size(); ++k)
      if (c.positions[k] == index) xs.push_back(c.strong[k]);
  return xs;
}

TEST(Carets, StrongWeakAndVisualWalksMatchPango) {
  const std::vector<Case> cases = read_cases();
  ASSERT_GE(cases.size(), 10u);
  FontCollection fonts;
  int compared = 0;
  for (const Case& c : cases) {
    SCOPED_TRACE(c.direction + " \"" + c.text + "\"");
    const Paragraph p = Paragraph::layout(fonts, c.text, {}, style(c.direction));
    for (std::size_t k = 0; k < c.positions.size(); ++k) {
      const Caret got = p.caret(c.positions[k]);
      EXPECT_NEAR(got.strong_x, c.strong[k], kToleranceSamePx) << "strong caret at " << c.positions[k];
      EXPECT_NEAR(got.weak_x, c.weak[k], kToleranceSamePx) << "weak caret at " << c.positions[k];
      ++compared;
    }
    for (int direction : {1, -1}) {
      const std::vector<double> got = walk_x(p, direction);
      const std::vector<double> want = pango_walk_x(c, direction > 0 ? c.right_walk : c.left_walk);
      ASSERT_EQ(got.size(), want.size()) << (direction > 0 ? "right" : "left") << " walk length";
      for (std::size_t i = 0; i < got.size(); ++i) {
        EXPECT_NEAR(got[i], want[i], kToleranceSamePx) << (direction > 0 ? "right" : "left") << " walk step " << i;
        if (i > 0) EXPECT_TRUE(direction > 0 ? got[i] > got[i - 1] : got[i] < got[i - 1]) << "not monotonic";
      }
    }
  }
  std::printf("%d caret positions compared with Pango over %zu paragraphs\n", compared, cases.size());
}

// A click past the end of a softly wrapped line keeps the caret on that line.
TEST(Carets, AffinityKeepsTheCaretOnTheLineClicked) {
  FontCollection fonts;
  ParagraphStyle s = style("ltr");
  s.width = 80.0;
  const Paragraph p = Paragraph::layout(fonts, "wrapping words here", {}, s);
  ASSERT_GE(p.lines().size(), 2u);
  const LayoutLine& first = p.lines()[0];
  const HitResult h = p.hit_test(first.x + first.width + 30.0, first.top + 1.0);
  EXPECT_EQ(h.index, first.end);
  EXPECT_EQ(h.affinity, CaretAffinity::Upstream);
  const Caret up = p.caret(h.index, h.affinity);
  EXPECT_EQ(up.line, 0u);
  EXPECT_GT(up.strong_x, first.x + first.width - 1e-6);
  const Caret down = p.caret(h.index);
  EXPECT_EQ(down.line, 1u);
  // Moving right from the upstream end goes to the next line's first position.
  const CaretPosition next = p.move_visually({h.index, h.affinity}, 1);
  EXPECT_EQ(p.caret(next).line, 1u);
}

// Word movement over "abc שלום עולם 123 def": each step lands on a word
// edge, strictly further right on screen, and the walk visits every word.
TEST(Carets, WordMovementIsMonotonicOnScreen) {
  FontCollection fonts;
  const std::string text = "abc \u05e9\u05dc\u05d5\u05dd \u05e2\u05d5\u05dc\u05dd 123 def";
  const Paragraph p = Paragraph::layout(fonts, text, {}, style("ltr"));
  CaretPosition at{0, CaretAffinity::Downstream};
  double x = p.caret(at).strong_x;
  int steps = 0;
  for (; steps < 20; ++steps) {
    const CaretPosition next = p.move_word_visually(at, 1);
    if (next.index == at.index) break;
    const double nx = p.caret(next).strong_x;
    EXPECT_GT(nx, x) << "step " << steps;
    x = nx;
    at = next;
  }
  EXPECT_EQ(steps, 5) << "one step per word";
  EXPECT_NEAR(x, p.lines()[0].x + p.lines()[0].width, 1e-6);
  // The logical order jumps backwards on screen: what visual movement fixes.
  int backwards = 0;
  for (std::size_t i = 0, last = 0; i < text.size(); last = i, i = p.next_boundary(i))
    if (i > 0 && p.caret(i).strong_x < p.caret(last).strong_x) ++backwards;
  std::printf("logical walk: %d steps backwards on screen; word walk: %d steps\n", backwards, steps);
  EXPECT_GT(backwards, 0);
}

}  // namespace
}  // namespace curvetext
