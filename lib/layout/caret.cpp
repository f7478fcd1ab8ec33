// Carets of a laid-out paragraph: strong and weak carets placed as Pango
// places them, caret affinity at soft line breaks, hit testing, and visual
// (arrow key) and word movement that walk monotonically on screen.
#include <wordbreak.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_map>
#include <utility>
#include <vector>

#include "curvetext/layout.hpp"

namespace curvetext {

namespace {

constexpr double kSameXPx = 1e-6;  // carets closer than this are at one place on screen

// Whether the text ends a line at `end` with a line or paragraph separator
// (a hard break: the position after it belongs to the next line only).
bool hard_break_before(const std::string& text, std::size_t end) {
  if (end == 0) return false;
  const unsigned char c = static_cast<unsigned char>(text[end - 1]);
  if (c == '\n' || c == '\r' || c == 0x0B || c == 0x0C) return true;
  // U+0085 (C2 85), U+2028 and U+2029 (E2 80 A8 / A9).
  if (end >= 2 && static_cast<unsigned char>(text[end - 2]) == 0xC2 && c == 0x85) return true;
  return end >= 3 && static_cast<unsigned char>(text[end - 3]) == 0xE2 &&
         static_cast<unsigned char>(text[end - 2]) == 0x80 && (c == 0xA8 || c == 0xA9);
}

bool is_white_space(const std::string& text, std::size_t start, std::size_t end) {
  for (std::size_t i = start; i < end; ++i) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c != ' ' && c != '\t' && c != 0xC2 && c != 0xA0 && c != '\n' && c != '\r') return false;
  }
  return end > start;
}

}  // namespace

std::size_t Paragraph::line_of(std::size_t index, CaretAffinity affinity) const {
  for (std::size_t k = 0; k < lines_.size(); ++k) {
    const LayoutLine& line = lines_[k];
    const bool last = k + 1 == lines_.size();
    if (affinity == CaretAffinity::Upstream && !last && index == line.end && index > line.start &&
        !hard_break_before(text_, index))
      return k;
    if (index >= line.start && index < line.end) return k;
  }
  return lines_.empty() ? 0 : lines_.size() - 1;
}

// Pango's rule: with c the grapheme before the position and d the one after
// it on this line (the line's edge, at the paragraph's level, where there is
// none), the strong caret is at c's trailing edge when c has the paragraph's
// direction and d has not or lies at a deeper level, else at d's leading
// edge; the weak caret at the other.
std::vector<Caret> Paragraph::carets_on(std::size_t li, const std::vector<std::size_t>& positions) const {
  const LayoutLine& line = lines_[li];
  const bool rtl_para = line.paragraph_level % 2 == 1;
  std::unordered_map<std::size_t, const ClusterBox*> ending, starting;
  double left = std::numeric_limits<double>::infinity(), right = -left;
  for (const ClusterBox& b : boxes_[li]) {
    ending[b.end] = &b;
    starting[b.start] = &b;
    left = std::min(left, b.left);
    right = std::max(right, b.right);
  }
  if (boxes_[li].empty()) left = right = line.x;
  std::vector<Caret> out;
  out.reserve(positions.size());
  for (std::size_t index : positions) {
    const auto e = ending.find(index), s = starting.find(index);
    const ClusterBox* before = e == ending.end() ? nullptr : e->second;
    const ClusterBox* after = s == starting.end() ? nullptr : s->second;
    const double x1 = before ? (before->rtl ? before->left : before->right) : (rtl_para ? right : left);
    const int level1 = before ? before->level : line.paragraph_level;
    const double x2 = after ? (after->rtl ? after->right : after->left) : (rtl_para ? left : right);
    const int level2 = after ? after->level : line.paragraph_level;
    const bool dir1 = level1 % 2 == 1, dir2 = level2 % 2 == 1;
    // c's edge where c has the paragraph's direction and d does not, or d is
    // embedded deeper (digits in a right-to-left stretch of a left-to-right
    // paragraph end before the stretch does).
    const bool first_strong = dir1 == rtl_para && (dir2 != dir1 || level1 < level2);
    Caret c;
    c.line = li;
    c.top = line.top;
    c.bottom = line.top + line.height;
    c.strong_x = first_strong ? x1 : x2;
    c.strong_rtl = first_strong ? dir1 : dir2;
    c.weak_x = first_strong ? x2 : x1;
    c.weak_rtl = first_strong ? dir2 : dir1;
    out.push_back(c);
  }
  return out;
}

Caret Paragraph::caret(std::size_t index, CaretAffinity affinity) const {
  if (lines_.empty()) return Caret{};
  index = std::min(index, text_.size());
  if (!std::binary_search(boundaries_.begin(), boundaries_.end(), index)) index = previous_boundary(index);
  return carets_on(line_of(index, affinity), {index}).front();
}

