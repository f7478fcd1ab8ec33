// Cleaning: outline contours -> rings without degenerate pieces
// (cleaning.hpp), and the coordinate rule of tolerance::kFlushCoordinate*.
#include "tessellate/cleaning.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <map>
#include <utility>
#include <vector>

#include "core/assert.hpp"
#include "curvetext/curves.hpp"
#include "core/tolerances.hpp"
#include "tessellate/positions.hpp"
#include "tessellate/predicates.hpp"

namespace curvetext {
namespace detail {

namespace {

// Within the flatness tolerance of its chord. A conic's farthest point from
// the chord's line, its shoulder, is w / (1 + w) of the control point's
// distance from that line: a weight near 0 flattens the curve onto its chord
// wherever the control point is (and its hull would be split into degenerate
// pieces). The control point's own distance is the bound for w >= 1.
bool nearly_flat(Vec2 a, Vec2 control, Vec2 b, double weight) {
  const Vec2 chord = b - a;
  const double len2 = dot(chord, chord);
  const double shoulder = weight >= 1.0 ? 1.0 : 2.0 * weight / (1.0 + weight);
  return std::fabs(cross(control - a, chord)) * shoulder <= tolerance::kConicFlatnessRelative * len2 ||
         orient2d(a, control, b) == 0;
}

// A conic of weight above 1 whose shoulder, (m - c) / (1 + w) from its
// control point c (m the chord's middle), is within the flatness tolerance of
// c: the curve is its two legs (a huge weight would split into hulls of zero
// area).
bool hugs_its_legs(const Segment& s) {
  if (!(s.weight > 1.0)) return false;
  const Vec2 chord = s.p[2] - s.p[0], to_middle = 0.5 * (s.p[0] + s.p[2]) - s.p[1];
  const double reach = tolerance::kConicFlatnessRelative * (1.0 + s.weight);
  return dot(to_middle, to_middle) <= reach * reach * dot(chord, chord);
}

// Two consecutive lines with directions ab and bc that go back along
// themselves: a spike, within the flatness tolerance.
bool folds_back(Vec2 ab, Vec2 bc) {
  return dot(ab, bc) < 0.0 &&
         std::fabs(cross(ab, bc)) <= tolerance::kConicFlatnessRelative * std::max(dot(ab, ab), dot(bc, bc));
}

// Whether simplify_pass would change the ring: its three tests (a
// zero-length piece, a flat conic, two lines in a row on one line or folding
// back) in one loop, for the usual ring, which needs none of them.
bool needs_simplifying(const Ring& ring, double merge2) {
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = i + 1 == n ? 0 : i + 1;
    const Vec2 a = ring[i].a, b = ring[j].a;
    const Vec2 ab = b - a;
    if (dot(ab, ab) <= merge2) return true;
    if (ring[i].conic) {
      if (nearly_flat(a, ring[i].control, b, ring[i].weight)) return true;
      continue;
    }
    if (ring[j].conic) continue;
    const Vec2 c = ring_end(ring, j), bc = c - b;
    if (orient2d(a, b, c) == 0 || folds_back(ab, bc)) return true;
  }
  return false;
}

// One pass of local simplifications; returns true when something changed.

// Removes zero-length pieces (repeated points, conics that return to their
// start). Compacted in place; piece i ends where piece i + 1 starts, which is
// not yet overwritten, except the wrap-around to piece 0, kept aside.
bool drop_zero_length_pieces(Ring& ring, double merge2) {
  bool changed = false;
  const Vec2 first = ring.empty() ? Vec2{} : ring[0].a;
  std::size_t kept = 0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Vec2 d = (i + 1 < ring.size() ? ring[i + 1].a : first) - ring[i].a;
    if (dot(d, d) <= merge2) {
      changed = true;
      continue;
    }
    CURVETEXT_ASSERT(kept <= i);          // the write index never passes the read index
    if (kept != i) ring[kept] = ring[i];  // (the usual ring: nothing moves)
    ++kept;
  }
  ring.resize(kept);
  return changed;
}

// Conics whose control point is on (or within the flatness tolerance of) the
// chord's line. Inside the chord span the curve is the chord. Outside it the
// curve runs past an end point and comes back along the same line: it traces
// a zero-width spike that encloses no area, so for the nonzero fill the conic
// is again equivalent to its chord (the spike is not part of any region).
bool straighten_flat_conics(Ring& ring, bool& approximated) {
  bool changed = false;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    Piece& p = ring[i];
    if (p.conic && nearly_flat(p.a, p.control, ring_end(ring, i), p.weight)) {
      approximated = approximated || orient2d(p.a, p.control, ring_end(ring, i)) != 0;
      p.conic = false;
      p.weight = 1.0;
      changed = true;
    }
  }
  return changed;
}

