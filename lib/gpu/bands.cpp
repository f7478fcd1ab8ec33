// Per-glyph curve bands and the exact pixel-box area over them (bands.hpp).
#include "gpu/bands.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

namespace curvetext::gpu {

namespace {

// A point of the conic in homogeneous form (x w, y w, w).
struct Homogeneous {
  double x, y, w;
  Vec2 point() const { return {x / w, y / w}; }
};

Homogeneous at(const BandPiece& p, double t) {
  const double a = 1.0 - t;
  const double b0 = a * a, b1 = 2.0 * t * a * p.w, b2 = t * t;
  return {b0 * p.p0.x + b1 * p.c.x + b2 * p.p2.x, b0 * p.p0.y + b1 * p.c.y + b2 * p.p2.y, b0 + b1 + b2};
}

// The blossom at (t0, t1): the homogeneous control point of the arc between them.
Homogeneous blossom(const BandPiece& p, double t0, double t1) {
  const double k0 = (1.0 - t0) * (1.0 - t1), k1 = ((1.0 - t0) * t1 + t0 * (1.0 - t1)) * p.w, k2 = t0 * t1;
  return {k0 * p.p0.x + k1 * p.c.x + k2 * p.p2.x, k0 * p.p0.y + k1 * p.c.y + k2 * p.p2.y, k0 + k1 + k2};
}

// The arc between parameters t0 and t1 as a conic of its own (end weights 1).
BandPiece sub_arc(const BandPiece& p, double t0, double t1) {
  const Homogeneous q0 = at(p, t0), q1 = blossom(p, t0, t1), q2 = at(p, t1);
  return {q0.point(), q1.point(), q2.point(), q1.w / std::sqrt(q0.w * q2.w)};
}

// The roots in (0, 1) of b0 (1-t)^2 + 2 b1 t (1-t) + b2 t^2 (Bernstein
// coefficients), by the cancellation-free pair q / a and c / q.
int roots_in_unit(double b0, double b1, double b2, double out[2]) {
  const double a = b0 - 2.0 * b1 + b2, b = b1 - b0, c = b0;
  int n = 0;
  auto keep = [&](double t) {
    if (t > 0.0 && t < 1.0) out[n++] = t;
  };
  if (a == 0.0) {
    if (b != 0.0) keep(-c / (2.0 * b));
    return n;
  }
  const double d = b * b - a * c;
  if (d < 0.0) return 0;
  const double q = -(b + std::copysign(std::sqrt(d), b));
  keep(q / a);
  if (q != 0.0 && c / q != q / a) keep(c / q);
  return n;
}

// The parameter where one coordinate (a0, a1, a2 at p0, c, p2) of a conic
// monotone in it reaches `level`; 0 or 1, the nearer end, where it does not.
double monotone_crossing(double a0, double a1, double a2, double w, double level) {
  const double b0 = a0 - level, b1 = w * (a1 - level), b2 = a2 - level;
  const bool increasing = a2 > a0;
  if (b0 >= 0.0 && b2 >= 0.0) return increasing ? 0.0 : 1.0;
  if (b0 <= 0.0 && b2 <= 0.0) return increasing ? 1.0 : 0.0;
  const double a = b0 - 2.0 * b1 + b2, b = b1 - b0;
  if (a == 0.0) return std::clamp(-b0 / (2.0 * b), 0.0, 1.0);
  const double q = -(b + std::copysign(std::sqrt(std::max(b * b - a * b0, 0.0)), b));
  const double r1 = q / a, r2 = q != 0.0 ? b0 / q : r1;
  return std::clamp(r1 >= 0.0 && r1 <= 1.0 ? r1 : r2, 0.0, 1.0);
}

double y_at(const BandPiece& p, double t) {
  const Homogeneous h = at(p, t);
  return h.y / h.w;
}

}  // namespace

double conic_segment_ratio(double w) {
  const double e = 1.0 - w;
  // Near the parabola the closed forms below cancel; their series in 1 - w.
  if (std::abs(e) < 0.02)
    return 2.0 / 3.0 - e * (4.0 / 15.0 + e * (6.0 / 35.0 + e * (32.0 / 315.0 + e * 40.0 / 693.0)));
  if (w < 1.0) {
    // An ellipse's arc: an affine image of a circular arc of half-angle acos w.
    const double s = std::sqrt(e * (1.0 + w));
    return w * (std::acos(w) - w * s) / (s * s * s);
  }
  const double s = std::sqrt((w - 1.0) * (w + 1.0));  // a hyperbola's
  return w * (w * s - std::acosh(w)) / (s * s * s);
}

double arc_x_dy(const BandPiece& piece, double t0, double t1) {
  const BandPiece s = sub_arc(piece, t0, t1);
  const Vec2 a = s.p0, b = s.p2;
  return 0.5 * (a.x + b.x) * (b.y - a.y) + conic_segment_ratio(s.w) * 0.5 * cross(s.c - a, b - a);
}

double piece_box_integral(const BandPiece& p) {
  double ts[10] = {0.0, 1.0};
  int n = 2;
  for (double level : {-0.5, 0.5}) {
    n += roots_in_unit(p.p0.x - level, p.w * (p.c.x - level), p.p2.x - level, ts + n);
    n += roots_in_unit(p.p0.y - level, p.w * (p.c.y - level), p.p2.y - level, ts + n);
  }
  // Insertion sort: at most 10 values.
  for (int i = 1; i < n; ++i)
    for (int j = i; j > 0 && ts[j - 1] > ts[j]; --j) std::swap(ts[j - 1], ts[j]);
  double sum = 0.0;
  for (int i = 0; i + 1 < n; ++i) {
    const double t0 = ts[i], t1 = ts[i + 1];
    if (!(t1 > t0)) continue;
    const Vec2 mid = at(p, 0.5 * (t0 + t1)).point();
    if (mid.y < -0.5 || mid.y > 0.5 || mid.x < -0.5) continue;
    const double dy = y_at(p, t1) - y_at(p, t0);
    sum += mid.x > 0.5 ? dy : arc_x_dy(p, t0, t1) + 0.5 * dy;
  }
  return sum;
}

double monotone_piece_box_integral(const BandPiece& p) {
  if (std::min(p.p0.x, p.p2.x) >= 0.5) return std::clamp(p.p2.y, -0.5, 0.5) - std::clamp(p.p0.y, -0.5, 0.5);
  const double ty0 = monotone_crossing(p.p0.y, p.c.y, p.p2.y, p.w, -0.5);
  const double ty1 = monotone_crossing(p.p0.y, p.c.y, p.p2.y, p.w, 0.5);
  const double lo = std::min(ty0, ty1), hi = std::max(ty0, ty1);
  if (!(hi > lo)) return 0.0;
  const double tx0 = std::clamp(monotone_crossing(p.p0.x, p.c.x, p.p2.x, p.w, -0.5), lo, hi);
  const double tx1 = std::clamp(monotone_crossing(p.p0.x, p.c.x, p.p2.x, p.w, 0.5), lo, hi);
  // The part right of the box: after the crossing of x = 1/2 where x grows,
  // before it where x falls.
  const bool increasing = p.p2.x > p.p0.x;
  const double r0 = increasing ? tx1 : lo, r1 = increasing ? hi : tx1;
  double sum = y_at(p, r1) - y_at(p, r0);
  const double m0 = std::min(tx0, tx1), m1 = std::max(tx0, tx1);
  if (m1 > m0) sum += arc_x_dy(p, m0, m1) + 0.5 * (y_at(p, m1) - y_at(p, m0));
  return sum;
}

// At a turn the control point is snapped onto the tangent's axis, so that
// each piece is monotone exactly.
void split_monotone(const BandPiece& p, std::vector<BandPiece>& out) {
  // The parameters where x turns (kind 1) and where y turns (kind 2):
  // x'(t) W - x W'(t) = 2 (w (x1 - x0) (1-t)^2 + (x2 - x0) t (1-t) + w (x2 - x1) t^2).
  double roots[2];
  std::pair<double, int> cuts[6];
  int n = 0;
  for (int axis = 0; axis < 2; ++axis) {
    const auto v = [axis](Vec2 q) { return axis == 0 ? q.x : q.y; };
    const int r = roots_in_unit(p.w * (v(p.c) - v(p.p0)), 0.5 * (v(p.p2) - v(p.p0)), p.w * (v(p.p2) - v(p.c)), roots);
    for (int i = 0; i < r; ++i) cuts[n++] = {roots[i], axis + 1};
  }
  if (n == 0) {
    out.push_back(p);
    return;
  }
  std::sort(cuts, cuts + n);
  cuts[n++] = {1.0, 0};
  double t0 = 0.0;
  int kind0 = 0;
  for (int i = 0; i < n; ++i) {
    const auto [t1, kind1] = cuts[i];
    if (!(t1 > t0)) continue;
    BandPiece s = sub_arc(p, t0, t1);
    if (t0 > 0.0) s.p0 = out.back().p2;  // shared exactly with the previous piece
    if (t1 == 1.0) s.p2 = p.p2;
    // The tangent at a turn is along an axis: the control point lies on it.
    if (kind0 != 0) (kind0 == 1 ? s.c.x : s.c.y) = kind0 == 1 ? s.p0.x : s.p0.y;
    if (kind1 != 0) (kind1 == 1 ? s.c.x : s.c.y) = kind1 == 1 ? s.p2.x : s.p2.y;
    out.push_back(s);
    t0 = t1;
    kind0 = kind1;
  }
}

void boundary_pieces(const Mesh& mesh, std::vector<BandPiece>& out) {
  out.clear();
  for (const auto& line : mesh.boundary_lines) {
    const Vec2 a = mesh.points[line[0]], b = mesh.points[line[1]];
    if (a == b) continue;
    out.push_back({a, 0.5 * (a + b), b, 1.0});
  }
  for (const CurvedTriangle& ct : mesh.curves) {
    BandPiece p{mesh.points[ct.p0], mesh.points[ct.control], mesh.points[ct.p2], ct.weight};
    // The fill lies left of the direction: the control point is right of it
    // where the fill is on the chord's side, left of it where beyond the arc.
    const bool control_left = cross(p.p2 - p.p0, p.c - p.p0) > 0.0;
    if (control_left == ct.convex) std::swap(p.p0, p.p2);
    split_monotone(p, out);
  }
}

namespace {

float round_down(double v) {
  const float f = static_cast<float>(v);
  return static_cast<double>(f) > v ? std::nextafter(f, -std::numeric_limits<float>::infinity()) : f;
}
float round_up(double v) {
  const float f = static_cast<float>(v);
  return static_cast<double>(f) < v ? std::nextafter(f, std::numeric_limits<float>::infinity()) : f;
}

// An entry's texel: the piece's x range (outward to floats) and its end
// points' heights (first, last: a monotone piece's y range, and its height).
std::array<float, 4> entry_of(const BandPiece& p) {
  return {round_up(std::max({p.p0.x, p.c.x, p.p2.x})), round_down(std::min({p.p0.x, p.c.x, p.p2.x})),
          static_cast<float>(p.p0.y), static_cast<float>(p.p2.y)};
}

// A line is stored as the conic whose control point is its midpoint (w 1).
bool is_line(const BandPiece& p) { return p.w == 1.0 && p.c == 0.5 * (p.p0 + p.p2); }

// Levels so that the finest level's bands hold a few pieces each: a band
// of level L spans 2 / 2^L of the glyph's height.
int levels_for(std::size_t pieces) {
  int levels = 1;
  while (levels < kMaxBandLevels && (std::size_t{1} << (levels - 1)) < pieces) ++levels;
  return levels;
}

}  // namespace

namespace {

// The bands a piece reaches on the finest of `levels` levels (n = 2^(levels
// - 1) bands of height h = 1 / n), its heights [lo, hi] in units of the box's
// height from its bottom: band k holds [k h, (k + 2) h], so k from lo n - 2
// to hi n. On level L, k >> (levels - 1 - L) of these, since floor(x / 2^j)
// = floor(floor(x) / 2^j). The margin, 1.6e-3 finest bands (at least 1e-4
// of a band on every level), covers the shader's rounding of the row's band.
std::pair<int, int> finest_bands(double lo, double hi, int levels) {
  const double n = static_cast<double>(1 << (levels - 1));
  constexpr double kMargin = 1.6e-3;
  return {static_cast<int>(std::floor(lo * n - kMargin)), static_cast<int>(std::floor(hi * n + kMargin))};
}

// The entries of every band of every level (level L, band k: 2^L - 1 + k),
// a band's by decreasing largest x, and their pieces' texels in `refs`:
// counted per band, then placed, pieces taken in that order (linear in the
// entries after one sort of the pieces).
void add_entries(const std::vector<BandPiece>& pieces, std::size_t piece_texel, GlyphBands& out, BandScratch& scratch) {
  const std::size_t n = pieces.size(), bands = (std::size_t{1} << out.levels) - 1;
  std::vector<std::array<float, 4>>& entries = scratch.entries;
  entries.resize(n);
  for (std::size_t i = 0; i < n; ++i) entries[i] = entry_of(pieces[i]);
  std::vector<std::uint32_t>& order = scratch.order;
  order.resize(n);
  for (std::uint32_t i = 0; i < n; ++i) order[i] = i;
  std::sort(order.begin(), order.end(),
            [&](std::uint32_t a, std::uint32_t b) { return entries[a][0] > entries[b][0]; });
  const double y0 = out.box.min.y, height = out.box.max.y - out.box.min.y;
  std::vector<std::uint32_t>& next = scratch.next;  // per band: its next entry
  next.assign(bands + 1, 0);
  const auto each_band = [&](std::size_t i, auto&& visit) {
    const BandPiece& p = pieces[i];
    const auto [f0, f1] = finest_bands((std::min({p.p0.y, p.c.y, p.p2.y}) - y0) / height,
                                       (std::max({p.p0.y, p.c.y, p.p2.y}) - y0) / height, out.levels);
    for (int level = 0; level < out.levels; ++level) {
      const int shift = out.levels - 1 - level, last = (1 << level) - 1;
      const int k0 = std::clamp((f0 >> shift) - 1, 0, last), k1 = std::clamp(f1 >> shift, 0, last);
      for (int k = k0; k <= k1; ++k) visit(static_cast<std::size_t>(last + k));
    }
  };
  for (std::size_t i = 0; i < n; ++i) each_band(i, [&](std::size_t band) { ++next[band + 1]; });
  for (std::size_t b = 0; b < bands; ++b) {
    std::array<float, 4>& header = out.texels[1 + b / 2];
    header[2 * (b % 2)] = static_cast<float>(next[b]);
    header[2 * (b % 2) + 1] = static_cast<float>(next[b + 1]);
    next[b + 1] += next[b];
  }
  const std::size_t total = next[bands], entry_texel = out.texels.size();
  out.texels.resize(entry_texel + total);
  scratch.refs.resize(total);
  for (std::uint32_t i : order)
    each_band(i, [&](std::size_t band) {
      const std::uint32_t j = next[band]++;
      out.texels[entry_texel + j] = entries[i];
      scratch.refs[j] = static_cast<std::uint32_t>(piece_texel + 2 * i);
    });
}

// The side of the square the grids divide: the box's larger side (square
// cells, so that a narrow glyph's cells are as large as a wide one's).
double grid_side(const Box& box) { return std::max(box.max.x - box.min.x, box.max.y - box.min.y); }

// The texels of grid g's blocks, (2^g + 1)^2 of 2 bits; the first of grid g,
// from the first cell texel.
constexpr int grid_texels(int g) { return (((1 << g) + 1) * ((1 << g) + 1) + 31) / 32; }
constexpr int grid_offset(int g) { return g <= kGridMinLog2 ? 0 : grid_offset(g - 1) + grid_texels(g - 1); }

// A triangle's edges, with their inverse heights (0 for a level edge), for
// the x extent of the triangle within slabs lo <= y <= hi.
struct SlabTriangle {
  Vec2 a[3], d[3];
  double inv[3];
  explicit SlabTriangle(const Vec2 (&t)[3]) {
    for (int e = 0; e < 3; ++e) {
      a[e] = t[e];
      d[e] = t[(e + 1) % 3] - t[e];
      inv[e] = d[e].y != 0.0 ? 1.0 / d[e].y : 0.0;
    }
  }
  // Empty (first > second) where the slab misses the triangle.
  std::pair<double, double> extent(double lo, double hi) const {
    double x_lo = std::numeric_limits<double>::infinity(), x_hi = -x_lo;
    for (int e = 0; e < 3; ++e) {
      if (std::max(a[e].y, a[e].y + d[e].y) < lo || std::min(a[e].y, a[e].y + d[e].y) > hi) continue;
      double s0 = 0.0, s1 = 1.0;  // the edge's part within the slab
      if (inv[e] != 0.0) {
        const double u = (lo - a[e].y) * inv[e], v = (hi - a[e].y) * inv[e];
        s0 = std::max(0.0, std::min(u, v));
        s1 = std::min(1.0, std::max(u, v));
      }
      const double x0 = a[e].x + s0 * d[e].x, x1 = a[e].x + s1 * d[e].x;
      x_lo = std::min({x_lo, x0, x1});
      x_hi = std::max({x_hi, x0, x1});
    }
    return {x_lo, x_hi};
  }
};

// The finest grid (n x n cells of side `cell`): cells a piece reaches are
// marked 2; each other cell 1 or 0 by the winding number
// at its centre: the pieces crossing its row's centre line right of it,
// upward +1 and downward -1 (fill on the left; half-open in y, so an end
// shared by two pieces counts once). A crossing in a cell makes it a 2, so
// a row's crossings are counted per column and summed from the right.
void mark_cells(const std::vector<BandPiece>& pieces, const Box& box, int n, BandScratch& scratch) {
  std::vector<std::uint8_t>& cells = scratch.cells;
  std::vector<int>& delta = scratch.delta;  // per row, per column: the crossings' signs
  const auto size = static_cast<std::size_t>(n) * static_cast<std::size_t>(n);
  cells.assign(size, 0);
  delta.assign(size, 0);
  const double cell = grid_side(box) / n;
  const auto index = [n](double v) { return std::clamp(static_cast<int>(std::floor(v)), 0, n - 1); };
  for (const BandPiece& p : pieces) {
    // In cell units: the control triangle (the arc lies in it), y0 <= y1 the
    // piece's heights.
    const auto to_cells = [&](Vec2 v) { return Vec2{(v.x - box.min.x) / cell, (v.y - box.min.y) / cell}; };
    const Vec2 tri[3] = {to_cells(p.p0), to_cells(p.c), to_cells(p.p2)};
    const SlabTriangle slabs(tri);
    const double y0 = std::min(tri[0].y, tri[2].y), y1 = std::max(tri[0].y, tri[2].y);
    // Each row the piece reaches (with a margin of 1/64 cell, more than the
    // shader's rounding of a box's cells): the columns of the triangle's
    // part within the row.
    constexpr double kMargin = 1.0 / 64;
    for (int r = index(y0 - kMargin); r <= index(y1 + kMargin); ++r) {
      const auto [x_lo, x_hi] = slabs.extent(r - kMargin, r + 1 + kMargin);
      if (!(x_hi >= x_lo)) continue;
      const int c1 = index(x_hi + kMargin);
      for (int c = index(x_lo - kMargin); c <= c1; ++c) cells[static_cast<std::size_t>(r * n + c)] = 2;
    }
    // The row centres r + 1/2 in [y0, y1): the piece crosses each once, in
    // the column of the triangle's part there where that is one column.
    const int sign = p.p2.y > p.p0.y ? 1 : -1;
    for (int r = std::max(0, static_cast<int>(std::ceil(y0 - 0.5))); r < n && r + 0.5 < y1; ++r) {
      const auto [x_lo, x_hi] = slabs.extent(r + 0.5, r + 0.5);
      int c = index(x_lo);
      if (index(x_hi) != c) {
        const double t = monotone_crossing(p.p0.y, p.c.y, p.p2.y, p.w, box.min.y + (r + 0.5) * cell);
        c = index((at(p, t).point().x - box.min.x) / cell);
      }
      delta[static_cast<std::size_t>(r * n + c)] += sign;
    }
  }
  for (int r = 0; r < n; ++r) {
    int winding = 0;  // of the crossings right of column c
    for (int c = n - 1; c >= 0; --c) {
      const auto i = static_cast<std::size_t>(r * n + c);
      if (cells[i] != 2) cells[i] = winding != 0 ? 1 : 0;
      winding += delta[i];
    }
  }
}

// A grid's cells as bit rows: bit c of inside[r] (outside[r]) set where cell
// (c, r) is wholly inside (outside); neither where a piece reaches it.
struct CellRows {
  std::array<std::uint32_t, 1 << kGridMaxLog2> inside{}, outside{};
};

CellRows cell_rows(const std::vector<std::uint8_t>& cells, int n) {
  CellRows rows;
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c) {
      const std::uint8_t v = cells[static_cast<std::size_t>(r * n + c)];
      rows.inside[r] |= static_cast<std::uint32_t>(v == 1) << c;
      rows.outside[r] |= static_cast<std::uint32_t>(v == 0) << c;
    }
  return rows;
}

// Grid n / 2 from grid n: a cell is inside (outside) where its four are.
CellRows halve_rows(const CellRows& fine, int n) {
  CellRows coarse;
  const auto halve = [n](std::uint32_t lower, std::uint32_t upper) {
    const std::uint32_t both = lower & upper, pairs = both & (both >> 1);
    std::uint32_t out = 0;
    for (int c = 0; 2 * c < n; ++c) out |= ((pairs >> (2 * c)) & 1u) << c;
    return out;
  };
  for (int r = 0; 2 * r < n; ++r) {
    coarse.inside[r] = halve(fine.inside[2 * r], fine.inside[2 * r + 1]);
    coarse.outside[r] = halve(fine.outside[2 * r], fine.outside[2 * r + 1]);
  }
  return coarse;
}

// Grid g's blocks packed 2 bits each (layout: bands.hpp): block (c, r),
// c, r = 0 .. n, covers cells c - 1 .. c, r - 1 .. r, those beyond the grid
// outside. Its code is 1 where all four are inside, 0 where all are outside,
// else 2.
void pack_blocks(const CellRows& rows, int n, std::array<float, 4>* texels) {
  const std::uint32_t border = (std::uint32_t{1} << (n + 2)) - 1;  // padded columns 0 .. n + 1
  const auto padded_row = [&](const std::array<std::uint32_t, 1 << kGridMaxLog2>& bits, int r, bool outside) {
    if (r < 1 || r > n) return outside ? border : 0u;
    return (bits[r - 1] << 1) | (outside ? 1u | (1u << (n + 1)) : 0u);
  };
  unsigned word = 0;  // blocks i - i % 8 .. i, 2 bits each
  int i = 0;
  for (int r = 0; r <= n; ++r) {
    const std::uint32_t in = padded_row(rows.inside, r, false) & padded_row(rows.inside, r + 1, false);
    const std::uint32_t out = padded_row(rows.outside, r, true) & padded_row(rows.outside, r + 1, true);
    const std::uint32_t in_pairs = in & (in >> 1), out_pairs = out & (out >> 1);
    for (int c = 0; c <= n; ++c, ++i) {
      const unsigned code = 2u - ((in_pairs >> c) & 1u) - 2u * ((out_pairs >> c) & 1u);
      word |= code << (2 * (i % 8));
      if (i % 8 == 7) {
        texels[i / 32][(i / 8) % 4] = static_cast<float>(word);
        word = 0;
      }
    }
  }
  if (i % 8 != 0) texels[(i - 1) / 32][((i - 1) / 8) % 4] = static_cast<float>(word);
}

// The cell grids (layout: bands.hpp), appended to the texels: the finest
// marked, each coarser one from the one below it.
void add_grids(const std::vector<BandPiece>& pieces, GlyphBands& out, BandScratch& scratch) {
  if (!(out.box.max.x > out.box.min.x)) return;
  const std::size_t first = out.texels.size();
  out.texels.resize(first + static_cast<std::size_t>(grid_offset(kGridMaxLog2 + 1)), {0.0f, 0.0f, 0.0f, 0.0f});
  mark_cells(pieces, out.box, 1 << kGridMaxLog2, scratch);
  CellRows rows = cell_rows(scratch.cells, 1 << kGridMaxLog2);
  for (int g = kGridMaxLog2; g >= kGridMinLog2; --g) {
    if (g < kGridMaxLog2) rows = halve_rows(rows, 2 << g);
    pack_blocks(rows, 1 << g, out.texels.data() + first + grid_offset(g));
  }
  out.texels[0][2] = static_cast<float>(first);
}

}  // namespace

