#include "support/union_coverage.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <vector>

namespace curvetext::test {
namespace {

// Deepest recursive halving of one curve while flattening: bounds the work on
// absurd input (2^20 pieces per curve); a glyph-sized curve at any test scale
// is flat long before.
constexpr int kMaxFlattenDepth = 20;
// Below this horizontal extent (px) a piece is integrated with the midpoint
// rule instead of the divided difference of the antiderivative, whose
// cancellation error grows as 1/extent; both are within 1e-7 px^2 there.
constexpr double kNearVerticalPx = 1e-7;
// Sub-slabs thinner than this (px) are skipped: they hold at most
// width * 1e-12 px^2 and their chain order is not resolvable in doubles.
constexpr double kThinSlabPx = 1e-12;

double distance_to_segment(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 d = b - a;
  const double len2 = dot(d, d);
  if (len2 == 0.0) return distance(p, a);
  const double t = std::clamp(dot(p - a, d) / len2, 0.0, 1.0);
  return distance(p, a + d * t);
}

// Appends the points after `a` of a polyline within `tol` of the conic
// (a, c, b; weight w), ending with b. Halving is done in homogeneous
// coordinates, which is exact for rational curves; a half of a conic with
// middle weight w has middle weight sqrt((1 + w) / 2). The curve lies in its
// control triangle (positive weights), so the control point's distance to the
// chord bounds the curve's.
void flatten_conic(Vec2 a, Vec2 c, Vec2 b, double w, double tol, int depth, std::vector<Vec2>& out) {
  if (depth >= kMaxFlattenDepth || distance_to_segment(c, a, b) <= tol) {
    out.push_back(b);
    return;
  }
  const Vec2 left_c = (a + c * w) / (1.0 + w);
  const Vec2 right_c = (c * w + b) / (1.0 + w);
  const Vec2 mid = (a + c * (2.0 * w) + b) / (2.0 * (1.0 + w));
  const double half_w = std::sqrt((1.0 + w) / 2.0);
  flatten_conic(a, left_c, mid, half_w, tol, depth + 1, out);
  flatten_conic(mid, right_c, b, half_w, tol, depth + 1, out);
}

void flatten_cubic(Vec2 a, Vec2 c1, Vec2 c2, Vec2 b, double tol, int depth, std::vector<Vec2>& out) {
  if (depth >= kMaxFlattenDepth || std::max(distance_to_segment(c1, a, b), distance_to_segment(c2, a, b)) <= tol) {
    out.push_back(b);
    return;
  }
  const Vec2 ab = (a + c1) * 0.5, bc = (c1 + c2) * 0.5, cd = (c2 + b) * 0.5;
  const Vec2 abc = (ab + bc) * 0.5, bcd = (bc + cd) * 0.5;
  const Vec2 mid = (abc + bcd) * 0.5;
  flatten_cubic(a, ab, abc, mid, tol, depth + 1, out);
  flatten_cubic(mid, bcd, cd, b, tol, depth + 1, out);
}

// A straight piece with ya < yb; x is linear in y between its ends.
struct Piece {
  double xa, ya, xb, yb;
  double x_at(double y) const { return xa + (xb - xa) * ((y - ya) / (yb - ya)); }
};

// A y-monotone run of pieces, sorted by increasing y and contiguous in y.
// dir: +1 when the contour runs towards +y along it, -1 otherwise.
struct Chain {
  std::vector<Piece> pieces;
  int dir = 0;
  double ymin = 0.0, ymax = 0.0;
};

void add_chains(const std::vector<Vec2>& ring, std::vector<Chain>& chains) {
  const std::size_t n = ring.size();
  if (n < 2) return;
  Chain current;
  auto finish = [&] {
    if (current.pieces.empty()) return;
    if (current.dir < 0) std::reverse(current.pieces.begin(), current.pieces.end());
    current.ymin = current.pieces.front().ya;
    current.ymax = current.pieces.back().yb;
    chains.push_back(std::move(current));
    current = Chain{};
  };
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 p = ring[i], q = ring[(i + 1) % n];
    if (p.y == q.y) {
      // Horizontal: no area against columns and no winding change, but the
      // chain must end here: continuing it would make x jump along the
      // chain, and a jump past another chain is a change of order that no
      // crossing test sees; a chain end is a cut.
      finish();
      current.dir = 0;
      continue;
    }
    const int dir = q.y > p.y ? 1 : -1;
    if (dir != current.dir) {
      finish();
      current.dir = dir;
    }
    if (dir > 0)
      current.pieces.push_back({p.x, p.y, q.x, q.y});
    else
      current.pieces.push_back({q.x, q.y, p.x, p.y});
  }
  finish();
}

// Integral over y in [ya, yb] of the length of [x(y), inf) inside column c,
// i.e. clamp(c + 1 - x, 0, 1), for a straight piece: through the
// antiderivative of that function of u = x - c.
double column_integral(double xa, double xb, double h, double c) {
  auto g = [](double u) { return std::clamp(1.0 - u, 0.0, 1.0); };
  if (std::abs(xb - xa) < kNearVerticalPx) return h * g(0.5 * (xa + xb) - c);
  auto antiderivative = [](double u) {
    if (u <= 0.0) return u;
    if (u >= 1.0) return 0.5;
    return u - 0.5 * u * u;
  };
  return h * (antiderivative(xb - c) - antiderivative(xa - c)) / (xb - xa);
}

// One pixel row, limited to the columns [col0, col0 + n) the outline spans:
// columns left of it get nothing and right of it the carries cancel.
struct RowAccumulator {
  int col0 = 0;
  std::vector<double> cover;  // per column, partial contributions
  std::vector<double> carry;  // difference array of full-height contributions
  RowAccumulator(int first_column, int count)
      : col0(first_column),
        cover(static_cast<std::size_t>(count), 0.0),
        carry(static_cast<std::size_t>(count) + 1, 0.0) {}
  void clear() {
    std::fill(cover.begin(), cover.end(), 0.0);
    std::fill(carry.begin(), carry.end(), 0.0);
  }

