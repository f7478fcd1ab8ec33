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
// side has winding != 0; it is kept, directed with the fill on its left, and
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
#include "curvetext/curves.hpp"
#include "curvetext/tolerances.hpp"
#include "tessellate/columns.hpp"
#include "tessellate/positions.hpp"
#include "tessellate/resolve.hpp"
#include "tessellate/rings.hpp"

namespace curvetext::detail {
namespace {

using Edge = ArrangementEdge;
using Cut = CutPoint;

Box edge_box(const Edge& e) {
  Box box;
  box.add(e.a);
  box.add(e.b);
  if (e.conic) box.add(e.control);
  return box;
}

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

std::vector<Edge> edges_of(const std::vector<Ring>& rings) {
  std::vector<Edge> edges;
  std::size_t count = 0;
  for (const Ring& ring : rings) count += ring.size();
  edges.reserve(count);
  for (const Ring& ring : rings) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      Edge e;
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

bool by_x(Vec2 a, Vec2 b) { return a.x != b.x ? a.x < b.x : a.y < b.y; }

// The loose cut points (near no vertex) onto each other, in (x, y) order:
// each becomes the nearest earlier representative within eps (the last in
// that order among equally near ones), or a representative itself. (Only
// equal points compare equal here, and they snap alike: the result does not
// depend on the order of the cuts.) The representatives come in x order
// because the loose points do.
template <class NearestRepresentative>
void snap_loose(std::vector<Cut>& cuts, ResolveScratch& scratch, NearestRepresentative&& nearest_rep) {
  using Loose = ResolveScratch::LooseCut;
  std::vector<Loose>& loose = scratch.loose;
  std::sort(loose.begin(), loose.end(), [&](const Loose& a, const Loose& b) { return by_x(a.p, b.p); });
  scratch.representatives.clear();
  for (const Loose& l : loose) {
    Vec2 r;
    if (nearest_rep(l.p, r)) {
      cuts[l.cut].p = r;
    } else {
      scratch.representatives.push_back(l.p);
    }
  }
}

// With few cuts (the usual resolve), each looks for its vertex by scanning
// them as they are, which costs less than sorting them: the same vertex as
// snap_many_cuts finds (the nearest within eps, Chebyshev; the last in (x, y)
// order among equally near ones). Most cut points are crossings near no
// vertex: a branch-free count of the vertices within eps finds those first.
// The loose ones then meet each other in a scan too.
void snap_few_cuts(std::vector<Cut>& cuts, double eps, ResolveScratch& scratch) {
  const std::vector<Vec2>& vertices = scratch.vertices;
  const auto [xs, ys] = columns<2>(scratch.coordinates, vertices.size());
  for (std::size_t k = 0; k < vertices.size(); ++k) {
    xs[k] = vertices[k].x;
    ys[k] = vertices[k].y;
  }
  for (std::size_t k = 0; k < cuts.size(); ++k) {
    Cut& c = cuts[k];
    std::size_t near = 0;
    for (std::size_t v = 0; v < vertices.size(); ++v)
      near += static_cast<std::size_t>((std::fabs(xs[v] - c.p.x) <= eps) & (std::fabs(ys[v] - c.p.y) <= eps));
    if (near == 0) {
      scratch.loose.push_back({c.p, k});
      continue;
    }
    double best = eps;
    bool found = false;
    Vec2 nearest{};
    for (const Vec2 v : vertices) {
      const double d = std::max(std::fabs(v.x - c.p.x), std::fabs(v.y - c.p.y));
      if (d < best || (d == best && (!found || !by_x(v, nearest)))) {
        best = d;
        nearest = v;
        found = true;
      }
    }
    c.p = nearest;
  }
  snap_loose(cuts, scratch, [&](Vec2 p, Vec2& out) {
    double best = eps;
    bool found = false;
    for (const Vec2 r : scratch.representatives) {
      const double d = std::max(std::fabs(r.x - p.x), std::fabs(r.y - p.y));
      if (d <= best) {
        best = d;
        out = r;
        found = true;
      }
    }
    return found;
  });
}

// The nearest point of a list sorted by x within eps (Chebyshev) of p.
bool nearest_sorted(const std::vector<Vec2>& sorted, Vec2 p, double eps, Vec2& out) {
  auto it = std::lower_bound(sorted.begin(), sorted.end(), p.x - eps, [](Vec2 v, double x) { return v.x < x; });
  double best = eps;
  bool found = false;
  for (; it != sorted.end() && it->x <= p.x + eps; ++it) {
    const double d = std::max(std::fabs(it->x - p.x), std::fabs(it->y - p.y));
    if (d <= best) {
      best = d;
      out = *it;
      found = true;
    }
  }
  return found;
}

// Many cuts: the vertices sorted by x, each cut looked up there. First onto
// existing vertices (all of them, whatever the order of discovery), then the
// remaining cut points onto each other.
void snap_many_cuts(std::vector<Cut>& cuts, double eps, ResolveScratch& scratch) {
  std::vector<Vec2>& vertices = scratch.vertices;
  std::sort(vertices.begin(), vertices.end(), by_x);
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  for (std::size_t k = 0; k < cuts.size(); ++k) {
    Vec2 v;
    if (nearest_sorted(vertices, cuts[k].p, eps, v)) {
      cuts[k].p = v;
    } else {
      scratch.loose.push_back({cuts[k].p, k});
    }
  }
  snap_loose(cuts, scratch, [&](Vec2 p, Vec2& out) { return nearest_sorted(scratch.representatives, p, eps, out); });
}

// Crossing points computed from different pairs of lines through one point
// differ in their last bits; left apart they make slivers and zero-length
// loops. Cut points closer than the merge distance to an end point of any
// edge become that end point, and to each other the first of them (the merge
// distance is 1e-12 of the outline's size or largest coordinate, far above the
// rounding error of a crossing of lines that are not nearly parallel).
void snap_cuts(const std::vector<Edge>& edges, std::vector<Cut>& cuts, ResolveScratch& scratch) {
  std::vector<Vec2>& vertices = scratch.vertices;
  vertices.clear();
  Box all;
  for (const Edge& e : edges) {
    vertices.push_back(e.a);
    vertices.push_back(e.b);
    all.add(e.a);
    all.add(e.b);
  }
  const double extent = std::max(all.max.x - all.min.x, all.max.y - all.min.y);
  const double largest =
      std::max({std::fabs(all.min.x), std::fabs(all.min.y), std::fabs(all.max.x), std::fabs(all.max.y)});
  const double eps = tolerance::kMergeDistanceRelative * std::max(extent, largest);
  scratch.loose.clear();
  if (cuts.size() <= 16) {
    snap_few_cuts(cuts, eps, scratch);
  } else {
    snap_many_cuts(cuts, eps, scratch);
  }
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

// Splits line edges at the cut points found on them (line_pair_cuts), after
// snapping the points together (snap_cuts). The pieces of a split edge are
// fresh; other edges keep their flag. Returns true when some edge was split.
bool split_at_cuts(std::vector<Edge>& edges, std::vector<Cut>& cuts, ResolveScratch& scratch) {
  if (cuts.empty()) return false;
  std::vector<Vec2>& along = scratch.along;
  std::vector<Edge>& next = scratch.split_edges;
  snap_cuts(edges, cuts, scratch);
  // Each edge's cuts together, in the order found.
  std::stable_sort(cuts.begin(), cuts.end(), [](const Cut& a, const Cut& b) { return a.edge < b.edge; });
  next.clear();
  next.reserve(edges.size() + cuts.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < edges.size(); ++i) {
    if (k == cuts.size() || cuts[k].edge != i) {
      next.push_back(edges[i]);
      continue;
    }
    const Edge& e = edges[i];
    const Vec2 dir = e.b - e.a;
    along.clear();
    for (; k < cuts.size() && cuts[k].edge == i; ++k) along.push_back(cuts[k].p);
    std::sort(along.begin(), along.end(), [&](Vec2 p, Vec2 q) { return dot(p - e.a, dir) < dot(q - e.a, dir); });
    along.erase(std::unique(along.begin(), along.end()), along.end());
    Vec2 from = e.a;
    along.push_back(e.b);
    for (const Vec2 p : along) {
      if (p == from) continue;
      Edge piece = e;
      piece.a = from;
      piece.b = p;
      piece.box = edge_box(piece);
      piece.fresh = true;
      next.push_back(piece);
      from = p;
    }
  }
  edges.swap(next);
  return true;
}

// Coincident edges become one with the sum of their directed counts; edges
// whose count cancels (a contour running back over another) disappear. Each
// edge is directed from its smaller end and looked up in a hash table of the
// edges kept so far: the merged edges come in the order of their first
// occurrence.
void merge_coincident(const std::vector<Edge>& edges, std::vector<Edge>& merged, std::vector<std::int32_t>& slots) {
  auto same_key = [](const Edge& e, const Edge& f) {
    return e.a == f.a && e.b == f.b && e.conic == f.conic &&
           (!e.conic || (e.control == f.control && e.weight == f.weight));
  };
  merged.clear();
  merged.reserve(edges.size());
  const int bits = position_table_bits(edges.size());
  slots.assign(std::size_t{1} << bits, -1);
  const std::size_t mask = (std::size_t{1} << bits) - 1;
  for (const Edge& e0 : edges) {
    Edge e = e0;
    if (std::make_pair(e.b.x, e.b.y) < std::make_pair(e.a.x, e.a.y)) {
      std::swap(e.a, e.b);
      e.count = -e.count;
    }
    if (e.a == e.b) continue;
    std::size_t slot = (position_hash(canonical(e.a), bits) ^ position_hash(canonical(e.b), bits) * 3) & mask;
    for (;; slot = (slot + 1) & mask) {
      const std::int32_t k = slots[slot];
      if (k < 0) {
        slots[slot] = static_cast<std::int32_t>(merged.size());
        merged.push_back(e);
        break;
      }
      if (same_key(merged[static_cast<std::size_t>(k)], e)) {
        merged[static_cast<std::size_t>(k)].count += e.count;
        break;
      }
    }
  }
  merged.erase(std::remove_if(merged.begin(), merged.end(), [](const Edge& e) { return e.count == 0; }), merged.end());
}

// Angular order of directions from a common vertex v (exact: signs of
// coordinate differences are exact in floating point, cross signs by orient2d).
bool angle_less(Vec2 v, Vec2 p, Vec2 q) {
  auto half = [v](Vec2 r) { return (r.y < v.y || (r.y == v.y && r.x < v.x)) ? 1 : 0; };
  const int hp = half(p), hq = half(q);
  if (hp != hq) return hp < hq;
  return orient2d(v, p, q) > 0;
}

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
            [&](std::uint32_t x, std::uint32_t y) { return angle_less(v, other_end(x), other_end(y)); });
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

void side_windings(const std::vector<Edge>& edges, std::vector<int>& left, std::vector<int>& right,
                   ResolveScratch& scratch) {
  SideWindings(edges, left, right, scratch).run();
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
  CrossingResolver(HullState hulls, std::size_t max_pieces, RingPool& pool, ResolveScratch& scratch)
      : hulls_separated_(hulls == HullState::Separated), max_pieces_(max_pieces), pool_(pool), s_(scratch) {}

  std::vector<Ring> run(const std::vector<Ring>& rings, bool* settled);

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
  const std::size_t max_pieces_;
  RingPool& pool_;
  ResolveScratch& s_;
  std::vector<Edge> edges_;
  std::vector<char> marked_;  // conics in conflict, to be halved
  std::vector<Edge> next_;
};

std::vector<Ring> CrossingResolver::run(const std::vector<Ring>& rings, bool* settled) {
  // Coincident edges (a path that retraces itself, contours sharing edges)
  // are merged first: n runs over one edge are one edge with a count, not
  // n^2 / 2 pairs to cut.
  merge_coincident(edges_of(rings), edges_, s_.slots);
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
// there are at most kMaxHullSubdivisionDepth + 2 of them; line splits settle
// in a few rounds (the cap is generous). Returns true when conflicts were
// left when the rounds ran out.
bool CrossingResolver::remove_conflicts() {
  constexpr int kMaxConicRounds = tolerance::kMaxHullSubdivisionDepth + 2;
  constexpr int kMaxRounds = 4 * (kMaxConicRounds + 1);
  int conic_rounds = 0;
  for (int round = 0; round < kMaxRounds; ++round) {
    if (!find_conflicts(round)) {
      // (The last round's cuts are still made, not looked at again.)
      if (!split_at_cuts(edges_, s_.cuts, s_)) return false;
      within_budget("crossing resolution (edges)", edges_.size());
      continue;
    }
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
    const bool l = s_.left[i] != 0, r = s_.right[i] != 0;
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
    if (best_any == UINT32_MAX || angle_less(v, kept[best_any].b, p)) best_any = o;
    if (angle_less(v, p, in.a) && (best_before == UINT32_MAX || angle_less(v, kept[best_before].b, p))) {
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

std::vector<Ring> resolve_crossings(const std::vector<Ring>& rings, HullState hulls, std::size_t max_pieces,
                                    RingPool& pool, ResolveScratch& scratch, bool* settled) {
  return CrossingResolver(hulls, max_pieces, pool, scratch).run(rings, settled);
}

}  // namespace curvetext::detail