void build_bands(const Mesh& mesh, GlyphBands& out, BandScratch& scratch) {
  out.texels.clear();
  out.levels = 0;
  out.conics = false;
  out.pieces = out.entries = 0;
  std::vector<BandPiece>& pieces = scratch.pieces;
  boundary_pieces(mesh, pieces);
  Box box;
  for (const BandPiece& p : pieces)
    for (Vec2 v : {p.p0, p.c, p.p2}) box.add({static_cast<float>(v.x), static_cast<float>(v.y)});
  out.box = box;
  if (pieces.empty() || !(box.max.y > box.min.y)) return;
  out.levels = levels_for(pieces.size());
  out.pieces = pieces.size();
  const std::size_t bands = (std::size_t{1} << out.levels) - 1;
  const std::size_t piece_texel = 1 + (bands + 1) / 2;  // after texel 0 and the headers
  out.texels.assign(piece_texel + 2 * pieces.size(), {0.0f, 0.0f, 0.0f, 0.0f});
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    const BandPiece& p = pieces[i];
    const auto f = [](double v) { return static_cast<float>(v); };
    out.conics = out.conics || f(p.w) != 1.0f;
    out.texels[piece_texel + 2 * i] = {f(p.p0.x), f(p.p0.y), f(p.c.x), f(p.c.y)};
    out.texels[piece_texel + 2 * i + 1] = {f(p.p2.x), f(p.p2.y), f(p.w), is_line(p) ? 1.0f : 0.0f};
  }
  const std::size_t entry_texel = out.texels.size();
  add_entries(pieces, piece_texel, out, scratch);
  const std::vector<std::uint32_t>& refs = scratch.refs;
  out.entries = refs.size();
  const std::size_t ref_texel = out.texels.size();
  for (std::size_t j = 0; j < refs.size(); j += 4) {
    std::array<float, 4> t{0.0f, 0.0f, 0.0f, 0.0f};
    for (std::size_t q = 0; q < 4 && j + q < refs.size(); ++q) t[q] = static_cast<float>(refs[j + q]);
    out.texels.push_back(t);
  }
  out.texels[0] = {static_cast<float>(entry_texel), static_cast<float>(ref_texel), 0.0f, 0.0f};
  add_grids(pieces, out, scratch);
}

