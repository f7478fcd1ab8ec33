// Resolving crossing contours into non-crossing rings (docs/design.md section 4:
// overlapping, self-intersecting and edge-sharing contours, nonzero rule).
//
// Strategy. Hull separation (separate_hulls) has already subdivided conics
// whose control triangles overlap another piece's, and split pieces whose
// chords cross at the point where their curves cross (they then meet at a
// common vertex); conics that touch something, or cross it where that point
// was not found, keep overlapping however deep they are split, so they end
// at the subdivision limit (parameter span 2^-kMaxHullSubdivisionDepth). Those last
// small pieces are replaced by their chords: their arcs deviate from the chord
// by a sagitta of ~1e-6 of the curve's size, far below a pixel. Every conic
// that is left then has a hull no other piece enters, so the arrangement's
// topology is that of the chords: a line arrangement. Lines are split at their
// crossings and T-junctions (exact orient2d decides; the crossing point is
// rounded to doubles and snapped to vertices within 1e-12 of the outline's
// size), conics the rounding pushed into conflict are split further (the
// loop in resolve_crossings), coincident edges merged with a net direction
// count, and each edge's left/right winding numbers obtained by a ray cast from
// its midpoint against the other edges (binned by span; exact orient2d) for
// one edge per connected part, and passed on to the others along chains and
// around crossing vertices (side_windings). An edge bounds the fill when exactly one
// side is filled (winding != 0, or odd under the even-odd rule); it is kept, directed with the fill on its left, and
// the kept edges are linked into loops turning at every vertex to the first
// edge clockwise from the one we came along (which traces face boundaries, so
// loops never cross). The loops go through the usual split/nesting path.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "core/assert.hpp"
#include "core/tolerances.hpp"
#include "curvetext/curves.hpp"
#include "tessellate/arrangement.hpp"
#include "tessellate/columns.hpp"
#include "tessellate/positions.hpp"
#include "tessellate/resolve.hpp"
#include "tessellate/rings.hpp"

