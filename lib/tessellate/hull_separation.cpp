// Hull separation (hull_separation.hpp): passes over every pair of pieces
// whose boxes meet, each pass splitting what overlaps, until nothing does.
#include "tessellate/hull_separation.hpp"

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "core/assert.hpp"
#include "curvetext/curves.hpp"
#include "core/tolerances.hpp"
#include "tessellate/columns.hpp"
#include "tessellate/hulls.hpp"
#include "tessellate/positions.hpp"
#include "tessellate/predicates.hpp"
#include "tessellate/resolve.hpp"

namespace curvetext::detail {

bool hulls_overlap(const Vec2* p, int np, const Vec2* q, int nq) { return hulls::overlap(p, np, q, nq); }

namespace {

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

// Up to this many pieces hull separation tests every pair's boxes instead
// of sorting them first (measured: as fast up to about 96 pieces, faster
// below).
constexpr std::size_t kAllPairsLimit = 64;
static_assert(kAllPairsLimit <= 64, "the all-pairs test reads one 64-bit block per piece");

using HullRef = HullScratch::HullRef;

// One call of separate_hulls. A pass tests pairs of pieces and marks what to
// split; the rings are then split, and the next pass tests again, until a
// pass finds no overlap it can split.
class HullSeparator {
 public:
  HullSeparator(std::vector<Ring>& rings, CrossingSplits splits, std::size_t max_pieces, HullScratch& scratch,
                RingPool& pool)
      : rings_(rings),
        split_at_crossings_(splits == CrossingSplits::Split),
        max_pieces_(max_pieces),
        pair_budget_(max_pieces == SIZE_MAX
                         ? SIZE_MAX
                         : tolerance::kMeshPairTestsPerPiece * (max_pieces / tolerance::kMeshWorkPerPiece) +
                               tolerance::kMeshPairTestsBase),
        s_(scratch),
        pool_(pool) {}

  HullSeparation run();

 private:
  void test_pass();
  void start_scan();
  void collect_refs();
  void find_joints_apart();
  void fill_box_columns();
  void test_pair(const HullRef& ri, const HullRef& rj);
  bool split_line_at_conic_point(const HullRef& ri, const HullRef& rj);
  bool split_at_crossing(const HullRef& ri, const HullRef& rj);
  std::uint64_t joints_apart(std::size_t i, std::size_t base) const;
  std::uint64_t meets_block(std::size_t i, std::size_t base, std::size_t from) const;
  void test_hits(std::size_t i, std::size_t base, std::uint64_t hits);
  void count_box_tests(std::size_t tests);
  void test_partners();
  void test_fresh_against_all();
  void test_all_pairs();
  void sweep_and_prune();
  void sort_boxes();
  void scan_line_pairs(std::size_t first_i, std::size_t first_j);
  bool align_all_tangent_legs();
  void number_children();
  void split_rings();
  void split_line(const Ring& ring, std::size_t i, std::size_t mark, Ring& next);

  std::vector<Ring>& rings_;
  const bool split_at_crossings_;
  const std::size_t max_pieces_;
  // Pair tests, against their budget: coincident pieces all meet.
  std::size_t pairs_tested_ = 0;
  const std::size_t pair_budget_;
  HullScratch& s_;
  RingPool& pool_;

  // Across passes:
  // Pieces split where they cross another piece, in some pass.
  bool crossing_split_ = false;
  // Two lines seen crossing in some pass. Lines are not split in the
  // partner-only passes, so their crossing stands there without being tested
  // again. (Only a split exactly at that crossing point would make it a
  // touch; the rings would then be resolved for nothing, which is harmless.)
  bool lines_crossed_ = false;
  // A pass after the first tests only the pairs with a fresh piece: the
  // others were tested in the pass before with the same hulls, and gave
  // "no overlap, no crossing" when that pass found no crossing and no overlap
  // it could not split (otherwise the pass tests every pair again).
  bool test_all_ = true;
  // After a split at a crossing, a pass tests every fresh piece against all
  // others instead of the children of the pairs that overlapped: the point is
  // the conic's, rounded, and off the other piece by that rounding, so that
  // piece's halves need not lie in its hull. Pairs of pieces that are not
  // fresh were tested in the pass before with the same hulls and did not
  // overlap (an overlap marks a piece for splitting, or sets test_all_).
  bool fresh_against_all_ = false;

