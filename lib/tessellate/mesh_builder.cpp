// build_mesh (docs/design.md section 4): outline -> cleaned rings
// (cleaning.cpp) -> separated hulls (hull_separation.cpp) -> (crossing,
// overlapping or edge-sharing contours only: resolve.cpp's non-crossing rings
// of the nonzero fill, hulls separated again unless the resolver left nothing
// in conflict) -> orientation -> polygon loops + curved triangles ->
// triangles -> Lawson flips -> indexed mesh. Loops that neither cross nor
// touch (the usual glyph) are triangulated by one plane sweep (sweep.cpp),
// first with every ring oriented by the outermost one, which the sweep
// checks; where it gives up, the rings are nested and oriented one by one
// (nesting.cpp) and swept again, or bridged and ear-clipped
// (triangulate.cpp). A MeshBuilder holds the scratch memory of every stage.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <new>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "core/assert.hpp"
#include "curvetext/curves.hpp"
#include "curvetext/error.hpp"
#include "curvetext/mesh.hpp"
#include "core/tolerances.hpp"
#include "tessellate/cleaning.hpp"
#include "tessellate/hull_separation.hpp"
#include "tessellate/nesting.hpp"
#include "tessellate/positions.hpp"
#include "tessellate/predicates.hpp"
#include "tessellate/resolve.hpp"
#include "tessellate/rings.hpp"
#include "tessellate/self_check.hpp"
#include "tessellate/stage_timing.hpp"
#include "tessellate/triangulate.hpp"

namespace curvetext {

namespace detail {

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

}  // namespace detail

// The scratch memory of every stage, kept from one build to the next.
struct MeshBuilder::Scratch {
  detail::RingPool pool;
  std::vector<detail::Ring> rings;
  std::vector<int> ring_counts;  // fold_repeated_rings (empty: every ring once)
  detail::CleanScratch clean;
  detail::HullScratch hulls;
  detail::ResolveScratch resolve;
  detail::NestScratch nest;
  detail::TriangulateScratch triangulate;
  // Polygon loops as vertex indices, grouped by region when nest_rings has
  // made regions (outer loop first, then its holes): loop l is
  // loop_vertices[loop_start[l] .. loop_start[l + 1]), region r's loops are
  // region_first_loop[r] .. region_first_loop[r + 1].
  std::vector<std::uint32_t> loop_vertices, loop_start;
  std::vector<std::size_t> region_first_loop;
  // Region r is rings region_rings[region_start[r] .. region_start[r + 1]):
  // its outer ring, then its holes.
  std::vector<std::uint32_t> region_rings, region_start;
  std::vector<std::uint32_t> sweep_vertices, sweep_start;  // the loops of three vertices or more
  std::vector<std::array<Vec2, 3>> triangle_points;        // ear clipping's output
  std::vector<detail::EdgeKey> constrained;                // the outline's edges, never flipped
  std::vector<std::uint32_t> point_slots;                  // PointIndex's table
  Outline flushed;                                         // tiny coordinates read as 0 (rarely needed)
};

namespace {

using namespace detail;
using Scratch = MeshBuilder::Scratch;

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

