// Cleaning, the first stage of build_mesh: the outline's contours become
// rings of lines and conics (cubics replaced by quadratics) with degenerate
// pieces removed (docs/design.md section 4).
#pragma once

#include <cstdint>
#include <vector>

#include "curvetext/outline.hpp"
#include "tessellate/rings.hpp"

namespace curvetext::detail {

// Whether rings that pass through a vertex twice are split there into
// sub-rings (split_at_repeated_vertices).
enum class RepeatedVertices { Split, Keep };

// Scratch memory of clean_rings, reused from outline to outline.
struct CleanScratch {
  std::vector<Segment> quadratics;  // one cubic's replacement
  std::vector<char> drop;           // simplify_pass: pieces to remove
  std::vector<std::int32_t> slots;  // the position table of repeats_a_vertex
  // fold_repeated_rings: per ring, its piece count, lowest start point and
  // that piece's index (SIZE_MAX where the lowest point repeats).
  struct RingKey {
    std::size_t size, start, ring;
    Vec2 lowest;
  };
  std::vector<RingKey> ring_keys;
};

// Rings of the outline (cubics replaced by quadratics within
// `cubic_tolerance`, as to_quadratic_outline does) with zero-length pieces
// (ends closer than `merge_distance`), flat conics, exact collinear runs and
// spikes removed, each split at its repeated vertices into sub-rings that
// pass through every vertex once (unless `repeated` is Keep: build_mesh looks
// for such rings only where they matter); rings without area dropped.
// Replaces the contents of `rings`, whose old rings go to `pool`, which the
// new ones draw from. Returns false when a coordinate or weight is not finite
// or a weight is not positive (Outline::is_finite): the rings are then not to
// be used. `approximated`, when given, is set when a piece was straightened
// that was within the flatness tolerance but not exactly flat (the area
// changed).
bool clean_rings(const Outline& outline, double cubic_tolerance, double merge_distance, std::vector<Ring>& rings,
                 RingPool& pool, CleanScratch& scratch, RepeatedVertices repeated = RepeatedVertices::Split,
                 bool* approximated = nullptr);

// True when the ring passes through some vertex twice (`slots`: scratch).
// Rings run over themselves: rings equal to each other (the same pieces from
// some start, in the same or the opposite direction) become one ring with a
// count, the net number of times the outline runs it (copies in opposite
// directions cancel; a ring whose count comes to 0 is dropped). Without this,
// n copies of a ring cost n^2 pair tests in hull separation. Only outlines of
// tolerance::kFoldRingsMinPieces pieces or more are searched. Returns true
// when rings were folded; `counts[r]` is then ring r's count (the crossing
// resolver takes it), and otherwise `counts` is left empty (every count 1).
bool fold_repeated_rings(std::vector<Ring>& rings, std::vector<int>& counts, RingPool& pool, CleanScratch& scratch);

bool repeats_a_vertex(const Ring& ring, std::vector<std::int32_t>& slots);

}  // namespace curvetext::detail