  // In one pass (one scan of the pairs; a pass that aligns tangent legs scans again):
  bool any_ = false;              // something marked for splitting
  bool overlap_left_ = false;     // an overlap seen
  bool unsplit_overlap_ = false;  // one where neither piece could be split
  bool cross_seen_ = false;       // rings_cross(rings, true) over the same pairs
  bool split_this_pass_ = false;  // pieces split at a crossing
  std::size_t count_ = 0;         // pieces
  // (Raw pointers into the scratch: the stores into the char marks may alias
  // anything, which would make every access through the vectors reload them.)
  HullRef* refs_ = nullptr;
  char* marks_ = nullptr;
  double *min_x_ = nullptr, *max_x_ = nullptr, *min_y_ = nullptr, *max_y_ = nullptr;
};

// The bits of the block at base for the pieces after (before) piece i.
std::uint64_t after(std::size_t i, std::size_t base) {
  if (i < base) return ~std::uint64_t{0};
  return i - base >= 63 ? 0 : ~std::uint64_t{0} << (i - base + 1);
}

std::uint64_t before(std::size_t i, std::size_t base) {
  if (i <= base) return 0;
  return i - base >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << (i - base)) - 1;
}

// (The pieces' `fresh` flags are not read in the first pass, which tests
// every pair; a pass that splits sets them all for the next one.)
HullSeparation HullSeparator::run() {
  for (int pass = 0; pass <= tolerance::kMaxHullSubdivisionDepth; ++pass) {
    test_pass();
    if (!any_) {
      const bool crossing = crossing_split_ || (!overlap_left_ && (cross_seen_ || lines_crossed_));
      return {!overlap_left_, crossing};
    }
    test_all_ = unsplit_overlap_ || (cross_seen_ && !lines_crossed_);
    fresh_against_all_ = split_this_pass_;
    crossing_split_ = crossing_split_ || split_this_pass_;
    number_children();
    s_.partners.swap(s_.overlaps);
    split_rings();
    std::size_t pieces = 0;
    for (const Ring& ring : rings_) pieces += ring.size();
    // Each piece became the children number_children counted for it (the
    // partner pass reads them by those numbers).
    CURVETEXT_ASSERT(pieces == s_.child_first.back());
    if (pieces > max_pieces_) work_budget_exceeded("hull separation", pieces, max_pieces_);
  }
  // Passes used up right after splitting: not known to be separated.
  return {false, crossing_split_};
}

// Tangent legs are aligned (align_tangent_legs) only when the pass has found
// an overlap, and then the pass is run again on the aligned rings: every
// tangency align_tangent_legs fixes is a hull corner on another hull's edge,
// which the pair tests report as an overlap, so a pass without one has
// nothing to align. The result is that of aligning first; the usual glyph
// skips the alignment scan.
void HullSeparator::test_pass() {
  for (bool aligned = false;;) {
    // (After aligning, pieces may have been inserted and the pairs of the
    // pass before no longer name them: the pass then scans the boxes.)
    const bool by_partners = !test_all_ && !fresh_against_all_ && !aligned;
    start_scan();
    if (!by_partners) {
      find_joints_apart();
      fill_box_columns();
    }
    if (by_partners) {
      test_partners();
    } else if (!test_all_) {
      test_fresh_against_all();
    } else if (count_ <= kAllPairsLimit) {
      test_all_pairs();
    } else {
      sweep_and_prune();
    }
    if (!overlap_left_ || aligned) break;
    aligned = true;
    if (!align_all_tangent_legs()) break;
  }
}

void HullSeparator::start_scan() {
  s_.overlaps.clear();
  any_ = false;
  overlap_left_ = false;
  unsplit_overlap_ = false;
  split_this_pass_ = false;
  cross_seen_ = false;
  s_.mark_base.assign(rings_.size() + 1, 0);
  for (std::size_t r = 0; r < rings_.size(); ++r) s_.mark_base[r + 1] = s_.mark_base[r] + rings_[r].size();
  count_ = s_.mark_base.back();
  s_.split_marks.assign(count_, 0);
  s_.more_line_points.clear();
  s_.split_point.resize(count_);  // (lines are split at points of them in every call)
  if (split_at_crossings_) s_.split_at.resize(count_);
  if (s_.refs.size() < count_) s_.refs.resize(count_);
  refs_ = s_.refs.data();
  marks_ = s_.split_marks.data();
  collect_refs();
  s_.next_piece.resize(count_);
  s_.previous_piece.resize(count_);
  s_.apart_from_next.resize(count_);
  const auto sides = columns<4>(s_.box_sides, count_);
  min_x_ = sides[0], max_x_ = sides[1], min_y_ = sides[2], max_y_ = sides[3];
}

void HullSeparator::collect_refs() {
  for (std::size_t r = 0; r < rings_.size(); ++r) {
    const Ring& ring = rings_[r];
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Piece& piece = ring[i];
      HullRef& ref = refs_[s_.mark_base[r] + i];
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
      ref.mark = s_.mark_base[r] + i;
    }
  }
}