double box_coverage(std::span<const BandPiece> pieces, Vec2 centre, Vec2 half) {
  const double kx = 0.5 / half.x, ky = 0.5 / half.y;
  double sum = 0.0;
  for (const BandPiece& p : pieces) {
    const auto px = [&](Vec2 v) { return Vec2{(v.x - centre.x) * kx, (v.y - centre.y) * ky}; };
    sum += piece_box_integral({px(p.p0), px(p.c), px(p.p2), p.w});
  }
  return sum;
}

int band_level(const GlyphBands& bands, double half_y) {
  const double height = bands.box.max.y - bands.box.min.y;
  const double ratio = height / (2.0 * half_y * 1.0001);
  const int level = ratio >= 1.0 ? static_cast<int>(std::floor(std::log2(ratio))) : 0;
  return std::clamp(level, 0, bands.levels - 1);
}

int block_state(const GlyphBands& bands, int g, int column, int row) {
  const int n = 1 << g;
  if (column < 0 || row < 0 || column > n || row > n) return 0;
  const int i = row * (n + 1) + column;
  const auto first = static_cast<std::size_t>(bands.texels[0][2]) + static_cast<std::size_t>(grid_offset(g));
  const auto bits = static_cast<unsigned>(bands.texels[first + static_cast<std::size_t>(i / 32)][(i / 8) % 4]);
  return static_cast<int>((bits >> (2 * (i % 8))) & 3u);
}

