// Side windings of the arrangement (arrangement.hpp): one ray per connected
// part, the windings passed on along chains and around nodes.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "core/assert.hpp"
#include "tessellate/arrangement.hpp"
#include "tessellate/columns.hpp"
#include "tessellate/positions.hpp"

namespace curvetext::detail {
namespace {

using Edge = ArrangementEdge;

// Winding numbers just left and right of each edge. A ray from the edge's
// midpoint m along +x (or +y for edges closer to horizontal, done by rotating
// every point by -90 degrees, which is exact) crosses the other edges; the
// half-open rule with exact orient2d counts each crossing once. Other edges
// do not pass within the edge's interior (the arrangement does not cross),
// so the rounded m is on the same side of all of them as the true midpoint;
// conic caps are not entered by the ray's start (hulls are separated), and a
// ray through a cap crosses chord and arc with the same net count.
//
// One ray per chain: where exactly two edges meet at a vertex, the faces on
// either side of one continue on the same sides of the other (the plane
// around the vertex is cut in two), so their windings are equal, sides
// swapped when the two edges point both into or both out of the vertex.
// Most vertices are such joints; only crossings and touches end a chain, and
// there the windings pass from chain to chain too (below), so one ray is cast
// per connected part of the arrangement instead of one per edge.
// The bins of side_windings's rays: only edges whose span in the ray's
// perpendicular coordinate contains the midpoint's can be crossed: the rays
// test every edge when they are few, and otherwise look at one bin of edges
// (of y for horizontal rays, of x for vertical ones, by their closed spans;
// about n / 2 bins, one array each, counted then filled).
struct Bins {
  double lo = 0.0, scale = 0.0;
  std::size_t count = 1;
  std::vector<std::uint32_t> start;  // bin k's edges: members[start[k] .. start[k + 1])
  std::vector<std::uint32_t> members;
  std::size_t bin(double v) const {
    const double k = (v - lo) * scale;
    if (!(k > 0.0)) return 0;
    return std::min(count - 1, static_cast<std::size_t>(k));
  }
};

class SideWindings {
 public:
  SideWindings(const std::vector<Edge>& edges, std::vector<int>& left, std::vector<int>& right, ResolveScratch& scratch)
      : edges_(edges), left_(left), right_(right), s_(scratch), n_(edges.size()) {}

  void run();

 private:
  // End k is edge k / 2's start (k even) or end (k odd).
  Vec2 end_point(std::size_t k) const { return (k & 1) != 0 ? edges_[k / 2].b : edges_[k / 2].a; }
  void find_joins();
  void fill_heights();
  Bins make_bins(bool use_x) const;
  void cast(std::size_t i);
  void find_nodes();
  void walk_chain(std::size_t first);
  void spread_at(std::uint32_t m);