// Consecutive pieces whose hulls certainly meet only at their common vertex
// (hulls::joint_apart): their pair is left out of the box scans.
void HullSeparator::find_joints_apart() {
  for (std::size_t r = 0; r < rings_.size(); ++r) {
    const std::size_t first = s_.mark_base[r], end = s_.mark_base[r + 1];
    for (std::size_t k = first; k < end; ++k) {
      const std::size_t next = k + 1 < end ? k + 1 : first;
      const HullRef &p = refs_[k], &q = refs_[next];
      s_.next_piece[k] = static_cast<std::uint32_t>(next);
      s_.previous_piece[next] = static_cast<std::uint32_t>(k);
      s_.apart_from_next[k] = static_cast<char>(
          hulls::joint_apart(p.hull[0], p.hull[1], p.n == 3, q.hull[0], q.hull[1], q.n == 3, q.end()));
    }
  }
}

// The boxes in one array per side, for tests written without branches
// (their outcomes are unpredictable; most pairs are rejected by their boxes
// alone).
void HullSeparator::fill_box_columns() {
  for (std::size_t k = 0; k < count_; ++k) {
    const Box& b = refs_[k].box;
    min_x_[k] = b.min.x;
    max_x_[k] = b.max.x;
    min_y_[k] = b.min.y;
    max_y_[k] = b.max.y;
  }
}

// The bits of the block at base for the pieces consecutive to piece i and
// apart from it (no branch: an index outside the block wraps to a large
// unsigned difference).
std::uint64_t HullSeparator::joints_apart(std::size_t i, std::size_t base) const {
  const std::size_t next = s_.next_piece[i] - base, previous = s_.previous_piece[i] - base;
  const std::uint64_t next_bit = static_cast<std::uint64_t>((s_.apart_from_next[i] != 0) & (next < 64)) << (next & 63);
  const std::uint64_t previous_bit =
      static_cast<std::uint64_t>((s_.apart_from_next[s_.previous_piece[i]] != 0) & (previous < 64)) << (previous & 63);
  return next_bit | previous_bit;
}