int grid_state(const GlyphBands& bands, Vec2 centre, Vec2 half) {
  if (bands.empty() || bands.texels[0][2] == 0.0f) return 2;
  const Box& b = bands.box;
  const double w = grid_side(b), h = w;
  // The finest grid whose cells are at least the box (both ways).
  const double ratio = w / (2.0 * std::max(half.x, half.y)) / 1.0001;
  if (!(ratio >= (1 << kGridMinLog2))) return 2;
  const int g = std::min(static_cast<int>(std::floor(std::log2(ratio))), kGridMaxLog2);
  const double n = 1 << g;
  const auto cell = [&](double v, double lo, double size) { return static_cast<int>(std::floor((v - lo) * n / size)); };
  const int c0 = cell(centre.x - half.x, b.min.x, w), c1 = cell(centre.x + half.x, b.min.x, w);
  const int r0 = cell(centre.y - half.y, b.min.y, h), r1 = cell(centre.y + half.y, b.min.y, h);
  if (c1 - c0 > 1 || r1 - r0 > 1) return 2;
  return block_state(bands, g, c0 + 1, r0 + 1);  // the cells c0 .. c0 + 1, r0 .. r0 + 1
}

namespace {

// The band of the rows [centre.y - half.y, centre.y + half.y] walked as the
// shader walks it: the early stop at the first entry wholly left of the box,
// entries outside its rows skipped. `right(y0, y1)` takes an entry wholly
// right of the box (its end heights in box units, the box being
// [-1/2, 1/2]^2), `across(piece)` the others' pieces in box units; their sum.
template <class Right, class Across>
double walk_band(const GlyphBands& bands, Vec2 centre, Vec2 half, Right&& right, Across&& across) {
  const int n = 1 << band_level(bands, half.y);
  const double h = (bands.box.max.y - bands.box.min.y) / n;
  const double row_lo = centre.y - half.y, row_hi = centre.y + half.y;
  const int band = n - 1 + std::clamp(static_cast<int>(std::floor((row_lo - bands.box.min.y) / h)), 0, n - 1);
  const auto texel = [&](std::size_t i) -> const std::array<float, 4>& { return bands.texels[i]; };
  const auto entry_texel = static_cast<std::size_t>(texel(0)[0]), ref_texel = static_cast<std::size_t>(texel(0)[1]);
  const std::array<float, 4>& header = texel(1 + static_cast<std::size_t>(band / 2));
  const auto first = static_cast<std::size_t>(header[2 * (band % 2)]);
  const auto count = static_cast<std::size_t>(header[2 * (band % 2) + 1]);
  const double kx = 0.5 / half.x, ky = 0.5 / half.y;
  const auto px = [&](double x, double y) { return Vec2{(x - centre.x) * kx, (y - centre.y) * ky}; };
  double sum = 0.0;
  for (std::size_t j = first; j < first + count; ++j) {
    const std::array<float, 4>& e = texel(entry_texel + j);  // (largest x, smallest x, y first, y last)
    if (e[0] < centre.x - half.x) break;
    if (std::max(e[2], e[3]) < row_lo || std::min(e[2], e[3]) > row_hi) continue;
    if (e[1] >= centre.x + half.x) {
      sum += right((e[2] - centre.y) * ky, (e[3] - centre.y) * ky);
      continue;
    }
    const auto piece = static_cast<std::size_t>(texel(ref_texel + j / 4)[j % 4]);
    const std::array<float, 4>&a = texel(piece), &b = texel(piece + 1);
    sum += across(BandPiece{px(a[0], a[1]), px(a[2], a[3]), px(b[0], b[1]), b[2]});
  }
  return sum;
}

}  // namespace

