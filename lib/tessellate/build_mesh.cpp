// build_mesh: outline -> cleaned rings -> separated hulls -> (crossing,
// overlapping or edge-sharing contours only: resolve.cpp's non-crossing rings
// of the nonzero fill, hulls separated again unless the resolver left nothing
// in conflict) -> orientation -> polygon
// loops + curved triangles -> triangles -> Lawson flips -> indexed mesh
// (DESIGN.md section 4, paper 3.1). Loops that neither cross nor touch (the
// usual glyph) are triangulated by one plane sweep (sweep.cpp), first with
// every ring oriented by the outermost one, which the sweep checks; where it
// gives up, the rings are nested and oriented one by one (nest_rings) and
// swept again, or bridged and ear-clipped (triangulate.cpp).
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <map>
#include <new>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <utility>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "curvetext/curves.hpp"
#include "curvetext/error.hpp"
#include "curvetext/mesh.hpp"
#include "core/tolerances.hpp"
#include "tessellate/columns.hpp"
#include "tessellate/positions.hpp"
#include "tessellate/predicates.hpp"
#include "tessellate/rings.hpp"
#include "tessellate/stage_timing.hpp"
#include "tessellate/triangulate.hpp"

namespace curvetext {
namespace detail {

// --- Cleaning -------------------------------------------------------------------

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
// `approximated` is set when a conic or a spike within the flatness
// tolerance, not exactly flat, was made straight (the area changes).
bool simplify_pass(Ring& ring, double merge2, bool& approximated) {
  bool changed = false;
  // Zero-length pieces (repeated points, conics that return to their start).
  // Compacted in place; piece i ends where piece i + 1 starts, which is not
  // yet overwritten (the write index never passes the read index), except
  // the wrap-around to piece 0, kept aside.
  {
    const Vec2 first = ring.empty() ? Vec2{} : ring[0].a;
    std::size_t kept = 0;
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Vec2 d = (i + 1 < ring.size() ? ring[i + 1].a : first) - ring[i].a;
      if (dot(d, d) <= merge2) {
        changed = true;
        continue;
      }
      if (kept != i) ring[kept] = ring[i];  // (the usual ring: nothing moves)
      ++kept;
    }
    ring.resize(kept);
  }
  // Conics whose control point is on (or within the flatness tolerance of) the
  // chord's line. Inside the chord span the curve is the chord. Outside it the
  // curve runs past an end point and comes back along the same line: it traces
  // a zero-width spike that encloses no area, so for the nonzero fill the conic
  // is again equivalent to its chord (the spike is not part of any region).
  for (std::size_t i = 0; i < ring.size(); ++i) {
    Piece& p = ring[i];
    if (p.conic && nearly_flat(p.a, p.control, ring_end(ring, i), p.weight)) {
      approximated = approximated || orient2d(p.a, p.control, ring_end(ring, i)) != 0;
      p.conic = false;
      p.weight = 1.0;
      changed = true;
    }
  }
  // Consecutive lines: exactly collinear and going on -> one line; going back
  // (a spike, within the flatness tolerance) -> the spike tip is removed.
  if (ring.size() >= 2) {
    thread_local std::vector<char> drop;  // scratch, reused across calls
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
    if (any_dropped) {
      changed = true;
      std::size_t kept = 0;
      for (std::size_t i = 0; i < n; ++i) {
        if (!drop[i]) ring[kept++] = ring[i];
      }
      ring.resize(kept);
    }
  }
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

namespace {

// True when the ring passes through some vertex twice: a piece whose start
// is not the first at its position, in one pass over a hash table.
bool repeats_a_vertex(const Ring& ring) {
  thread_local std::vector<std::int32_t> slots;  // scratch
  FirstAtPosition starts(slots, ring.size(), [&](std::uint32_t i) { return ring[i].a; });
  for (std::uint32_t i = 0; i < ring.size(); ++i)
    if (starts.add(i) != i) return true;
  return false;
}

}  // namespace

std::vector<Ring> split_at_repeated_vertices(const Ring& ring) {
  std::vector<Ring> loops;
  // The usual ring passes through each vertex once: nothing to split.
  if (!repeats_a_vertex(ring)) {
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

namespace {

std::vector<Ring>& spare_rings() {
  thread_local std::vector<Ring> spare;
  return spare;
}

}  // namespace

Ring take_ring() {
  std::vector<Ring>& spare = spare_rings();
  if (spare.empty()) return Ring();
  Ring ring = std::move(spare.back());
  spare.pop_back();
  ring.clear();
  return ring;
}

void recycle_ring(Ring&& ring) {
  // A glyph uses a few rings at a time; the crossing resolver makes new ones
  // that come back here too, so the pool is capped (beyond it rings are freed).
  constexpr std::size_t kMaxSpareRings = 64;
  std::vector<Ring>& spare = spare_rings();
  if (ring.capacity() != 0 && spare.size() < kMaxSpareRings) spare.push_back(std::move(ring));
}

void recycle_rings(std::vector<Ring>& rings) {
  for (Ring& ring : rings) recycle_ring(std::move(ring));
  rings.clear();
}

bool clean_rings(const Outline& outline, double cubic_tolerance, double merge_distance, std::vector<Ring>& rings,
                 bool split_repeated, bool* approximated) {
  recycle_rings(rings);
  bool approximated_any = false;
  thread_local std::vector<Segment> quadratics;  // scratch: one cubic's replacement
  // Outline::is_finite's test, made here on the points as they are read
  // (a pass of its own over the outline cost more): x * 0 is 0 for finite x
  // and NaN for an infinity or a NaN, and a NaN stays in the sum. Every
  // segment's start and end, controls and weight are taken.
  double zero = 0.0;
  bool weights_ok = true;
  auto finite_term = [](Vec2 p) { return p.x * 0.0 + p.y * 0.0; };
  auto add_piece = [&](Ring& ring, const Segment& s) {
    // Written in place (a temporary's copy would reload its bool and int
    // fields in wider loads, which stall; see append() in lib/curves/outline.cpp).
    if (s.kind == Segment::Kind::Conic && hugs_its_legs(s)) {
      zero += finite_term(s.p[0]) + finite_term(s.p[1]);
      ring.emplace_back().a = canonical(s.p[0]);
      ring.emplace_back().a = canonical(s.p[1]);
      approximated_any = true;
      return;
    }
    Piece& p = ring.emplace_back();
    p.a = canonical(s.p[0]);
    zero += finite_term(s.p[0]) + finite_term(s.p[1]);  // a line's start and end, a conic's start and control
    if (s.kind == Segment::Kind::Conic) {
      p.conic = true;
      p.control = canonical(s.p[1]);
      p.weight = s.weight;
      zero += finite_term(s.p[2]);
      weights_ok = weights_ok && s.weight > 0.0 && s.weight <= std::numeric_limits<double>::max();
    }
  };
  for (const Contour& contour : outline.contours()) {
    Ring ring = take_ring();
    ring.reserve(contour.segments.size());
    for (const Segment& s : contour.segments) {
      if (s.kind != Segment::Kind::Cubic) {
        add_piece(ring, s);
        continue;
      }
      zero += (finite_term(s.p[0]) + finite_term(s.p[1])) + (finite_term(s.p[2]) + finite_term(s.p[3]));
      // What to_quadratic_outline would give, without copying the outline.
      quadratics.clear();
      cubic_to_quadratics(s, cubic_tolerance, quadratics);
      for (const Segment& q : quadratics) add_piece(ring, q);
    }
    // Each pass shrinks the ring or stops the loop; the cap only matters for
    // adversarial input, where leftovers are handled by the ear clipper.
    // (The first pass's tests in one loop: the usual ring needs no pass.)
    const double merge2 = merge_distance * merge_distance;
    if (ring.size() >= 2 && needs_simplifying(ring, merge2)) {
      for (int pass = 0; pass < 16 && ring.size() >= 2 && simplify_pass(ring, merge2, approximated_any); ++pass) {
      }
    }
    // Split after simplifying: simplification only deletes vertices, so it
    // cannot create new repeats, while the sub-rings are not simplified again
    // because merging a straight run through a split vertex would leave that
    // vertex in the middle of an edge of the sub-ring, a T-junction against
    // the other sub-ring that touches it there.
    auto keep = [&](Ring& loop) {
      if (loop.size() < 2) return;
      if (loop.size() == 2 && !loop[0].conic && !loop[1].conic) return;  // a lone back-and-forth: no area
      // A ring without area is dropped only when it is a flat run of lines:
      // a self-crossing ring (a bow-tie) can have zero signed area and still
      // fill its lobes, which the crossing resolver sorts out. (The cheap
      // test first: the usual ring's second vertex is off the first line.)
      if (kResolveCrossingContours ? all_collinear(loop) && ring_area(loop) == 0.0 : ring_area(loop) == 0.0) return;
      rings.push_back(std::move(loop));
    };
    // The usual ring passes through each vertex once: kept as it is, without
    // the copy split_at_repeated_vertices would make.
    if (!split_repeated || !repeats_a_vertex(ring)) {
      keep(ring);
    } else {
      for (Ring& loop : split_at_repeated_vertices(ring)) keep(loop);
    }
    recycle_ring(std::move(ring));  // (when not kept)
  }
  if (approximated != nullptr) *approximated = approximated_any;
  return zero == 0.0 && weights_ok;
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
          largest = std::fmax(largest, c);
          if (c > 0.0) smallest = std::fmin(smallest, c);
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

// --- Hull separation --------------------------------------------------------------

namespace {

bool in_closed_hull(const Vec2* hull, int n, Vec2 p) {
  if (n == 2) return point_on_segment(hull[0], hull[1], p);
  return point_in_triangle(hull[0], hull[1], hull[2], p) != Where::Outside;
}

bool triangle_interiors_intersect(const Vec2* p, const Vec2* q) {
  // Separating axis theorem on the edges of both (convex) triangles; touching
  // (all on the closed outer side) counts as separated.
  auto separated_by_edges_of = [](const Vec2* t, const Vec2* other) {
    const int o = orient2d(t[0], t[1], t[2]);
    if (o == 0) return true;  // a degenerate triangle has no interior
    for (int k = 0; k < 3; ++k) {
      const Vec2 a = t[k], b = t[(k + 1) % 3];
      bool all_outside = true;
      for (int m = 0; m < 3 && all_outside; ++m) all_outside = orient2d(a, b, other[m]) * o <= 0;
      if (all_outside) return true;
    }
    return false;
  };
  return !separated_by_edges_of(p, q) && !separated_by_edges_of(q, p);
}

Piece conic_piece(const Segment& s, int depth) {
  Piece q;
  q.a = canonical(s.p[0]);
  q.control = canonical(s.p[1]);
  q.weight = s.weight;
  q.conic = true;
  q.depth = depth;
  return q;
}

// Curves tangent to a neighbour at a shared vertex (a conic leaving a line
// back along it, or two conics meeting in a cusp) keep their legs on one line
// however often they are subdivided: the hulls touch along that line and one
// hull's corner sits on the other's edge. Instead of subdividing, make the
// overlapping edges coincide exactly: split the line at the control point, or
// split the conic with the longer leg at the parameter where its new control
// point lands on the other conic's control point (then snapped to it, a move
// of a few ulps along the tangent line). Returns true when something changed.
bool align_tangent_legs(Ring& ring) {
  const std::size_t n = ring.size();
  if (n < 2) return false;
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t j = (i + 1) % n;  // piece i ends where piece j starts, at v
    Piece& first = ring[i];
    Piece& second = ring[j];
    if (!first.conic && !second.conic) continue;
    const Vec2 v = second.a;
    const Vec2 start = first.a, end = ring_end(ring, j);
    if (first.conic && !second.conic) {
      // Line v->end running back over the conic's last leg.
      if (point_on_segment(v, end, first.control) && first.control != v && first.control != end) {
        Piece tail = second;
        tail.a = first.control;
        tail.fresh = true;
        second.fresh = true;  // now ends at the control point
        ring.insert(ring.begin() + static_cast<std::ptrdiff_t>(j) + 1, tail);
        return true;
      }
      continue;
    }
    if (!first.conic && second.conic) {
      if (point_on_segment(start, v, second.control) && second.control != v && second.control != start) {
        Piece tail = first;
        tail.a = second.control;
        tail.fresh = true;
        first.fresh = true;  // now ends at the control point
        ring.insert(ring.begin() + static_cast<std::ptrdiff_t>(i) + 1, tail);
        return true;
      }
      continue;
    }
    const Vec2 ca = first.control, cb = second.control;
    // (The cheap dot test first: at a smooth join the controls lie on opposite
    // sides of v, exactly collinear, which orient2d only decides slowly.)
    if (ca == cb || dot(ca - v, cb - v) <= 0.0 || orient2d(ca, v, cb) != 0) continue;
    const double la = length(ca - v), lb = length(cb - v);
    if (la > lb) {
      // Split `first` (start -> v) at t so its last piece's control is cb.
      const double rho = lb / la, w = first.weight;
      const double t = w * (1.0 - rho) / (w * (1.0 - rho) + rho);
      if (!(t > 0.0 && t < 1.0)) continue;
      const auto halves = split(Segment::conic(start, ca, v, w), t);
      Piece head = conic_piece(halves.first, first.depth + 1);
      Piece tail = conic_piece(halves.second, first.depth + 1);
      tail.control = cb;
      ring[i] = head;
      ring.insert(ring.begin() + static_cast<std::ptrdiff_t>(i) + 1, tail);
      return true;
    }
    // Split `second` (v -> end) at t so its first piece's control is ca.
    const double rho = la / lb, w = second.weight;
    const double t = rho / (w * (1.0 - rho) + rho);
    if (!(t > 0.0 && t < 1.0)) continue;
    const auto halves = split(Segment::conic(v, cb, end, w), t);
    Piece head = conic_piece(halves.first, second.depth + 1);
    Piece tail = conic_piece(halves.second, second.depth + 1);
    head.control = ca;
    ring[j] = head;
    ring.insert(ring.begin() + static_cast<std::ptrdiff_t>(j) + 1, tail);
    return true;
  }
  return false;
}

}  // namespace

namespace {

// Filtered orientation sign: +1 / -1 when certain (orient2d's error bound),
// 0 when exactly collinear because c is a or b, 2 when undecided.
int certain_side(Vec2 a, Vec2 b, Vec2 c) {
  if (c == a || c == b) return 0;
  const double detleft = (a.x - c.x) * (b.y - c.y);
  const double detright = (a.y - c.y) * (b.x - c.x);
  const double det = detleft - detright;
  const double errbound = kOrient2dErrorBound * (std::fabs(detleft) + std::fabs(detright));
  if (det > errbound) return 1;
  if (-det > errbound) return -1;
  return 2;
}

// True when the line through edge (a, b) of hull `own` (whose other vertex
// `opposite` is strictly on one side) has every point of `other` strictly on
// the other side or equal to a or b: then the hulls share no point but common
// vertices (hulls_overlap would say false). Only certain signs count.
bool separates(Vec2 a, Vec2 b, int inner, const Vec2* other, int n) {
  for (int k = 0; k < n; ++k) {
    const int side = certain_side(a, b, other[k]);
    if (side == 2 || side == inner) return false;
  }
  return true;
}

// A quick, conservative "no" for hulls_overlap: a separating line along an
// edge of either hull, decided with filtered signs only. False means "not
// known", and the exact test decides.
bool hulls_clearly_apart(const Vec2* p, int np, const Vec2* q, int nq) {
  auto by_edges_of = [](const Vec2* t, int nt, const Vec2* other, int no) {
    if (nt == 2) {
      // A segment's own line separates when the other hull is strictly on one
      // side of it (shared end points aside).
      int side = 0;
      for (int k = 0; k < no; ++k) {
        const int s = certain_side(t[0], t[1], other[k]);
        if (s == 2) return false;
        if (s == 0) continue;
        if (side != 0 && s != side) return false;
        side = s;
      }
      return side != 0;
    }
    const int o = certain_side(t[0], t[1], t[2]);
    if (o != 1 && o != -1) return false;
    // The chord (t[2], t[0]) first: at a smooth join of consecutive pieces
    // the legs through the shared vertex are collinear with the neighbour's
    // (undecided), while the chord separates.
    return separates(t[2], t[0], o, other, no) || separates(t[0], t[1], o, other, no) ||
           separates(t[1], t[2], o, other, no);
  };
  // A conic's hull first, for the same reason.
  if (np == 2 && nq == 3) return by_edges_of(q, nq, p, np) || by_edges_of(p, np, q, nq);
  return by_edges_of(p, np, q, nq) || by_edges_of(q, nq, p, np);
}

}  // namespace

bool hulls_overlap(const Vec2* p, int np, const Vec2* q, int nq) {
  if (hulls_clearly_apart(p, np, q, nq)) return false;
  auto is_vertex_of = [](Vec2 v, const Vec2* hull, int n) {
    for (int k = 0; k < n; ++k) {
      if (hull[k] == v) return true;
    }
    return false;
  };
  for (int k = 0; k < nq; ++k) {
    if (!is_vertex_of(q[k], p, np) && in_closed_hull(p, np, q[k])) return true;
  }
  for (int k = 0; k < np; ++k) {
    if (!is_vertex_of(p[k], q, nq) && in_closed_hull(q, nq, p[k])) return true;
  }
  const int ep = np == 2 ? 1 : 3, eq = nq == 2 ? 1 : 3;
  for (int i = 0; i < ep; ++i) {
    for (int j = 0; j < eq; ++j) {
      if (segments_cross_properly(p[i], p[i + 1 == np ? 0 : i + 1], q[j], q[j + 1 == nq ? 0 : j + 1])) return true;
    }
  }
  return np == 3 && nq == 3 && triangle_interiors_intersect(p, q);
}

namespace {

// Certain sign of cross(x, y) for x and y differences from a common point v:
// that is orient2d(x + v, y + v, v), with orient2d's filter (Shewchuk's bound
// covers the rounding of the differences too); 0 when the filter cannot
// decide (or an overflow made the products infinite). Written without
// branches.
int certain_cross_sign(Vec2 x, Vec2 y) {
  const double left = x.x * y.y, right = x.y * y.x, det = left - right;
  const double errbound = kOrient2dErrorBound * (std::fabs(left) + std::fabs(right));
  return static_cast<int>(det > errbound) - static_cast<int>(-det > errbound);
}

// Consecutive pieces of a ring, p (a -> v, control c when a conic) and q
// (v -> b, control d): true when their hulls certainly meet only at v, so
// that their pair test would find nothing (no overlap, and for two lines no
// run along each other). A line through v separates them: p's chord (v, a)
// with b and d strictly on one side and c strictly on the other, or q's
// chord (v, b) likewise. At a glyph's smooth joins (legs on one line through
// v) and corners one of the two chords does. Decided in straight-line code
// from five signs: a ring's consecutive pairs are most of the pairs whose
// boxes meet, and the branches of the general test, taken in a data-dependent
// order, cost more than these few products. For a line p, c is taken as v,
// for a line q, d as b (their hulls' middle points: no select between points,
// which compiles to a branch on the piece kind); the conditions on a line's
// control are then not asked.
bool joint_apart(Vec2 a, Vec2 c, bool p_conic, Vec2 v, Vec2 d, bool q_conic, Vec2 b) {
  const Vec2 va = a - v, vb = b - v, vc = c - v, vd = d - v;
  const int ab = certain_cross_sign(va, vb);
  const int ad = certain_cross_sign(va, vd), ac = certain_cross_sign(va, vc);
  const int bc = certain_cross_sign(vb, vc), bd = certain_cross_sign(vb, vd);
  const bool by_p_chord = (ad == ab) & ((!p_conic) | (ac == -ab));
  const bool by_q_chord = ((!p_conic) | (bc == -ab)) & ((!q_conic) | (bd == ab));
  return (ab != 0) & (by_p_chord | by_q_chord);
}

// A piece's point and derivative at parameter t: a line a + t (b - a), or
// a conic N(t) / D(t), N = (1-t)^2 a + 2t(1-t) w c + t^2 b, D its weights.
void piece_at(const Vec2* h, int n, double w, double t, Vec2& point, Vec2& derivative) {
  if (n == 2) {
    derivative = h[1] - h[0];
    point = h[0] + derivative * t;
    return;
  }
  const double u = 1.0 - t;
  const Vec2 numerator = h[0] * (u * u) + h[1] * (2.0 * t * u * w) + h[2] * (t * t);
  const double denominator = u * u + 2.0 * t * u * w + t * t;
  const Vec2 numerator_d = ((h[1] * w - h[0]) * u + (h[2] - h[1] * w) * t) * 2.0;
  const double denominator_d = 2.0 * (w - 1.0) * (u - t);
  point = numerator / denominator;
  derivative = (numerator_d * denominator - numerator * denominator_d) / (denominator * denominator);
}

// Parameters t on p and s on q where their curves cross, for splitting both
// there. Asked only when their chords cross properly (exact signs), from
// the chords' crossing, by Newton's method on p(t) = q(s); accepted when the
// steps fall below 1e-12 with a conic's parameter in [1/64, 63/64] (no
// sliver of a curve next to its end: halving moves such a crossing inward)
// and a line's anywhere inside (halving the conic never moves the crossing
// along the line). Tangent curves (a singular step), curves that do not
// cross, and slow convergence give false: the pieces are then halved.
bool crossing_parameters(const Vec2* p, int np, double wp, const Vec2* q, int nq, double wq, double& t, double& s) {
  const Vec2 pa = p[0], pb = p[np - 1], qa = q[0], qb = q[nq - 1];
  if (orient2d(pa, pb, qa) * orient2d(pa, pb, qb) >= 0 || orient2d(qa, qb, pa) * orient2d(qa, qb, pb) >= 0)
    return false;
  const Vec2 r = pb - pa, d = qb - qa;
  const double denominator = cross(r, d);
  t = cross(qa - pa, d) / denominator;
  s = cross(qa - pa, r) / denominator;
  constexpr int kSteps = 12;
  constexpr double kSettled = 1e-12, kMargin = 1.0 / 64.0;
  for (int step = 0; step < kSteps; ++step) {
    Vec2 at_p, dp, at_q, dq;
    piece_at(p, np, wp, t, at_p, dp);
    piece_at(q, nq, wq, s, at_q, dq);
    const Vec2 gap = at_p - at_q;
    const double det = cross(dp, dq);
    if (!(std::fabs(det) > 0.0)) return false;
    const double dt = -cross(gap, dq) / det, ds = cross(dp, gap) / det;
    t += dt;
    s += ds;
    if (!(t > 0.0 && t < 1.0 && s > 0.0 && s < 1.0)) return false;
    if (std::fabs(dt) < kSettled && std::fabs(ds) < kSettled)
      return (np == 2 || (t >= kMargin && t <= 1.0 - kMargin)) && (nq == 2 || (s >= kMargin && s <= 1.0 - kMargin));
  }
  return false;
}

}  // namespace

// Up to this many pieces hull separation tests every pair's boxes instead
// of sorting them first (measured: as fast up to about 96 pieces, faster
// below).
constexpr std::size_t kAllPairsLimit = 64;
static_assert(kAllPairsLimit <= 64, "the all-pairs test reads one 64-bit block per piece");

std::size_t ear_clip_budget(std::size_t vertices) {
  return vertices * (vertices + tolerance::kEarClipVisitsPerVertex) + tolerance::kEarClipVisitsBase;
}

std::size_t mesh_work_budget(std::size_t pieces) {
  return tolerance::kMeshWorkPerPiece * pieces + tolerance::kMeshWorkBase;
}

void work_budget_exceeded(const char* stage, std::size_t used, std::size_t budget) {
  throw Error(ErrorCode::Geometry, std::string("build_mesh: ") + stage + " needs more than its work budget (" +
                                       std::to_string(used) + " > " + std::to_string(budget) +
                                       "): the outline is too degenerate to mesh");
}

bool separate_hulls(std::vector<Ring>& rings, bool* crossing, bool split_at_crossings, std::size_t max_pieces) {
  // A piece's hull with what the sweep needs, copied out of the rings so the
  // pair loop reads one compact array.
  struct HullRef {
    Box box;
    Vec2 hull[3];  // a, b (line) or a, control, b (conic)
    int n;         // 2 or 3
    int depth;
    double weight;
    std::size_t mark;  // index into split_marks
    Vec2 end() const { return hull[n - 1]; }
  };
  // Pieces split where they cross another piece, in some pass.
  bool crossing_split = false;
  // Two lines seen crossing in some pass. Lines are not split in the
  // partner-only passes, so their crossing stands there without being tested
  // again. (Only a split exactly at that crossing point would make it a
  // touch; the rings would then be resolved for nothing, which is harmless.)
  bool lines_crossed = false;
  // A pass after the first tests only the pairs with a fresh piece: the
  // others were tested in the pass before with the same hulls, and gave
  // "no overlap, no crossing" when that pass found no crossing and no overlap
  // it could not split (otherwise the pass tests every pair again).
  bool test_all = true;
  // After a split at a crossing, a pass tests every fresh piece against all
  // others instead of the children of the pairs that overlapped: the point is
  // the conic's, rounded, and off the other piece by that rounding, so that
  // piece's halves need not lie in its hull. Pairs of pieces that are not
  // fresh were tested in the pass before with the same hulls and did not
  // overlap (an overlap marks a piece for splitting, or sets test_all).
  bool fresh_against_all = false;
  // The overlapping pairs of the pass (ref indices: first piece << 32 |
  // second), and those of the pass before with where each of its pieces went
  // (piece k became pieces child_first[k] .. child_first[k + 1] - 1: two
  // when it was split, more for a line split at several points). A pass that
  // tests only fresh pieces tests just the children of the pairs that
  // overlapped before: a child's hull lies in its parent's, so a child can
  // only overlap what its parent overlapped (its sibling and its ring
  // neighbours it meets only at their common vertex), and a piece that is
  // not split and overlapped nothing before has not changed.
  thread_local std::vector<std::uint64_t> overlaps, partners;
  thread_local std::vector<std::uint32_t> child_first;
  // Pair tests, against their budget: coincident pieces all meet.
  std::size_t pairs_tested = 0;
  const std::size_t pair_budget = max_pieces == SIZE_MAX
                                      ? SIZE_MAX
                                      : tolerance::kMeshPairTestsPerPiece * (max_pieces / tolerance::kMeshWorkPerPiece);
  // (The pieces' `fresh` flags are not read in the first pass, which tests
  // every pair; a pass that splits sets them all for the next one.)
  for (int pass = 0; pass <= tolerance::kMaxHullSubdivisionDepth; ++pass) {
    bool any = false;
    bool overlap_left = false;     // an overlap seen in this pass
    bool unsplit_overlap = false;  // one where neither piece could be split
    // rings_cross(rings, true) over the same pairs; it stands when this pass
    // is the last (no conic split). Once true, nothing more to look for.
    bool cross_seen = crossing == nullptr;
    // Scratch reused across passes and calls (no allocation once warm).
    thread_local std::vector<std::size_t> mark_base;  // ring r's marks start at mark_base[r]
    // 0: kept; 1: halved; 2: split at split_at[k], the new vertex being
    // split_point[k] (a crossing, shared by the two pieces split there).
    thread_local std::vector<char> split_marks;
    thread_local std::vector<double> split_at;
    thread_local std::vector<Vec2> split_point;
    // Further points of the pass to split lines at (mark, point): a line is
    // split at every T-junction found on it in one pass, besides its
    // split_point, because a line split at a crossing alone gets a vertex off
    // the line (the crossing rounded), and a T-junction point on the line
    // would then no longer be on either half.
    thread_local std::vector<std::pair<std::uint32_t, Vec2>> more_line_points;
    bool split_this_pass = false;
    // Tangent legs are aligned (align_tangent_legs) only when the pass has
    // found an overlap, and then the pass is run again on the aligned rings:
    // every tangency align_tangent_legs fixes is a hull corner on another
    // hull's edge, which the pair tests report as an overlap, so a pass
    // without one has nothing to align. The result is that of aligning
    // first; the usual glyph skips the alignment scan.
    for (bool aligned = false;;) {
      // (After aligning, pieces may have been inserted and the pairs of the
      // pass before no longer name them: the pass then scans the boxes.)
      const bool by_partners = !test_all && !fresh_against_all && !aligned;
      overlaps.clear();
      any = false;
      overlap_left = false;
      unsplit_overlap = false;
      split_this_pass = false;
      cross_seen = crossing == nullptr;
      thread_local std::vector<HullRef> refs;
      mark_base.assign(rings.size() + 1, 0);
      for (std::size_t r = 0; r < rings.size(); ++r) mark_base[r + 1] = mark_base[r] + rings[r].size();
      const std::size_t count = mark_base.back();
      split_marks.assign(count, 0);
      more_line_points.clear();
      split_point.resize(count);  // (lines are split at points of them in every call)
      if (split_at_crossings) split_at.resize(count);
      // Grown, never shrunk: resize() would construct every record again.
      if (refs.size() < count) refs.resize(count);
      HullRef* const unsorted = refs.data();
      for (std::size_t r = 0; r < rings.size(); ++r) {
        const Ring& ring = rings[r];
        for (std::size_t i = 0; i < ring.size(); ++i) {
          const Piece& piece = ring[i];
          HullRef& ref = unsorted[mark_base[r] + i];
          // Without branches on the piece kind (they follow the outline's
          // unpredictable mix): a line's hull[1] and hull[2] are both its end.
          const Vec2 end = ring[i + 1 < ring.size() ? i + 1 : 0].a;
          ref.hull[0] = piece.a;
          ref.n = 2 + static_cast<int>(piece.conic);
          ref.hull[1] = piece.control;
          ref.hull[2] = end;
          ref.hull[ref.n - 1] = end;
          ref.box = Box{};
          for (int k = 0; k < 3; ++k) ref.box.add(ref.hull[k]);
          ref.depth = piece.depth;
          ref.weight = piece.weight;
          ref.mark = mark_base[r] + i;
        }
      }
      // (Raw pointers: the stores into the char marks may alias anything,
      // which would make every access through the thread-local vectors reload
      // them.)
      char* const marks = split_marks.data();
      // Consecutive pieces whose hulls certainly meet only at their common
      // vertex (joint_apart): their pair is left out of the tests below.
      thread_local std::vector<std::uint32_t> next_piece, previous_piece;
      thread_local std::vector<char> apart_from_next;
      next_piece.resize(count);
      previous_piece.resize(count);
      apart_from_next.resize(count);
      for (std::size_t r = 0; r < rings.size() && !by_partners; ++r) {
        const std::size_t first = mark_base[r], end = mark_base[r + 1];
        for (std::size_t k = first; k < end; ++k) {
          const std::size_t next = k + 1 < end ? k + 1 : first;
          const HullRef &p = unsorted[k], &q = unsorted[next];
          next_piece[k] = static_cast<std::uint32_t>(next);
          previous_piece[next] = static_cast<std::uint32_t>(k);
          apart_from_next[k] =
              static_cast<char>(joint_apart(p.hull[0], p.hull[1], p.n == 3, q.hull[0], q.hull[1], q.n == 3, q.end()));
        }
      }
      // The bits of the block at base for the pieces consecutive to piece i
      // and apart from it (no branch: an index outside the block wraps to a
      // large unsigned difference).
      auto joints_apart = [&](std::size_t i, std::size_t base) -> std::uint64_t {
        const std::size_t next = next_piece[i] - base, previous = previous_piece[i] - base;
        const std::uint64_t next_bit = static_cast<std::uint64_t>((apart_from_next[i] != 0) & (next < 64))
                                       << (next & 63);
        const std::uint64_t previous_bit =
            static_cast<std::uint64_t>((apart_from_next[previous_piece[i]] != 0) & (previous < 64)) << (previous & 63);
        return next_bit | previous_bit;
      };
      auto test_pair = [&](const HullRef& ri, const HullRef& rj) {
        if (++pairs_tested > pair_budget)
          work_budget_exceeded("hull separation (pair tests)", pairs_tested, pair_budget);
        const bool ci = ri.n == 3, cj = rj.n == 3;
        if (!ci && !cj) {
          if (!cross_seen && lines_cross(ri.hull[0], ri.hull[1], rj.hull[0], rj.hull[1])) {
            cross_seen = true;
            lines_crossed = true;
          }
          return;
        }
        const Vec2 ai = ri.hull[0], ei = ri.end(), aj = rj.hull[0], ej = rj.end();
        const bool same_ends = (ai == aj && ei == ej) || (ai == ej && ei == aj);
        // A conic and a piece with the same end points: their chords would
        // coincide, rings_cross's answer is true.
        cross_seen = cross_seen || same_ends;
        // Identical curves (duplicated contours) overlap at every depth;
        // splitting them is useless, the crossing resolver merges them.
        if (same_ends && ci && cj && ri.hull[1] == rj.hull[1] && ri.weight == rj.weight) return;
        if (!hulls_overlap(ri.hull, ri.n, rj.hull, rj.n)) return;
        overlaps.push_back(static_cast<std::uint64_t>(ri.mark) << 32 | rj.mark);
        overlap_left = true;
        // A line and a conic that halving would never get apart, because a
        // point of the conic's hull stays on the line however often the
        // conic is halved: the line is split at that point (exact: the point
        // is on it), so that the two meet at a common vertex. Either an end
        // of the conic on the line (a T-junction: an ogonek or a cedilla
        // drawn onto a stem), or its control with the leg through it along
        // the line (a conic leaving another contour's line tangentially;
        // align_tangent_legs does this for neighbours in one ring).
        if (ci != cj) {
          const HullRef& line = ci ? rj : ri;
          const HullRef& conic = ci ? ri : rj;
          const Vec2 la = line.hull[0], lb = line.hull[1];
          for (int k : {0, 2, 1}) {
            const Vec2 e = conic.hull[k];
            if (e == la || e == lb || !point_on_segment(la, lb, e)) continue;
            if (k == 1 && orient2d(la, lb, conic.hull[0]) != 0 && orient2d(la, lb, conic.hull[2]) != 0) continue;
            if (marks[line.mark] == 0) {
              marks[line.mark] = 2;
              split_point[line.mark] = e;
            } else if (split_point[line.mark] != e) {
              more_line_points.push_back({static_cast<std::uint32_t>(line.mark), e});
            }
            // Contours that touch there may still overlap (a lobe of one
            // inside the other, their outlines meeting only at such
            // points): before resolving, that calls for the resolver, as a
            // crossing does.
            crossing_split = crossing_split || split_at_crossings;
            any = true;
            return;
          }
        }
        // Pieces that cross: both split at the crossing (once per pass
        // each), which saves halving the conics down to the limit around
        // it. The point is the conic's, rounded; the other piece gets
        // the same point as its new vertex (a move of an ulp or so).
        // (Pieces with a common end, most overlapping pairs, have no proper
        // chord crossing: not asked.)
        const bool common_end = ai == aj || ai == ej || ei == aj || ei == ej;
        if (split_at_crossings && !common_end && marks[ri.mark] == 0 && marks[rj.mark] == 0 &&
            (!ci || ri.depth < tolerance::kMaxHullSubdivisionDepth) &&
            (!cj || rj.depth < tolerance::kMaxHullSubdivisionDepth)) {
          double t = 0.0, u = 0.0;
          if (crossing_parameters(ri.hull, ri.n, ri.weight, rj.hull, rj.n, rj.weight, t, u)) {
            const HullRef& conic = ci ? ri : rj;
            Vec2 x =
                canonical(split(Segment::conic(conic.hull[0], conic.hull[1], conic.hull[2], conic.weight), ci ? t : u)
                              .second.p[0]);
            // On a horizontal or vertical line (most of a font's lines) the
            // point is put on the line exactly, a move of its rounding: then
            // it is on every line along that one too (another contour's
            // edge there), where the conic's half could otherwise start a
            // rounding away and cross it again next to its end.
            if (ci != cj) {
              const HullRef& line = ci ? rj : ri;
              if (line.hull[0].y == line.hull[1].y) x.y = line.hull[0].y;
              if (line.hull[0].x == line.hull[1].x) x.x = line.hull[0].x;
            }
            if (x != ai && x != ei && x != aj && x != ej) {
              marks[ri.mark] = 2;
              marks[rj.mark] = 2;
              split_at[ri.mark] = t;
              split_at[rj.mark] = u;
              split_point[ri.mark] = x;
              split_point[rj.mark] = x;
              split_this_pass = true;
              any = true;
              return;
            }
          }
        }
        // Subdividing a conic shrinks its hull towards the arc; lines stay.
        bool split_one = false;
        if (ci && ri.depth < tolerance::kMaxHullSubdivisionDepth) {
          if (marks[ri.mark] == 0) marks[ri.mark] = 1;
          split_one = true;
        }
        if (cj && rj.depth < tolerance::kMaxHullSubdivisionDepth) {
          if (marks[rj.mark] == 0) marks[rj.mark] = 1;
          split_one = true;
        }
        any = any || split_one;
        unsplit_overlap = unsplit_overlap || !split_one;
      };
      // The boxes in one array per side, for tests written without branches
      // (their outcomes are unpredictable; most pairs are rejected by their
      // boxes alone).
      thread_local std::vector<double> box_sides;
      // Named pointers, not a structured binding: the lambda below captures
      // them, which clang before 16 does not allow for bindings.
      const auto sides = columns<4>(box_sides, count);
      double *const min_x = sides[0], *const max_x = sides[1], *const min_y = sides[2], *const max_y = sides[3];
      for (std::size_t k = 0; k < count && !by_partners; ++k) {
        const Box& b = unsorted[k].box;
        min_x[k] = b.min.x;
        max_x[k] = b.max.x;
        min_y[k] = b.min.y;
        max_y[k] = b.max.y;
      }
      // One bit per piece j of the block [base, base + 64) (base a multiple
      // of 64) whose box meets box i, tested from piece `from` on (the bits
      // below may be set or not); two boxes per step with SSE2 (part of every
      // x86-64 CPU). Hits are then read with countr_zero.
      auto meets_block = [&](std::size_t i, std::size_t base, std::size_t from) {
        const double left = min_x[i], right = max_x[i], bottom = min_y[i], top = max_y[i];
        const std::size_t end = std::min(count, base + 64);
        std::uint64_t hits = 0;
        std::size_t j = std::max(base, from & ~std::size_t{1});
#if defined(__SSE2__)
        const __m128d vl = _mm_set1_pd(left), vr = _mm_set1_pd(right), vb = _mm_set1_pd(bottom), vt = _mm_set1_pd(top);
        for (; j + 2 <= end; j += 2) {
          const __m128d in_x =
              _mm_and_pd(_mm_cmple_pd(_mm_loadu_pd(min_x + j), vr), _mm_cmple_pd(vl, _mm_loadu_pd(max_x + j)));
          const __m128d in_y =
              _mm_and_pd(_mm_cmple_pd(_mm_loadu_pd(min_y + j), vt), _mm_cmple_pd(vb, _mm_loadu_pd(max_y + j)));
          hits |= static_cast<std::uint64_t>(_mm_movemask_pd(_mm_and_pd(in_x, in_y))) << (j - base);
        }
#endif
        for (; j < end; ++j) {
          const bool meets = (min_x[j] <= right) & (left <= max_x[j]) & (min_y[j] <= top) & (bottom <= max_y[j]);
          hits |= static_cast<std::uint64_t>(meets) << (j - base);
        }
        return hits;
      };
      // The bits of the block at base for the pieces after (before) piece i.
      auto after = [](std::size_t i, std::size_t base) -> std::uint64_t {
        if (i < base) return ~std::uint64_t{0};
        return i - base >= 63 ? 0 : ~std::uint64_t{0} << (i - base + 1);
      };
      auto before = [](std::size_t i, std::size_t base) -> std::uint64_t {
        if (i <= base) return 0;
        return i - base >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << (i - base)) - 1;
      };
      auto test_hits = [&](std::size_t i, std::size_t base, std::uint64_t hits) {
        for (; hits != 0; hits &= hits - 1)
          test_pair(unsorted[i], unsorted[base + static_cast<std::size_t>(std::countr_zero(hits))]);
      };
      if (by_partners) {
        for (const std::uint64_t pair : partners) {
          const std::size_t p = pair >> 32, q = pair & 0xffffffffu;
          for (std::size_t cp = child_first[p]; cp < child_first[p + 1]; ++cp)
            for (std::size_t cq = child_first[q]; cq < child_first[q + 1]; ++cq) test_pair(unsorted[cp], unsorted[cq]);
        }
        // A child's hull lies in its parent's only in exact arithmetic: its
        // rounded control point can cross a line that its parent's leg lay
        // along (a hairpin conic closed by that line), a ring neighbour the
        // parent only touched. Fresh pieces are tested against their ring
        // neighbours again.
        for (std::size_t r = 0; r < rings.size(); ++r) {
          const std::size_t first = mark_base[r], end = mark_base[r + 1];
          for (std::size_t k = first; k + 1 < end || (k + 1 == end && end - first > 2); ++k) {
            const std::size_t next = k + 1 < end ? k + 1 : first;
            if (rings[r][k - first].fresh || rings[r][next - first].fresh) test_pair(unsorted[k], unsorted[next]);
          }
        }
      } else if (!test_all) {
        // (After a split at a crossing, or after aligning tangent legs in a
        // pass that tests only fresh pieces.) Each fresh piece against every
        // piece whose box meets its own (a fresh pair once, from its first
        // piece).
        thread_local std::vector<std::uint32_t> fresh_refs;
        fresh_refs.clear();
        for (std::size_t r = 0; r < rings.size(); ++r)
          for (std::size_t i = 0; i < rings[r].size(); ++i)
            if (rings[r][i].fresh) fresh_refs.push_back(static_cast<std::uint32_t>(mark_base[r] + i));
        thread_local std::vector<std::uint64_t> fresh_words;
        fresh_words.assign((count + 63) / 64, 0);
        for (const std::uint32_t i : fresh_refs) fresh_words[i / 64] |= std::uint64_t{1} << (i % 64);
        // (Every fresh piece's box against every box: counted against the
        // pair budget, as a contour drawn twice keeps many pieces fresh.)
        pairs_tested += fresh_refs.size() * count;
        if (pairs_tested > pair_budget) work_budget_exceeded("hull separation (pair tests)", pairs_tested, pair_budget);
        for (const std::uint32_t i : fresh_refs) {
          for (std::size_t base = 0; base < count; base += 64) {
            const std::uint64_t others = after(i, base) | (before(i, base) & ~fresh_words[base / 64]);
            test_hits(i, base, meets_block(i, base, base) & others & ~joints_apart(i, base));
          }
        }
      } else if (count <= kAllPairsLimit) {
        // A glyph's few dozen pieces: every pair's boxes, which costs less
        // than sorting them (a sort's branches are unpredictable too).
        for (std::size_t i = 0; i < count; ++i)
          test_hits(i, 0, meets_block(i, 0, i + 1) & after(i, 0) & ~joints_apart(i, 0));  // one block
      } else {
        // Sweep and prune: sorted by the boxes' lower sides along the glyph's
        // longer axis, where the boxes overlap less (a tall glyph's pieces
        // share x ranges); "a" below is that axis, "b" the other. Which pairs
        // are met does not depend on the order among equal keys, and the
        // answers are combined order-independently.
        Box all;
        for (std::size_t k = 0; k < count; ++k) {
          all.add(unsorted[k].box.min);
          all.add(unsorted[k].box.max);
        }
        const bool along_y = all.max.y - all.min.y > all.max.x - all.min.x;
        const double* const min_a = along_y ? min_y : min_x;
        const double* const max_a = along_y ? max_y : max_x;
        const double* const min_b = along_y ? min_x : min_y;
        const double* const max_b = along_y ? max_x : max_y;
        struct SortKey {
          double min_a;
          std::uint32_t ref;
        };
        thread_local std::vector<SortKey> keys;
        keys.resize(count);
        for (std::size_t k = 0; k < count; ++k) keys[k] = {min_a[k], static_cast<std::uint32_t>(k)};
        std::sort(keys.begin(), keys.end(), [](const SortKey& a, const SortKey& b) { return a.min_a < b.min_a; });
        // The sides again in sorted order (the scan reads them in a row).
        thread_local std::vector<double> sorted_sides;
        thread_local std::vector<std::uint32_t> candidates;
        candidates.resize(count);
        std::uint32_t* const candidate = candidates.data();
        const auto [s_min_a, s_max_a, s_min_b, s_max_b] = columns<4>(sorted_sides, count);
        for (std::size_t k = 0; k < count; ++k) {
          const std::uint32_t r = keys[k].ref;
          s_min_a[k] = min_a[r];
          s_max_a[k] = max_a[r];
          s_min_b[k] = min_b[r];
          s_max_b[k] = max_b[r];
        }
        for (std::size_t i = 0; i < count; ++i) {
          // Boxes after box i in the order start at or after its lower side
          // along a: they overlap it along a while they start before its upper
          // side, and then in both when their b ranges meet. (Pieces with the
          // same end points have overlapping boxes.)
          const double upper = s_max_a[i], low_b = s_min_b[i], high_b = s_max_b[i];
          std::size_t found = 0, j = i + 1;
          for (; j < count && s_min_a[j] <= upper; ++j) {
            candidate[found] = keys[j].ref;
            found += static_cast<std::size_t>((s_min_b[j] <= high_b) & (low_b <= s_max_b[j]));
          }
          // The boxes scanned count against the pair budget too (those tested
          // are counted by test_pair): pieces stacked on each other (a
          // contour drawn twice) make every pass's scan quadratic.
          pairs_tested += j - i - 1 - found;
          if (pairs_tested > pair_budget)
            work_budget_exceeded("hull separation (pair tests)", pairs_tested, pair_budget);
          for (std::size_t f = 0; f < found; ++f) test_pair(unsorted[keys[i].ref], unsorted[candidate[f]]);
        }
      }
      if (!overlap_left || aligned) break;
      aligned = true;
      bool changed = false;
      for (Ring& ring : rings) {
        // Each call fixes one tangency; a ring has at most one per vertex.
        for (std::size_t fixes = 0, limit = 2 * ring.size() + 2; fixes < limit && align_tangent_legs(ring); ++fixes)
          changed = true;
      }
      if (!changed) break;
    }  // (the pass again, on the aligned rings)
    if (!any) {
      if (!overlap_left && crossing) *crossing = cross_seen || lines_crossed;
      if (crossing_split) *crossing = true;
      return !overlap_left;
    }
    test_all = unsplit_overlap || (crossing != nullptr && cross_seen && !lines_crossed);
    fresh_against_all = split_this_pass;
    crossing_split = crossing_split || split_this_pass;
    // (Each line's further points once, in mark order.)
    std::sort(more_line_points.begin(), more_line_points.end(), [](const auto& u, const auto& v) {
      return u.first != v.first ? u.first < v.first
                                : std::make_pair(u.second.x, u.second.y) < std::make_pair(v.second.x, v.second.y);
    });
    more_line_points.erase(std::unique(more_line_points.begin(), more_line_points.end()), more_line_points.end());
    child_first.resize(split_marks.size() + 1);
    child_first[0] = 0;
    for (std::size_t k = 0, m = 0; k < split_marks.size(); ++k) {
      std::uint32_t children = 1 + static_cast<std::uint32_t>(split_marks[k] != 0);
      for (; m < more_line_points.size() && more_line_points[m].first == k; ++m) ++children;
      child_first[k + 1] = child_first[k] + children;
    }
    partners.swap(overlaps);
    for (std::size_t r = 0; r < rings.size(); ++r) {
      const char* ring_marks = split_marks.data() + mark_base[r];
      for (Piece& piece : rings[r]) piece.fresh = false;
      if (std::all_of(ring_marks, ring_marks + rings[r].size(), [](char m) { return m == 0; }))
        continue;  // nothing to split
      Ring next = take_ring();
      next.reserve(rings[r].size() + 8);
      for (std::size_t i = 0; i < rings[r].size(); ++i) {
        const Piece& p = rings[r][i];
        if (!ring_marks[i]) {
          next.push_back(p);
          continue;
        }
        const bool at_crossing = ring_marks[i] == 2;
        if (!p.conic) {  // (a line is only split at a crossing or T-junctions)
          // Its split point and further points, in order along the line.
          const std::size_t mark = mark_base[r] + i;
          const auto more = std::equal_range(more_line_points.begin(), more_line_points.end(),
                                             std::pair{static_cast<std::uint32_t>(mark), Vec2{}},
                                             [](const auto& u, const auto& v) { return u.first < v.first; });
          thread_local std::vector<Vec2> points;
          points.assign(1, split_point[mark]);
          for (auto it = more.first; it != more.second; ++it) points.push_back(it->second);
          const Vec2 direction = ring_end(rings[r], i) - p.a;
          std::sort(points.begin(), points.end(),
                    [&](Vec2 u, Vec2 v) { return dot(u - p.a, direction) < dot(v - p.a, direction); });
          next.push_back(p);
          next.back().fresh = true;
          for (const Vec2 point : points) {
            next.push_back(p);
            next.back().a = point;
            next.back().fresh = true;
          }
          continue;
        }
        const double at = at_crossing ? split_at[mark_base[r] + i] : 0.5;
        const auto halves = split(Segment::conic(p.a, p.control, ring_end(rings[r], i), p.weight), at);
        next.push_back(conic_piece(halves.first, p.depth + 1));
        next.push_back(conic_piece(halves.second, p.depth + 1));
        if (at_crossing) next.back().a = split_point[mark_base[r] + i];
      }
      rings[r].swap(next);
      recycle_ring(std::move(next));
    }
    std::size_t pieces = 0;
    for (const Ring& ring : rings) pieces += ring.size();
    if (pieces > max_pieces) work_budget_exceeded("hull separation", pieces, max_pieces);
  }
  if (crossing_split) *crossing = true;
  return false;  // passes used up right after splitting: not known to be separated
}

// --- Nesting -------------------------------------------------------------------------

Where point_in_ring(const Ring& ring, Vec2 p) {
  return point_in_polygon(
      ring.size(),
      [&](std::size_t i) {
        return std::pair{ring[i].a, ring_end(ring, i)};
      },
      p);
}

namespace {

Box ring_box(const Ring& ring) {
  Box box;
  for (const Piece& p : ring) box.add(p.a);
  return box;
}

bool box_contains(const Box& outer, const Box& inner) {
  return outer.min.x <= inner.min.x && outer.min.y <= inner.min.y && inner.max.x <= outer.max.x &&
         inner.max.y <= outer.max.y;
}

// Ring `inner` lies inside ring `outer` (they do not cross). After hull
// separation no vertex of one ring lies in a curved cap of another, so the
// chord polygon answers for the curved region.
bool ring_inside(const Ring& inner, const Ring& outer) {
  for (const Piece& p : inner) {
    const Where w = point_in_ring(outer, p.a);
    if (w == Where::Inside) return true;
    if (w == Where::Outside) return false;
  }
  // Every vertex on the other ring: an island touching its hole at all its
  // corners (common after resolving crossings), or a duplicate. Ask the
  // middles of the chords; a chord that is not an edge of `outer` has its
  // middle strictly inside or outside it.
  for (std::size_t i = 0; i < inner.size(); ++i) {
    const Where w = point_in_ring(outer, (inner[i].a + ring_end(inner, i)) * 0.5);
    if (w == Where::Inside) return true;
    if (w == Where::Outside) return false;
  }
  return false;  // every chord on the other ring: a duplicate, not nested
}

// Reverses the direction of a ring in place: piece k of the result is piece
// n - 1 - k traversed backwards, so it starts where that piece ended.
void reverse_ring(Ring& ring) {
  const std::size_t n = ring.size();
  if (n == 0) return;
  std::reverse(ring.begin(), ring.end());
  // Now ring[k] is the old piece n - 1 - k, whose end is the old piece
  // n - k's start, i.e. the new ring[k - 1].a (cyclically): shift the starts.
  const Vec2 last = ring[n - 1].a;
  for (std::size_t k = n - 1; k > 0; --k) ring[k].a = ring[k - 1].a;
  ring[0].a = last;
}

}  // namespace

void nest_rings(std::vector<Ring>& rings, std::vector<std::uint32_t>& region_rings,
                std::vector<std::uint32_t>& region_start) {
  const std::size_t n = rings.size();
  // Scratch reused across calls (no allocation per glyph once warm).
  thread_local std::vector<double> area;
  thread_local std::vector<Box> box;
  area.resize(n);
  box.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    area[i] = ring_area(rings[i]);
    box[i] = ring_box(rings[i]);
  }
  // The rings that contain ring i: container_list[container_start[i] ..
  // container_start[i + 1]).
  thread_local std::vector<std::size_t> container_start, container_list;
  container_start.assign(n + 1, 0);
  container_list.clear();
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j) {
      if (i == j || !box_contains(box[j], box[i]) || std::fabs(area[j]) < std::fabs(area[i])) continue;
      if (ring_inside(rings[i], rings[j])) container_list.push_back(j);
    }
    container_start[i + 1] = container_list.size();
  }
  auto containers = [&](std::size_t i) {
    return std::span<const std::size_t>(container_list.data() + container_start[i],
                                        container_start[i + 1] - container_start[i]);
  };
  // Nonzero rule: winding just outside ring i is the sum of the orientations
  // of the rings around it; just inside it adds its own orientation. The ring
  // bounds the fill only where exactly one of the two is non-zero.
  enum class Role { Drop, Outer, Hole };
  thread_local std::vector<Role> role;
  role.assign(n, Role::Drop);
  for (std::size_t i = 0; i < n; ++i) {
    int outside = 0;
    for (std::size_t j : containers(i)) outside += area[j] > 0 ? 1 : -1;
    const int inside = outside + (area[i] > 0 ? 1 : -1);
    if ((outside != 0) == (inside != 0)) continue;
    role[i] = inside != 0 ? Role::Outer : Role::Hole;
    // Normalise: filled side on the left (outer counter-clockwise, holes clockwise).
    const bool ccw = area[i] > 0;
    if ((role[i] == Role::Outer) != ccw) reverse_ring(rings[i]);
  }
  // Each hole's region is its innermost containing outer ring.
  thread_local std::vector<std::size_t> owner;
  owner.assign(n, n);
  for (std::size_t i = 0; i < n; ++i) {
    if (role[i] != Role::Hole) continue;
    std::size_t best = n;
    for (std::size_t j : containers(i)) {
      if (role[j] == Role::Outer && (best == n || std::fabs(area[j]) < std::fabs(area[best]))) best = j;
    }
    owner[i] = best;  // n: cannot happen for non-crossing rings; the hole is dropped
  }
  // Regions in the order of their outer rings, each followed by its holes
  // in ring order.
  region_rings.clear();
  region_start.clear();
  for (std::size_t i = 0; i < n; ++i) {
    if (role[i] != Role::Outer) continue;
    region_start.push_back(static_cast<std::uint32_t>(region_rings.size()));
    region_rings.push_back(static_cast<std::uint32_t>(i));
    for (std::size_t h = 0; h < n; ++h)
      if (role[h] == Role::Hole && owner[h] == i) region_rings.push_back(static_cast<std::uint32_t>(h));
  }
  region_start.push_back(static_cast<std::uint32_t>(region_rings.size()));
}

}  // namespace detail