  const std::vector<Edge>& edges_;
  std::vector<int>& left_;
  std::vector<int>& right_;
  ResolveScratch& s_;
  const std::size_t n_;
  Box all_;
  std::size_t bin_count_ = 1;
  std::optional<Bins> by_y_, by_x_;
  std::size_t rays_ = 0;
  // The ends' heights in either frame, one array each: y, and for rotated
  // rays -x (the rotated frame's y, exact).
  double *a_y_ = nullptr, *b_y_ = nullptr, *a_rotated_ = nullptr, *b_rotated_ = nullptr;
};

void SideWindings::run() {
  left_.assign(n_, 0);
  right_.assign(n_, 0);
  if (n_ == 0) return;
  find_joins();
  for (const Edge& e : edges_) {
    all_.add(e.a);
    all_.add(e.b);
  }
  bin_count_ = std::clamp<std::size_t>(n_ / 2, 1, 4096);
  fill_heights();
  find_nodes();
  s_.done.assign(n_, 0);
  s_.pending.clear();
  for (std::size_t first = 0; first < n_; ++first) {
    if (s_.done[first]) continue;
    cast(first);
    s_.done[first] = 1;
    walk_chain(first);
    while (!s_.pending.empty()) {
      const std::uint32_t e = s_.pending.back();
      s_.pending.pop_back();
      for (std::uint32_t k = 2 * e; k < 2 * e + 2; ++k) {
        const std::uint32_t m = s_.node_of[s_.first_of[k]];
        if (m != UINT32_MAX && !s_.node_done[m]) spread_at(m);
      }
    }
  }
  // Every edge got its windings, by a ray or passed on.
  CURVETEXT_ASSERT(std::all_of(s_.done.begin(), s_.done.end(), [](char d) { return d != 0; }));
}

// The chains: a position held by exactly two ends of two different edges
// joins them. A hash table of positions holds each position's first end,
// with how many ends it has and its second.
void SideWindings::find_joins() {
  const std::size_t n = n_;
  std::vector<ResolveScratch::Join>& joins = s_.joins;
  joins.assign(2 * n, ResolveScratch::Join{});
  // Each end's position's first end; per first end, how many ends are there.
  std::vector<std::uint32_t>& first_of = s_.first_of;
  std::vector<std::uint32_t>& ends_at = s_.ends_at;
  first_of.resize(2 * n);
  std::vector<std::uint32_t>& second_end = s_.second_end;  // per first end
  FirstAtPosition ends(s_.slots, 2 * n, [this](std::size_t k) { return end_point(k); });
  ends_at.assign(2 * n, 0);
  second_end.resize(2 * n);
  for (std::uint32_t k = 0; k < 2 * n; ++k) {
    const std::uint32_t first = ends.add(k);
    first_of[k] = first;
    if (++ends_at[first] == 2) second_end[first] = k;
  }
  for (std::size_t k = 0; k < 2 * n; ++k) {
    if (ends_at[k] != 2) continue;
    const std::size_t u = k, v = second_end[k];
    const std::uint32_t eu = static_cast<std::uint32_t>(u / 2), ev = static_cast<std::uint32_t>(v / 2);
    if (eu == ev) continue;
    const bool u_at_b = (u & 1) != 0, v_at_b = (v & 1) != 0;
    const bool swapped = u_at_b == v_at_b;
    joins[u] = {ev, swapped};
    joins[v] = {eu, swapped};
  }
}

void SideWindings::fill_heights() {
  const auto height_columns = columns<4>(s_.heights, n_);
  a_y_ = height_columns[0], b_y_ = height_columns[1], a_rotated_ = height_columns[2], b_rotated_ = height_columns[3];
  for (std::size_t j = 0; j < n_; ++j) {
    a_y_[j] = edges_[j].a.y;
    b_y_[j] = edges_[j].b.y;
    a_rotated_[j] = -edges_[j].a.x;
    b_rotated_[j] = -edges_[j].b.x;
  }
  s_.straddling.resize(n_);
}

Bins SideWindings::make_bins(bool use_x) const {
  const std::vector<Edge>& edges = edges_;
  const std::size_t count = bin_count_;
  Bins b;
  b.count = count;
  b.lo = use_x ? all_.min.x : all_.min.y;
  const double hi = use_x ? all_.max.x : all_.max.y;
  b.scale = hi > b.lo ? static_cast<double>(count) / (hi - b.lo) : 0.0;
  auto span = [&](std::uint32_t j) {
    const double v0 = use_x ? std::min(edges[j].a.x, edges[j].b.x) : std::min(edges[j].a.y, edges[j].b.y);
    const double v1 = use_x ? std::max(edges[j].a.x, edges[j].b.x) : std::max(edges[j].a.y, edges[j].b.y);
    return std::pair{b.bin(v0), b.bin(v1)};
  };
  b.start.assign(count + 1, 0);
  for (std::uint32_t j = 0; j < n_; ++j) {
    const auto [first, last] = span(j);
    for (std::size_t k = first; k <= last; ++k) ++b.start[k + 1];
  }
  for (std::size_t k = 0; k < count; ++k) b.start[k + 1] += b.start[k];
  b.members.resize(b.start[count]);
  std::vector<std::uint32_t> fill(b.start.begin(), b.start.end() - 1);
  for (std::uint32_t j = 0; j < n_; ++j) {
    const auto [first, last] = span(j);
    for (std::size_t k = first; k <= last; ++k) b.members[fill[k]++] = j;
  }
  return b;
}

// Left and right winding of edge i by its own ray.
void SideWindings::cast(std::size_t i) {
  const Edge& e = edges_[i];
  const bool rotate = std::fabs(e.b.x - e.a.x) > std::fabs(e.b.y - e.a.y);
  auto tf = [rotate](Vec2 p) { return rotate ? Vec2{p.y, -p.x} : p; };
  const Vec2 mid = (e.a + e.b) * 0.5;
  const Vec2 m = tf(mid);
  int w = 0;
  // Only an edge whose span straddles the ray's line can be crossed: those
  // are gathered first, without a branch per edge (most do not straddle, in
  // no order a predictor could learn).
  const double* const a_height = rotate ? a_rotated_ : a_y_;
  const double* const b_height = rotate ? b_rotated_ : b_y_;
  std::uint32_t* const straddling = s_.straddling.data();
  std::size_t found = 0;
  auto gather = [&](std::uint32_t j) {
    straddling[found] = j;
    found += static_cast<std::size_t>(((a_height[j] <= m.y) != (b_height[j] <= m.y)) & (j != i));
  };
  auto test = [&](std::uint32_t j) {
    const Edge& f = edges_[j];
    const Vec2 a = tf(f.a), b = tf(f.b);
    // For an edge sharing an end point with e, every point of e's open
    // interior is on the side of f's line where e's other end is; asking that
    // end instead of the rounded midpoint is exact even for a tiny e.
    Vec2 probe = m;
    if (f.a == e.a || f.b == e.a) probe = tf(e.b);
    if (f.a == e.b || f.b == e.b) probe = tf(e.a);
    if (a.y <= m.y) {
      if (b.y > m.y && orient2d(a, b, probe) > 0) w += f.count;
    } else if (b.y <= m.y && orient2d(a, b, probe) < 0) {
      w -= f.count;
    }
  };
  // The first 16 rays (or all of them, for fewer than 64 edges) test every
  // edge, about what making the bins costs; later ones use the bins.
  if (++rays_ <= 16 || n_ < 64) {
    for (std::uint32_t j = 0; j < n_; ++j) gather(j);
  } else {
    std::optional<Bins>& slot = rotate ? by_x_ : by_y_;
    if (!slot) slot = make_bins(rotate);
    const std::size_t k = slot->bin(rotate ? mid.x : mid.y);
    for (std::uint32_t c = slot->start[k]; c < slot->start[k + 1]; ++c) gather(slot->members[c]);
  }
  for (std::size_t c = 0; c < found; ++c) test(straddling[c]);
  const bool upward = tf(e.b).y > tf(e.a).y;
  left_[i] = upward ? w + e.count : w;
  right_[i] = upward ? w : w - e.count;
}

// The nodes: positions where other than two ends meet (crossings, touches,
// merged edges), which end chains. Around a node the faces between
// consecutive edges (in angular order) differ by the count of the edge
// between them, so one edge's windings there give all the others': the
// windings spread from chain to chain through the nodes, and a ray is cast
// only for a chain none of that reaches (one per connected part of the
// arrangement). Node m's ends are node_ends[node_start[m] .. node_start[m +
// 1]), sorted by angle when the node is first used.
void SideWindings::find_nodes() {
  std::vector<std::uint32_t>& node_of = s_.node_of;
  std::vector<std::uint32_t>& node_start = s_.node_start;
  node_of.assign(2 * n_, UINT32_MAX);  // per first end: its node
  node_start.assign(1, 0);
  for (std::size_t k = 0; k < 2 * n_; ++k) {
    if (s_.first_of[k] != k || s_.ends_at[k] == 2) continue;
    node_of[k] = static_cast<std::uint32_t>(node_start.size() - 1);
    node_start.push_back(node_start.back() + s_.ends_at[k]);
  }
  const std::size_t nodes = node_start.size() - 1;
  s_.node_ends.resize(node_start.back());
  std::vector<std::uint32_t>& fill = s_.fill;
  fill.assign(node_start.begin(), node_start.end() - 1);
  for (std::size_t k = 0; k < 2 * n_; ++k) {
    const std::uint32_t m = node_of[s_.first_of[k]];
    if (m != UINT32_MAX) s_.node_ends[fill[m]++] = static_cast<std::uint32_t>(k);
  }
  s_.node_done.assign(nodes, 0);
}

// Along the chain of `first` (windings set) both ways; the edges reached
// wait in `pending` (windings set, ends not yet looked at).
void SideWindings::walk_chain(std::size_t first) {
  s_.pending.push_back(static_cast<std::uint32_t>(first));
  for (int way = 0; way < 2; ++way) {
    std::size_t from = first;
    bool at_b = way == 0;  // leave `from` through this end
    for (;;) {
      const ResolveScratch::Join join = s_.joins[2 * from + at_b];
      if (join.other == UINT32_MAX || s_.done[join.other]) break;
      const std::size_t to = join.other;
      left_[to] = join.swapped ? right_[from] : left_[from];
      right_[to] = join.swapped ? left_[from] : right_[from];
      s_.done[to] = 1;
      s_.pending.push_back(static_cast<std::uint32_t>(to));
      // `to` was entered through its end at the join: at b when the sides
      // were not swapped and we left `from` through b, and so on; leave it
      // through the other end.
      const bool entered_at_b = join.swapped ? at_b : !at_b;
      at_b = !entered_at_b;
      from = to;
    }
  }
}

// Node m, where some edge's windings are known: every other edge there.
void SideWindings::spread_at(std::uint32_t m) {
  s_.node_done[m] = 1;
  std::uint32_t* const first_end = s_.node_ends.data() + s_.node_start[m];
  std::uint32_t* const last_end = s_.node_ends.data() + s_.node_start[m + 1];
  const Vec2 v = end_point(*first_end);
  // Counter-clockwise by the direction to each edge's other end (a conic's
  // chord: hulls are separated, so chords and arcs leave v in one order).
  auto other_end = [&](std::uint32_t k) { return end_point(k ^ 1u); };
  std::sort(first_end, last_end,
            [&](std::uint32_t x, std::uint32_t y) { return arrangement_angle_less(v, other_end(x), other_end(y)); });
  const std::size_t degree = static_cast<std::size_t>(last_end - first_end);
  std::size_t known = degree;
  for (std::size_t j = 0; j < degree; ++j)
    if (s_.done[first_end[j] / 2]) {
      known = j;
      break;
    }
  if (known == degree) return;
  // sector = the winding just counter-clockwise of the current end. An edge
  // leaving v has its left side counter-clockwise of it, one arriving its
  // right side.
  auto leaves = [](std::uint32_t k) { return (k & 1) == 0; };
  std::uint32_t k = first_end[known];
  int sector = leaves(k) ? left_[k / 2] : right_[k / 2];
  for (std::size_t step = 1; step < degree; ++step) {
    k = first_end[(known + step) % degree];
    const std::size_t e = k / 2;
    const int before = sector;
    sector += leaves(k) ? edges_[e].count : -edges_[e].count;
    if (s_.done[e]) continue;
    left_[e] = leaves(k) ? sector : before;
    right_[e] = leaves(k) ? before : sector;
    s_.done[e] = 1;
    walk_chain(e);
  }
}

}  // namespace

void side_windings(const std::vector<Edge>& edges, std::vector<int>& left, std::vector<int>& right,
                   ResolveScratch& scratch) {
  SideWindings(edges, left, right, scratch).run();
}

}  // namespace curvetext::detail
