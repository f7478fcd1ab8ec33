// Paragraph layout, queries on a laid out paragraph: bounds, grapheme
// boundaries for carets, selection rectangles.

#include <hb.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "curvetext/layout.hpp"
#include "font/face_queries.hpp"

namespace curvetext {

Rect Paragraph::logical_bounds() const {
  Rect r;
  if (lines_.empty()) return r;
  double left = 0.0, right = width_;
  for (const LayoutLine& l : lines_) {
    left = std::min(left, l.x);
    right = std::max(right, l.x + l.width);
  }
  r.x = left;
  r.y = lines_.front().top;
  r.width = right - left;
  r.height = lines_.back().top + lines_.back().height - r.y;
  return r;
}

Rect Paragraph::ink_bounds() const {
  double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
  for (const LayoutLine& l : lines_)
    for (const GlyphRun& r : l.runs) {
      const double s = r.size_px / r.font->metrics().units_per_em;
      for (const PositionedGlyph& g : r.glyphs) {
        hb_glyph_extents_t e{};
        if (!detail::glyph_extents(*r.font, g.id, e) || e.width == 0 || e.height == 0) continue;
        const double gx0 = g.x + e.x_bearing * s, gx1 = gx0 + e.width * s;
        const double gy0 = g.y - e.y_bearing * s, gy1 = gy0 - e.height * s;
        x0 = std::min({x0, gx0, gx1});
        x1 = std::max({x1, gx0, gx1});
        y0 = std::min({y0, gy0, gy1});
        y1 = std::max({y1, gy0, gy1});
      }
    }
  if (x0 > x1) return {};
  return {x0, y0, x1 - x0, y1 - y0};
}

std::size_t Paragraph::previous_boundary(std::size_t index) const {
  index = std::min(index, text_.size());
  auto it = std::lower_bound(boundaries_.begin(), boundaries_.end(), index);
  if (it != boundaries_.end() && *it == index) {
    return it == boundaries_.begin() ? index : *(it - 1);
  }
  return it == boundaries_.begin() ? 0 : *(it - 1);
}

std::size_t Paragraph::next_boundary(std::size_t index) const {
  auto it = std::upper_bound(boundaries_.begin(), boundaries_.end(), index);
  return it == boundaries_.end() ? text_.size() : *it;
}

std::vector<Rect> Paragraph::selection_rects(std::size_t start, std::size_t end) const {
  std::vector<Rect> rects;
  if (start > end) std::swap(start, end);
  for (std::size_t k = 0; k < lines_.size(); ++k) {
    const LayoutLine& line = lines_[k];
    if (line.end <= start || line.start >= end) continue;
    std::vector<std::pair<double, double>> spans;
    for (const ClusterBox& b : boxes_[k])
      if (b.start < end && b.end > start) spans.push_back({b.left, b.right});
    std::sort(spans.begin(), spans.end());
    for (const auto& [l, r] : spans) {
      if (!rects.empty() && rects.back().y == line.top && std::abs(rects.back().x + rects.back().width - l) < 1e-6) {
        rects.back().width = r - rects.back().x;
      } else {
        rects.push_back({l, line.top, r - l, line.height});
      }
    }
  }
  return rects;
}

}  // namespace curvetext
