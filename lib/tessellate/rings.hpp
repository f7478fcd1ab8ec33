// Private to tessellate/: the ring model the mesh builder works on between
// the quadratic outline and the polygon loops.
#pragma once

#include <vector>

#include "curvetext/outline.hpp"
#include "tessellate/predicates.hpp"

namespace curvetext::detail {

// One piece of a closed ring: a line or a conic from `a` to the next piece's `a`.
struct Piece {
  Vec2 a;
  Vec2 control;  // conics only
  double weight = 1.0;
  bool conic = false;
  int depth = 0;  // hull-separation subdivisions that produced this piece
};
using Ring = std::vector<Piece>;

inline Vec2 ring_end(const Ring& ring, std::size_t i) { return ring[(i + 1) % ring.size()].a; }

// A filled region: its outer ring (counter-clockwise) and its holes (clockwise).
struct Region {
  Ring outer;
  std::vector<Ring> holes;
};

// Exact signed area of a ring (conic caps included), counter-clockwise > 0.
double ring_area(const Ring& ring);

// Rings of the quadratic outline with zero-length pieces, flat conics, exact
// collinear runs and spikes removed, each split at its repeated vertices into
// sub-rings that pass through every vertex once; rings without area dropped.
std::vector<Ring> clean_rings(const Outline& quadratic);

// True when two hulls (2 points: a segment; 3: a control triangle) share any
// point other than a common vertex.
bool hulls_overlap(const Vec2* p, int np, const Vec2* q, int nq);

// Subdivides conics until no conic hull overlaps another piece's hull, to at
// most tolerance::kMaxHullSubdivisionDepth levels.
void separate_hulls(std::vector<Ring>& rings);

// Position of p against the chord polygon of a ring (nonzero winding).
Where point_in_ring(const Ring& ring, Vec2 p);

// Nonzero-rule roles of non-crossing rings: which bound the fill, their
// orientation normalised, holes attached to their innermost container.
std::vector<Region> nest_rings(std::vector<Ring> rings);

}  // namespace curvetext::detail