// Consecutive lines: exactly collinear and going on -> one line; going back
// (a spike, within the flatness tolerance) -> the spike tip is removed.
bool merge_straight_runs(Ring& ring, bool& approximated, std::vector<char>& drop) {
  if (ring.size() < 2) return false;
  const std::size_t n = ring.size();
  drop.assign(n, 0);
  bool any_dropped = false;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = i + 1 == n ? 0 : i + 1;
    const std::size_t after_j = j + 1 == n ? 0 : j + 1;
    // At the wrap-around the piece after j may already be gone, which would
    // change where j ends; leave that pair to the next pass.
    if (ring[i].conic || ring[j].conic || drop[i] || drop[j] || drop[after_j]) continue;
    const Vec2 a = ring[i].a, b = ring[j].a, c = ring_end(ring, j);
    const int turn = orient2d(a, b, c);
    if (turn == 0 || folds_back(b - a, c - b)) {
      approximated = approximated || turn != 0;
      drop[j] = 1;  // the piece starting at b disappears; piece i now ends at c
      any_dropped = true;
    }
  }
  if (!any_dropped) return false;
  std::size_t kept = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (!drop[i]) ring[kept++] = ring[i];
  }
  ring.resize(kept);
  return true;
}

// One pass of local simplifications; returns true when something changed.
// `approximated` is set when a conic or a spike within the flatness
// tolerance, not exactly flat, was made straight (the area changes).
bool simplify_pass(Ring& ring, double merge2, bool& approximated, std::vector<char>& drop) {
  bool changed = drop_zero_length_pieces(ring, merge2);
  changed = straighten_flat_conics(ring, approximated) || changed;
  changed = merge_straight_runs(ring, approximated, drop) || changed;
  return changed;
}

// Every piece a line and every vertex on one line: a ring that encloses nothing.
bool all_collinear(const Ring& ring) {
  std::size_t k = 1;
  while (k < ring.size() && ring[k].a == ring[0].a) ++k;
  if (k == ring.size()) return true;
  for (const Piece& p : ring) {
    if (p.conic || orient2d(ring[0].a, ring[k].a, p.a) != 0) return false;
  }
  return true;
}

// A ring that encloses nothing and is dropped: a lone back-and-forth, or a
// flat run of lines. (A self-crossing ring, a bow-tie, can have zero signed
// area and still fill its lobes, which the crossing resolver sorts out. The
// cheap test first: the usual ring's second vertex is off the first line.)
bool encloses_nothing(const Ring& loop) {
  if (loop.size() < 2) return true;
  if (loop.size() == 2 && !loop[0].conic && !loop[1].conic) return true;
  return all_collinear(loop) && ring_area(loop) == 0.0;
}

// What a contour's segments become, piece by piece, with Outline::is_finite's
// test made on the points as they are read (a pass of its own over the
// outline cost more): x * 0 is 0 for finite x and NaN for an infinity or a
// NaN, and a NaN stays in `zero`. Every segment's start and end, controls and
// weight are taken.
class ContourReader {
 public:
  explicit ContourReader(std::vector<Segment>& quadratics) : quadratics_(quadratics) {}

  void read(const Contour& contour, double cubic_tolerance, Ring& ring) {
    for (const Segment& s : contour.segments) {
      if (s.kind != Segment::Kind::Cubic) {
        add_piece(ring, s);
        continue;
      }
      zero_ += (finite_term(s.p[0]) + finite_term(s.p[1])) + (finite_term(s.p[2]) + finite_term(s.p[3]));
      // What to_quadratic_outline would give, without copying the outline.
      quadratics_.clear();
      cubic_to_quadratics(s, cubic_tolerance, quadratics_);
      for (const Segment& q : quadratics_) add_piece(ring, q);
    }
  }

  bool finite() const { return zero_ == 0.0 && weights_ok_; }
  bool& approximated() { return approximated_; }

 private:
  static double finite_term(Vec2 p) { return p.x * 0.0 + p.y * 0.0; }