double band_box_coverage(const GlyphBands& bands, Vec2 centre, Vec2 half) {
  if (bands.empty()) return 0.0;
  if (const int state = grid_state(bands, centre, half); state != 2) return state;
  // A piece wholly right adds its height within the rows.
  const auto right = [](double y0, double y1) { return std::clamp(y1, -0.5, 0.5) - std::clamp(y0, -0.5, 0.5); };
  return walk_band(bands, centre, half, right, [](const BandPiece& p) { return monotone_piece_box_integral(p); });
}

namespace {

// The parallelogram's corners, counter-clockwise.
std::array<Vec2, 4> corners(const Footprint& f) {
  const Vec2 u = cross(f.u, f.v) >= 0.0 ? f.u : f.v, v = cross(f.u, f.v) >= 0.0 ? f.v : f.u;
  return {-0.5 * (u + v), 0.5 * (u - v), 0.5 * (u + v), 0.5 * (v - u)};
}

// The edge from a to b (not level) as the line x = e(y): e at a height
// within its rows, from the parameter along it (no division by the slope).
double edge_x(Vec2 a, Vec2 d, double y) { return a.x + d.x * std::clamp((y - a.y) / d.y, 0.0, 1.0); }

// The integral of x - e(y) dy along the arc between t0 and t1 (within the
// edge's rows).
double beyond_edge(const BandPiece& p, double t0, double t1, Vec2 a, Vec2 d) {
  const double y0 = y_at(p, t0), y1 = y_at(p, t1);
  return arc_x_dy(p, t0, t1) - (y1 - y0) * edge_x(a, d, 0.5 * (y0 + y1));
}

// Positive right of the line through a along d (d.y != 0), as x - e(y) is
// (scaled by |d.y|).
double right_of(Vec2 q, Vec2 a, Vec2 d) { return (d.y * (q.x - a.x) - d.x * (q.y - a.y)) * (d.y > 0.0 ? 1.0 : -1.0); }

// Edge a -> b of the parallelogram (counter-clockwise): the integral of
// max(0, x - e(y)) dy over the piece's part within the edge's rows and
// within parameters [m0, m1], plus on
// the left chain (a above b), minus on the right. The piece is monotone in y:
// the rows are one parameter interval; its line crossings, two at most, cut
// it into parts alternately right and left of the line.
double edge_term(const BandPiece& p, Vec2 a, Vec2 b, double m0, double m1) {
  const Vec2 d = b - a;
  if (d.y == 0.0) return 0.0;
  const double s0 = monotone_crossing(p.p0.y, p.c.y, p.p2.y, p.w, std::min(a.y, b.y));
  const double s1 = monotone_crossing(p.p0.y, p.c.y, p.p2.y, p.w, std::max(a.y, b.y));
  const double ta = std::max(std::min(s0, s1), m0), tb = std::min(std::max(s0, s1), m1);
  if (!(tb > ta)) return 0.0;
  double roots[2];
  const int n = roots_in_unit(right_of(p.p0, a, d), p.w * right_of(p.c, a, d), right_of(p.p2, a, d), roots);
  double r0 = n > 0 ? roots[0] : 2.0, r1 = n > 1 ? roots[1] : r0;
  if (r0 > r1) std::swap(r0, r1);
  if (n == 1) r1 = 2.0;
  r0 = std::clamp(r0, ta, tb);
  r1 = std::clamp(r1, ta, tb);
  // The middle part [r0, r1] lies on one side, the outer parts on the
  // other; the side is read at the middle of the longest part (a short
  // part's may lie on the line within rounding).
  const double outer = std::max(r0 - ta, tb - r1);
  const double probe = r1 - r0 >= outer ? 0.5 * (r0 + r1) : r0 - ta >= tb - r1 ? 0.5 * (ta + r0) : 0.5 * (r1 + tb);
  const bool middle_right = (right_of(at(p, probe).point(), a, d) > 0.0) == (r1 - r0 >= outer);
  const double mid = r1 > r0 ? beyond_edge(p, r0, r1, a, d) : 0.0;
  const double sum = middle_right ? mid : beyond_edge(p, ta, tb, a, d) - mid;
  return a.y > b.y ? sum : -sum;
}

}  // namespace

