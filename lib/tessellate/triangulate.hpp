// Polygon stage of the tessellator (paper 3.1): the plane sweep for loops
// that neither cross nor touch (sweep.cpp); for the others, holes bridged
// into their container and ear clipping of the resulting weakly simple loops;
// then Lawson flips towards a constrained Delaunay triangulation.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <set>
#include <utility>
#include <vector>

#include "core/assert.hpp"
#include "curvetext/geometry.hpp"
#include "tessellate/positions.hpp"

namespace curvetext::detail {

using EdgeKey = std::pair<std::uint32_t, std::uint32_t>;  // (min index, max index)
inline EdgeKey edge_key(std::uint32_t a, std::uint32_t b) { return a < b ? EdgeKey{a, b} : EdgeKey{b, a}; }

// The sweep's state (sweep.cpp), kept from call to call for its memory.
struct SweepScratch {
  static constexpr int kNoPolygon = -1;
  // A status interval: the fill between boundary edges `left` and `right`
  // (an edge is named by the loop position it starts at). `poly[0]` is the
  // monotone polygon in progress; after a merge vertex (`merged`) the
  // interval holds two, left (poly[0]) and right (poly[1]) of it, until the
  // next vertex in the interval connects to the merge vertex, which is the
  // top of both stacks.
  struct Interval {
    std::uint32_t left = 0, right = 0;
    int poly[2] = {kNoPolygon, kNoPolygon};
    bool merged = false;
  };
  // A loop position's (y, x) key (position_key).
  struct Key {
    Uint128 yx;
    std::uint32_t position;
  };
  // Per loop position: the neighbours in its loop, the rank in sweep order,
  // its loop, its point (one indirection fewer than points[vertices[i]]).
  std::vector<std::uint32_t> prev, next, rank, order, loop_of;
  std::vector<Vec2> position;
  std::vector<Interval> status;
  // Monotone polygon stacks: loop positions, a flag bit on right-chain entries.
  std::vector<std::vector<std::uint32_t>> stacks;
  std::vector<int> free_stacks;
  std::vector<Key> keys, sorted;                // sort_by_key's input and buckets
  std::vector<std::uint32_t> bucket_of, first;  // (its distribution pass)
  std::vector<char> loop_seen;
};

// The live vertices of the loop being clipped, each with the box of its
// outgoing edge, in a compact array (removal swaps with the last entry). An
// ear test must look at every vertex p whose edge p -> next(p) has a box
// overlapping the candidate triangle's box (that includes every vertex inside
// the box); the test's answer does not depend on the order the vertices are
// looked at, so scanning this array, where the box test is a few loads and
// compares per vertex, replaces the walk along the linked loop.
class LiveEdges {
 public:
  struct Entry {
    double x0, x1, y0, y1;  // box of the edge p -> next[p]
    std::uint32_t p;
  };

  void reset(std::size_t n) {
    entries_.clear();
    slot_.assign(n, kNone);
  }
  void set(std::uint32_t p, Vec2 a, Vec2 b) {
    Entry e{std::min(a.x, b.x), std::max(a.x, b.x), std::min(a.y, b.y), std::max(a.y, b.y), p};
    if (slot_[p] == kNone) {
      slot_[p] = static_cast<std::uint32_t>(entries_.size());
      entries_.push_back(e);
    } else {
      entries_[slot_[p]] = e;
    }
  }
  void erase(std::uint32_t p) {
    const std::uint32_t k = slot_[p];
    if (k == kNone) return;
    CURVETEXT_ASSERT(entries_[k].p == p);  // slot_ and entries_ name each other
    entries_[k] = entries_.back();
    slot_[entries_[k].p] = k;
    entries_.pop_back();
    slot_[p] = kNone;
  }
  const std::vector<Entry>& entries() const { return entries_; }

