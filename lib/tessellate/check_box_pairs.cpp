#include "tessellate/check_box_pairs.hpp"

#include <algorithm>

namespace curvetext::detail {

// (A finished sweep has erased every box it inserted: the lists are empty.)
void ActiveIntervals::reset(std::size_t ranks, std::size_t boxes) {
  leaves_ = 1;
  while (leaves_ < ranks) leaves_ *= 2;
  if (covers_.size() < 2 * leaves_) {
    covers_.resize(2 * leaves_, kNone);
    starts_.resize(2 * leaves_, kNone);
    count_.resize(2 * leaves_, 0);
  }
  if (first_.size() < boxes) {
    first_.resize(boxes, kNone);
    start_entry_.resize(boxes, kNone);
  }
}

std::uint32_t ActiveIntervals::link(std::vector<std::uint32_t>& heads, std::size_t node, std::uint32_t box) {
  std::uint32_t e = free_;
  if (e != kNone) {
    free_ = pool_[e].next;
  } else {
    e = static_cast<std::uint32_t>(pool_.size());
    pool_.emplace_back();
  }
  const std::uint32_t head = heads[node];
  pool_[e] = {box, kNone, head, static_cast<std::uint32_t>(node), kNone};
  if (head != kNone) pool_[head].prev = e;
  heads[node] = e;
  return e;
}

void ActiveIntervals::unlink(std::vector<std::uint32_t>& heads, std::uint32_t e) {
  const Entry& entry = pool_[e];
  if (entry.prev != kNone) {
    pool_[entry.prev].next = entry.next;
  } else {
    heads[entry.node] = entry.next;
  }
  if (entry.next != kNone) pool_[entry.next].prev = entry.prev;
  pool_[e].next = free_;
  free_ = e;
}

void ActiveIntervals::insert(std::uint32_t box, std::uint32_t lo, std::uint32_t hi) {
  // The canonical nodes of [lo, hi], bottom-up.
  first_[box] = kNone;
  for (std::size_t l = lo + leaves_, r = hi + leaves_ + 1; l < r; l /= 2, r /= 2) {
    for (const std::size_t node : {l & 1 ? l++ : 0, r & 1 ? --r : 0}) {
      if (node == 0) continue;
      const std::uint32_t e = link(covers_, node, box);
      pool_[e].sibling = first_[box];
      first_[box] = e;
    }
  }
  start_entry_[box] = link(starts_, lo + leaves_, box);
  for (std::size_t node = lo + leaves_; node >= 1; node /= 2) ++count_[node];
}

void ActiveIntervals::erase(std::uint32_t box, std::uint32_t lo) {
  for (std::uint32_t e = first_[box]; e != kNone;) {
    const std::uint32_t sibling = pool_[e].sibling;
    unlink(covers_, e);
    e = sibling;
  }
  first_[box] = kNone;
  unlink(starts_, start_entry_[box]);
  for (std::size_t node = lo + leaves_; node >= 1; node /= 2) --count_[node];
}

bool BoxPairSearch::counts(const Box& b) const {
  if (contact_ == BoxContact::Touching) return !b.empty();
  return b.min.x < b.max.x && b.min.y < b.max.y;
}

// Sorts the boxes along x and counts the pairs a forward scan would meet
// (boxes starting within each box's x range); whether that is cheap.
bool BoxPairSearch::prepare_scan(const std::vector<Box>& boxes) {
  order_.clear();
  for (std::size_t i = 0; i < boxes.size(); ++i)
    if (counts(boxes[i])) order_.push_back({boxes[i].min.x, boxes[i].max.x, static_cast<std::uint32_t>(i)});
  std::sort(order_.begin(), order_.end(), [](const Extent& a, const Extent& b) { return a.lo < b.lo; });
  if (method_ == Method::Scan) return true;
  const std::size_t budget = kScanPairsPerBox * order_.size() + kScanPairsConstant;
  starts_.resize(order_.size());
  for (std::size_t k = 0; k < order_.size(); ++k) starts_[k] = order_[k].lo;
  const bool open = contact_ == BoxContact::Interiors;
  std::size_t pairs = 0;
  for (std::size_t k = 0; k < order_.size(); ++k) {
    const auto from = starts_.begin() + static_cast<std::ptrdiff_t>(k + 1);
    const auto end = open ? std::lower_bound(from, starts_.end(), order_[k].hi)
                          : std::upper_bound(from, starts_.end(), order_[k].hi);
    pairs += static_cast<std::size_t>(end - from);
    if (pairs > budget) return false;
  }
  return true;
}

void BoxPairSearch::prepare_events(const std::vector<Box>& boxes) {
  events_.clear();
  events_.reserve(2 * boxes.size());
  bounds_.clear();
  bounds_.reserve(2 * boxes.size());
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    const Box& b = boxes[i];
    if (!counts(b)) continue;
    const auto box = static_cast<std::uint32_t>(i);
    events_.push_back({b.min.x, box, false, flags_[i] != 0});
    events_.push_back({b.max.x, box, true, flags_[i] != 0});
    bounds_.push_back({b.min.y, 2 * box});
    bounds_.push_back({b.max.y, 2 * box + 1});
  }
  // At one x, starts before ends when boxes that touch overlap, else after.
  const bool starts_first = contact_ == BoxContact::Touching;
  std::sort(events_.begin(), events_.end(), [&](const Event& a, const Event& b) {
    if (a.x != b.x) return a.x < b.x;
    if (a.end != b.end) return starts_first ? b.end : a.end;
    return a.box < b.box;
  });
  // y bounds as ranks among the distinct values. Open boxes: [lo, hi)
  // between distinct bounds, as the closed rank range [lo, hi - 1] (hi > lo
  // for the boxes that count).
  std::sort(bounds_.begin(), bounds_.end(), [](const Bound& a, const Bound& b) { return a.y < b.y; });
  lo_.resize(boxes.size());
  hi_.resize(boxes.size());
  const std::uint32_t open = contact_ == BoxContact::Interiors ? 1 : 0;
  std::uint32_t rank = 0;
  for (std::size_t k = 0; k < bounds_.size(); ++k) {
    if (k > 0 && bounds_[k].y != bounds_[k - 1].y) ++rank;
    const std::uint32_t box = bounds_[k].end / 2;
    if (bounds_[k].end % 2 == 0) {
      lo_[box] = rank;
    } else {
      hi_[box] = rank - open;
    }
  }
  const std::size_t ranks = bounds_.empty() ? 0 : rank + 1;
  keyed_.reset(ranks, boxes.size());
  unkeyed_.reset(ranks, boxes.size());
}

}  // namespace curvetext::detail