  // Adds sign * (area of the part of each column right of the piece) over
  // the piece's height: a left boundary adds, a right boundary subtracts, so
  // every column receives the length of [left, right] inside it.
  void add(double xa, double ya, double xb, double yb, double sign) {
    const double h = yb - ya;
    if (!(h > 0.0)) return;
    const double n = static_cast<double>(cover.size());
    const double lo = std::min(xa, xb) - col0, hi = std::max(xa, xb) - col0;
    const double c_lo = std::floor(lo), c_hi = std::floor(hi);
    // Columns outside the span do not matter, except through the carry.
    const int first = static_cast<int>(std::clamp(c_lo, 0.0, n));
    const int last = static_cast<int>(std::clamp(c_hi, -1.0, n - 1.0));
    for (int c = first; c <= last; ++c)
      cover[static_cast<std::size_t>(c)] += sign * column_integral(xa - col0, xb - col0, h, c);
    const double full_from = std::max(c_hi + 1.0, 0.0);
    if (full_from < n) carry[static_cast<std::size_t>(full_from)] += sign * h;
  }
};

// Heights, strictly inside (y0, y1), where chains a and b cross or touch.
void crossings(const Chain& a, std::size_t a0, std::size_t a1, const Chain& b, std::size_t b0, std::size_t b1,
               double y0, double y1, std::vector<double>& out) {
  std::size_t i = a0, k = b0;
  while (i < a1 && k < b1) {
    const Piece& p = a.pieces[i];
    const Piece& q = b.pieces[k];
    const double lo = std::max({p.ya, q.ya, y0}), hi = std::min({p.yb, q.yb, y1});
    if (hi > lo) {
      const double d_lo = p.x_at(lo) - q.x_at(lo), d_hi = p.x_at(hi) - q.x_at(hi);
      if ((d_lo < 0.0 && d_hi > 0.0) || (d_lo > 0.0 && d_hi < 0.0)) {
        out.push_back(std::clamp(lo + (hi - lo) * (d_lo / (d_lo - d_hi)), lo, hi));
      } else {
        if (d_lo == 0.0) out.push_back(lo);
        if (d_hi == 0.0) out.push_back(hi);
      }
    }
    if (p.yb < q.yb)
      ++i;
    else
      ++k;
  }
}

}  // namespace