 private:
  static constexpr std::uint32_t kNone = 0xffffffffu;
  std::vector<Entry> entries_;
  std::vector<std::uint32_t> slot_;
};

// Edge (min index, max index) -> the triangles on its two sides, in an
// open-addressing table (no per-edge allocation). A flipped-away edge keeps
// its slot with count 0, which reads as "no such edge".
class EdgeTable {
 public:
  struct Faces {
    std::uint64_t key = kEmpty;
    std::uint32_t face[2] = {0, 0};
    int count = 0;
    bool fixed = false;  // a constrained (outline) edge: never flipped
  };

  // Empties the table for about `expected` edges, keeping its memory.
  void reset(std::size_t expected) {
    std::size_t capacity = 16;
    while (capacity < 2 * expected + 16) capacity *= 2;
    slots_.assign(capacity, Faces{});
    used_ = 0;
  }

  static std::uint64_t pack(EdgeKey k) { return (std::uint64_t{k.first} << 32) | k.second; }

  Faces& at(EdgeKey k) {
    const std::uint64_t key = pack(k);
    if (2 * (used_ + 1) > slots_.size()) grow();
    std::size_t slot = hash(key) & (slots_.size() - 1);
    while (slots_[slot].key != kEmpty && slots_[slot].key != key) slot = (slot + 1) & (slots_.size() - 1);
    if (slots_[slot].key == kEmpty) {
      slots_[slot].key = key;
      ++used_;
    }
    return slots_[slot];
  }

  // The live entry of edge k (count > 0), or null.
  Faces* find(EdgeKey k) {
    const std::uint64_t key = pack(k);
    std::size_t slot = hash(key) & (slots_.size() - 1);
    while (slots_[slot].key != kEmpty) {
      if (slots_[slot].key == key) return slots_[slot].count > 0 ? &slots_[slot] : nullptr;
      slot = (slot + 1) & (slots_.size() - 1);
    }
    return nullptr;
  }

 private:
  static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};
  std::vector<Faces> slots_;
  std::size_t used_ = 0;

  static std::size_t hash(std::uint64_t key) {
    // One multiply, then the high half folded down so that both vertex
    // indices reach the low bits the table masks with (lookups only: the
    // table's order never decides anything).
    const std::uint64_t h = key * 0x9e3779b97f4a7c15ull;
    return static_cast<std::size_t>(h ^ (h >> 32));
  }

  void grow() {
    std::vector<Faces> old(slots_.size() * 2, Faces{});
    old.swap(slots_);
    for (const Faces& f : old) {
      if (f.key == kEmpty) continue;
      std::size_t slot = hash(f.key) & (slots_.size() - 1);
      while (slots_[slot].key != kEmpty) slot = (slot + 1) & (slots_.size() - 1);
      slots_[slot] = f;
    }
  }
};

// Scratch memory of the polygon stage, reused from mesh to mesh (no
// allocation per glyph once warm).
struct TriangulateScratch {
  SweepScratch sweep;
  std::vector<std::pair<double, double>> relink_sorted;  // relink_touching_loops's quick test
  std::vector<std::uint32_t> ear_prev, ear_next;         // ear_clip's linked loop
  LiveEdges live;
  EdgeTable edges;  // delaunay_flips
  std::vector<EdgeKey> flip_stack, missing;
  // delaunay_flips_manifold: half-edge twins, from a direct table or a hash.
  std::vector<std::int32_t> twin;
  std::vector<std::uint16_t> direct;
  std::vector<std::uint64_t> twin_keys;
  std::vector<std::int32_t> twin_half_edges;
  std::vector<std::uint32_t> manifold_stack;
};

// Joins each hole (clockwise, y up) into the counter-clockwise `outer` loop by
// two sibling edges between a close, mutually visible vertex pair, so the
// polygon with holes becomes one weakly simple loop (bridge vertices repeat).
std::vector<Vec2> bridge_holes(std::vector<Vec2> outer, std::vector<std::vector<Vec2>> holes);

// One polygon for bridge_holes: a counter-clockwise outer loop and the
// clockwise loops of its holes.
struct PolygonLoops {
  std::vector<Vec2> outer;
  std::vector<std::vector<Vec2>> holes;
};