void HullSeparator::test_pair(const HullRef& ri, const HullRef& rj) {
  if (++pairs_tested_ > pair_budget_) work_budget_exceeded("hull separation (pair tests)", pairs_tested_, pair_budget_);
  const bool ci = ri.n == 3, cj = rj.n == 3;
  if (!ci && !cj) {
    if (!cross_seen_ && lines_cross(ri.hull[0], ri.hull[1], rj.hull[0], rj.hull[1])) {
      cross_seen_ = true;
      lines_crossed_ = true;
    }
    return;
  }
  const Vec2 ai = ri.hull[0], ei = ri.end(), aj = rj.hull[0], ej = rj.end();
  const bool same_ends = (ai == aj && ei == ej) || (ai == ej && ei == aj);
  // A conic and a piece with the same end points: their chords would
  // coincide, rings_cross's answer is true.
  cross_seen_ = cross_seen_ || same_ends;
  // Identical curves (duplicated contours) overlap at every depth;
  // splitting them is useless, the crossing resolver merges them.
  if (same_ends && ci && cj && ri.hull[1] == rj.hull[1] && ri.weight == rj.weight) return;
  if (!hulls::overlap(ri.hull, ri.n, rj.hull, rj.n)) return;
  s_.overlaps.push_back(static_cast<std::uint64_t>(ri.mark) << 32 | rj.mark);
  overlap_left_ = true;
  if (ci != cj && split_line_at_conic_point(ri, rj)) return;
  if (split_at_crossings_ && split_at_crossing(ri, rj)) return;
  // Subdividing a conic shrinks its hull towards the arc; lines stay.
  bool split_one = false;
  if (ci && ri.depth < tolerance::kMaxHullSubdivisionDepth) {
    if (marks_[ri.mark] == 0) marks_[ri.mark] = 1;
    split_one = true;
  }
  if (cj && rj.depth < tolerance::kMaxHullSubdivisionDepth) {
    if (marks_[rj.mark] == 0) marks_[rj.mark] = 1;
    split_one = true;
  }
  any_ = any_ || split_one;
  unsplit_overlap_ = unsplit_overlap_ || !split_one;
}

// A line and a conic that halving would never get apart, because a point of
// the conic's hull stays on the line however often the conic is halved: the
// line is split at that point (exact: the point is on it), so that the two
// meet at a common vertex. Either an end of the conic on the line (a
// T-junction: an ogonek or a cedilla drawn onto a stem), or its control with
// the leg through it along the line (a conic leaving another contour's line
// tangentially; align_tangent_legs does this for neighbours in one ring).
bool HullSeparator::split_line_at_conic_point(const HullRef& ri, const HullRef& rj) {
  const bool ci = ri.n == 3;
  const HullRef& line = ci ? rj : ri;
  const HullRef& conic = ci ? ri : rj;
  const Vec2 la = line.hull[0], lb = line.hull[1];
  for (int k : {0, 2, 1}) {
    const Vec2 e = conic.hull[k];
    if (e == la || e == lb || !point_on_segment(la, lb, e)) continue;
    if (k == 1 && orient2d(la, lb, conic.hull[0]) != 0 && orient2d(la, lb, conic.hull[2]) != 0) continue;
    if (marks_[line.mark] == 0) {
      marks_[line.mark] = 2;
      s_.split_point[line.mark] = e;
    } else if (s_.split_point[line.mark] != e) {
      s_.more_line_points.push_back({static_cast<std::uint32_t>(line.mark), e});
    }
    // Contours that touch there may still overlap (a lobe of one inside the
    // other, their outlines meeting only at such points): before resolving,
    // that calls for the resolver, as a crossing does.
    crossing_split_ = crossing_split_ || split_at_crossings_;
    any_ = true;
    return true;
  }
  return false;
}

