// Private to tessellate/: the ring model the mesh builder works on between
// the quadratic outline and the polygon loops.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "curvetext/outline.hpp"
#include "tessellate/predicates.hpp"

namespace curvetext::detail {

// Whether a point of winding number `winding` is filled under `rule`.
inline bool fills(FillRule rule, int winding) { return rule == FillRule::NonZero ? winding != 0 : (winding & 1) != 0; }

// One piece of a closed ring: a line or a conic from `a` to the next piece's `a`.
struct Piece {
  Vec2 a;
  Vec2 control;  // conics only
  double weight = 1.0;
  bool conic = false;
  int depth = 0;  // hull-separation subdivisions that produced this piece
  // separate_hulls: the piece's hull is new since its last pass (a new piece,
  // or one whose end moved); only pairs with a fresh piece are tested again.
  bool fresh = true;
};
using Ring = std::vector<Piece>;

// Rings out of use, kept with their storage: the rings of the next outline
// reuse it (no allocation per glyph once warm). take gives an empty ring,
// with storage from the pool when it has some; recycle(_all) give storage
// back (the pool is capped).
class RingPool {
 public:
  Ring take();
  void recycle(Ring&& ring);
  void recycle_all(std::vector<Ring>& rings);  // and clears `rings`

 private:
  std::vector<Ring> spare_;
};

// (i < ring.size(); a compare instead of a division in the hot loops.)
inline Vec2 ring_end(const Ring& ring, std::size_t i) { return ring[i + 1 == ring.size() ? 0 : i + 1].a; }

// Reverses the direction of a ring in place (nesting.cpp).
void reverse_ring(Ring& ring);

// Exact signed area of a ring (conic caps included), counter-clockwise > 0.
double ring_area(const Ring& ring);

// The coordinate rule of tolerance::kFlushCoordinate*: when some coordinate
// of `outline` is to be read as 0, `flushed` becomes a copy with those
// coordinates 0 and the result is true. `largest` is set to the largest
// |coordinate| (infinite or NaN ones aside), for the kMaxMeshCoordinate test.
bool flush_tiny_coordinates(const Outline& outline, Outline& flushed, double& largest);

// True when two hulls (2 points: a segment; 3: a control triangle) share any
// point other than a common vertex.
bool hulls_overlap(const Vec2* p, int np, const Vec2* q, int nq);

// Ear clipping's budget of vertex visits for a polygon of `vertices`
// (tolerance::kEarClipVisitsPerVertex).
std::size_t ear_clip_budget(std::size_t vertices);

// The work budget of one build from its cleaned rings' piece count
// (tolerance::kMeshWorkPerPiece, kMeshWorkBase).
std::size_t mesh_work_budget(std::size_t pieces);

// Throws Error(Geometry) naming the stage whose work (pieces, edges or cut
// points) went past the budget.
[[noreturn]] void work_budget_exceeded(const char* stage, std::size_t used, std::size_t budget);

// Position of p against the chord polygon of a ring (nonzero winding).
Where point_in_ring(const Ring& ring, Vec2 p);

// Splits a closed ring at every vertex it passes through more than once into
// sub-rings that pass through each vertex once (same winding everywhere).
// `slots`: scratch for the position table.
std::vector<Ring> split_at_repeated_vertices(const Ring& ring, std::vector<std::int32_t>& slots);

}  // namespace curvetext::detail