  void add_piece(Ring& ring, const Segment& s) {
    // Written in place (a temporary's copy would reload its bool and int
    // fields in wider loads, which stall; see append() in lib/curves/outline.cpp).
    if (s.kind == Segment::Kind::Conic && hugs_its_legs(s)) {
      zero_ += finite_term(s.p[0]) + finite_term(s.p[1]);
      ring.emplace_back().a = canonical(s.p[0]);
      ring.emplace_back().a = canonical(s.p[1]);
      approximated_ = true;
      return;
    }
    Piece& p = ring.emplace_back();
    p.a = canonical(s.p[0]);
    zero_ += finite_term(s.p[0]) + finite_term(s.p[1]);  // a line's start and end, a conic's start and control
    if (s.kind == Segment::Kind::Conic) {
      p.conic = true;
      p.control = canonical(s.p[1]);
      p.weight = s.weight;
      zero_ += finite_term(s.p[2]);
      weights_ok_ = weights_ok_ && s.weight > 0.0 && s.weight <= std::numeric_limits<double>::max();
    }
  }

  std::vector<Segment>& quadratics_;
  double zero_ = 0.0;
  bool weights_ok_ = true;
  bool approximated_ = false;
};

}  // namespace

// Splits a closed ring at every vertex it passes through more than once into
// closed sub-rings without repeated vertices (a checkerboard drawn as one
// contour that touches itself at cell corners becomes one ring per lobe).
// The pieces are kept as they are, so the sub-rings together trace exactly
// the original ring and the winding number of every point is unchanged: the
// nonzero fill of the sub-rings is the fill of the ring. Each sub-ring keeps
// the orientation it has, and nest_rings decides its role (outer, hole, or
// neither) by the nonzero rule like for any other ring. Sub-rings of contours
// that do not cross only touch at the split vertices; the ear clipper then
// never sees a pinch vertex inside one ring, where its local ear tests cannot
// tell which lobe a triangle would cover.
//
// Walk the pieces keeping the open path on a stack; when a piece starts at a
// vertex already on the stack, the pieces since that vertex form a closed
// loop: cut it off. What remains at the end starts and ends at ring[0].a.

// A piece whose start is not the first at its position, in one pass over a
// hash table.
namespace {

bool same_curve(const Piece& p, const Piece& q) {
  return p.conic == q.conic && (!p.conic || (p.control == q.control && p.weight == q.weight));
}

// Ring b run from piece sb is ring a run from piece sa (equal sizes).
bool runs_alike(const Ring& a, std::size_t sa, const Ring& b, std::size_t sb) {
  const std::size_t n = a.size();
  for (std::size_t k = 0; k < n; ++k) {
    const Piece &p = a[(sa + k) % n], &q = b[(sb + k) % n];
    if (p.a != q.a || !same_curve(p, q)) return false;
  }
  return true;
}

// Ring b run backwards, from the piece ending at b[sb].a, is ring a run from
// piece sa (equal sizes; a[sa].a == b[sb].a).
bool runs_reversed(const Ring& a, std::size_t sa, const Ring& b, std::size_t sb) {
  const std::size_t n = a.size();
  for (std::size_t k = 0; k < n; ++k) {
    const std::size_t i = (sa + k) % n, j = (sb + 2 * n - 1 - k) % n;
    if (ring_end(a, i) != b[j].a || !same_curve(a[i], b[j])) return false;
  }
  return true;
}

// The index of the piece starting at the ring's lowest point (least y, then
// least x), or SIZE_MAX when the ring passes through that point twice.
std::size_t lowest_start(const Ring& ring) {
  std::size_t best = 0;
  bool tie = false;
  for (std::size_t i = 1; i < ring.size(); ++i) {
    const Vec2 p = ring[i].a, q = ring[best].a;
    if (p == q) tie = true;
    if (p.y < q.y || (p.y == q.y && p.x < q.x)) {
      best = i;
      tie = false;
    }
  }
  return tie ? SIZE_MAX : best;
}

// A ring through its lowest point twice may be one path run round more than
// once: its loops are what can be equal, so it is split into them.
void split_laps(std::vector<Ring>& rings, RingPool& pool, CleanScratch& scratch) {
  const std::size_t original = rings.size();
  for (std::size_t r = 0; r < original; ++r) {
    if (rings[r].size() < 4 || lowest_start(rings[r]) != SIZE_MAX) continue;
    std::vector<Ring> loops = split_at_repeated_vertices(rings[r], scratch.slots);
    if (loops.empty()) continue;
    pool.recycle(std::move(rings[r]));
    rings[r] = std::move(loops.front());
    for (std::size_t k = 1; k < loops.size(); ++k) rings.push_back(std::move(loops[k]));
  }
}

// Rings whose count is 0 (folded into another, or cancelled) leave; rings
// run once either way need no count (a ring run backwards once is that ring
// reversed), and then `counts` is cleared.
void drop_folded(std::vector<Ring>& rings, std::vector<int>& counts, RingPool& pool) {
  std::size_t kept = 0;
  for (std::size_t r = 0; r < rings.size(); ++r) {
    if (counts[r] == 0) {
      pool.recycle(std::move(rings[r]));
      continue;
    }
    if (kept != r) {
      rings[kept] = std::move(rings[r]);
      counts[kept] = counts[r];
    }
    ++kept;
  }
  rings.resize(kept);
  counts.resize(kept);
  if (std::all_of(counts.begin(), counts.end(), [](int c) { return c == 1 || c == -1; })) {
    for (std::size_t r = 0; r < rings.size(); ++r)
      if (counts[r] == -1) reverse_ring(rings[r]);
    counts.clear();
  }
}

}  // namespace