// Pieces that cross: both split at the crossing (once per pass each), which
// saves halving the conics down to the limit around it. The point is the
// conic's, rounded; the other piece gets the same point as its new vertex (a
// move of an ulp or so). (Pieces with a common end, most overlapping pairs,
// have no proper chord crossing: not asked.)
bool HullSeparator::split_at_crossing(const HullRef& ri, const HullRef& rj) {
  const bool ci = ri.n == 3, cj = rj.n == 3;
  const Vec2 ai = ri.hull[0], ei = ri.end(), aj = rj.hull[0], ej = rj.end();
  const bool common_end = ai == aj || ai == ej || ei == aj || ei == ej;
  if (common_end || marks_[ri.mark] != 0 || marks_[rj.mark] != 0 ||
      (ci && ri.depth >= tolerance::kMaxHullSubdivisionDepth) ||
      (cj && rj.depth >= tolerance::kMaxHullSubdivisionDepth))
    return false;
  double t = 0.0, u = 0.0;
  if (!hulls::crossing_parameters(ri.hull, ri.n, ri.weight, rj.hull, rj.n, rj.weight, t, u)) return false;
  const HullRef& conic = ci ? ri : rj;
  Vec2 x = canonical(
      split(Segment::conic(conic.hull[0], conic.hull[1], conic.hull[2], conic.weight), ci ? t : u).second.p[0]);
  // On a horizontal or vertical line (most of a font's lines) the point is
  // put on the line exactly, a move of its rounding: then it is on every line
  // along that one too (another contour's edge there), where the conic's half
  // could otherwise start a rounding away and cross it again next to its end.
  if (ci != cj) {
    const HullRef& line = ci ? rj : ri;
    if (line.hull[0].y == line.hull[1].y) x.y = line.hull[0].y;
    if (line.hull[0].x == line.hull[1].x) x.x = line.hull[0].x;
  }
  if (x == ai || x == ei || x == aj || x == ej) return false;
  marks_[ri.mark] = 2;
  marks_[rj.mark] = 2;
  s_.split_at[ri.mark] = t;
  s_.split_at[rj.mark] = u;
  s_.split_point[ri.mark] = x;
  s_.split_point[rj.mark] = x;
  split_this_pass_ = true;
  any_ = true;
  return true;
}

// One bit per piece j of the block [base, base + 64) (base a multiple of 64)
// whose box meets box i, tested from piece `from` on (the bits below may be
// set or not); two boxes per step with SSE2 (part of every x86-64 CPU). Hits
// are then read with countr_zero.
std::uint64_t HullSeparator::meets_block(std::size_t i, std::size_t base, std::size_t from) const {
  const double* const min_x = min_x_;
  const double* const max_x = max_x_;
  const double* const min_y = min_y_;
  const double* const max_y = max_y_;
  const double left = min_x[i], right = max_x[i], bottom = min_y[i], top = max_y[i];
  const std::size_t end = std::min(count_, base + 64);
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
}

void HullSeparator::test_hits(std::size_t i, std::size_t base, std::uint64_t hits) {
  for (; hits != 0; hits &= hits - 1)
    test_pair(refs_[i], refs_[base + static_cast<std::size_t>(std::countr_zero(hits))]);
}

void HullSeparator::count_box_tests(std::size_t tests) {
  pairs_tested_ += tests;
  if (pairs_tested_ > pair_budget_) work_budget_exceeded("hull separation (pair tests)", pairs_tested_, pair_budget_);
}

// A pass that tests only fresh pieces tests just the children of the pairs
// that overlapped before: a child's hull lies in its parent's, so a child can
// only overlap what its parent overlapped (its sibling and its ring
// neighbours it meets only at their common vertex), and a piece that is not
// split and overlapped nothing before has not changed.
void HullSeparator::test_partners() {
  const std::vector<std::uint32_t>& child_first = s_.child_first;
  for (const std::uint64_t pair : s_.partners) {
    const std::size_t p = pair >> 32, q = pair & 0xffffffffu;
    CURVETEXT_ASSERT(child_first[p + 1] <= count_ && child_first[q + 1] <= count_);
    for (std::size_t cp = child_first[p]; cp < child_first[p + 1]; ++cp)
      for (std::size_t cq = child_first[q]; cq < child_first[q + 1]; ++cq) test_pair(refs_[cp], refs_[cq]);
  }
  // A child's hull lies in its parent's only in exact arithmetic: its rounded
  // control point can cross a line that its parent's leg lay along (a hairpin
  // conic closed by that line), a ring neighbour the parent only touched.
  // Fresh pieces are tested against their ring neighbours again.
  for (std::size_t r = 0; r < rings_.size(); ++r) {
    const std::size_t first = s_.mark_base[r], end = s_.mark_base[r + 1];
    for (std::size_t k = first; k + 1 < end || (k + 1 == end && end - first > 2); ++k) {
      const std::size_t next = k + 1 < end ? k + 1 : first;
      if (rings_[r][k - first].fresh || rings_[r][next - first].fresh) test_pair(refs_[k], refs_[next]);
    }
  }
}