namespace curvetext::detail {
namespace {

using Edge = ArrangementEdge;
using Cut = CutPoint;

int hull_points(const Edge& e, Vec2* out) {
  out[0] = e.a;
  if (e.conic) {
    out[1] = e.control;
    out[2] = e.b;
    return 3;
  }
  out[1] = e.b;
  return 2;
}

bool shares_an_end(const Edge& e, const Edge& f) { return e.a == f.a || e.a == f.b || e.b == f.a || e.b == f.b; }

bool same_ends(const Edge& e, const Edge& f) { return (e.a == f.a && e.b == f.b) || (e.a == f.b && e.b == f.a); }

// Same curve, in either direction.
bool same_curve(const Edge& e, const Edge& f) {
  if (!same_ends(e, f) || e.conic != f.conic) return false;
  return !e.conic || (e.control == f.control && e.weight == f.weight);
}

// Two lines share a point other than one common end point (a crossing, a
// T-junction, a collinear overlap or a duplicate).
// When segments a-b and c-d share an end point: that point and the two
// other ends.
bool shared_end(Vec2 a, Vec2 b, Vec2 c, Vec2 d, Vec2& shared, Vec2& p, Vec2& q) {
  if (a == c) {
    shared = a, p = b, q = d;
  } else if (a == d) {
    shared = a, p = b, q = c;
  } else if (b == c) {
    shared = b, p = a, q = d;
  } else if (b == d) {
    shared = b, p = a, q = c;
  } else {
    return false;
  }
  return true;
}

bool lines_conflict(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  if (!segments_intersect(a, b, c, d)) return false;
  if ((a == c && b == d) || (a == d && b == c)) return true;
  Vec2 shared, p, q;  // the common end point and the two other ends
  if (!shared_end(a, b, c, d, shared, p, q)) return true;
  // Sharing an end, they meet elsewhere only when one runs along the other.
  return point_on_segment(shared, p, q) || point_on_segment(shared, q, p);
}

// Pairs of edges with overlapping boxes; f(i, j) returns true to stop. Sweep
// and prune along the longer side of all the boxes (a tall glyph's edges
// share x ranges), with the sides copied in sorted order so the scan reads
// them in a row. The pairs come in no particular order and either way round:
// every caller's answer is independent of both.
template <class F>
bool for_each_close_pair(const std::vector<Edge>& edges, ResolveScratch& scratch, F&& f) {
  const std::size_t n = edges.size();
  Box all;
  for (const Edge& e : edges) {
    all.add(e.box.min);
    all.add(e.box.max);
  }
  const bool along_y = all.max.y - all.min.y > all.max.x - all.min.x;
  using Key = ResolveScratch::CloseKey;
  std::vector<Key>& keys = scratch.close_keys;  // (callers never nest this loop)
  std::vector<double>& sides = scratch.close_sides;
  keys.resize(n);
  for (std::size_t k = 0; k < n; ++k)
    keys[k] = {along_y ? edges[k].box.min.y : edges[k].box.min.x, static_cast<std::uint32_t>(k)};
  std::sort(keys.begin(), keys.end(), [](const Key& a, const Key& b) { return a.low < b.low; });
  const auto [high_a, low_b, high_b] = columns<3>(sides, n);
  for (std::size_t k = 0; k < n; ++k) {
    const Box& box = edges[keys[k].edge].box;
    high_a[k] = along_y ? box.max.y : box.max.x;
    low_b[k] = along_y ? box.min.x : box.min.y;
    high_b[k] = along_y ? box.max.x : box.max.y;
  }
  // The boxes after box i that meet it along a are gathered first, those
  // that also meet it along b kept without a branch (whether they do follows
  // no pattern a predictor could learn; a branch per candidate cost more
  // than the pairs' tests for a glyph whose long stems overlap most edges
  // along a).
  std::vector<std::uint32_t>& candidates = scratch.candidates;
  candidates.resize(n);
  std::uint32_t* const candidate = candidates.data();
  for (std::size_t i = 0; i < n; ++i) {
    const double upper = high_a[i], lo = low_b[i], hi = high_b[i];
    std::size_t found = 0;
    for (std::size_t j = i + 1; j < n && keys[j].low <= upper; ++j) {
      candidate[found] = keys[j].edge;
      found += static_cast<std::size_t>((low_b[j] <= hi) & (lo <= high_b[j]));
    }
    for (std::size_t k = 0; k < found; ++k)
      if (f(keys[i].edge, candidate[k])) return true;
  }
  return false;
}

// Pairs of edges with overlapping boxes and at least one of them fresh, as
// for_each_close_pair gives them, found by testing each fresh edge's box
// against every other (no sort): after a round of splits the fresh pieces are
// few. Each pair once.
template <class F>
bool for_each_fresh_pair(const std::vector<Edge>& edges, ResolveScratch& scratch, F&& f) {
  const std::size_t n = edges.size();
  std::vector<std::uint32_t>& candidates = scratch.candidates;
  candidates.resize(n);
  std::uint32_t* const candidate = candidates.data();
  for (std::uint32_t i = 0; i < n; ++i) {
    if (!edges[i].fresh) continue;
    const Box& b = edges[i].box;
    std::size_t found = 0;
    for (std::uint32_t j = 0; j < n; ++j) {
      const Box& c = edges[j].box;
      candidate[found] = j;
      // Fresh pairs once (from their lower index), never an edge with itself.
      const bool once = !edges[j].fresh || j > i;
      found += static_cast<std::size_t>(once & (c.min.x <= b.max.x) & (b.min.x <= c.max.x) & (c.min.y <= b.max.y) &
                                        (b.min.y <= c.max.y));
    }
    for (std::size_t k = 0; k < found; ++k)
      if (f(i, candidate[k])) return true;
  }
  return false;
}

// Whether two pieces conflict: lines by lines_conflict; with a conic, any
// overlap of hulls beyond a shared vertex, or the same end points (the chords
// would coincide). Identical curves are reported too (they merge later).
bool pieces_conflict(const Edge& e, const Edge& f) {
  if (!e.conic && !f.conic) return lines_conflict(e.a, e.b, f.a, f.b);
  if (same_ends(e, f)) return true;
  Vec2 he[3], hf[3];
  const int ne = hull_points(e, he), nf = hull_points(f, hf);
  return hulls_overlap(he, ne, hf, nf);
}

// The rings' pieces as edges; `counts` (empty: all 1) gives each ring's
// count (fold_repeated_rings).
std::vector<Edge> edges_of(const std::vector<Ring>& rings, const std::vector<int>& counts = {}) {
  std::vector<Edge> edges;
  std::size_t count = 0;
  for (const Ring& ring : rings) count += ring.size();
  edges.reserve(count);
  for (std::size_t r = 0; r < rings.size(); ++r) {
    const Ring& ring = rings[r];
    for (std::size_t i = 0; i < ring.size(); ++i) {
      Edge e;
      e.count = counts.empty() ? 1 : counts[r];
      e.a = ring[i].a;
      e.b = ring_end(ring, i);
      e.conic = ring[i].conic;
      e.control = ring[i].control;
      e.weight = ring[i].weight;
      e.depth = ring[i].depth;
      e.box = edge_box(e);
      edges.push_back(e);
    }
  }
  return edges;
}

// The cut points two lines i and j (not the same segment) make on each
// other: their crossing, or the end points of one lying inside the other.
void line_pair_cuts(const std::vector<Edge>& edges, std::uint32_t i, std::uint32_t j, std::vector<Cut>& cuts) {
  const Edge& e = edges[i];
  const Edge& f = edges[j];
  auto cut = [&](std::uint32_t k, Vec2 p) {
    if (p == edges[k].a || p == edges[k].b) return;
    cuts.push_back({k, canonical(p)});
  };
  const int o1 = orient2d(e.a, e.b, f.a), o2 = orient2d(e.a, e.b, f.b);
  // f strictly on one side of e's line (most pairs whose boxes meet): it
  // neither crosses nor touches e, and no end of e can lie on it.
  if (o1 * o2 > 0) return;
  const int o3 = orient2d(f.a, f.b, e.a), o4 = orient2d(f.a, f.b, e.b);
  if (o1 * o2 < 0 && o3 * o4 < 0) {
    // Proper crossing: the point from the parametrisation of the edge
    // whose start is least (so the point does not depend on the order
    // the pair comes in), t clamped to the closed interval (rounding
    // cannot push it past an end).
    const bool e_first = std::make_pair(e.a.x, e.a.y) < std::make_pair(f.a.x, f.a.y) ||
                         (e.a == f.a && std::make_pair(e.b.x, e.b.y) < std::make_pair(f.b.x, f.b.y));
    const Edge& g = e_first ? e : f;
    const Edge& h = e_first ? f : e;
    const Vec2 r = g.b - g.a, s = h.b - h.a;
    double t = cross(h.a - g.a, s) / cross(r, s);
    // (Nearly parallel lines can cross with a cross product that rounds to
    // 0: the point is then ill-conditioned anyway; the middle stands in.)
    t = std::isnan(t) ? 0.5 : std::clamp(t, 0.0, 1.0);
    const Vec2 p = g.a + r * t;
    cut(i, p);
    cut(j, p);
    return;
  }
  // Touching: an end point of one on the other (T-junction, overlap).
  if (o1 == 0 && point_on_segment(e.a, e.b, f.a)) cut(i, f.a);
  if (o2 == 0 && point_on_segment(e.a, e.b, f.b)) cut(i, f.b);
  if (o3 == 0 && point_on_segment(f.a, f.b, e.a)) cut(j, e.a);
  if (o4 == 0 && point_on_segment(f.a, f.b, e.b)) cut(j, e.b);
}

}  // namespace

bool rings_cross(const std::vector<Ring>& rings, HullState hulls, ResolveScratch& scratch) {
  const bool hulls_separated = hulls == HullState::Separated;
  const std::vector<Edge> edges = edges_of(rings);
  return for_each_close_pair(edges, scratch, [&](std::uint32_t i, std::uint32_t j) {
    const Edge& e = edges[i];
    const Edge& f = edges[j];
    if (e.conic || f.conic) {
      if (same_ends(e, f)) return true;  // chords would coincide (or duplicates)
      if (hulls_separated) return false;
      return pieces_conflict(e, f);
    }
    return lines_cross(e.a, e.b, f.a, f.b);
  });
}

bool lines_cross(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  // Lines sharing one end point (consecutive pieces, mostly) conflict only
  // when they run along each other: one exact orientation test.
  Vec2 shared, p, q;
  if (!shared_end(a, b, c, d, shared, p, q)) return segments_intersect(a, b, c, d);
  if (p == q) return true;  // the same segment twice
  return orient2d(shared, p, q) == 0 && dot(p - shared, q - shared) > 0.0;
}

namespace {

// One call of resolve_crossings: the arrangement of the rings' pieces made
// free of conflicts (rounds of splits), its edges' windings, and the loops
// of the edges that bound the fill.
class CrossingResolver {
 public:
  CrossingResolver(HullState hulls, FillRule rule, std::size_t max_pieces, RingPool& pool, ResolveScratch& scratch)
      : hulls_separated_(hulls == HullState::Separated),
        rule_(rule),
        max_pieces_(max_pieces),
        pool_(pool),
        s_(scratch) {}