double monotone_piece_footprint_integral(const BandPiece& p, const Footprint& f) {
  // The part right of the bounding box adds the width over its rows, the
  // part left of it nothing; the edges' terms run over the part between
  // (bounded terms: no cancelling of large ones in the shader's floats).
  const std::array<Vec2, 4> v = corners(f);
  const double hx = f.half().x;
  const double tx0 = monotone_crossing(p.p0.x, p.c.x, p.p2.x, p.w, -hx);
  const double tx1 = monotone_crossing(p.p0.x, p.c.x, p.p2.x, p.w, hx);
  const bool increasing = p.p2.x > p.p0.x;
  double sum = footprint_width_integral(f, y_at(p, increasing ? tx1 : 0.0), y_at(p, increasing ? 1.0 : tx1));
  const double m0 = std::min(tx0, tx1), m1 = std::max(tx0, tx1);
  for (int e = 0; e < 4; ++e) sum += edge_term(p, v[e], v[(e + 1) % 4], m0, m1);
  return sum;
}

double footprint_width_integral(const Footprint& f, double y0, double y1) {
  // The x of the two chains cancel: minus the integral of e(y) dy on the
  // left chain, plus on the right, over each edge's rows.
  const std::array<Vec2, 4> v = corners(f);
  double sum = 0.0;
  for (int e = 0; e < 4; ++e) {
    const Vec2 a = v[e], d = v[(e + 1) % 4] - a;
    if (d.y == 0.0) continue;
    const double lo = std::min(a.y, a.y + d.y), hi = std::max(a.y, a.y + d.y);
    const double c0 = std::clamp(y0, lo, hi), c1 = std::clamp(y1, lo, hi);
    sum += (d.y > 0.0 ? 1.0 : -1.0) * (c1 - c0) * edge_x(a, d, 0.5 * (c0 + c1));
  }
  return sum;
}