// (After a split at a crossing, or after aligning tangent legs in a pass
// that tests only fresh pieces.) Each fresh piece against every piece whose
// box meets its own (a fresh pair once, from its first piece).
void HullSeparator::test_fresh_against_all() {
  std::vector<std::uint32_t>& fresh_refs = s_.fresh_refs;
  fresh_refs.clear();
  for (std::size_t r = 0; r < rings_.size(); ++r)
    for (std::size_t i = 0; i < rings_[r].size(); ++i)
      if (rings_[r][i].fresh) fresh_refs.push_back(static_cast<std::uint32_t>(s_.mark_base[r] + i));
  std::vector<std::uint64_t>& fresh_words = s_.fresh_words;
  fresh_words.assign((count_ + 63) / 64, 0);
  for (const std::uint32_t i : fresh_refs) fresh_words[i / 64] |= std::uint64_t{1} << (i % 64);
  // (Every fresh piece's box against every box: counted against the pair
  // budget, as a contour drawn twice keeps many pieces fresh.)
  count_box_tests(fresh_refs.size() * count_);
  for (const std::uint32_t i : fresh_refs) {
    for (std::size_t base = 0; base < count_; base += 64) {
      const std::uint64_t others = after(i, base) | (before(i, base) & ~fresh_words[base / 64]);
      test_hits(i, base, meets_block(i, base, base) & others & ~joints_apart(i, base));
    }
  }
}

// A glyph's few dozen pieces: every pair's boxes, which costs less than
// sorting them (a sort's branches are unpredictable too).
void HullSeparator::test_all_pairs() {
  CURVETEXT_ASSERT(count_ <= 64);  // one block
  for (std::size_t i = 0; i < count_; ++i)
    test_hits(i, 0, meets_block(i, 0, i + 1) & after(i, 0) & ~joints_apart(i, 0));
}

// Sweep and prune: sorted by the boxes' lower sides along the glyph's longer
// axis, where the boxes overlap less (a tall glyph's pieces share x ranges);
// "a" below is that axis, "b" the other. Which pairs are met does not depend
// on the order among equal keys, and the answers are combined
// order-independently.
void HullSeparator::sweep_and_prune() {
  sort_boxes();
  const auto [s_min_a, s_max_a, s_min_b, s_max_b] = columns<4>(s_.sorted_sides, count_);
  const std::vector<HullScratch::SortKey>& keys = s_.keys;
  std::uint32_t* const candidate = s_.candidates.data();
  const std::vector<std::uint32_t>& conics = s_.sorted_conics;
  // The first pair (in this scan's order) that set cross_seen_, for the
  // scan of line pairs below.
  std::size_t first_i = SIZE_MAX, first_j = SIZE_MAX;
  for (std::size_t i = 0, next_conic = 0; i < count_; ++i) {
    while (next_conic < conics.size() && conics[next_conic] <= i) ++next_conic;
    // Boxes after box i in the order start at or after its lower side along
    // a: they overlap it along a while they start before its upper side, and
    // then in both when their b ranges meet. (Pieces with the same end points
    // have overlapping boxes.) A line is paired here with the conics only:
    // two lines have no hull to separate (see scan_line_pairs).
    const bool conic = refs_[keys[i].ref].n == 3;
    const double upper = s_max_a[i], low_b = s_min_b[i], high_b = s_max_b[i];
    std::size_t found = 0, scanned = 0;
    for (std::size_t c = next_conic, j = i + 1;; ++scanned) {
      if (!conic) j = c < conics.size() ? conics[c++] : count_;
      if (j >= count_ || s_min_a[j] > upper) break;
      candidate[found] = static_cast<std::uint32_t>(j);
      found += static_cast<std::size_t>((s_min_b[j] <= high_b) & (low_b <= s_max_b[j]));
      if (conic) ++j;
    }
    // The boxes scanned count against the pair budget too (those tested are
    // counted by test_pair): pieces stacked on each other (a contour drawn
    // twice) make every pass's scan quadratic.
    count_box_tests(scanned - found);
    for (std::size_t f = 0; f < found; ++f) {
      const bool seen = cross_seen_;
      test_pair(refs_[keys[i].ref], refs_[keys[candidate[f]].ref]);
      if (!seen && cross_seen_) {
        first_i = i;
        first_j = candidate[f];
      }
    }
  }
  scan_line_pairs(first_i, first_j);
}