  std::vector<Ring> run(const std::vector<Ring>& rings, const std::vector<int>& counts, bool* settled);

 private:
  // Rounded crossing points can make new crossings round after round; the
  // budget stops an arrangement that keeps growing.
  void within_budget(const char* what, std::size_t used) const {
    if (used > max_pieces_) work_budget_exceeded(what, used, max_pieces_);
  }
  bool remove_conflicts();
  bool find_conflicts(int round);
  void split_marked_conics();
  void keep_boundary_edges();
  void number_vertices();
  std::uint32_t out_degree(std::uint32_t v) const {
    return v == kNoVertex ? 0u : s_.out_first[v + 1] - s_.out_first[v];
  }
  std::uint32_t next_edge(std::uint32_t incoming) const;
  bool trace_loop(std::uint32_t start);
  Ring drop_straight_vertices();
  void keep(Ring&& loop, std::vector<Ring>& out);

  static constexpr std::uint32_t kNoVertex = UINT32_MAX;
  const bool hulls_separated_;
  const FillRule rule_;
  const std::size_t max_pieces_;
  RingPool& pool_;
  ResolveScratch& s_;
  std::vector<Edge> edges_;
  std::vector<char> marked_;  // conics in conflict, to be halved
  std::vector<Edge> next_;
};

std::vector<Ring> CrossingResolver::run(const std::vector<Ring>& rings, const std::vector<int>& counts, bool* settled) {
  // Coincident edges (a path that retraces itself, contours sharing edges)
  // are merged first: n runs over one edge are one edge with a count, not
  // n^2 / 2 pairs to cut.
  merge_coincident(edges_of(rings, counts), edges_, s_.slots);
  const bool conflicts_left = remove_conflicts();
  keep_boundary_edges();
  number_vertices();
  s_.controls.clear();
  for (const Edge& e : s_.kept)
    if (e.conic) s_.controls.push_back(e.control);
  s_.used.assign(s_.kept.size(), 0);
  std::vector<Ring> out;
  for (std::uint32_t start = 0; start < s_.kept.size(); ++start) {
    if (s_.used[start]) continue;
    const bool may_repeat = trace_loop(start);
    Ring simple = drop_straight_vertices();
    // A loop passes through a vertex twice only where two kept edges leave it.
    if (!may_repeat) {
      keep(std::move(simple), out);
      continue;
    }
    for (Ring& sub : split_at_repeated_vertices(simple, s_.slots)) keep(std::move(sub), out);
    pool_.recycle(std::move(simple));
  }
  if (settled != nullptr) *settled = !conflicts_left;
  return out;
}

// Conics in conflict with another piece (sharing a point other than a common
// vertex, or both end points) are halved, and flattened once at the
// subdivision limit, where their arcs are within ~1e-6 of the curve's size of
// their chords. Lines are split at their cut points (crossings, and end
// points lying inside them). Each crossing point is rounded to doubles, which
// can move a piece by an ulp into a new crossing, or near a conic's vertex
// into the conic's hull, so conflicts are looked for again after every round
// of splits. Each round with a conic in conflict deepens every such conic, so
// there are at most kMaxHullSubdivisionDepth + 2 of them. Line splits settle
// in one to three rounds; bundles of nearly parallel lines, whose crossings
// are found far along them, can instead cut each other again every round, so
// after tolerance::kMaxLineSplitRounds such rounds in a row the resolver stops
// there. Returns true when conflicts were left when the rounds ran out.
bool CrossingResolver::remove_conflicts() {
  constexpr int kMaxConicRounds = tolerance::kMaxHullSubdivisionDepth + 2;
  constexpr int kMaxRounds = 4 * (kMaxConicRounds + 1);
  int conic_rounds = 0, line_rounds = 0;
  for (int round = 0; round < kMaxRounds; ++round) {
    if (!find_conflicts(round)) {
      // (The last round's cuts are still made, not looked at again.)
      if (!split_at_cuts(edges_, s_.cuts, s_)) return false;
      within_budget("crossing resolution (edges)", edges_.size());
      if (++line_rounds == tolerance::kMaxLineSplitRounds) return true;
      continue;
    }
    line_rounds = 0;
    if (conic_rounds++ == kMaxConicRounds) {
      split_at_cuts(edges_, s_.cuts, s_);
      within_budget("crossing resolution (edges)", edges_.size());
      return true;
    }
    // Conics first; the lines' cuts are found again in the next round (the
    // lines they were on stay fresh for it).
    for (const Cut& c : s_.cuts) edges_[c.edge].fresh = true;
    split_marked_conics();
    within_budget("crossing resolution (edges)", edges_.size());
  }
  return true;
}

// One sweep per round finds both the conics in conflict (marked_; returns
// true when there is one) and the lines' cut points (s_.cuts). Pairs of
// edges that are both unchanged since the last sweep are skipped: it found
// them apart, or one of them would have been split and so be new.
bool CrossingResolver::find_conflicts(int round) {
  // Up to this many box tests (fresh edges times all), testing the fresh
  // edges against all costs less than the sweep's sort.
  constexpr std::size_t kFreshPairsDirect = 4096;
  std::vector<Edge>& edges = edges_;
  std::vector<Cut>& cuts = s_.cuts;
  marked_.assign(edges.size(), 0);
  cuts.clear();
  bool any = false;
  auto test_pair = [&](std::uint32_t i, std::uint32_t j) {
    const Edge& e = edges[i];
    const Edge& f = edges[j];
    if (!e.fresh && !f.fresh) return false;
    if (!e.conic && !f.conic) {
      if (!same_ends(e, f)) line_pair_cuts(edges, i, j, cuts);
      within_budget("crossing resolution (cut points)", cuts.size());
      return false;
    }
    // Hull separation has kept the conics apart from every piece they share
    // no vertex with; where it split two curves at their crossing, the pieces
    // meet at that vertex with their hulls across each other.
    if (round == 0 && hulls_separated_ && !shares_an_end(e, f)) return false;
    if (same_curve(e, f) || !pieces_conflict(e, f)) return false;
    if (e.conic) marked_[i] = 1;
    if (f.conic) marked_[j] = 1;
    any = true;
    return false;
  };
  // (Every edge is fresh in the first round.)
  std::size_t fresh = 0;
  for (const Edge& e : edges) fresh += static_cast<std::size_t>(e.fresh);
  if (round > 0 && fresh * edges.size() <= kFreshPairsDirect) {
    for_each_fresh_pair(edges, s_, test_pair);
  } else {
    for_each_close_pair(edges, s_, test_pair);
  }
  for (Edge& e : edges) e.fresh = false;
  return any;
}

// The marked conics halved, or made their chords at the subdivision limit.
void CrossingResolver::split_marked_conics() {
  next_.clear();
  next_.reserve(edges_.size() + 16);
  for (std::size_t i = 0; i < edges_.size(); ++i) {
    const Edge& e = edges_[i];
    if (!marked_[i]) {
      next_.push_back(e);
    } else if (e.depth >= tolerance::kMaxHullSubdivisionDepth) {
      Edge flat = e;
      flat.conic = false;
      flat.weight = 1.0;
      flat.box = edge_box(flat);
      flat.fresh = true;
      next_.push_back(flat);
    } else {
      const auto halves = split(Segment::conic(e.a, e.control, e.b, e.weight), 0.5);
      for (const Segment& h : {halves.first, halves.second}) {
        Edge half = e;
        half.a = canonical(h.p[0]);
        half.control = canonical(h.p[1]);
        half.b = canonical(h.p[2]);
        half.weight = h.weight;
        half.depth = e.depth + 1;
        half.box = edge_box(half);
        half.fresh = true;
        next_.push_back(half);
      }
    }
  }
  edges_.swap(next_);
}

// Kept edges (s_.kept): those with the fill on exactly one side, directed
// with the fill on the left.
void CrossingResolver::keep_boundary_edges() {
  std::vector<Edge>& merged = s_.merged;
  merge_coincident(edges_, merged, s_.slots);
  side_windings(merged, s_.left, s_.right, s_);
  s_.kept.clear();
  s_.kept.reserve(merged.size());
  for (std::size_t i = 0; i < merged.size(); ++i) {
    const bool l = fills(rule_, s_.left[i]), r = fills(rule_, s_.right[i]);
    if (l == r) continue;
    Edge e = merged[i];
    if (!l) std::swap(e.a, e.b);
    e.count = 1;
    s_.kept.push_back(e);
  }
}

// Vertices of the kept edges, numbered: each edge's start and end vertex (an
// end where no kept edge starts has none), found in a hash table of
// positions, and per vertex its outgoing edges in increasing index order
// (counted, then filled in edge order).
void CrossingResolver::number_vertices() {
  const std::vector<Edge>& kept = s_.kept;
  const std::size_t kept_count = kept.size();
  std::vector<std::uint32_t>& start_vertex = s_.start_vertex;
  std::vector<std::uint32_t>& end_vertex = s_.end_vertex;
  std::vector<std::uint32_t>& out_first = s_.out_first;
  std::vector<std::uint32_t>& out_edges = s_.out_edges;
  FirstAtPosition starts(s_.slots, kept_count, [&](std::uint32_t i) { return kept[i].a; });
  std::uint32_t vertices = 0;
  start_vertex.resize(kept_count);
  for (std::uint32_t i = 0; i < kept_count; ++i) {
    const std::uint32_t first = starts.add(i);
    start_vertex[i] = first == i ? vertices++ : start_vertex[first];
  }
  end_vertex.resize(kept_count);
  for (std::size_t i = 0; i < kept_count; ++i) {
    const std::int32_t first = starts.find(kept[i].b);
    end_vertex[i] = first < 0 ? kNoVertex : start_vertex[static_cast<std::size_t>(first)];
  }
  out_first.assign(vertices + 1, 0);
  for (std::size_t i = 0; i < kept_count; ++i) ++out_first[start_vertex[i] + 1];
  for (std::size_t v = 0; v < vertices; ++v) out_first[v + 1] += out_first[v];
  out_edges.resize(kept_count);
  for (std::size_t i = 0; i < kept_count; ++i) out_edges[out_first[start_vertex[i]]++] = static_cast<std::uint32_t>(i);
  // (Filling moved each vertex's first to its end: shift back.)
  for (std::size_t v = vertices; v > 0; --v) out_first[v] = out_first[v - 1];
  out_first[0] = 0;
  CURVETEXT_ASSERT(out_first[vertices] == kept_count);  // every kept edge leaves one vertex
}

// At v, coming along u -> v: the next edge is the first outgoing one
// clockwise from the direction back to u. Fill-on-left edges alternate in
// and out around v, so this pairs each incoming edge with one outgoing edge.
std::uint32_t CrossingResolver::next_edge(std::uint32_t incoming) const {
  const std::vector<Edge>& kept = s_.kept;
  const Edge& in = kept[incoming];
  const Vec2 v = in.b;
  const std::uint32_t vertex = s_.end_vertex[incoming];
  std::uint32_t best_before = UINT32_MAX, best_any = UINT32_MAX;
  if (vertex == kNoVertex) return best_any;
  for (std::uint32_t k = s_.out_first[vertex]; k < s_.out_first[vertex + 1]; ++k) {
    const std::uint32_t o = s_.out_edges[k];
    const Vec2 p = kept[o].b;
    if (best_any == UINT32_MAX || arrangement_angle_less(v, kept[best_any].b, p)) best_any = o;
    if (arrangement_angle_less(v, p, in.a) &&
        (best_before == UINT32_MAX || arrangement_angle_less(v, kept[best_before].b, p))) {
      best_before = o;
    }
  }
  return best_before != UINT32_MAX ? best_before : best_any;
}

// One loop of kept edges from `start`, into s_.traced (with each piece's
// edge in s_.ring_edges). Returns true when it may pass through a vertex
// twice (it left a vertex where two kept edges leave).
bool CrossingResolver::trace_loop(std::uint32_t start) {
  const std::vector<Edge>& kept = s_.kept;
  s_.traced.clear();
  s_.ring_edges.clear();
  bool may_repeat = false;
  std::uint32_t cur = start;
  for (std::size_t steps = 0; steps <= kept.size(); ++steps) {
    s_.used[cur] = 1;
    Piece p;
    p.a = kept[cur].a;
    p.conic = kept[cur].conic;
    p.control = kept[cur].control;
    p.weight = kept[cur].weight;
    p.depth = kept[cur].depth;
    s_.traced.push_back(p);
    s_.ring_edges.push_back(cur);
    may_repeat |= out_degree(s_.start_vertex[cur]) > 1;
    const std::uint32_t nxt = next_edge(cur);
    if (nxt == UINT32_MAX || nxt == start || s_.used[nxt]) break;
    cur = nxt;
  }
  return may_repeat;
}

// The traced loop without its straight-through vertices where the boundary
// passes alone (one kept edge out): they come from splitting at crossings
// whose other edges turned out interior. A vertex at a conic's control point
// is kept: there a conic's leg runs exactly along the line (as hull
// separation aligned it), and the longer line would overlap the leg.
// Dropping is decided against the original neighbours; consecutive drops are
// fine because each dropped vertex lies on the line through its neighbours
// and all of them on one straight run.
Ring CrossingResolver::drop_straight_vertices() {
  const Ring& traced = s_.traced;
  auto is_control_point = [&](Vec2 p) {
    return std::find(s_.controls.begin(), s_.controls.end(), p) != s_.controls.end();
  };
  Ring simple = pool_.take();
  for (std::size_t i = 0; i < traced.size(); ++i) {
    const std::size_t prev = (i + traced.size() - 1) % traced.size();
    if (traced.size() > 3 && !traced[i].conic && !traced[prev].conic &&
        out_degree(s_.start_vertex[s_.ring_edges[i]]) == 1) {
      const Vec2 a = traced[prev].a, b = traced[i].a, c = ring_end(traced, i);
      if (orient2d(a, b, c) == 0 && dot(b - a, c - b) > 0.0 && !is_control_point(b)) continue;
    }
    simple.push_back(traced[i]);
  }
  return simple;
}

void CrossingResolver::keep(Ring&& loop, std::vector<Ring>& out) {
  const bool has_conic = std::any_of(loop.begin(), loop.end(), [](const Piece& p) { return p.conic; });
  if (loop.size() < 2 || (loop.size() == 2 && !has_conic) || ring_area(loop) == 0.0) {
    pool_.recycle(std::move(loop));
    return;
  }
  out.push_back(std::move(loop));
}

}  // namespace

std::vector<Ring> resolve_crossings(const std::vector<Ring>& rings, const std::vector<int>& counts, HullState hulls,
                                    FillRule rule, std::size_t max_pieces, RingPool& pool, ResolveScratch& scratch,
                                    bool* settled) {
  return CrossingResolver(hulls, rule, max_pieces, pool, scratch).run(rings, counts, settled);
}

}  // namespace curvetext::detail