// --- Assembly ---------------------------------------------------------------------------

namespace {

// Removes zero-width folds "c, v, c" from a polygon loop. They arise where a
// concave conic's leg and the next piece retrace each other (a tangent cusp
// after align_tangent_legs); the fold encloses nothing, and the curved
// triangle on the other side of the shared leg covers the sliver of fill.
std::vector<Vec2> remove_folds(std::vector<Vec2> loop) {
  // The usual loop has no fold anywhere (no p[i] == p[i + 2], cyclically):
  // then the rounds below only rotate it, by n/2 twice; do just that.
  const std::size_t n = loop.size();
  bool folded = false;
  for (std::size_t i = 0; i < n && !folded; ++i) folded = loop[i] == loop[(i + 2) % n];
  if (!folded) {
    if (n > 0) std::rotate(loop.begin(), loop.begin() + static_cast<std::ptrdiff_t>((2 * (n / 2)) % n), loop.end());
    return loop;
  }
  std::vector<Vec2> current = std::move(loop);
  for (int round = 0; round < 2; ++round) {
    std::vector<Vec2> out;
    out.reserve(current.size());
    for (const Vec2 p : current) {
      out.push_back(p);
      while (out.size() >= 3 && out[out.size() - 3] == out.back()) {
        out.pop_back();
        out.pop_back();
      }
    }
    // Rotate by half so folds across the seam are met in the middle next time.
    std::rotate(out.begin(), out.begin() + static_cast<std::ptrdiff_t>(out.size() / 2), out.end());
    current.swap(out);
  }
  return current;
}

// Position -> vertex index, in order of first use: an open-addressing hash
// table on the coordinates' bits (positions are canonical, see canonical()).
class PointIndex {
 public:
  std::vector<Vec2>& points;  // index -> position (filled by the lookups)