// Loops of one filled region (outer counter-clockwise, holes clockwise, the
// filled side on the left of every loop) re-linked where they touch: at a
// vertex that several loops (or one loop several times) pass through, each
// arrival continues along the departure that keeps the filled corner tight
// (nothing else between them), so that every corner of the resulting loops
// is a single filled sector. Loops with positive area become outers, with
// negative area holes of the smallest outer around them. A hole that touches
// its outer at two vertices thus cuts it into two polygons; holes touching each
// other become one pinched hole. Without shared vertices, returns the input.
std::vector<PolygonLoops> relink_touching_loops(std::vector<Vec2> outer, std::vector<std::vector<Vec2>> holes,
                                                TriangulateScratch& scratch);

// Appends counter-clockwise triangles covering the loop (filled side on the
// left). Works on weakly simple loops with repeated vertices and collinear
// runs. Always terminates in O(n^2) ear tests per removed vertex at most; on an
// invalid loop it falls back to best-effort ears (check_mesh reports the damage).
// Returns false when a fallback was needed. (Simple loops that neither cross
// nor touch each other go to sweep_triangulate instead.) Throws
// Error(Geometry) once its ear tests have looked at more than `max_visits`
// vertices in all (each test looks at up to every vertex left).
bool ear_clip(const std::vector<Vec2>& loop, std::vector<std::array<Vec2, 3>>& triangles, TriangulateScratch& scratch,
              std::size_t max_visits = SIZE_MAX);

// Triangulates polygon loops that neither cross nor touch (each loop simple,
// no position repeated anywhere, the filled side on the left of every edge,
// as nest_rings orients them) by one plane sweep (sweep.cpp), appending
// counter-clockwise triangles of `points` indices. Loop l is
// loop_vertices[loop_start[l] .. loop_start[l + 1]) (indices into `points`).
// Returns false, appending nothing, when the input breaks the contract or any
// decision is degenerate (a zero orientation where a strict one is needed);
// the caller then uses bridge_holes and ear_clip. Loops oriented without
// nest_rings are checked too: a loop starting inside the fill (nested with
// the fill's orientation) or a hole outside it makes it return false, and so
// does a triangle count other than n - 2 per loop around fill and n + 2 per
// hole. `repeated_position`, when given, tells whether it gave up because a
// position repeats (loops that touch: no orientation makes them sweepable).
bool sweep_triangulate(const std::vector<Vec2>& points, const std::vector<std::uint32_t>& loop_vertices,
                       const std::vector<std::uint32_t>& loop_start,
                       std::vector<std::array<std::uint32_t, 3>>& triangles, TriangulateScratch& scratch,
                       bool* repeated_position = nullptr);

// Lawson flips on counter-clockwise index triangles: an edge shared by two
// triangles whose quad is strictly convex is flipped while the opposite vertex
// lies inside the circumcircle. Edges in `constrained` are never flipped. The
// number of flips is bounded (see implementation), so it always terminates.
// `constrained` is sorted and free of duplicates.
void delaunay_flips(const std::vector<Vec2>& points, std::vector<std::array<std::uint32_t, 3>>& triangles,
                    const std::vector<EdgeKey>& constrained, TriangulateScratch& scratch);

// The same flips for the triangulation of polygon loops that sweep_triangulate
// makes: planar and manifold, every edge of a loop on exactly one triangle
// and every other edge on two. The constrained edges are then exactly the
// edges with one triangle, which are never flipped, so no list is needed;
// triangle adjacency comes from a table indexed by an edge's two vertices (a
// hash of them for large meshes), and a flip never checks whether the new
// diagonal exists (in a planar triangulation the diagonal of a convex quad
// cannot).
void delaunay_flips_manifold(const std::vector<Vec2>& points, std::vector<std::array<std::uint32_t, 3>>& triangles,
                             TriangulateScratch& scratch);

}  // namespace curvetext::detail
