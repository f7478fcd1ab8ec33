// Private to tessellate/: the ring model the mesh builder works on between
// the quadratic outline and the polygon loops.
#pragma once

#include <cstddef>
#include <cstdint>
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
  // separate_hulls: the piece's hull is new since its last pass (a new piece,
  // or one whose end moved); only pairs with a fresh piece are tested again.
  bool fresh = true;
};
using Ring = std::vector<Piece>;

// Rings out of use, kept with their storage in a per-thread pool: the rings
// of the next glyph reuse it (no allocation per glyph once warm). take_ring
// gives an empty ring, with storage from the pool when it has some;
// recycle_ring(s) give storage back (the pool is capped).
Ring take_ring();
void recycle_ring(Ring&& ring);
void recycle_rings(std::vector<Ring>& rings);  // and clears `rings`

// (i < ring.size(); a compare instead of a division in the hot loops.)
inline Vec2 ring_end(const Ring& ring, std::size_t i) { return ring[i + 1 == ring.size() ? 0 : i + 1].a; }

// Exact signed area of a ring (conic caps included), counter-clockwise > 0.
double ring_area(const Ring& ring);

// The coordinate rule of tolerance::kFlushCoordinate*: when some coordinate
// of `outline` is to be read as 0, `flushed` becomes a copy with those
// coordinates 0 and the result is true. `largest` is set to the largest
// |coordinate| (infinite or NaN ones aside), for the kMaxMeshCoordinate test.
bool flush_tiny_coordinates(const Outline& outline, Outline& flushed, double& largest);

// Rings of the outline (cubics replaced by quadratics within
// `cubic_tolerance`, as to_quadratic_outline does) with zero-length pieces
// (ends closer than `merge_distance`), flat conics, exact collinear runs and spikes removed, each split at its
// repeated vertices into sub-rings that pass through every vertex once
// (unless split_repeated is false: build_mesh looks for such rings only where
// they matter); rings without area dropped. Replaces the contents of `rings`,
// whose old rings go to a per-thread pool that the new ones draw from (their
// storage is reused: no allocation per glyph once warm). Returns false when
// a coordinate or weight is not finite or a weight is not positive
// (Outline::is_finite): the rings are then not to be used.
// `approximated`, when given, is set when a piece was straightened that was
// within the flatness tolerance but not exactly flat (the area changed).
bool clean_rings(const Outline& outline, double cubic_tolerance, double merge_distance, std::vector<Ring>& rings,
                 bool split_repeated = true, bool* approximated = nullptr);

// True when two hulls (2 points: a segment; 3: a control triangle) share any
// point other than a common vertex.
bool hulls_overlap(const Vec2* p, int np, const Vec2* q, int nq);

// Subdivides conics until no conic hull overlaps another piece's hull, to at
// most tolerance::kMaxHullSubdivisionDepth levels. Returns true when no conic
// hull overlaps another piece's any more (identical conics aside). Then, if
// `crossing` is not null, it is set to rings_cross(rings, true), found in the
// same sweep over the pieces (the usual glyph then needs no second sweep).
// With `split_at_crossings`, a conic whose chord crosses the chord of another
// piece is split where the two curves cross (found by Newton's
// method), and that piece too, both at the same point, instead of halving the
// conic ten times towards the crossing; `crossing` is then set to true
// whatever else is found (the rings now cross at a common vertex, which only
// the crossing resolver deals with), and it must not be null. In every call,
// a line on which a conic ends, or along which a conic's leg runs, is split
// at that point (exact: the point is on the line) instead of the conic being
// halved towards it; with `split_at_crossings` that too sets `crossing`
// (contours touching there may overlap without crossing anywhere).
// `max_pieces`: the work budget (tolerance::kMeshWorkPerPiece); a pass that
// leaves more pieces than that, or more pair tests than
// tolerance::kMeshPairTestsPerPiece per kMeshWorkPerPiece of it, throws
// Error(Geometry).
bool separate_hulls(std::vector<Ring>& rings, bool* crossing = nullptr, bool split_at_crossings = false,
                    std::size_t max_pieces = SIZE_MAX);

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
std::vector<Ring> split_at_repeated_vertices(const Ring& ring);

// Internal switch for the crossing resolver (resolve.cpp). Off, crossing
// outlines go through the non-crossing path as before (wrong fill, no crash).
inline constexpr bool kResolveCrossingContours = true;

// True when two pieces of the (hull-separated) rings share a point other
// than a common vertex: crossings, T-junctions, shared stretches, duplicates,
// conic hulls still overlapping something at the subdivision limit.
// `hulls_separated`: separate_hulls reported success, so conic hulls need not
// be tested again (only lines against lines and shared end points).
bool rings_cross(const std::vector<Ring>& rings, bool hulls_separated);

// rings_cross's test for two line pieces [a, b] and [c, d]: true when they
// share a point other than one common end point.
bool lines_cross(Vec2 a, Vec2 b, Vec2 c, Vec2 d);

// Non-crossing rings, fill on the left (outer counter-clockwise, holes
// clockwise), covering exactly the nonzero fill of `rings` (crossing conics
// replaced by chords at the hull-subdivision limit). Input: the rings after
// separate_hulls; `hulls_separated`: it reported success (no conic hull
// overlaps another piece), which spares looking for conics in conflict
// until lines have been split. `settled`, when given, is set to true when the
// last look found no conflict left (no crossing, no T-junction, no conic hull
// overlapping another piece): the rings are then as separate_hulls would
// leave them, with no crossing.
// Edges and each round's cut points beyond `max_pieces` throw Error(Geometry).
std::vector<Ring> resolve_crossings(const std::vector<Ring>& rings, bool hulls_separated = false,
                                    bool* settled = nullptr, std::size_t max_pieces = SIZE_MAX);

// Nonzero-rule roles of non-crossing rings: which bound the fill, their
// orientation normalised in place (fill on the left: outer rings
// counter-clockwise, holes clockwise), holes attached to their innermost
// container. Region r is the rings region_rings[region_start[r] ..
// region_start[r + 1]): its outer ring, then its holes; rings bounding no fill
// are in no region.
void nest_rings(std::vector<Ring>& rings, std::vector<std::uint32_t>& region_rings,
                std::vector<std::uint32_t>& region_start);

}  // namespace curvetext::detail
