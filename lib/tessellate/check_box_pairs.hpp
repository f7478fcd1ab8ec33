// Overlapping pairs among many axis-aligned boxes, for check_mesh's searches
// (hull overlaps, contact refinement, nested contours, contacts between
// edges): a sweep over x whose active boxes are kept in an interval structure
// over y, so that the work is O((n + pairs) log n) whatever the boxes' shapes.
// Sorting along x and scanning forward is quadratic when long boxes lie along
// both axes (a comb's fan triangles span its width, its teeth its height),
// but on most inputs (a glyph's pieces) it meets few boxes per box and costs
// a fraction of the sweep: so the boxes are sorted along x first, the pairs
// the scan would meet counted (binary search, O(n log n)), and the scan used
// when they are at most kScanPairsPerBox per box (plus a constant).
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "curvetext/geometry.hpp"

namespace curvetext::detail {

// The active y-intervals of the sweep, as ranks among the distinct y bounds.
// A segment tree over the ranks answers "which intervals contain rank r"
// (each interval listed at the O(log n) nodes that cover it) and "which
// intervals start within (lo, hi]" (each listed at the leaf of its start,
// with per-node counts to skip empty subtrees). Together: every interval
// overlapping [lo, hi] exactly once, in O((1 + found) log n). The lists are
// linked through one pool, so that a sweep allocates nothing once warm.
class ActiveIntervals {
 public:
  void reset(std::size_t ranks, std::size_t boxes);
  void insert(std::uint32_t box, std::uint32_t lo, std::uint32_t hi);
  void erase(std::uint32_t box, std::uint32_t lo);
  template <class Visit>
  void overlapping(std::uint32_t lo, std::uint32_t hi, Visit&& visit) const {
    for (std::size_t node = lo + leaves_; node >= 1; node /= 2)
      for (std::uint32_t e = covers_[node]; e != kNone; e = pool_[e].next) visit(pool_[e].box);
    if (lo < hi) starting_in(1, 0, static_cast<std::uint32_t>(leaves_ - 1), lo + 1, hi, visit);
  }

 private:
  static constexpr std::uint32_t kNone = ~std::uint32_t{0};
  struct Entry {
    std::uint32_t box, prev, next;  // in its node's list
    std::uint32_t node, sibling;    // the box's next entry
  };
  template <class Visit>
  void starting_in(std::size_t node, std::uint32_t first, std::uint32_t last, std::uint32_t lo, std::uint32_t hi,
                   Visit& visit) const {
    if (count_[node] == 0 || last < lo || first > hi) return;
    if (first == last) {
      for (std::uint32_t e = starts_[node]; e != kNone; e = pool_[e].next) visit(pool_[e].box);
      return;
    }
    const std::uint32_t middle = first + (last - first) / 2;
    starting_in(2 * node, first, middle, lo, hi, visit);
    starting_in(2 * node + 1, middle + 1, last, lo, hi, visit);
  }
  std::uint32_t link(std::vector<std::uint32_t>& heads, std::size_t node, std::uint32_t box);
  void unlink(std::vector<std::uint32_t>& heads, std::uint32_t e);

  std::size_t leaves_ = 1;
  std::vector<Entry> pool_;
  std::uint32_t free_ = kNone;
  std::vector<std::uint32_t> covers_;  // per node: intervals covering it
  std::vector<std::uint32_t> starts_;  // per leaf node: intervals starting there
  std::vector<std::uint32_t> count_;   // per node: intervals starting in its subtree
  std::vector<std::uint32_t> first_;   // per box: its first entry in covers_ lists, and its start entry
  std::vector<std::uint32_t> start_entry_;
};

// Whether boxes that only share boundary points are a pair. Interiors of
// faces meet only where the open boxes do: a fan of triangles on a comb's
// base touches every tooth's box along one line, but overlaps none.
enum class BoxContact { Touching, Interiors };

// Calls report(i, j) once for every pair of boxes i != j that overlap (closed
// boxes, or open ones: `contact`) and of which at least one is `keyed` (pairs
// of two unkeyed boxes are not searched: hull overlaps need a curved face in
// each pair). Empty boxes meet nothing, nor, for Interiors, flat ones. The
// scratch memory is kept for the next search.
class BoxPairSearch {
 public:
  // Which method run uses: Auto as above; the others for tests.
  enum class Method { Auto, Scan, Sweep };
  static constexpr std::size_t kScanPairsPerBox = 8, kScanPairsConstant = 1024;