  PointIndex(std::vector<Vec2>& points_out, std::size_t expected) : points(points_out) {
    std::size_t capacity = 16;
    bits_ = 4;
    while (capacity < 4 * expected + 16) {  // at most a quarter full, as position_table_bits
      capacity *= 2;
      ++bits_;
    }
    slots_.assign(capacity, kEmpty);
    points.reserve(expected);
  }

  std::uint32_t operator()(Vec2 p) {
    if (4 * (points.size() + 1) > slots_.size()) grow();
    std::size_t slot = this->slot(p);
    while (slots_[slot] != kEmpty) {
      if (points[slots_[slot]] == p) return slots_[slot];
      slot = (slot + 1) & (slots_.size() - 1);
    }
    slots_[slot] = static_cast<std::uint32_t>(points.size());
    points.push_back(p);
    return slots_[slot];
  }

 private:
  static constexpr std::uint32_t kEmpty = 0xffffffffu;
  // Scratch reused across calls (one index at a time per thread).
  static std::vector<std::uint32_t>& scratch_slots() {
    thread_local std::vector<std::uint32_t> slots;
    return slots;
  }
  std::vector<std::uint32_t>& slots_ = scratch_slots();
  int bits_ = 4;  // log2(slots_.size())

  // (-0.0 == +0.0 must hash alike.)
  std::size_t slot(Vec2 p) const { return detail::position_hash(detail::canonical(p), bits_); }

