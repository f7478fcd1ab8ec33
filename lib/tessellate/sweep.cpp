// Plane-sweep triangulation of non-crossing polygon loops (the fast path of
// build_mesh; see triangulate.hpp for the contract).
//
// One sweep over all loops of a glyph at once, in (y, x) order, with the
// status kept as the intervals of the fill between a left and a right
// boundary edge. Each interval carries the monotone polygon being built in it
// (or two, left and right of a pending merge vertex) as the classic reflex
// chain stack, so the polygon is triangulated while it is swept: no diagonals
// are stored, no monotone pieces are extracted, holes need no bridges and
// nesting needs no point-in-polygon tests. Vertex types (start, split, end,
// merge, regular) follow de Berg et al., "Computational Geometry", ch. 3, with
// the filled side on the left of every loop edge.
//
// Every decision is an exact orient2d sign. A zero where the algorithm needs a
// strict answer (a vertex on another loop's edge, a spike, a flat corner at a
// start or end) makes it give up and return false; so do a repeated position
// and a fan triangle that is not strictly counter-clockwise (the triangles
// popped off a chain are strictly so by the test that pops them), a start
// vertex inside the fill or a split vertex outside it (loops whose
// orientation does not fit their nesting), and a triangle count other than
// the polygon's (vertices - 2 per loop around fill, + 2 per hole). On any
// failure build_mesh nests and orients the rings itself and then takes this
// sweep again or the general path (bridges and ear clipping).
#include <algorithm>
#include <cstdint>
#include <vector>

#include "core/assert.hpp"
#include "tessellate/positions.hpp"
#include "tessellate/predicates.hpp"
#include "tessellate/triangulate.hpp"

namespace curvetext::detail {
namespace {

constexpr std::uint32_t kRightSide = 0x80000000u;  // stack entry flag: on the right chain
constexpr std::uint32_t kIndexMask = 0x7fffffffu;
constexpr int kNone = -1;

// One interval of the fill at the sweep line: between edge `left` and edge
// `right` (an edge is named by the loop position it starts at). `poly[0]` is
// the monotone polygon in progress; after a merge vertex (`merged`) the
// interval holds two, left (poly[0]) and right (poly[1]) of it, until the
// next vertex in the interval connects to the merge vertex, which is the top
// of both stacks.
using Interval = SweepScratch::Interval;
// The chain of a monotone polygon a vertex joins.
enum class Chain { Left, Right };
static_assert(SweepScratch::kNoPolygon == kNone);

class Sweep {
 public:
  Sweep(const std::vector<Vec2>& points, const std::vector<std::uint32_t>& loop_vertices,
        const std::vector<std::uint32_t>& loop_start, std::vector<std::array<std::uint32_t, 3>>& triangles,
        SweepScratch& scratch)
      : points_(points), vertices_(loop_vertices), start_(loop_start), out_(triangles), s_(scratch) {}

  bool run();
  // After run(): the number of triangles a valid input gives, and whether it
  // gave up on a repeated position.
  std::size_t expected_triangles() const { return expected_; }
  bool repeated_position() const { return repeated_; }

 private:
  const std::vector<Vec2>& points_;
  const std::vector<std::uint32_t>& vertices_;
  const std::vector<std::uint32_t>& start_;
  std::vector<std::array<std::uint32_t, 3>>& out_;
  SweepScratch& s_;
  bool ok_ = true;
  bool repeated_ = false;
  std::size_t expected_ = 0;

  // Per loop position: the neighbours in its loop, and the rank in sweep order.
  std::vector<std::uint32_t>& prev_ = s_.prev;
  std::vector<std::uint32_t>& next_ = s_.next;
  std::vector<std::uint32_t>& rank_ = s_.rank;
  std::vector<std::uint32_t>& order_ = s_.order;
  std::vector<std::uint32_t>& loop_of_ = s_.loop_of;
  std::vector<Vec2>& position_ = s_.position;
  std::vector<Interval>& status_ = s_.status;
  std::vector<std::vector<std::uint32_t>>& stacks_ = s_.stacks;
  std::vector<int>& free_stacks_ = s_.free_stacks;
  std::size_t stacks_used_ = 0;

  Vec2 at(std::uint32_t position) const { return position_[position & kIndexMask]; }

