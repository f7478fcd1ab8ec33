// Hull separation, the second stage of build_mesh: conics are subdivided
// until no conic's control triangle overlaps another piece's hull, so that
// every curved triangle can be drawn on its own (docs/design.md section 4).
#pragma once

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "curvetext/geometry.hpp"
#include "tessellate/rings.hpp"

namespace curvetext::detail {

// Whether hull separation splits two pieces whose curves cross at their
// crossing (Split), or only halves conics (Keep).
enum class CrossingSplits { Split, Keep };

// Scratch memory of separate_hulls, reused from outline to outline (no
// allocation once warm). Read by one HullSeparator at a time.
struct HullScratch {
  // A piece's hull with what the pair tests need, copied out of the rings so
  // the pair loop reads one compact array.
  struct HullRef {
    Box box;
    Vec2 hull[3];  // a, b (line) or a, control, b (conic)
    int n;         // 2 or 3
    int depth;
    double weight;
    std::size_t mark;  // index into split_marks
    Vec2 end() const { return hull[n - 1]; }
  };
  struct SortKey {
    double min_a;
    std::uint32_t ref;
  };
  std::vector<HullRef> refs;  // grown, never shrunk (resize would construct every record again)
  // The overlapping pairs of the pass (ref indices: first piece << 32 |
  // second), and those of the pass before with where each of its pieces went:
  // piece k became pieces child_first[k] .. child_first[k + 1] - 1.
  std::vector<std::uint64_t> overlaps, partners;
  std::vector<std::uint32_t> child_first;
  std::vector<std::size_t> mark_base;  // ring r's marks start at mark_base[r]
  // 0: kept; 1: halved; 2: split at split_at[k], the new vertex being
  // split_point[k] (a crossing, shared by the two pieces split there).
  std::vector<char> split_marks;
  std::vector<double> split_at;
  std::vector<Vec2> split_point;
  // Further points of the pass to split lines at (mark, point).
  std::vector<std::pair<std::uint32_t, Vec2>> more_line_points;
  // Ring neighbours of each piece, and whether a piece's hull certainly meets
  // its successor's only at their common vertex.
  std::vector<std::uint32_t> next_piece, previous_piece;
  std::vector<char> apart_from_next;
  std::vector<double> box_sides, sorted_sides;  // columns<4>: min x, max x, min y, max y
  std::vector<std::uint32_t> fresh_refs, candidates;
  std::vector<std::uint32_t> sorted_conics;  // positions of the conics in the sweep's order
  std::vector<std::uint64_t> fresh_words;
  std::vector<SortKey> keys;
  std::vector<Vec2> line_points;  // one line's split points, in order along it
};

struct HullSeparation {
  // No conic hull overlaps another piece's any more (identical conics aside).
  bool separated = false;
  // When separated: rings_cross(rings, true), found in the same sweep over
  // the pieces (the usual glyph then needs no second sweep). Whatever else
  // is found, true when pieces were split at a crossing or at a point where
  // a conic touches a line (CrossingSplits::Split).
  bool crossing = false;
};

// Subdivides conics until no conic hull overlaps another piece's hull, to at
// most tolerance::kMaxHullSubdivisionDepth levels. With CrossingSplits::Split,
// a conic whose chord crosses the chord of another piece is split where the
// two curves cross (found by Newton's method), and that piece too, both at
// the same point, instead of halving the conic ten times towards the
// crossing; the rings then cross at a common vertex, which only the crossing
// resolver deals with. In every call, a line on which a conic ends, or along
// which a conic's leg runs, is split at that point (exact: the point is on
// the line) instead of the conic being halved towards it. `max_pieces`: the
// work budget (tolerance::kMeshWorkPerPiece); a pass that leaves more pieces
// than that, or more pair tests than tolerance::kMeshPairTestsPerPiece per
// kMeshWorkPerPiece of it, throws Error(Geometry).
HullSeparation separate_hulls(std::vector<Ring>& rings, CrossingSplits splits, std::size_t max_pieces,
                              HullScratch& scratch, RingPool& pool);

}  // namespace curvetext::detail