  void set_method(Method method) { method_ = method; }

  template <class Keyed, class Report>
  void run(const std::vector<Box>& boxes, BoxContact contact, Keyed&& keyed, Report&& report) {
    if (!scan_if_cheap(boxes, contact, keyed, report)) sweep(boxes, contact, keyed, report);
  }

  // The same by the scan when that is cheap (as above); otherwise reports
  // nothing and returns false. The pairs reported are then at most
  // kScanPairsPerBox * n + kScanPairsConstant.
  template <class Keyed, class Report>
  bool scan_if_cheap(const std::vector<Box>& boxes, BoxContact contact, Keyed&& keyed, Report&& report) {
    contact_ = contact;
    bool any_keyed = false;  // none (a mesh without curved faces): no pair to search
    for (std::size_t i = 0; i < boxes.size() && !any_keyed; ++i) any_keyed = static_cast<bool>(keyed(i));
    if (!any_keyed) return true;
    if (method_ == Method::Sweep || !prepare_scan(boxes)) return false;
    const bool open = contact_ == BoxContact::Interiors;
    for (std::size_t a = 0; a < order_.size(); ++a) {
      const Extent& p = order_[a];
      const bool p_keyed = static_cast<bool>(keyed(p.box));
      for (std::size_t b = a + 1; b < order_.size(); ++b) {
        const Extent& q = order_[b];
        if (open ? q.lo >= p.hi : q.lo > p.hi) break;
        if (!p_keyed && !keyed(q.box)) continue;
        const Box &bp = boxes[p.box], &bq = boxes[q.box];
        const bool meet =
            open ? bq.min.y < bp.max.y && bp.min.y < bq.max.y : bq.min.y <= bp.max.y && bp.min.y <= bq.max.y;
        if (meet) report(static_cast<std::size_t>(p.box), static_cast<std::size_t>(q.box));
      }
    }
    return true;
  }

 private:
  template <class Keyed, class Report>
  void sweep(const std::vector<Box>& boxes, BoxContact contact, Keyed&& keyed, Report&& report) {
    contact_ = contact;
    prepare(boxes, [&](std::size_t i) { return static_cast<bool>(keyed(i)); });
    for (const Event& e : events_) {
      ActiveIntervals& own = e.keyed ? keyed_ : unkeyed_;
      if (e.end) {
        own.erase(e.box, lo_[e.box]);
        continue;
      }
      auto visit = [&](std::uint32_t other) {
        report(static_cast<std::size_t>(e.box), static_cast<std::size_t>(other));
      };
      keyed_.overlapping(lo_[e.box], hi_[e.box], visit);
      if (e.keyed) unkeyed_.overlapping(lo_[e.box], hi_[e.box], visit);
      own.insert(e.box, lo_[e.box], hi_[e.box]);
    }
  }

  struct Event {
    double x;
    std::uint32_t box;
    bool end, keyed;
  };
  template <class Keyed>
  void prepare(const std::vector<Box>& boxes, Keyed&& keyed) {
    flags_.resize(boxes.size());
    for (std::size_t i = 0; i < boxes.size(); ++i) flags_[i] = keyed(i);
    prepare_events(boxes);
  }
  void prepare_events(const std::vector<Box>& boxes);

  bool counts(const Box& b) const;
  bool prepare_scan(const std::vector<Box>& boxes);

  struct Extent {
    double lo, hi;  // along x
    std::uint32_t box;
  };
  Method method_ = Method::Auto;
  std::vector<Extent> order_;  // the boxes that count, by lo
  std::vector<double> starts_;
  BoxContact contact_ = BoxContact::Touching;
  std::vector<char> flags_;
  std::vector<Event> events_;
  struct Bound {
    double y;
    std::uint32_t end;  // 2 * box, + 1 for its upper bound
  };
  std::vector<Bound> bounds_;
  std::vector<std::uint32_t> lo_, hi_;  // y bounds as ranks among the distinct ones
  ActiveIntervals keyed_, unkeyed_;
};

}  // namespace curvetext::detail