  void grow() {
    slots_.assign(slots_.size() * 2, kEmpty);
    ++bits_;
    for (std::uint32_t i = 0; i < points.size(); ++i) {
      std::size_t slot = this->slot(points[i]);
      while (slots_[slot] != kEmpty) slot = (slot + 1) & (slots_.size() - 1);
      slots_[slot] = i;
    }
  }
};

}  // namespace

namespace {

bool any_ring_repeats_a_vertex(const std::vector<detail::Ring>& rings) {
  return std::any_of(rings.begin(), rings.end(), detail::repeats_a_vertex);
}

// One build. With split_repeated false, rings that pass through a vertex
// twice are not split into their lobes (clean_rings): that search costs a
// hash table per ring, and such rings are rare (none in DejaVu Sans, Noto
// Sans or Inter, 31 of 20,000 Noto Sans CJK glyphs). Where it matters the
// build looks for them and returns false on finding one: when the sweep
// gives up (a ring through a vertex twice always makes it give up: the
// vertex repeats among its loops). The caller then builds again with the
// split, exactly as a build that split first. The crossing resolver needs no
// split: it takes the edges of all rings together and splits the loops it
// makes at repeated vertices itself. (Hull separation makes a ring pass
// through a point twice where it splits two of its pieces at their crossing;
// looking for repeats before resolving would build such glyphs twice, about
// one in 25 of Inter's.) Returns true when the mesh is built.
bool build_mesh_once(const Outline& outline, const MeshOptions& options, double merge_distance, Mesh& mesh,
                     bool split_repeated, bool& needs_check) {
  using namespace detail;
  // The rings (and their storage) are reused from glyph to glyph.
  thread_local std::vector<Ring> rings;
  bool approximated = false;
  if (!clean_rings(outline, options.cubic_tolerance, merge_distance, rings, split_repeated, &approximated))
    throw Error(ErrorCode::Geometry, "build_mesh: outline has non-finite coordinates or weights");
  // Straightening within the flatness tolerance changes the area by up to
  // 1e-9 of a chord squared, which a sliver's area may not allow.
  needs_check = needs_check || approximated;
  stage_mark(MeshStage::Clean);
  std::size_t input_pieces = 0;
  for (const Ring& ring : rings) input_pieces += ring.size();
  const std::size_t budget = mesh_work_budget(input_pieces);
  bool crossing = false;
  const bool separated = separate_hulls(rings, &crossing, kResolveCrossingContours, budget);
  stage_mark(MeshStage::Separate);
  // Crossing, overlapping or edge-sharing contours: resolve them into
  // non-crossing rings of the nonzero fill first (skipped for the usual
  // glyph whose contours do not meet; separate_hulls's sweep already told).
  // Pieces of separated, non-crossing rings meet only at common vertices,
  // which lets sweep_triangulate take their loops when no position repeats.
  bool simple_edges = separated && !crossing;
  bool resolved_rings = false;
  auto resolve = [&](bool hulls_separated) {
    bool settled = false;
    std::vector<Ring> resolved = resolve_crossings(rings, hulls_separated, &settled, budget);
    recycle_rings(rings);
    rings = std::move(resolved);
    resolved_rings = true;
    // The resolved rings do not cross; where the resolver found nothing left
    // in conflict, or the same test as above agrees (and no position repeats:
    // the sweep checks), they take the sweep too.
    bool still_crossing = true;
    simple_edges = settled || (separate_hulls(rings, &still_crossing, false, budget) && !still_crossing);
    needs_check = needs_check || !settled;
  };
  if (kResolveCrossingContours && (crossing || (!separated && rings_cross(rings, false)))) resolve(separated);
  stage_mark(MeshStage::Resolve);
  mesh.triangles.clear();
  // Polygon loops as vertex indices, grouped by region when nest_rings has
  // made regions (outer loop first, then its holes): loop l is
  // loop_vertices[loop_start[l] .. loop_start[l + 1]), region r's loops are
  // region_first_loop[r] .. region_first_loop[r + 1]. Scratch reused across
  // calls (no allocation per glyph once warm).
  thread_local std::vector<std::uint32_t> loop_vertices, loop_start;
  thread_local std::vector<std::size_t> region_first_loop;
  // Region r is rings region_rings[region_start[r] .. region_start[r + 1]):
  // its outer ring, then its holes.
  thread_local std::vector<std::uint32_t> region_rings, region_start;
  std::size_t piece_count = 0;
  // Positions get vertex indices in order of first use. `index` gives a
  // position its index: a PointIndex (one index per distinct position), or,
  // where the loops go to the sweep, simply the next one: a ring passes
  // through each of its vertices once (clean_rings), and the sweep gives up
  // where a position repeats among the loops (rings that touch), so the
  // table is only needed when it does, and the loops are then made again
  // with it. (A convex curve's control point, which no loop holds, may then
  // keep an index of its own where it coincides with another point; nothing
  // joins the two.) `reversed`: every ring is walked backwards (the fill is
  // on its right), as nest_rings's reverse_ring would turn it.
  auto make_loops = [&](auto&& index, bool reversed) {
    mesh.points.clear();
    mesh.curves.clear();
    mesh.boundary_lines.clear();
    mesh.points.reserve(2 * piece_count);
    mesh.boundary_lines.reserve(piece_count);
    mesh.curves.reserve(piece_count);
    loop_vertices.clear();
    loop_vertices.reserve(2 * piece_count);
    loop_start.assign(1, 0);
    auto polygonise = [&](const Ring& ring) {
      // Piece k of the walk is ring[k], or backwards ring[n - 1 - k] from its
      // end to its start (reverse_ring's order: the walk starts at ring[0].a
      // either way). Piece k starts where piece k - 1 ends: its index is
      // carried over, and the last piece ends where the first starts.
      const std::size_t n = ring.size();
      const std::uint32_t first_index = n == 0 ? 0 : index(ring[0].a);
      std::uint32_t next_ia = first_index;
      for (std::size_t k = 0; k < n; ++k) {
        const Piece& p = reversed ? ring[n - 1 - k] : ring[k];
        const Vec2 start = reversed ? ring_end(ring, n - 1 - k) : p.a;
        const Vec2 end = reversed ? p.a : ring_end(ring, k);
        const std::uint32_t ia = next_ia, ib = k + 1 < n ? index(end) : first_index;
        next_ia = ib;
        loop_vertices.push_back(ia);
        // A conic split into a piece whose control point lies exactly on its
        // chord's line (the tail of a nearly straight arc) is that chord: a
        // curved triangle of zero area would break the mesh's invariants.
        const int side = p.conic ? orient2d(start, end, p.control) : 0;
        if (side == 0) {
          mesh.boundary_lines.push_back({ia, ib});
          continue;
        }
        // Filled side is on the left: a control point on the right of the
        // chord bulges out (convex, the polygon keeps the chord), on the left
        // it bulges in (concave, the polygon goes through the control point).
        const bool convex = side < 0;
        const std::uint32_t ic = index(p.control);
        mesh.curves.push_back({ia, ic, ib, p.weight, convex});
        if (!convex) loop_vertices.push_back(ic);
      }
      loop_start.push_back(static_cast<std::uint32_t>(loop_vertices.size()));
    };
    region_first_loop.assign(1, 0);
    if (region_start.empty()) {
      // No regions (see the fast path below): every ring, as one group.
      for (const Ring& ring : rings) polygonise(ring);
      region_first_loop.push_back(loop_start.size() - 1);
      return;
    }
    for (std::size_t r = 0; r + 1 < region_start.size(); ++r) {
      for (std::uint32_t k = region_start[r]; k < region_start[r + 1]; ++k) polygonise(rings[region_rings[k]]);
      region_first_loop.push_back(loop_start.size() - 1);
    }
  };
  auto next_index = [&](Vec2 p) {
    mesh.points.push_back(p);
    return static_cast<std::uint32_t>(mesh.points.size() - 1);
  };
  std::optional<PointIndex> index;  // made when the general path needs it
  // Loops that neither cross nor touch are triangulated by one sweep (which
  // gives up where a position repeats: touching loops). Loops of fewer than
  // three vertices (a line and a convex conic, two convex conics) enclose no
  // polygon area and are left out, as ear_clip would leave them.
  auto sweep_loops = [&](bool* repeated) {
    thread_local std::vector<std::uint32_t> sweep_vertices, sweep_start;
    sweep_vertices.clear();
    sweep_start.assign(1, 0);
    for (std::size_t l = 0; l + 1 < loop_start.size(); ++l) {
      const std::uint32_t first = loop_start[l], last = loop_start[l + 1];
      if (last - first < 3) continue;
      sweep_vertices.insert(sweep_vertices.end(), loop_vertices.begin() + first, loop_vertices.begin() + last);
      sweep_start.push_back(static_cast<std::uint32_t>(sweep_vertices.size()));
    }
    mesh.triangles.reserve(sweep_vertices.size() + 4 * sweep_start.size());
    return sweep_triangulate(mesh.points, sweep_vertices, sweep_start, mesh.triangles, repeated);
  };

  // Fast path, without nesting: under the nonzero rule the ring through the
  // lowest vertex (least y, then least x) is outermost and bounds the fill,
  // so its orientation tells on which side of every ring the fill lies in a
  // glyph whose rings are oriented consistently (outer rings one way, holes
  // the other, as fonts draw them). The sweep checks that this holds (a
  // loop starting inside the fill or a hole outside it, and a wrong
  // triangle count, make it give up) and then nest_rings sorts the rings out.
  bool swept = false;
  bool repeated = false;
  region_start.clear();
  // Rings that meet at vertices without crossing (the sweep gives up where a
  // position repeats) may still overlap: two contours through the same two
  // vertices, one bulging into the other between them, enclose a lens that
  // no edge test sees. The resolver sorts out any such meeting by windings;
  // the fast path is then tried again on its rings.
  for (int attempt = 0; attempt < 2 && simple_edges && !rings.empty() && !swept; ++attempt) {
    if (attempt == 1) {
      if (!repeated || resolved_rings || !kResolveCrossingContours) break;
      resolve(true);
      stage_mark(MeshStage::Resolve);
      repeated = false;
      if (!simple_edges || rings.empty()) break;
    }
    piece_count = 0;
    std::size_t lowest_ring = 0, lowest_piece = 0;
    Vec2 lowest = rings[0].empty() ? Vec2{} : rings[0][0].a;
    for (std::size_t r = 0; r < rings.size(); ++r) {
      piece_count += rings[r].size();
      for (std::size_t i = 0; i < rings[r].size(); ++i) {
        const Vec2 a = rings[r][i].a;
        const bool below = (a.y < lowest.y) | ((a.y == lowest.y) & (a.x < lowest.x));
        lowest = below ? a : lowest;
        lowest_ring = below ? r : lowest_ring;
        lowest_piece = below ? i : lowest_piece;
      }
    }
    // The ring's orientation is its chord polygon's (its caps cannot turn the
    // sign: a concave cap lies inside the polygon, hull separation keeping
    // it off the other pieces), read off the turn at the polygon's lowest
    // vertex, which is convex; its area decides where the turn is flat (a
    // ring of two pieces). A wrong answer would only make the sweep give up.
    const Ring& ring = rings[lowest_ring];
    const std::size_t n = ring.size();
    const int turn =
        orient2d(ring[lowest_piece == 0 ? n - 1 : lowest_piece - 1].a, lowest, ring_end(ring, lowest_piece));
    make_loops(next_index, turn != 0 ? turn < 0 : ring_area(ring) < 0.0);
    stage_mark(MeshStage::Loops);
    swept = sweep_loops(&repeated);
    stage_mark(MeshStage::Triangles);
  }

  if (!swept) {
    if (!split_repeated && any_ring_repeats_a_vertex(rings)) return false;
    nest_rings(rings, region_rings, region_start);
    piece_count = 0;
    for (const std::uint32_t r : region_rings) piece_count += rings[r].size();
    // The sweep again on the oriented rings (unless loops touch: then no
    // orientation helps), else the general path with one index per position.
    if (simple_edges && !repeated) {
      make_loops(next_index, false);
      stage_mark(MeshStage::Loops);
      swept = sweep_loops(nullptr);
      stage_mark(MeshStage::Triangles);
    }
    if (!swept) {
      index.emplace(mesh.points, 2 * piece_count);
      make_loops(*index, false);
    }
    stage_mark(MeshStage::Loops);
  }
  recycle_rings(rings);
  // The sweep checks its own output (triangle counts, orientations); the
  // other paths are checked by the caller.
  needs_check = needs_check || !swept;
  if (!swept) {
    thread_local std::vector<std::array<Vec2, 3>> triangle_points;
    triangle_points.clear();
    triangle_points.reserve(2 * piece_count + 8);  // about two triangles per loop vertex
    auto positions = [&](std::size_t l) {
      std::vector<Vec2> loop;
      loop.reserve(loop_start[l + 1] - loop_start[l]);
      for (std::uint32_t k = loop_start[l]; k < loop_start[l + 1]; ++k) loop.push_back(mesh.points[loop_vertices[k]]);
      return remove_folds(std::move(loop));
    };
    for (std::size_t r = 0; r + 1 < region_first_loop.size(); ++r) {
      std::vector<Vec2> outer = positions(region_first_loop[r]);
      std::vector<std::vector<Vec2>> holes;
      for (std::size_t l = region_first_loop[r] + 1; l < region_first_loop[r + 1]; ++l) holes.push_back(positions(l));
      // Where loops touch at vertices, re-link them first so that each polygon
      // handed to the ear clipper has one filled sector per corner.
      for (PolygonLoops& polygon : relink_touching_loops(std::move(outer), std::move(holes))) {
        const std::vector<Vec2> loop = bridge_holes(std::move(polygon.outer), std::move(polygon.holes));
        ear_clip(loop, triangle_points, ear_clip_budget(loop.size()));
      }
    }
    mesh.triangles.reserve(triangle_points.size());
    for (const auto& t : triangle_points) mesh.triangles.push_back({(*index)(t[0]), (*index)(t[1]), (*index)(t[2])});
    stage_mark(MeshStage::Triangles);
  }
  if (swept) {
    delaunay_flips_manifold(mesh.points, mesh.triangles);
  } else {
    // The outline edges, never flipped: lines, convex curves' chords and
    // concave curves' legs.
    thread_local std::vector<EdgeKey> constrained;  // scratch
    constrained.clear();
    for (const auto& line : mesh.boundary_lines) constrained.push_back(edge_key(line[0], line[1]));
    for (const CurvedTriangle& c : mesh.curves) {
      if (c.convex) {
        constrained.push_back(edge_key(c.p0, c.p2));
      } else {
        constrained.push_back(edge_key(c.p0, c.control));
        constrained.push_back(edge_key(c.control, c.p2));
      }
    }
    std::sort(constrained.begin(), constrained.end());
    constrained.erase(std::unique(constrained.begin(), constrained.end()), constrained.end());
    delaunay_flips(mesh.points, mesh.triangles, constrained);
  }
  stage_mark(MeshStage::Flips);
  return true;
}

}  // namespace