// The boxes sorted along a (keys), their sides in that order (sorted_sides),
// and the positions of the conics in it (sorted_conics).
void HullSeparator::sort_boxes() {
  Box all;
  for (std::size_t k = 0; k < count_; ++k) {
    all.add(refs_[k].box.min);
    all.add(refs_[k].box.max);
  }
  const bool along_y = all.max.y - all.min.y > all.max.x - all.min.x;
  const double* const min_a = along_y ? min_y_ : min_x_;
  const double* const max_a = along_y ? max_y_ : max_x_;
  const double* const min_b = along_y ? min_x_ : min_y_;
  const double* const max_b = along_y ? max_x_ : max_y_;
  std::vector<HullScratch::SortKey>& keys = s_.keys;
  keys.resize(count_);
  for (std::size_t k = 0; k < count_; ++k) keys[k] = {min_a[k], static_cast<std::uint32_t>(k)};
  std::sort(keys.begin(), keys.end(),
            [](const HullScratch::SortKey& a, const HullScratch::SortKey& b) { return a.min_a < b.min_a; });
  // The sides again in sorted order (the scans read them in a row).
  s_.candidates.resize(count_);
  s_.sorted_conics.clear();
  const auto [s_min_a, s_max_a, s_min_b, s_max_b] = columns<4>(s_.sorted_sides, count_);
  for (std::size_t k = 0; k < count_; ++k) {
    const std::uint32_t r = keys[k].ref;
    s_min_a[k] = min_a[r];
    s_max_a[k] = max_a[r];
    s_min_b[k] = min_b[r];
    s_max_b[k] = max_b[r];
    if (refs_[r].n == 3) s_.sorted_conics.push_back(static_cast<std::uint32_t>(k));
  }
}

// Pairs of lines matter only for rings_cross's answer: whether some two
// lines cross (cross_seen_), and whether the first such pair in the order of
// the sweep comes before the pair (first_i, first_j) at which cross_seen_
// was set (lines_crossed_). The scan stops at the first line crossing, so a
// path run over itself many times (its lines stacked, each crossing the
// next) costs no more than its first crossing.
void HullSeparator::scan_line_pairs(std::size_t first_i, std::size_t first_j) {
  const auto [s_min_a, s_max_a, s_min_b, s_max_b] = columns<4>(s_.sorted_sides, count_);
  const std::vector<HullScratch::SortKey>& keys = s_.keys;
  for (std::size_t i = 0; i < count_ && i <= first_i; ++i) {
    const HullRef& ri = refs_[keys[i].ref];
    if (ri.n == 3) continue;
    const double upper = s_max_a[i], low_b = s_min_b[i], high_b = s_max_b[i];
    std::size_t j = i + 1;
    for (; j < count_ && s_min_a[j] <= upper && (i < first_i || j < first_j); ++j) {
      const HullRef& rj = refs_[keys[j].ref];
      if (rj.n == 3 || s_min_b[j] > high_b || low_b > s_max_b[j]) continue;
      if (lines_cross(ri.hull[0], ri.hull[1], rj.hull[0], rj.hull[1])) {
        cross_seen_ = true;
        lines_crossed_ = true;
        count_box_tests(j - i);
        return;
      }
    }
    count_box_tests(j - i - 1);
  }
}

// Returns true when some ring changed.
bool HullSeparator::align_all_tangent_legs() {
  bool changed = false;
  for (Ring& ring : rings_) {
    // Each call fixes one tangency; a ring has at most one per vertex.
    for (std::size_t fixes = 0, limit = 2 * ring.size() + 2; fixes < limit && align_tangent_legs(ring); ++fixes)
      changed = true;
  }
  return changed;
}