  PointIndex(std::vector<Vec2>& points_out, std::vector<std::uint32_t>& slots, std::size_t expected)
      : points(points_out), slots_(slots) {
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
    CURVETEXT_ASSERT(4 * (points.size() + 1) <= slots_.size());  // at most a quarter full: a free slot ends every probe
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
  std::vector<std::uint32_t>& slots_;  // the caller's storage
  int bits_ = 4;                       // log2(slots_.size())

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

// The next vertex index for every position (loops for the sweep, where no
// position repeats).
struct NextIndex {
  std::vector<Vec2>& points;
  std::uint32_t operator()(Vec2 p) {
    points.push_back(p);
    return static_cast<std::uint32_t>(points.size() - 1);
  }
};

// How the rings are walked into polygon loops: as they are, or every ring
// backwards (the fill on its right), as nest_rings's reverse_ring would turn it.
enum class Walk { Forward, Backward };

// One build of one outline into a mesh: the stages in order, with what they
// hand on to each other as members.
class Build {
 public:
  Build(Scratch& scratch, const MeshOptions& options, double merge_distance, RepeatedVertices repeated, Mesh& mesh)
      : s_(scratch), options_(options), merge_distance_(merge_distance), repeated_(repeated), mesh_(mesh) {}

  // Returns true when the mesh is built; false when, with
  // RepeatedVertices::Keep, a ring through a vertex twice made the sweep give
  // up: the caller then builds again with RepeatedVertices::Split.
  bool run(const Outline& outline);
  // The outline's cleaned rings after crossing resolution under the fill
  // rule (always resolved, so oriented with the fill on their left).
  Outline boundary(const Outline& outline);
  // boundary() lost the whole fill of unsplit rings (see run()): ask again
  // with RepeatedVertices::Split.
  bool wants_split() const { return resolved_to_nothing_ && repeated_ == RepeatedVertices::Keep; }
  // The mesh does not come from the self-checking sweep, or the outline was
  // approximated: check_mesh must pass before it is returned.
  bool needs_check() const { return needs_check_; }

 private:
  void clean(const Outline& outline);
  void separate();
  void resolve(HullState hulls);
  void sweep_as_oriented();
  Walk fast_path_walk();
  void nest();
  template <class Index>
  void make_loops(Index& index, Walk walk);
  template <class Index>
  void polygonise(const Ring& ring, Index& index, Walk walk);
  bool sweep_loops(bool* repeated);
  std::vector<Vec2> loop_positions(std::size_t l) const;
  void ear_clip_regions();
  void flip();

  Scratch& s_;
  const MeshOptions& options_;
  const double merge_distance_;
  const RepeatedVertices repeated_;
  Mesh& mesh_;
  std::size_t budget_ = 0;       // tolerance::kMeshWorkPerPiece per cleaned piece
  std::size_t piece_count_ = 0;  // pieces of the rings made into loops
  bool needs_check_ = false;
  // Pieces of separated, non-crossing rings meet only at common vertices,
  // which lets sweep_triangulate take their loops when no position repeats.
  bool simple_edges_ = false;
  bool resolved_rings_ = false;
  bool force_resolve_ = false;        // boundary(): resolve whether or not rings meet
  bool resolved_to_nothing_ = false;  // rings went into the resolver and none came out
  bool swept_ = false;
  bool repeated_position_ = false;   // the sweep gave up where a position repeats
  std::optional<PointIndex> index_;  // made when the general path needs it
};

// With RepeatedVertices::Keep, rings that pass through a vertex twice are not
// split into their lobes (clean_rings): that search costs a hash table per
// ring, and such rings are rare (none in DejaVu Sans, Noto Sans or Inter, 31
// of 20,000 Noto Sans CJK glyphs). Where it matters the build looks for them
// and returns false on finding one: when the sweep gives up (a ring through a
// vertex twice always makes it give up: the vertex repeats among its loops).
// The caller then builds again with the split, exactly as a build that split
// first. The crossing resolver needs no split: it takes the edges of all
// rings together and splits the loops it makes at repeated vertices itself.
// (Hull separation makes a ring pass through a point twice where it splits
// two of its pieces at their crossing; looking for repeats before resolving
// would build such glyphs twice, about one in 25 of Inter's.)
bool Build::run(const Outline& outline) {
  clean(outline);
  separate();
  // Rings that leave nothing once resolved, unsplit: a ring through a vertex
  // twice can lose its whole fill there (a stroke's loop run twice round a
  // capsule), where its split loops resolve right. Build again with the split.
  if (wants_split()) return false;
  mesh_.triangles.clear();
  sweep_as_oriented();
  if (wants_split()) return false;
  if (!swept_) {
    if (repeated_ == RepeatedVertices::Keep && std::any_of(s_.rings.begin(), s_.rings.end(), [&](const Ring& ring) {
          return repeats_a_vertex(ring, s_.clean.slots);
        }))
      return false;
    nest();
  }
  s_.pool.recycle_all(s_.rings);
  // The sweep checks its own output (triangle counts, orientations); the
  // other paths are checked by the caller.
  needs_check_ = needs_check_ || !swept_;
  if (!swept_) ear_clip_regions();
  flip();
  stage_mark(MeshStage::Flips);
  return true;
}

Outline Build::boundary(const Outline& outline) {
  force_resolve_ = true;
  clean(outline);
  separate();
  Outline out;
  for (const Ring& ring : s_.rings) {
    if (ring.empty()) continue;
    out.move_to(ring[0].a);
    for (std::size_t i = 0; i < ring.size(); ++i) {
      if (ring[i].conic) {
        out.conic_to(ring[i].control, ring_end(ring, i), ring[i].weight);
      } else {
        out.line_to(ring_end(ring, i));
      }
    }
    out.close();
  }
  s_.pool.recycle_all(s_.rings);
  return out;
}

void Build::clean(const Outline& outline) {
  bool approximated = false;
  if (!clean_rings(outline, options_.cubic_tolerance, merge_distance_, s_.rings, s_.pool, s_.clean, repeated_,
                   &approximated))
    throw Error(ErrorCode::Geometry, "build_mesh: outline has non-finite coordinates or weights");
  fold_repeated_rings(s_.rings, s_.ring_counts, s_.pool, s_.clean);
  // Straightening within the flatness tolerance changes the area by up to
  // 1e-9 of a chord squared, which a sliver's area may not allow.
  needs_check_ = needs_check_ || approximated;
  stage_mark(MeshStage::Clean);
  std::size_t input_pieces = 0;
  for (const Ring& ring : s_.rings) input_pieces += ring.size();
  budget_ = mesh_work_budget(input_pieces);
}

// Crossing, overlapping or edge-sharing contours: resolved into non-crossing
// rings of the nonzero fill first (skipped for the usual glyph whose
// contours do not meet; separate_hulls's sweep already told).
void Build::separate() {
  const HullSeparation separation = separate_hulls(s_.rings, CrossingSplits::Split, budget_, s_.hulls, s_.pool);
  stage_mark(MeshStage::Separate);
  simple_edges_ = separation.separated && !separation.crossing;
  // Under the even-odd rule nesting (which counts nonzero windings) cannot
  // tell the fill, nor for rings run more than once: the resolver runs, and
  // its rings bound the fill.
  const bool always = force_resolve_ || options_.fill_rule == FillRule::EvenOdd || !s_.ring_counts.empty();
  if ((always && !s_.rings.empty()) || separation.crossing ||
      (!separation.separated && rings_cross(s_.rings, HullState::NotSeparated, s_.resolve)))
    resolve(separation.separated ? HullState::Separated : HullState::NotSeparated);
  stage_mark(MeshStage::Resolve);
}

void Build::resolve(HullState hulls) {
  bool settled = false;
  std::vector<Ring> resolved =
      resolve_crossings(s_.rings, s_.ring_counts, hulls, options_.fill_rule, budget_, s_.pool, s_.resolve, &settled);
  s_.ring_counts.clear();
  resolved_to_nothing_ = resolved.empty() && !s_.rings.empty();
  s_.pool.recycle_all(s_.rings);
  s_.rings = std::move(resolved);
  resolved_rings_ = true;
  // The resolved rings do not cross; where the resolver found nothing left in
  // conflict, or the same test as in separate() agrees (and no position
  // repeats: the sweep checks), they take the sweep too.
  if (settled) {
    simple_edges_ = true;
  } else {
    const HullSeparation again = separate_hulls(s_.rings, CrossingSplits::Keep, budget_, s_.hulls, s_.pool);
    simple_edges_ = again.separated && !again.crossing;
  }
  needs_check_ = needs_check_ || !settled;
}

// Fast path, without nesting: under the nonzero rule the ring through the
// lowest vertex (least y, then least x) is outermost and bounds the fill, so
// its orientation tells on which side of every ring the fill lies in a glyph
// whose rings are oriented consistently (outer rings one way, holes the
// other, as fonts draw them). The sweep checks that this holds (a loop
// starting inside the fill or a hole outside it, and a wrong triangle count,
// make it give up) and then nest() sorts the rings out. Rings that meet at
// vertices without crossing (the sweep gives up where a position repeats)
// may still overlap: two contours through the same two vertices, one bulging
// into the other between them, enclose a lens that no edge test sees. The
// resolver sorts out any such meeting by windings; the fast path is then
// tried again on its rings.
void Build::sweep_as_oriented() {
  s_.region_start.clear();
  for (int attempt = 0; attempt < 2 && simple_edges_ && !s_.rings.empty() && !swept_; ++attempt) {
    if (attempt == 1) {
      if (!repeated_position_ || resolved_rings_) break;
      resolve(HullState::Separated);
      stage_mark(MeshStage::Resolve);
      repeated_position_ = false;
      if (!simple_edges_ || s_.rings.empty()) break;
    }
    NextIndex next{mesh_.points};
    make_loops(next, fast_path_walk());
    stage_mark(MeshStage::Loops);
    swept_ = sweep_loops(&repeated_position_);
    stage_mark(MeshStage::Triangles);
  }
}

// The walk that puts the fill on the left of the ring through the lowest
// vertex. The ring's orientation is its chord polygon's (its caps cannot turn
// the sign: a concave cap lies inside the polygon, hull separation keeping it
// off the other pieces), read off the turn at the polygon's lowest vertex,
// which is convex; its area decides where the turn is flat (a ring of two
// pieces). A wrong answer would only make the sweep give up.
Walk Build::fast_path_walk() {
  const std::vector<Ring>& rings = s_.rings;
  piece_count_ = 0;
  std::size_t lowest_ring = 0, lowest_piece = 0;
  Vec2 lowest = rings[0].empty() ? Vec2{} : rings[0][0].a;
  for (std::size_t r = 0; r < rings.size(); ++r) {
    piece_count_ += rings[r].size();
    for (std::size_t i = 0; i < rings[r].size(); ++i) {
      const Vec2 a = rings[r][i].a;
      const bool below = (a.y < lowest.y) | ((a.y == lowest.y) & (a.x < lowest.x));
      lowest = below ? a : lowest;
      lowest_ring = below ? r : lowest_ring;
      lowest_piece = below ? i : lowest_piece;
    }
  }
  const Ring& ring = rings[lowest_ring];
  const std::size_t n = ring.size();
  const int turn = orient2d(ring[lowest_piece == 0 ? n - 1 : lowest_piece - 1].a, lowest, ring_end(ring, lowest_piece));
  const bool backward = turn != 0 ? turn < 0 : ring_area(ring) < 0.0;
  return backward ? Walk::Backward : Walk::Forward;
}

// The rings nested and oriented one by one; the sweep again on them (unless
// loops touch: then no orientation helps), else the general path's loops
// with one index per position.
void Build::nest() {
  nest_rings(s_.rings, s_.region_rings, s_.region_start, s_.nest);
  piece_count_ = 0;
  for (const std::uint32_t r : s_.region_rings) piece_count_ += s_.rings[r].size();
  if (simple_edges_ && !repeated_position_) {
    NextIndex next{mesh_.points};
    make_loops(next, Walk::Forward);
    stage_mark(MeshStage::Loops);
    swept_ = sweep_loops(nullptr);
    stage_mark(MeshStage::Triangles);
  }
  if (!swept_) {
    index_.emplace(mesh_.points, s_.point_slots, 2 * piece_count_);
    make_loops(*index_, Walk::Forward);
  }
  stage_mark(MeshStage::Loops);
}

// Positions get vertex indices in order of first use. `index` gives a
// position its index: a PointIndex (one index per distinct position), or,
// where the loops go to the sweep, simply the next one (NextIndex): a ring
// passes through each of its vertices once (clean_rings), and the sweep gives
// up where a position repeats among the loops (rings that touch), so the
// table is only needed when it does, and the loops are then made again with
// it. (A convex curve's control point, which no loop holds, may then keep an
// index of its own where it coincides with another point; nothing joins the
// two.)
template <class Index>
void Build::make_loops(Index& index, Walk walk) {
  mesh_.points.clear();
  mesh_.curves.clear();
  mesh_.boundary_lines.clear();
  mesh_.points.reserve(2 * piece_count_);
  mesh_.boundary_lines.reserve(piece_count_);
  mesh_.curves.reserve(piece_count_);
  s_.loop_vertices.clear();
  s_.loop_vertices.reserve(2 * piece_count_);
  s_.loop_start.assign(1, 0);
  s_.region_first_loop.assign(1, 0);
  if (s_.region_start.empty()) {
    // No regions (the fast path): every ring, as one group.
    for (const Ring& ring : s_.rings) polygonise(ring, index, walk);
    s_.region_first_loop.push_back(s_.loop_start.size() - 1);
    return;
  }
  for (std::size_t r = 0; r + 1 < s_.region_start.size(); ++r) {
    for (std::uint32_t k = s_.region_start[r]; k < s_.region_start[r + 1]; ++k)
      polygonise(s_.rings[s_.region_rings[k]], index, walk);
    s_.region_first_loop.push_back(s_.loop_start.size() - 1);
  }
}

// One ring's polygon loop, boundary lines and curved triangles. Piece k of
// the walk is ring[k], or backwards ring[n - 1 - k] from its end to its start
// (reverse_ring's order: the walk starts at ring[0].a either way). Piece k
// starts where piece k - 1 ends: its index is carried over, and the last
// piece ends where the first starts.
template <class Index>
void Build::polygonise(const Ring& ring, Index& index, Walk walk) {
  const bool reversed = walk == Walk::Backward;
  const std::size_t n = ring.size();
  const std::uint32_t first_index = n == 0 ? 0 : index(ring[0].a);
  std::uint32_t next_ia = first_index;
  for (std::size_t k = 0; k < n; ++k) {
    const Piece& p = reversed ? ring[n - 1 - k] : ring[k];
    const Vec2 start = reversed ? ring_end(ring, n - 1 - k) : p.a;
    const Vec2 end = reversed ? p.a : ring_end(ring, k);
    const std::uint32_t ia = next_ia, ib = k + 1 < n ? index(end) : first_index;
    next_ia = ib;
    s_.loop_vertices.push_back(ia);
    // A conic split into a piece whose control point lies exactly on its
    // chord's line (the tail of a nearly straight arc) is that chord: a
    // curved triangle of zero area would break the mesh's invariants.
    const int side = p.conic ? orient2d(start, end, p.control) : 0;
    if (side == 0) {
      mesh_.boundary_lines.push_back({ia, ib});
      continue;
    }
    // Filled side is on the left: a control point on the right of the chord
    // bulges out (convex, the polygon keeps the chord), on the left it
    // bulges in (concave, the polygon goes through the control point).
    const bool convex = side < 0;
    const std::uint32_t ic = index(p.control);
    mesh_.curves.push_back({ia, ic, ib, p.weight, convex});
    if (!convex) s_.loop_vertices.push_back(ic);
  }
  s_.loop_start.push_back(static_cast<std::uint32_t>(s_.loop_vertices.size()));
}

// Loops that neither cross nor touch are triangulated by one sweep (which
// gives up where a position repeats: touching loops). Loops of fewer than
// three vertices (a line and a convex conic, two convex conics) enclose no
// polygon area and are left out, as ear_clip would leave them.
bool Build::sweep_loops(bool* repeated) {
  s_.sweep_vertices.clear();
  s_.sweep_start.assign(1, 0);
  for (std::size_t l = 0; l + 1 < s_.loop_start.size(); ++l) {
    const std::uint32_t first = s_.loop_start[l], last = s_.loop_start[l + 1];
    if (last - first < 3) continue;
    s_.sweep_vertices.insert(s_.sweep_vertices.end(), s_.loop_vertices.begin() + first,
                             s_.loop_vertices.begin() + last);
    s_.sweep_start.push_back(static_cast<std::uint32_t>(s_.sweep_vertices.size()));
  }
  CURVETEXT_ASSERT(s_.sweep_start.back() == s_.sweep_vertices.size());
  mesh_.triangles.reserve(s_.sweep_vertices.size() + 4 * s_.sweep_start.size());
  return sweep_triangulate(mesh_.points, s_.sweep_vertices, s_.sweep_start, mesh_.triangles, s_.triangulate, repeated);
}

std::vector<Vec2> Build::loop_positions(std::size_t l) const {
  std::vector<Vec2> loop;
  loop.reserve(s_.loop_start[l + 1] - s_.loop_start[l]);
  for (std::uint32_t k = s_.loop_start[l]; k < s_.loop_start[l + 1]; ++k)
    loop.push_back(mesh_.points[s_.loop_vertices[k]]);
  return remove_folds(std::move(loop));
}

// The general path: each region's loops re-linked where they touch at
// vertices (so that each polygon handed to the ear clipper has one filled
// sector per corner), holes bridged, ear-clipped.
void Build::ear_clip_regions() {
  CURVETEXT_ASSERT(index_.has_value());  // the loops were made with one index per position
  std::vector<std::array<Vec2, 3>>& triangle_points = s_.triangle_points;
  triangle_points.clear();
  triangle_points.reserve(2 * piece_count_ + 8);  // about two triangles per loop vertex
  for (std::size_t r = 0; r + 1 < s_.region_first_loop.size(); ++r) {
    std::vector<Vec2> outer = loop_positions(s_.region_first_loop[r]);
    std::vector<std::vector<Vec2>> holes;
    for (std::size_t l = s_.region_first_loop[r] + 1; l < s_.region_first_loop[r + 1]; ++l)
      holes.push_back(loop_positions(l));
    for (PolygonLoops& polygon : relink_touching_loops(std::move(outer), std::move(holes), s_.triangulate)) {
      const std::vector<Vec2> loop = bridge_holes(std::move(polygon.outer), std::move(polygon.holes));
      ear_clip(loop, triangle_points, s_.triangulate, ear_clip_budget(loop.size()));
    }
  }
  mesh_.triangles.reserve(triangle_points.size());
  PointIndex& index = *index_;
  for (const auto& t : triangle_points) mesh_.triangles.push_back({index(t[0]), index(t[1]), index(t[2])});
  stage_mark(MeshStage::Triangles);
}

// Lawson flips: on the sweep's manifold triangulation without a list of
// constrained edges; otherwise the outline's edges (lines, convex curves'
// chords and concave curves' legs) are never flipped.
void Build::flip() {
  if (swept_) {
    delaunay_flips_manifold(mesh_.points, mesh_.triangles, s_.triangulate);
    return;
  }
  std::vector<EdgeKey>& constrained = s_.constrained;
  constrained.clear();
  for (const auto& line : mesh_.boundary_lines) constrained.push_back(edge_key(line[0], line[1]));
  for (const CurvedTriangle& c : mesh_.curves) {
    if (c.convex) {
      constrained.push_back(edge_key(c.p0, c.p2));
    } else {
      constrained.push_back(edge_key(c.p0, c.control));
      constrained.push_back(edge_key(c.control, c.p2));
    }
  }
  std::sort(constrained.begin(), constrained.end());
  constrained.erase(std::unique(constrained.begin(), constrained.end()), constrained.end());
  delaunay_flips(mesh_.points, mesh_.triangles, constrained, s_.triangulate);
}

void build_checked_mesh(Scratch& scratch, const Outline& outline, const MeshOptions& options, double largest,
                        Mesh& mesh) {
  const double merge_distance = tolerance::kMergeDistanceRelative * largest;
  // (A first build that finds a ring through a vertex twice where it matters
  // builds again with the split: Build::run.)
  Build first(scratch, options, merge_distance, RepeatedVertices::Keep, mesh);
  bool needs_check = false;
  if (first.run(outline)) {
    needs_check = first.needs_check();
  } else {
    Build again(scratch, options, merge_distance, RepeatedVertices::Split, mesh);
    const bool built = again.run(outline);
    CURVETEXT_ASSERT(built);  // (with the split it always builds)
    static_cast<void>(built);
    needs_check = again.needs_check();
  }
  if (!needs_check) return;
  // Self-check before success: a mesh from the general path (ear clipping, or
  // crossings resolved with conflicts left) that breaks an invariant is an
  // error, never a result.
  const MeshCheck check = self_check(mesh, to_quadratic_outline(outline, options.cubic_tolerance), options.fill_rule);
  if (!check.ok())
    throw Error(ErrorCode::Geometry, "build_mesh: the mesh fails its own check (" + check.problems.front() + ")");
}

}  // namespace

MeshBuilder::MeshBuilder() : scratch_(std::make_unique<Scratch>()) {}
MeshBuilder::~MeshBuilder() = default;
MeshBuilder::MeshBuilder(MeshBuilder&&) noexcept = default;
MeshBuilder& MeshBuilder::operator=(MeshBuilder&&) noexcept = default;

namespace {

// The checks every entry makes; returns the outline as the stages read it
// (tiny coordinates as 0) and its largest |coordinate|.
const Outline& checked_input(Scratch& scratch, const Outline& outline, const MeshOptions& options, double& largest) {
  // (Non-finite coordinates and weights are found while cleaning: clean_rings.)
  if (!(options.cubic_tolerance > 0.0) || !std::isfinite(options.cubic_tolerance)) {
    throw Error(ErrorCode::Geometry, "build_mesh: cubic_tolerance must be positive and finite");
  }
  largest = 0.0;
  const bool flush = detail::flush_tiny_coordinates(outline, scratch.flushed, largest);
  if (std::isfinite(largest) && largest > tolerance::kMaxMeshCoordinate) {
    char message[160];
    std::snprintf(message, sizeof message, "build_mesh: outline coordinate %.17g is beyond the largest accepted (%g)",
                  largest, tolerance::kMaxMeshCoordinate);
    throw Error(ErrorCode::Geometry, message);
  }
  return flush ? scratch.flushed : outline;
}

}  // namespace

void MeshBuilder::build(const Outline& outline, const MeshOptions& options, Mesh& mesh) {
  if (!scratch_) scratch_ = std::make_unique<Scratch>();  // (a moved-from builder)
  detail::stage_start();                                  // (no-op unless built with CURVETEXT_STAGE_TIMING)
  try {
    double largest = 0.0;
    const Outline& input = checked_input(*scratch_, outline, options, largest);
    build_checked_mesh(*scratch_, input, options, largest, mesh);
  } catch (const std::bad_alloc&) {
    mesh = Mesh{};
    throw Error(ErrorCode::Geometry, "build_mesh: out of memory while meshing the outline");
  }
}

Outline MeshBuilder::boundary(const Outline& outline, const MeshOptions& options) {
  if (!scratch_) scratch_ = std::make_unique<Scratch>();
  try {
    double largest = 0.0;
    const Outline& input = checked_input(*scratch_, outline, options, largest);
    Mesh unused;
    const double merge_distance = tolerance::kMergeDistanceRelative * largest;
    Build build(*scratch_, options, merge_distance, RepeatedVertices::Keep, unused);
    Outline out = build.boundary(input);
    if (!build.wants_split()) return out;
    return Build(*scratch_, options, merge_distance, RepeatedVertices::Split, unused).boundary(input);
  } catch (const std::bad_alloc&) {
    throw Error(ErrorCode::Geometry, "fill_boundary: out of memory while resolving the outline");
  }
}

namespace {

// The one builder of this thread: no allocation per mesh once warm.
MeshBuilder& thread_builder() {
  thread_local MeshBuilder builder;
  return builder;
}

}  // namespace

Outline fill_boundary(const Outline& outline, FillRule rule, double cubic_tolerance) {
  MeshOptions options;
  options.cubic_tolerance = cubic_tolerance;
  options.fill_rule = rule;
  return thread_builder().boundary(outline, options);
}

void build_mesh(const Outline& outline, const MeshOptions& options, Mesh& mesh, MeshBuilder& builder) {
  builder.build(outline, options, mesh);
}

void build_mesh(const Outline& outline, const MeshOptions& options, Mesh& mesh) {
  thread_builder().build(outline, options, mesh);
}

Mesh build_mesh(const Outline& outline, const MeshOptions& options) {
  Mesh mesh;
  build_mesh(outline, options, mesh);
  return mesh;
}

}  // namespace curvetext