HitResult Paragraph::hit_test(double x, double y) const {
  HitResult h;
  if (lines_.empty()) return h;
  std::size_t li = lines_.size() - 1;
  for (std::size_t k = 0; k < lines_.size(); ++k)
    if (y < lines_[k].top + lines_[k].height) {
      li = k;
      break;
    }
  h.line = li;
  const LayoutLine& line = lines_[li];
  const auto& boxes = boxes_[li];
  if (boxes.empty()) {
    h.index = line.start;
    return h;
  }
  const ClusterBox* leftmost = &boxes.front();
  const ClusterBox* rightmost = &boxes.front();
  for (const ClusterBox& b : boxes) {
    if (b.left < leftmost->left) leftmost = &b;
    if (b.right > rightmost->right) rightmost = &b;
  }
  const bool in_y = y >= line.top && y < line.top + line.height;
  if (x < leftmost->left || x >= rightmost->right) {
    // Beyond the line's ends: the position whose strong caret is there (at
    // a bidi boundary the grapheme's edge may hold only a weak one).
    const double edge = x < leftmost->left ? leftmost->left : rightmost->right;
    std::vector<std::size_t> positions;
    for (auto it = std::lower_bound(boundaries_.begin(), boundaries_.end(), line.start);
         it != boundaries_.end() && *it <= line.end; ++it)
      positions.push_back(*it);
    const std::vector<Caret> carets = carets_on(li, positions);
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < positions.size(); ++k)
      if (std::abs(carets[k].strong_x - edge) < best) {
        best = std::abs(carets[k].strong_x - edge);
        h.index = positions[k];
      }
  } else {
    double best = std::numeric_limits<double>::infinity();
    for (const ClusterBox& b : boxes) {
      if (x >= b.left && x < b.right) {
        const bool left_half = x < (b.left + b.right) / 2.0;
        h.index = (left_half != b.rtl) ? b.start : b.end;
        h.inside = in_y;
        break;
      }
      // In a gap between boxes (justified spaces are inside boxes; rare).
      const double d = std::min(std::abs(x - b.left), std::abs(x - b.right));
      if (d < best) {
        best = d;
        h.index = (std::abs(x - b.left) < std::abs(x - b.right)) != b.rtl ? b.start : b.end;
      }
    }
  }
  // A position that ends a softly wrapped line stays on it.
  if (h.index == line.end && li + 1 < lines_.size() && !hard_break_before(text_, h.index))
    h.affinity = CaretAffinity::Upstream;
  return h;
}

namespace {

// A line's caret positions with their strong x, left to right on screen
// (equal x: logical order).
std::vector<std::pair<double, std::size_t>> sorted_carets(const std::vector<std::size_t>& positions,
                                                          const std::vector<double>& xs) {
  std::vector<std::pair<double, std::size_t>> out;
  for (std::size_t i = 0; i < positions.size(); ++i) out.push_back({xs[i], positions[i]});
  std::stable_sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  return out;
}

}  // namespace

CaretPosition Paragraph::move_visually(CaretPosition from, int direction) const {
  if (lines_.empty() || direction == 0) return from;
  from.index = std::min(from.index, text_.size());
  const std::size_t li = line_of(from.index, from.affinity);
  // The positions on a line: its grapheme boundaries, and its end where the
  // end is not a hard break (a soft wrap, or the text's end).
  auto carets_of = [&](std::size_t k) {
    const LayoutLine& line = lines_[k];
    std::vector<std::size_t> positions;
    for (auto it = std::lower_bound(boundaries_.begin(), boundaries_.end(), line.start);
         it != boundaries_.end() && *it < line.end; ++it)
      positions.push_back(*it);
    const bool last = k + 1 == lines_.size();
    if ((last || !hard_break_before(text_, line.end)) && (positions.empty() || positions.back() != line.end))
      positions.push_back(line.end);
    std::vector<double> xs;
    for (const Caret& c : carets_on(k, positions)) xs.push_back(c.strong_x);
    return sorted_carets(positions, xs);
  };
  auto position_on = [&](std::size_t k, std::size_t index) {
    const bool upstream = index == lines_[k].end && k + 1 < lines_.size();
    return CaretPosition{index, upstream ? CaretAffinity::Upstream : CaretAffinity::Downstream};
  };
  const auto here = carets_of(li);
  const double x = carets_on(li, {from.index}).front().strong_x;
  if (direction > 0) {
    for (const auto& [cx, index] : here)
      if (cx > x + kSameXPx) return position_on(li, index);
  } else {
    for (auto it = here.rbegin(); it != here.rend(); ++it)
      if (it->first < x - kSameXPx) return position_on(li, it->second);
  }
  // Past the line's end that way: the following line when moving in the
  // paragraph's direction, else the preceding one, entered from its edge.
  const bool rtl = lines_[li].paragraph_level % 2 == 1;
  const bool forward = (direction > 0) != rtl;
  if (forward ? li + 1 >= lines_.size() : li == 0) return from;
  const std::size_t next = forward ? li + 1 : li - 1;
  const auto there = carets_of(next);
  if (there.empty()) return from;
  return position_on(next, direction > 0 ? there.front().second : there.back().second);
}

CaretPosition Paragraph::move_word_visually(CaretPosition from, int direction) const {
  std::vector<char> breaks(text_.size());
  if (!text_.empty())
    set_wordbreaks_utf8(reinterpret_cast<const utf8_t*>(text_.data()), text_.size(), "", breaks.data());
  auto word_boundary = [&](std::size_t i) { return i == 0 || i >= text_.size() || breaks[i - 1] == WORDBREAK_BREAK; };
  const std::size_t line = line_of(from.index, from.affinity);
  bool crossed_word = false;
  for (;;) {
    const CaretPosition next = move_visually(from, direction);
    if (next.index == from.index && next.affinity == from.affinity) return from;
    if (line_of(next.index, next.affinity) != line) return crossed_word ? from : next;
    crossed_word =
        crossed_word || !is_white_space(text_, std::min(from.index, next.index), std::max(from.index, next.index));
    from = next;
    if (crossed_word && word_boundary(from.index)) return from;
  }
}

}  // namespace curvetext