  int new_poly(std::uint32_t first) {
    int id;
    if (!free_stacks_.empty()) {
      id = free_stacks_.back();
      free_stacks_.pop_back();
    } else {
      if (stacks_used_ == stacks_.size()) stacks_.emplace_back();
      id = static_cast<int>(stacks_used_++);
    }
    stacks_[static_cast<std::size_t>(id)].assign(1, first);
    return id;
  }

  void triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    out_.push_back({vertices_[a & kIndexMask], vertices_[b & kIndexMask], vertices_[c & kIndexMask]});
  }

  // The fan from v to every stack edge; v is on the side opposite the top.
  // Each triangle is checked: a fan is only as good as the classification.
  void fan(std::vector<std::uint32_t>& st, std::uint32_t v) {
    const bool top_right = (st.back() & kRightSide) != 0;
    for (std::size_t i = 0; i + 1 < st.size(); ++i) {
      const std::uint32_t a = st[i], b = top_right ? st[i + 1] : v, c = top_right ? v : st[i + 1];
      if (orient2d(at(a), at(b), at(c)) <= 0) ok_ = false;
      triangle(a, b, c);
    }
  }

  // Vertex v joins the polygon's left (or right) chain.
  void add(int poly, std::uint32_t v, Chain chain) {
    const bool right = chain == Chain::Right;
    std::vector<std::uint32_t>& st = stacks_[static_cast<std::size_t>(poly)];
    const std::uint32_t entry = v | (right ? kRightSide : 0u);
    if (((st.back() & kRightSide) != 0) != right) {
      fan(st, v);
      const std::uint32_t top = st.back();
      st.assign({top, entry});
      return;
    }
    const Vec2 pv = at(v);
    while (st.size() >= 2) {
      const std::uint32_t a = st[st.size() - 2], b = st.back();
      const int o = orient2d(at(a), pv, at(b));
      if (right ? o >= 0 : o <= 0) break;  // b is not a convex corner seen from v
      if (right) {
        triangle(a, b, v);
      } else {
        triangle(a, v, b);
      }
      st.pop_back();
    }
    st.push_back(entry);
  }

  // Vertex v is the polygon's top: triangulate what is left, free the stack.
  void close(int poly, std::uint32_t v) {
    std::vector<std::uint32_t>& st = stacks_[static_cast<std::size_t>(poly)];
    if (st.size() < 2) ok_ = false;
    fan(st, v);
    free_stacks_.push_back(poly);
  }

  // Side of p relative to the line of edge `edge` (> 0: the filled side, as
  // every edge has the fill on its left).
  int side_of_edge(std::uint32_t edge, Vec2 p) { return orient2d(at(edge), at(next_[edge]), p); }

  // The status is ordered left to right along the sweep line, so the
  // intervals wholly left of p (p right of their right edge) come first: the
  // first one that is not, by binary search. Long outlines (a stroked
  // zigzag) keep thousands of intervals open at once.
  std::size_t first_not_left_of(Vec2 p) {
    std::size_t lo = 0, hi = status_.size();
    while (lo < hi) {
      const std::size_t mid = lo + (hi - lo) / 2;
      if (side_of_edge(status_[mid].right, p) < 0) {
        lo = mid + 1;
      } else {
        hi = mid;
      }
    }
    return lo;
  }
  // The interval whose left (right) edge is `edge`, an edge through the
  // event point p: found next to where p lies, else by a full scan.
  int find_by_left(std::uint32_t edge, Vec2 p) {
    return find_near(p, [&](const Interval& iv) { return iv.left == edge; });
  }
  int find_by_right(std::uint32_t edge, Vec2 p) {
    return find_near(p, [&](const Interval& iv) { return iv.right == edge; });
  }
  template <class Match>
  int find_near(Vec2 p, Match match) {
    constexpr std::size_t kNear = 4;
    const std::size_t k0 = first_not_left_of(p), from = k0 > kNear ? k0 - kNear : 0;
    for (std::size_t k = from; k < status_.size() && k <= k0 + kNear; ++k)
      if (match(status_[k])) return static_cast<int>(k);
    for (std::size_t k = 0; k < status_.size(); ++k)
      if (match(status_[k])) return static_cast<int>(k);
    return kNone;
  }