bool fold_repeated_rings(std::vector<Ring>& rings, std::vector<int>& counts, RingPool& pool, CleanScratch& scratch) {
  counts.clear();
  std::size_t pieces = 0;
  for (const Ring& ring : rings) pieces += ring.size();
  if (pieces < tolerance::kFoldRingsMinPieces) return false;
  split_laps(rings, pool, scratch);
  if (rings.size() < 2) return false;
  using Key = CleanScratch::RingKey;
  std::vector<Key>& keys = scratch.ring_keys;
  keys.clear();
  for (std::size_t r = 0; r < rings.size(); ++r) {
    const std::size_t start = lowest_start(rings[r]);
    if (start != SIZE_MAX) keys.push_back({rings[r].size(), start, r, rings[r][start].a});
  }
  // Equal rings have equal sizes and lowest points: only those are compared.
  auto less = [](const Key& u, const Key& v) {
    if (u.size != v.size) return u.size < v.size;
    if (u.lowest.y != v.lowest.y) return u.lowest.y < v.lowest.y;
    if (u.lowest.x != v.lowest.x) return u.lowest.x < v.lowest.x;
    return u.ring < v.ring;
  };
  std::sort(keys.begin(), keys.end(), less);
  bool folded = false;
  counts.assign(rings.size(), 1);
  for (std::size_t first = 0; first < keys.size();) {
    std::size_t last = first + 1;
    while (last < keys.size() && keys[last].size == keys[first].size && keys[last].lowest == keys[first].lowest) ++last;
    // Each ring of the run joins the first earlier one it equals (in either direction).
    for (std::size_t k = first + 1; k < last; ++k) {
      const Ring& ring = rings[keys[k].ring];
      for (std::size_t m = first; m < k; ++m) {
        if (keys[m].size == 0) continue;  // folded into another
        const Ring& other = rings[keys[m].ring];
        const int sign = runs_alike(other, keys[m].start, ring, keys[k].start)      ? 1
                         : runs_reversed(other, keys[m].start, ring, keys[k].start) ? -1
                                                                                    : 0;
        if (sign == 0) continue;
        counts[keys[m].ring] += sign;
        counts[keys[k].ring] = 0;
        keys[k].size = 0;  // folded: no later ring joins it
        folded = true;
        break;
      }
    }
    first = last;
  }
  if (!folded) {
    counts.clear();
    return false;
  }
  drop_folded(rings, counts, pool);
  return true;
}

bool repeats_a_vertex(const Ring& ring, std::vector<std::int32_t>& slots) {
  FirstAtPosition starts(slots, ring.size(), [&](std::uint32_t i) { return ring[i].a; });
  for (std::uint32_t i = 0; i < ring.size(); ++i)
    if (starts.add(i) != i) return true;
  return false;
}

std::vector<Ring> split_at_repeated_vertices(const Ring& ring, std::vector<std::int32_t>& slots) {
  std::vector<Ring> loops;
  // The usual ring passes through each vertex once: nothing to split.
  if (!repeats_a_vertex(ring, slots)) {
    loops.push_back(ring);
    return loops;
  }
  Ring path;
  path.reserve(ring.size());
  std::map<std::pair<double, double>, std::size_t> position;  // vertex -> index in path
  for (const Piece& piece : ring) {
    const std::pair<double, double> key{piece.a.x, piece.a.y};
    const auto found = position.find(key);
    if (found != position.end()) {
      const std::size_t k = found->second;
      for (std::size_t m = k + 1; m < path.size(); ++m) position.erase({path[m].a.x, path[m].a.y});
      loops.emplace_back(path.begin() + static_cast<std::ptrdiff_t>(k), path.end());
      path.resize(k);
    }
    position[key] = path.size();
    path.push_back(piece);
  }
  if (!path.empty()) loops.push_back(std::move(path));
  return loops;
}

