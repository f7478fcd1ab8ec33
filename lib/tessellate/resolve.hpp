// Crossing resolution (resolve.cpp): crossing, overlapping and edge-sharing
// contours become non-crossing rings of their nonzero fill, through the
// arrangement of their pieces (docs/design.md section 4).
#pragma once

#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "curvetext/geometry.hpp"
#include "tessellate/rings.hpp"

namespace curvetext::detail {

// Whether hull separation reported success on the rings given (no conic hull
// overlaps another piece), which spares looking for conics in conflict until
// lines have been split.
enum class HullState { Separated, NotSeparated };

// A piece of the arrangement: a line or a conic whose hull nothing enters.
struct ArrangementEdge {
  Vec2 a, b;
  Vec2 control;
  double weight = 1.0;
  bool conic = false;
  int depth = 0;
  int count = 1;  // net number of times the outline runs a -> b
  Box box;
  // New since the last conflict sweep (resolve_crossings): only pairs with a
  // fresh edge can conflict in a way that sweep has not seen.
  bool fresh = true;
};

// A point where a line edge is to be split.
struct CutPoint {
  std::uint32_t edge;
  Vec2 p;
};

// Scratch memory of the crossing resolver, reused from outline to outline
// (no allocation once warm).
struct ResolveScratch {
  struct CloseKey {
    double low;
    std::uint32_t edge;
  };
  struct LooseCut {
    Vec2 p;
    std::size_t cut;
  };
  // Up to two joins per edge (at a and at b): the other edge, and whether its
  // sides are swapped.
  struct Join {
    std::uint32_t other = UINT32_MAX;
    bool swapped = false;
  };
  std::vector<std::int32_t> slots;  // the position tables (one in use at a time)
  // Pairs of edges whose boxes meet (for_each_close_pair, for_each_fresh_pair).
  std::vector<CloseKey> close_keys;
  std::vector<double> close_sides;
  std::vector<std::uint32_t> candidates;
  // Cut points: found, snapped (snap_cuts), and the edges they split.
  std::vector<CutPoint> cuts;
  std::vector<Vec2> vertices, representatives, along;
  // snap_many_cuts: points by cell of side eps (cell key -> points).
  using SnapCells = std::unordered_map<std::uint64_t, std::vector<Vec2>>;
  SnapCells vertex_cells, representative_cells;
  std::vector<LooseCut> loose;
  std::vector<double> coordinates;
  std::vector<ArrangementEdge> split_edges, merged, kept;
  // side_windings: chains, rays and nodes.
  std::vector<Join> joins;
  std::vector<std::uint32_t> first_of, ends_at, second_end, straddling, node_of, node_start, node_ends, fill, pending;
  std::vector<double> heights;
  std::vector<char> done, node_done;
  std::vector<int> left, right;
  // Tracing the kept edges into rings.
  std::vector<std::uint32_t> start_vertex, end_vertex, out_first, out_edges, ring_edges;
  std::vector<Vec2> controls;
  std::vector<char> used;
  Ring traced;
};

// True when two pieces of the (hull-separated) rings share a point other
// than a common vertex: crossings, T-junctions, shared stretches, duplicates,
// conic hulls still overlapping something at the subdivision limit. With
// HullState::Separated conic hulls are not tested again (only lines against
// lines and shared end points).
bool rings_cross(const std::vector<Ring>& rings, HullState hulls, ResolveScratch& scratch);

// rings_cross's test for two line pieces [a, b] and [c, d]: true when they
// share a point other than one common end point.
bool lines_cross(Vec2 a, Vec2 b, Vec2 c, Vec2 d);

// Non-crossing rings, fill on the left (outer counter-clockwise, holes
// clockwise), covering exactly the fill of `rings` under `rule`, ring r run
// counts[r] times (`counts` empty: once each; fold_repeated_rings) (crossing conics
// replaced by chords at the hull-subdivision limit). Input: the rings after
// separate_hulls, which reported `hulls`. `settled`, when given, is set to
// true when the last look found no conflict left (no crossing, no
// T-junction, no conic hull overlapping another piece): the rings are then as
// separate_hulls would leave them, with no crossing. Edges and each round's
// cut points beyond `max_pieces` throw Error(Geometry). The rings come from
// `pool`, and rings dropped go back to it.
std::vector<Ring> resolve_crossings(const std::vector<Ring>& rings, const std::vector<int>& counts, HullState hulls,
                                    FillRule rule, std::size_t max_pieces, RingPool& pool, ResolveScratch& scratch,
                                    bool* settled = nullptr);

}  // namespace curvetext::detail