namespace {

void build_checked_mesh(const Outline& outline, const MeshOptions& options, double largest, Mesh& mesh) {
  const double merge_distance = tolerance::kMergeDistanceRelative * largest;
  bool needs_check = false;
  if (!build_mesh_once(outline, options, merge_distance, mesh, false, needs_check)) {
    needs_check = false;
    build_mesh_once(outline, options, merge_distance, mesh, true, needs_check);
  }
  if (!needs_check) return;
  // Self-check before success: a mesh from the general path (ear clipping, or
  // crossings resolved with conflicts left) that breaks an invariant is an
  // error, never a result.
  const MeshCheck check = check_mesh(mesh, to_quadratic_outline(outline, options.cubic_tolerance));
  if (!check.ok())
    throw Error(ErrorCode::Geometry, "build_mesh: the mesh fails its own check (" + check.problems.front() + ")");
}

}  // namespace

void build_mesh(const Outline& outline, const MeshOptions& options, Mesh& mesh) {
  // (Non-finite coordinates and weights are found while cleaning: clean_rings.)
  if (!(options.cubic_tolerance > 0.0) || !std::isfinite(options.cubic_tolerance)) {
    throw Error(ErrorCode::Geometry, "build_mesh: cubic_tolerance must be positive and finite");
  }
  detail::stage_start();  // (no-op unless built with CURVETEXT_STAGE_TIMING)
  try {
    thread_local Outline flushed;  // (storage reused; rarely needed)
    double largest = 0.0;
    const bool flush = detail::flush_tiny_coordinates(outline, flushed, largest);
    if (std::isfinite(largest) && largest > tolerance::kMaxMeshCoordinate) {
      char message[160];
      std::snprintf(message, sizeof message, "build_mesh: outline coordinate %.17g is beyond the largest accepted (%g)",
                    largest, tolerance::kMaxMeshCoordinate);
      throw Error(ErrorCode::Geometry, message);
    }
    build_checked_mesh(flush ? flushed : outline, options, largest, mesh);
  } catch (const std::bad_alloc&) {
    mesh = Mesh{};
    throw Error(ErrorCode::Geometry, "build_mesh: out of memory while meshing the outline");
  }
}

Mesh build_mesh(const Outline& outline, const MeshOptions& options) {
  Mesh mesh;
  build_mesh(outline, options, mesh);
  return mesh;
}

}  // namespace curvetext