double ring_area(const Ring& ring) {
  double area = 0.0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Vec2 a = ring[i].a, b = ring_end(ring, i);
    area += 0.5 * cross(a, b);
    if (ring[i].conic) {
      // The arc adds the area between chord and arc when it bulges to the
      // right of a->b (the exterior of a counter-clockwise ring).
      // (Weight 1, every glyph's conic: the ratio is 2/3, as conic_area_ratio
      // returns it, without the call.)
      const double ratio = ring[i].weight == 1.0 ? 2.0 / 3.0 : conic_area_ratio(ring[i].weight);
      area += ratio * 0.5 * cross(ring[i].control - a, b - a);
    }
  }
  return area;
}

Ring RingPool::take() {
  if (spare_.empty()) return Ring();
  Ring ring = std::move(spare_.back());
  spare_.pop_back();
  ring.clear();
  return ring;
}

void RingPool::recycle(Ring&& ring) {
  // A glyph uses a few rings at a time; the crossing resolver makes new ones
  // that come back here too, so the pool is capped (beyond it rings are freed).
  constexpr std::size_t kMaxSpareRings = 64;
  if (ring.capacity() != 0 && spare_.size() < kMaxSpareRings) spare_.push_back(std::move(ring));
}

void RingPool::recycle_all(std::vector<Ring>& rings) {
  for (Ring& ring : rings) recycle(std::move(ring));
  rings.clear();
}

bool clean_rings(const Outline& outline, double cubic_tolerance, double merge_distance, std::vector<Ring>& rings,
                 RingPool& pool, CleanScratch& scratch, RepeatedVertices repeated, bool* approximated) {
  pool.recycle_all(rings);
  ContourReader reader(scratch.quadratics);
  const double merge2 = merge_distance * merge_distance;
  for (const Contour& contour : outline.contours()) {
    Ring ring = pool.take();
    ring.reserve(contour.segments.size());
    reader.read(contour, cubic_tolerance, ring);
    // Each pass shrinks the ring or stops the loop; the cap only matters for
    // adversarial input, where leftovers are handled by the ear clipper.
    // (The first pass's tests in one loop: the usual ring needs no pass.)
    if (ring.size() >= 2 && needs_simplifying(ring, merge2)) {
      for (int pass = 0;
           pass < 16 && ring.size() >= 2 && simplify_pass(ring, merge2, reader.approximated(), scratch.drop); ++pass) {
      }
    }
    // Split after simplifying: simplification only deletes vertices, so it
    // cannot create new repeats, while the sub-rings are not simplified again
    // because merging a straight run through a split vertex would leave that
    // vertex in the middle of an edge of the sub-ring, a T-junction against
    // the other sub-ring that touches it there. The usual ring passes through
    // each vertex once: kept as it is, without the copy
    // split_at_repeated_vertices would make.
    if (repeated == RepeatedVertices::Keep || !repeats_a_vertex(ring, scratch.slots)) {
      if (!encloses_nothing(ring)) rings.push_back(std::move(ring));
    } else {
      for (Ring& loop : split_at_repeated_vertices(ring, scratch.slots))
        if (!encloses_nothing(loop)) rings.push_back(std::move(loop));
    }
    pool.recycle(std::move(ring));  // (when not kept)
  }
  if (approximated != nullptr) *approximated = reader.approximated();
  return reader.finite();
}

// --- Coordinates -------------------------------------------------------------------

namespace {

int point_count(const Segment& s) { return s.kind == Segment::Kind::Line ? 2 : s.kind == Segment::Kind::Conic ? 3 : 4; }

}  // namespace

bool flush_tiny_coordinates(const Outline& outline, Outline& flushed, double& largest) {
  largest = 0.0;
  double smallest = std::numeric_limits<double>::infinity();
  for (const Contour& contour : outline.contours()) {
    for (const Segment& s : contour.segments) {
      for (int k = 0; k < point_count(s); ++k) {
        for (const double c : {std::fabs(s.p[k].x), std::fabs(s.p[k].y)}) {
          // (std::fmax's and fmin's results, NaN skipped, without their calls
          // into libm: a third of this scan's time.)
          largest = c > largest ? c : largest;
          smallest = c > 0.0 && c < smallest ? c : smallest;
        }
      }
    }
  }
  const double flush = std::fmax(tolerance::kFlushCoordinateRelative * largest, tolerance::kFlushCoordinateAbsolute);
  if (!(smallest < flush)) return false;
  flushed = outline;
  for (Contour& contour : flushed.contours()) {
    for (Segment& s : contour.segments) {
      for (int k = 0; k < point_count(s); ++k) {
        if (std::fabs(s.p[k].x) < flush) s.p[k].x = 0.0;
        if (std::fabs(s.p[k].y) < flush) s.p[k].y = 0.0;
      }
    }
  }
  return true;
}

}  // namespace detail
}  // namespace curvetext