// Where each piece of the pass goes: piece k becomes pieces child_first[k] ..
// child_first[k + 1] - 1 (two when it is split, more for a line split at
// several points). Each line's further points once, in mark order.
void HullSeparator::number_children() {
  auto& more = s_.more_line_points;
  std::sort(more.begin(), more.end(), [](const auto& u, const auto& v) {
    return u.first != v.first ? u.first < v.first
                              : std::make_pair(u.second.x, u.second.y) < std::make_pair(v.second.x, v.second.y);
  });
  more.erase(std::unique(more.begin(), more.end()), more.end());
  std::vector<std::uint32_t>& child_first = s_.child_first;
  child_first.resize(s_.split_marks.size() + 1);
  child_first[0] = 0;
  for (std::size_t k = 0, m = 0; k < s_.split_marks.size(); ++k) {
    std::uint32_t children = 1 + static_cast<std::uint32_t>(s_.split_marks[k] != 0);
    for (; m < more.size() && more[m].first == k; ++m) ++children;
    child_first[k + 1] = child_first[k] + children;
  }
  CURVETEXT_ASSERT(
      std::is_sorted(more.begin(), more.end(), [](const auto& u, const auto& v) { return u.first < v.first; }));
}

void HullSeparator::split_rings() {
  for (std::size_t r = 0; r < rings_.size(); ++r) {
    const char* ring_marks = s_.split_marks.data() + s_.mark_base[r];
    for (Piece& piece : rings_[r]) piece.fresh = false;
    if (std::all_of(ring_marks, ring_marks + rings_[r].size(), [](char m) { return m == 0; }))
      continue;  // nothing to split
    Ring next = pool_.take();
    next.reserve(rings_[r].size() + 8);
    for (std::size_t i = 0; i < rings_[r].size(); ++i) {
      const Piece& p = rings_[r][i];
      if (!ring_marks[i]) {
        next.push_back(p);
        continue;
      }
      const std::size_t mark = s_.mark_base[r] + i;
      if (!p.conic) {  // (a line is only split at a crossing or T-junctions)
        split_line(rings_[r], i, mark, next);
        continue;
      }
      const bool at_crossing = ring_marks[i] == 2;
      const double at = at_crossing ? s_.split_at[mark] : 0.5;
      const auto halves = split(Segment::conic(p.a, p.control, ring_end(rings_[r], i), p.weight), at);
      next.push_back(conic_piece(halves.first, p.depth + 1));
      next.push_back(conic_piece(halves.second, p.depth + 1));
      if (at_crossing) next.back().a = s_.split_point[mark];
    }
    rings_[r].swap(next);
    pool_.recycle(std::move(next));
  }
}

// A line split at its split point and further points, in order along it.
// (A line is split at every T-junction found on it in one pass, besides its
// split point, because a line split at a crossing alone gets a vertex off the
// line, the crossing rounded, and a T-junction point on the line would then
// no longer be on either half.)
void HullSeparator::split_line(const Ring& ring, std::size_t i, std::size_t mark, Ring& next) {
  const Piece& p = ring[i];
  const auto more = std::equal_range(s_.more_line_points.begin(), s_.more_line_points.end(),
                                     std::pair{static_cast<std::uint32_t>(mark), Vec2{}},
                                     [](const auto& u, const auto& v) { return u.first < v.first; });
  std::vector<Vec2>& points = s_.line_points;
  points.assign(1, s_.split_point[mark]);
  for (auto it = more.first; it != more.second; ++it) points.push_back(it->second);
  const Vec2 direction = ring_end(ring, i) - p.a;
  std::sort(points.begin(), points.end(),
            [&](Vec2 u, Vec2 v) { return dot(u - p.a, direction) < dot(v - p.a, direction); });
  next.push_back(p);
  next.back().fresh = true;
  for (const Vec2 point : points) {
    next.push_back(p);
    next.back().a = point;
    next.back().fresh = true;
  }
}

}  // namespace

HullSeparation separate_hulls(std::vector<Ring>& rings, CrossingSplits splits, std::size_t max_pieces,
                              HullScratch& scratch, RingPool& pool) {
  return HullSeparator(rings, splits, max_pieces, scratch, pool).run();
}

}  // namespace curvetext::detail