void add_union_coverage(const Outline& pixel_outline, Coverage& target, double flatness_px) {
  if (!pixel_outline.is_finite()) throw std::runtime_error("union_coverage: outline is not finite");
  if (!(flatness_px > 0.0)) throw std::runtime_error("union_coverage: flatness must be positive");
  std::vector<Chain> chains;
  std::vector<Vec2> ring;
  for (const Contour& contour : pixel_outline.contours()) {
    if (contour.segments.empty()) continue;
    ring.clear();
    ring.push_back(contour.segments.front().start());
    for (const Segment& s : contour.segments) {
      switch (s.kind) {
        case Segment::Kind::Line:
          ring.push_back(s.p[1]);
          break;
        case Segment::Kind::Conic:
          flatten_conic(s.p[0], s.p[1], s.p[2], s.weight, flatness_px, 0, ring);
          break;
        case Segment::Kind::Cubic:
          flatten_cubic(s.p[0], s.p[1], s.p[2], s.p[3], flatness_px, 0, ring);
          break;
      }
    }
    ring.pop_back();  // the contour is closed: its last point is its first
    add_chains(ring, chains);
  }
  if (chains.empty() || target.width <= 0 || target.height <= 0) return;

  double ymin = chains.front().ymin, ymax = chains.front().ymax;
  double xmin = 1e300, xmax = -1e300;
  for (const Chain& c : chains) {
    ymin = std::min(ymin, c.ymin);
    ymax = std::max(ymax, c.ymax);
    for (const Piece& p : c.pieces) {
      xmin = std::min({xmin, p.xa, p.xb});
      xmax = std::max({xmax, p.xa, p.xb});
    }
  }
  const int col_first = static_cast<int>(std::clamp(std::floor(xmin), 0.0, static_cast<double>(target.width)));
  const int col_last = static_cast<int>(std::clamp(std::floor(xmax), -1.0, static_cast<double>(target.width) - 1));
  if (col_last < col_first) return;
  RowAccumulator acc(col_first, col_last - col_first + 1);
  const int row_first = static_cast<int>(std::clamp(std::floor(ymin), 0.0, static_cast<double>(target.height)));
  const int row_last = static_cast<int>(std::clamp(std::floor(ymax), -1.0, static_cast<double>(target.height) - 1));

  struct Active {
    std::size_t chain;
    std::size_t first, end;  // pieces overlapping the row
    double xlo, xhi;         // their x extent
    std::size_t cursor;      // first piece not yet below the current sub-slab
    int sign;                // +1 left boundary, -1 right boundary, 0 inside or outside
    double x_mid;
  };
  std::vector<Active> active;
  std::vector<std::size_t> order;
  std::vector<double> cuts;
  for (int row = row_first; row <= row_last; ++row) {
    const double y0 = row, y1 = row + 1.0;
    active.clear();
    cuts.assign({y0, y1});
    for (std::size_t ci = 0; ci < chains.size(); ++ci) {
      const Chain& c = chains[ci];
      if (!(c.ymin < y1 && c.ymax > y0)) continue;
      const auto begin =
          std::partition_point(c.pieces.begin(), c.pieces.end(), [&](const Piece& p) { return p.yb <= y0; });
      const auto end = std::partition_point(begin, c.pieces.end(), [&](const Piece& p) { return p.ya < y1; });
      Active a{ci,
               static_cast<std::size_t>(begin - c.pieces.begin()),
               static_cast<std::size_t>(end - c.pieces.begin()),
               1e300,
               -1e300,
               0,
               0,
               0.0};
      for (auto it = begin; it != end; ++it) {
        a.xlo = std::min({a.xlo, it->xa, it->xb});
        a.xhi = std::max({a.xhi, it->xa, it->xb});
      }
      a.cursor = a.first;
      active.push_back(a);
      if (c.ymin > y0) cuts.push_back(c.ymin);
      if (c.ymax < y1) cuts.push_back(c.ymax);
    }
    if (active.empty()) continue;
    // Crossings between chains whose x extents in this row overlap.
    std::sort(active.begin(), active.end(), [](const Active& a, const Active& b) { return a.xlo < b.xlo; });
    for (std::size_t i = 0; i < active.size(); ++i)
      for (std::size_t k = i + 1; k < active.size() && active[k].xlo <= active[i].xhi; ++k)
        crossings(chains[active[i].chain], active[i].first, active[i].end, chains[active[k].chain], active[k].first,
                  active[k].end, y0, y1, cuts);
    std::sort(cuts.begin(), cuts.end());
    cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());

    acc.clear();
    for (std::size_t s = 0; s + 1 < cuts.size(); ++s) {
      const double ya = cuts[s], yb = cuts[s + 1];
      if (yb - ya < kThinSlabPx) continue;
      const double ym = 0.5 * (ya + yb);
      order.clear();
      for (std::size_t i = 0; i < active.size(); ++i) {
        Active& a = active[i];
        const Chain& c = chains[a.chain];
        a.sign = 0;
        while (a.cursor < a.end && c.pieces[a.cursor].yb <= ya) ++a.cursor;
        if (!(c.ymin < ym && c.ymax > ym)) continue;
        std::size_t k = a.cursor;
        while (k + 1 < a.end && c.pieces[k].yb < ym) ++k;
        a.x_mid = c.pieces[k].x_at(ym);
        order.push_back(i);
      }
      std::sort(order.begin(), order.end(),
                [&](std::size_t l, std::size_t r) { return active[l].x_mid < active[r].x_mid; });
      int winding = 0;
      for (const std::size_t i : order) {
        const int before = winding;
        winding += chains[active[i].chain].dir;
        if (before == 0 && winding != 0)
          active[i].sign = 1;
        else if (before != 0 && winding == 0)
          active[i].sign = -1;
      }
      for (const std::size_t i : order) {
        const Active& a = active[i];
        if (a.sign == 0) continue;
        const Chain& c = chains[a.chain];
        for (std::size_t k = a.cursor; k < a.end && c.pieces[k].ya < yb; ++k) {
          const Piece& p = c.pieces[k];
          const double lo = std::max(p.ya, ya), hi = std::min(p.yb, yb);
          if (hi > lo) acc.add(p.x_at(lo), lo, p.x_at(hi), hi, a.sign);
        }
      }
    }
    double running = 0.0;
    for (std::size_t k = 0; k < acc.cover.size(); ++k) {
      running += acc.carry[k];
      const double v = std::clamp(acc.cover[k] + running, 0.0, 1.0);
      target.at(col_first + static_cast<int>(k), row) += static_cast<float>(v);
    }
  }
}

Coverage union_coverage(const Outline& pixel_outline, int width, int height, double flatness_px) {
  Coverage c(width, height);
  add_union_coverage(pixel_outline, c, flatness_px);
  return c;
}

}  // namespace curvetext::test