double piece_footprint_integral(const BandPiece& p, const Footprint& f) {
  const std::array<Vec2, 4> v = corners(f);
  double ts[18] = {0.0, 1.0};
  int n = 2;
  for (int e = 0; e < 4; ++e) {
    n += roots_in_unit(p.p0.y - v[e].y, p.w * (p.c.y - v[e].y), p.p2.y - v[e].y, ts + n);
    const Vec2 a = v[e], d = v[(e + 1) % 4] - a;
    const auto side = [&](Vec2 q) { return cross(d, q - a); };
    n += roots_in_unit(side(p.p0), p.w * side(p.c), side(p.p2), ts + n);
  }
  std::sort(ts, ts + n);
  const double y_lo = std::min({v[0].y, v[1].y, v[2].y, v[3].y}), y_hi = std::max({v[0].y, v[1].y, v[2].y, v[3].y});
  double sum = 0.0;
  for (int i = 0; i + 1 < n; ++i) {
    const double t0 = ts[i], t1 = ts[i + 1];
    if (!(t1 > t0)) continue;
    const Vec2 m = at(p, 0.5 * (t0 + t1)).point();
    if (!(m.y > y_lo && m.y < y_hi)) continue;
    // The row at the midpoint's height: the edges of the left chain (going
    // down) and of the right (going up) that span it; the part stays within
    // their rows, where each is one line.
    Vec2 la{0.0, 0.0}, ld{0.0, 1.0}, ra{0.0, 0.0}, rd{0.0, 1.0};
    for (int e = 0; e < 4; ++e) {
      const Vec2 a = v[e], d = v[(e + 1) % 4] - a;
      if (d.y == 0.0 || m.y < std::min(a.y, a.y + d.y) || m.y > std::max(a.y, a.y + d.y)) continue;
      (d.y < 0.0 ? la : ra) = a;
      (d.y < 0.0 ? ld : rd) = d;
    }
    const auto line_x = [](Vec2 a, Vec2 d, double y) { return a.x + (y - a.y) * d.x / d.y; };
    const double xl = line_x(la, ld, m.y), xr = line_x(ra, rd, m.y);
    if (m.x <= xl) continue;
    const double y0 = y_at(p, t0), y1 = y_at(p, t1), ym = 0.5 * (y0 + y1);
    sum += m.x >= xr ? (y1 - y0) * (line_x(ra, rd, ym) - line_x(la, ld, ym))
                     : arc_x_dy(p, t0, t1) - (y1 - y0) * line_x(la, ld, ym);
  }
  return sum;
}

double footprint_coverage(std::span<const BandPiece> pieces, Vec2 centre, const Footprint& f) {
  double sum = 0.0;
  for (const BandPiece& p : pieces)
    sum += piece_footprint_integral({p.p0 - centre, p.c - centre, p.p2 - centre, p.w}, f);
  return sum / f.area();
}

double band_footprint_coverage(const GlyphBands& bands, Vec2 centre, const Footprint& f) {
  if (bands.empty()) return 0.0;
  const Vec2 half = f.half();
  if (const int state = grid_state(bands, centre, half); state != 2) return state;
  // In the units where the bounding box is [-1/2, 1/2]^2 (the shader's).
  const double kx = 0.5 / half.x, ky = 0.5 / half.y;
  const Footprint g{{f.u.x * kx, f.u.y * ky}, {f.v.x * kx, f.v.y * ky}};
  const double sum = walk_band(
      bands, centre, half, [&](double y0, double y1) { return footprint_width_integral(g, y0, y1); },
      [&](const BandPiece& p) { return monotone_piece_footprint_integral(p, g); });
  return sum / g.area();
}

}  // namespace curvetext::gpu
