// Polygon stage of the tessellator (paper 3.1): the plane sweep for loops
// that neither cross nor touch (sweep.cpp); for the others, holes bridged
// into their container and ear clipping of the resulting weakly simple loops;
// then Lawson flips towards a constrained Delaunay triangulation.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <set>
#include <utility>
#include <vector>

#include "curvetext/geometry.hpp"

namespace curvetext::detail {

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
std::vector<PolygonLoops> relink_touching_loops(std::vector<Vec2> outer, std::vector<std::vector<Vec2>> holes);

// Appends counter-clockwise triangles covering the loop (filled side on the
// left). Works on weakly simple loops with repeated vertices and collinear
// runs. Always terminates in O(n^2) ear tests per removed vertex at most; on an
// invalid loop it falls back to best-effort ears (check_mesh reports the damage).
// Returns false when a fallback was needed. (Simple loops that neither cross
// nor touch each other go to sweep_triangulate instead.) Throws
// Error(Geometry) once its ear tests have looked at more than `max_visits`
// vertices in all (each test looks at up to every vertex left).
bool ear_clip(const std::vector<Vec2>& loop, std::vector<std::array<Vec2, 3>>& triangles,
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
                       std::vector<std::array<std::uint32_t, 3>>& triangles, bool* repeated_position = nullptr);

using EdgeKey = std::pair<std::uint32_t, std::uint32_t>;  // (min index, max index)
inline EdgeKey edge_key(std::uint32_t a, std::uint32_t b) { return a < b ? EdgeKey{a, b} : EdgeKey{b, a}; }

// Lawson flips on counter-clockwise index triangles: an edge shared by two
// triangles whose quad is strictly convex is flipped while the opposite vertex
// lies inside the circumcircle. Edges in `constrained` are never flipped. The
// number of flips is bounded (see implementation), so it always terminates.
// `constrained` is sorted and free of duplicates.
void delaunay_flips(const std::vector<Vec2>& points, std::vector<std::array<std::uint32_t, 3>>& triangles,
                    const std::vector<EdgeKey>& constrained);

// The same flips for the triangulation of polygon loops that sweep_triangulate
// makes: planar and manifold, every edge of a loop on exactly one triangle
// and every other edge on two. The constrained edges are then exactly the
// edges with one triangle, which are never flipped, so no list is needed;
// triangle adjacency comes from a table indexed by an edge's two vertices (a
// hash of them for large meshes), and a flip never checks whether the new
// diagonal exists (in a planar triangulation the diagonal of a convex quad
// cannot).
void delaunay_flips_manifold(const std::vector<Vec2>& points, std::vector<std::array<std::uint32_t, 3>>& triangles);

}  // namespace curvetext::detail