  void start(std::uint32_t v, std::uint32_t u);
  void split(std::uint32_t v, std::uint32_t u);
  void end(std::uint32_t v, std::uint32_t u);
  void merge(std::uint32_t v, std::uint32_t u);
  void regular_left(std::uint32_t v, std::uint32_t u);
  void regular_right(std::uint32_t v, std::uint32_t u);
};

// Both edges above v, convex: a new interval [edge u -> v, edge v -> w].
// v must lie outside the fill: inside an interval it would start a loop
// nested in the fill with the fill's own orientation (winding 2 under the
// nonzero rule, where that loop bounds nothing), which the caller's
// orientation of the loops did not foresee.
void Sweep::start(std::uint32_t v, std::uint32_t u) {
  const Vec2 p = at(v);
  // The first interval whose left edge has v on its outer side (v is left of
  // it, and outside every interval from there on).
  std::size_t lo = 0, hi = status_.size();
  while (lo < hi) {
    const std::size_t mid = lo + (hi - lo) / 2;
    const int s = side_of_edge(status_[mid].left, p);
    if (s == 0) ok_ = false;
    if (s < 0) {
      hi = mid;
    } else {
      lo = mid + 1;
    }
  }
  const std::size_t k = lo;
  if (k < status_.size() && side_of_edge(status_[k].left, p) == 0) ok_ = false;
  // Right of interval k - 1's left edge: v must also be right of its right edge.
  if (k > 0 && side_of_edge(status_[k - 1].right, p) >= 0) ok_ = false;
  Interval iv;
  iv.left = u;
  iv.right = v;
  iv.poly[0] = new_poly(v);
  status_.insert(status_.begin() + static_cast<std::ptrdiff_t>(k), iv);
}

// Both edges above v, reflex: v splits the interval it lies in, with a
// diagonal to the interval's last vertex (or to its pending merge vertex).
void Sweep::split(std::uint32_t v, std::uint32_t u) {
  const Vec2 p = at(v);
  // Only the first interval not wholly left of v can hold it; v on an edge
  // of it or of its left neighbour is a degenerate input.
  int found = kNone;
  const std::size_t k = first_not_left_of(p);
  if (k > 0 && side_of_edge(status_[k - 1].right, p) == 0) ok_ = false;
  if (k < status_.size()) {
    const int l = side_of_edge(status_[k].left, p), r = side_of_edge(status_[k].right, p);
    if (l == 0 || r == 0) ok_ = false;
    if (l > 0 && r > 0) found = static_cast<int>(k);
  }
  if (found == kNone) {
    ok_ = false;
    return;
  }
  Interval& iv = status_[static_cast<std::size_t>(found)];
  Interval left_part, right_part;
  left_part.left = iv.left;
  left_part.right = v;
  right_part.left = u;
  right_part.right = iv.right;
  if (iv.merged) {
    add(iv.poly[0], v, Chain::Right);
    add(iv.poly[1], v, Chain::Left);
    left_part.poly[0] = iv.poly[0];
    right_part.poly[0] = iv.poly[1];
  } else {
    const int poly = iv.poly[0];
    std::vector<std::uint32_t>& st = stacks_[static_cast<std::size_t>(poly)];
    const std::uint32_t helper = st.back();
    if (helper & kRightSide) {
      // The reflex chain is on the right: it stays with the left part.
      add(poly, v, Chain::Right);
      left_part.poly[0] = poly;
      right_part.poly[0] = new_poly(helper);
      add(right_part.poly[0], v, Chain::Left);
    } else {
      add(poly, v, Chain::Left);
      right_part.poly[0] = poly;
      left_part.poly[0] = new_poly(helper);
      add(left_part.poly[0], v, Chain::Right);
    }
  }
  iv = left_part;
  status_.insert(status_.begin() + found + 1, right_part);
}

// Both edges below v, convex: the interval [edge v -> w, edge u -> v] ends.
void Sweep::end(std::uint32_t v, std::uint32_t u) {
  const int k = find_by_left(v, at(v));
  if (k == kNone || status_[static_cast<std::size_t>(k)].right != u) {
    ok_ = false;
    return;
  }
  const Interval iv = status_[static_cast<std::size_t>(k)];
  close(iv.poly[0], v);
  if (iv.merged) close(iv.poly[1], v);
  status_.erase(status_.begin() + k);
}

// Both edges below v, reflex: the intervals left and right of v become one,
// with v as its pending merge vertex.
void Sweep::merge(std::uint32_t v, std::uint32_t u) {
  const int k = find_by_right(u, at(v));
  if (k == kNone || static_cast<std::size_t>(k) + 1 >= status_.size() ||
      status_[static_cast<std::size_t>(k) + 1].left != v) {
    ok_ = false;
    return;
  }
  Interval& a = status_[static_cast<std::size_t>(k)];
  const Interval b = status_[static_cast<std::size_t>(k) + 1];
  int left_poly, right_poly;
  if (a.merged) {
    close(a.poly[1], v);
    add(a.poly[0], v, Chain::Right);
  } else {
    add(a.poly[0], v, Chain::Right);
  }
  left_poly = a.poly[0];
  if (b.merged) {
    close(b.poly[0], v);
    add(b.poly[1], v, Chain::Left);
    right_poly = b.poly[1];
  } else {
    add(b.poly[0], v, Chain::Left);
    right_poly = b.poly[0];
  }
  a.right = b.right;
  a.poly[0] = left_poly;
  a.poly[1] = right_poly;
  a.merged = true;
  status_.erase(status_.begin() + k + 1);
}

// Edge u -> v above, v -> w below: v is on a left boundary.
void Sweep::regular_left(std::uint32_t v, std::uint32_t u) {
  const int k = find_by_left(v, at(v));
  if (k == kNone) {
    ok_ = false;
    return;
  }
  Interval& iv = status_[static_cast<std::size_t>(k)];
  if (iv.merged) {
    close(iv.poly[0], v);
    iv.poly[0] = iv.poly[1];
    iv.poly[1] = kNone;
    iv.merged = false;
  }
  add(iv.poly[0], v, Chain::Left);
  iv.left = u;
}

// Edge u -> v below, v -> w above: v is on a right boundary.
void Sweep::regular_right(std::uint32_t v, std::uint32_t u) {
  const int k = find_by_right(u, at(v));
  if (k == kNone) {
    ok_ = false;
    return;
  }
  Interval& iv = status_[static_cast<std::size_t>(k)];
  if (iv.merged) {
    close(iv.poly[1], v);
    iv.poly[1] = kNone;
    iv.merged = false;
  }
  add(iv.poly[0], v, Chain::Right);
  iv.right = v;
}

// Sorts the events by key with a distribution pass: each goes to one of
// 2 n buckets by where its y lies between the lowest and the highest (a
// monotone map, so the buckets come in key order), and an insertion sort
// then orders each bucket's few events by the whole key. A comparison sort
// takes about log2 n data-dependent branches per event, half of them
// mispredicted on a glyph seen once; this takes about one per bucket that
// holds more than one event (equal y, mostly: a horizontal edge's ends).
// Key k is that of position k, whose y lies in [low, high].
template <class Key>
void sort_by_key(std::vector<Key>& keys, const std::vector<Vec2>& position, double low, double high,
                 std::vector<std::uint32_t>& bucket_of, std::vector<std::uint32_t>& first, std::vector<Key>& sorted) {
  const std::size_t n = keys.size();
  auto by_key = [](const Key& a, const Key& b) { return a.yx < b.yx; };
  // (Too few events to gain: the comparison sort.)
  if (n < 8) {
    std::sort(keys.begin(), keys.end(), by_key);
    return;
  }
  const double scale = static_cast<double>(2 * n) / (high - low);
  // (All at one height, or a range or scale that overflows: the comparison
  // sort.)
  if (!(scale > 0.0 && scale < 1e300)) {
    std::sort(keys.begin(), keys.end(), by_key);
    return;
  }
  const std::size_t buckets = 2 * n;
  bucket_of.resize(n);
  first.assign(buckets + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    // (y - low) * scale lies in [0, buckets] up to rounding, which keeps the
    // map monotone; the top end goes to the last bucket.
    const auto b = static_cast<std::uint32_t>((position[i].y - low) * scale);
    bucket_of[i] = std::min<std::uint32_t>(b, static_cast<std::uint32_t>(buckets - 1));
    ++first[bucket_of[i] + 1];
  }
  // The insertion sort's work is about the sum of the squared bucket sizes:
  // where the heights cluster (one far outlier puts all others in a bucket),
  // the comparison sort is kept instead.
  std::size_t crowding = 0;
  for (std::size_t b = 1; b <= buckets; ++b) crowding += std::size_t{first[b]} * first[b];
  if (crowding > 4 * n) {
    std::sort(keys.begin(), keys.end(), by_key);
    return;
  }
  for (std::size_t b = 0; b < buckets; ++b) first[b + 1] += first[b];
  sorted.resize(n);
  for (std::size_t i = 0; i < n; ++i) sorted[first[bucket_of[i]]++] = keys[i];
  // Insertion sort: only events sharing a bucket are out of order.
  for (std::size_t i = 1; i < n; ++i) {
    const Key k = sorted[i];
    std::size_t j = i;
    for (; j > 0 && by_key(k, sorted[j - 1]); --j) sorted[j] = sorted[j - 1];
    sorted[j] = k;
  }
  keys.swap(sorted);
}

bool Sweep::run() {
  const std::size_t n = vertices_.size();
  if (n >= kIndexMask) return false;
  prev_.resize(n);
  next_.resize(n);
  loop_of_.resize(n);
  rank_.resize(n);
  position_.resize(n);
  std::vector<SweepScratch::Key>& keys = s_.keys;
  keys.clear();
  double low = n == 0 ? 0.0 : points_[vertices_[0]].y, high = low;
  for (std::size_t l = 0; l + 1 < start_.size(); ++l) {
    const std::uint32_t first = start_[l], last = start_[l + 1];
    if (last - first < 3) return false;
    for (std::uint32_t i = first; i < last; ++i) {
      prev_[i] = i == first ? last - 1 : i - 1;
      next_[i] = i + 1 == last ? first : i + 1;
      const Vec2 p = points_[vertices_[i]];
      position_[i] = p;
      loop_of_[i] = static_cast<std::uint32_t>(l);
      keys.push_back({position_key(p), i});
      low = std::min(low, p.y);
      high = std::max(high, p.y);
    }
  }
  sort_by_key(keys, position_, low, high, s_.bucket_of, s_.first, s_.sorted);
  order_.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    if (k > 0 && keys[k - 1].yx == keys[k].yx) {
      repeated_ = true;
      return false;
    }
    order_[k] = keys[k].position;
    rank_[keys[k].position] = static_cast<std::uint32_t>(k);
  }
  status_.clear();
  free_stacks_.clear();
  stacks_used_ = 0;
  // A loop's lowest vertex is its first in sweep order: a start vertex for a
  // loop around fill (n - 2 triangles), a split vertex for a hole (n + 2:
  // its two "bridges"). Any other count means the loops broke the contract.
  const std::size_t loops = start_.size() - 1;
  std::vector<char>& loop_seen = s_.loop_seen;
  loop_seen.assign(loops, 0);
  expected_ = n - 2 * loops;
  for (std::size_t k = 0; k < order_.size() && ok_; ++k) {
    const std::uint32_t v = order_[k], u = prev_[v], w = next_[v];
    const std::uint32_t loop = loop_of_[v];
    const bool lowest = loop_seen[loop] == 0;
    loop_seen[loop] = 1;
    const bool u_below = rank_[u] < rank_[v], w_below = rank_[w] < rank_[v];
    if (u_below != w_below) {
      if (u_below) {
        regular_right(v, u);
      } else {
        regular_left(v, u);
      }
      continue;
    }
    const int turn = orient2d(at(u), at(v), at(w));
    if (turn == 0) return false;  // a spike or a flat extreme vertex
    if (!u_below) {
      if (turn > 0) {
        start(v, u);
      } else {
        expected_ += lowest ? 4 : 0;
        split(v, u);
      }
    } else if (turn > 0) {
      end(v, u);
    } else {
      merge(v, u);
    }
  }
  return ok_ && status_.empty();
}

}  // namespace

bool sweep_triangulate(const std::vector<Vec2>& points, const std::vector<std::uint32_t>& loop_vertices,
                       const std::vector<std::uint32_t>& loop_start,
                       std::vector<std::array<std::uint32_t, 3>>& triangles, TriangulateScratch& scratch,
                       bool* repeated_position) {
  const std::size_t first_triangle = triangles.size();
  Sweep sweep(points, loop_vertices, loop_start, triangles, scratch.sweep);
  const bool ok = sweep.run() && triangles.size() - first_triangle == sweep.expected_triangles();
  if (repeated_position != nullptr) *repeated_position = sweep.repeated_position();
  if (ok) return true;
  triangles.resize(first_triangle);
  return false;
}

}  // namespace curvetext::detail
