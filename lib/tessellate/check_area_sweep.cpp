#include "tessellate/check_area_sweep.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>

#include "tessellate/predicates.hpp"

namespace curvetext::detail {
namespace {

// (y, x) order: the order the sweep meets points in.
bool later(Vec2 a, Vec2 b) { return a.y > b.y || (a.y == b.y && a.x > b.x); }

bool finite(Vec2 p) { return std::isfinite(p.x) && std::isfinite(p.y); }

}  // namespace

bool AreaSweep::LaterKey::operator()(const Crossing& a, const Crossing& b) const { return later(a.key, b.key); }

bool AreaSweep::Order::operator()(Slot a, Vec2 v) const {
  const Piece& p = sweep->pieces_[a.piece];
  return orient2d(p.lo, p.hi, v) < 0;
}

bool AreaSweep::Order::operator()(Vec2 v, Slot a) const {
  const Piece& p = sweep->pieces_[a.piece];
  return orient2d(p.lo, p.hi, v) > 0;
}

// Which side of `of` (as a line lo -> hi) `other` starts on: its lo, or its
// hi when its lo lies on that line; 0 when both do (collinear).
int AreaSweep::side(const Piece& of, const Piece& other) const {
  const int o = orient2d(of.lo, of.hi, other.lo);
  return o != 0 ? o : orient2d(of.lo, of.hi, other.hi);
}

// Whether piece a lies left of piece b where the sweep line meets both: the
// one that started later is placed by where it starts. Ties (collinear
// pieces, which bound no area between them) by index.
bool AreaSweep::left_of(std::uint32_t a, std::uint32_t b) const {
  const Piece& pa = pieces_[a];
  const Piece& pb = pieces_[b];
  int s = 0;
  if (pa.lo == pb.lo) {
    s = orient2d(pa.lo, pb.hi, pa.hi);
  } else if (later(pa.lo, pb.lo)) {
    s = side(pb, pa);
  } else {
    s = -side(pa, pb);
  }
  return s != 0 ? s > 0 : a < b;
}

// Two adjacent pieces, `left` before `right` in the tree, that cross
// properly and are still in their order below the crossing.
bool AreaSweep::crosses_ahead(const Piece& left, const Piece& right) const {
  if (!segments_cross_properly(left.lo, left.hi, right.lo, right.hi)) return false;
  if (later(right.lo, left.lo)) return orient2d(left.lo, left.hi, right.lo) < 0;
  return orient2d(right.lo, right.hi, left.lo) > 0;
}

void AreaSweep::prepare(const std::vector<Edge>& edges) {
  pieces_.clear();
  pieces_.reserve(edges.size());
  endpoints_.clear();
  endpoints_.reserve(2 * edges.size());
  Box box;
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const Edge& e = edges[i];
    // Non-finite edges bound nothing measurable; zero-length ones nothing.
    if (!finite(e.a) || !finite(e.b) || e.a == e.b) continue;
    Piece p{};
    const bool forward = later(e.b, e.a);
    p.lo = forward ? e.a : e.b;
    p.hi = forward ? e.b : e.a;
    p.from = p.lo;
    p.cap = e.cap;
    p.dy = p.hi.y - p.lo.y;
    p.up = forward ? 1 : -1;
    p.edge = static_cast<std::uint32_t>(i);
    const auto id = static_cast<std::uint32_t>(pieces_.size());
    endpoints_.push_back({p.lo, id, true});
    endpoints_.push_back({p.hi, id, false});
    box.add(p.lo);
    box.add(p.hi);
    pieces_.push_back(p);
  }
  std::sort(endpoints_.begin(), endpoints_.end(), [](const Endpoint& a, const Endpoint& b) {
    if (a.p == b.p) return a.piece < b.piece;
    return later(b.p, a.p);
  });
  centre_x_ = box.empty() ? 0.0 : 0.5 * (box.min.x + box.max.x);
}

double AreaSweep::run(const std::vector<Edge>& edges, const std::vector<std::size_t>& contour_size, FillRule rule,
                      bool& touching) {
  rule_ = rule;
  edges_ = &edges;
  contour_size_ = &contour_size;
  prepare(edges);
  tree_.clear();
  crossings_ = {};
  area_ = caps_ = 0.0;
  touching_ = false;
  for (std::size_t first = 0; first < endpoints_.size();) {
    const Vec2 v = endpoints_[first].p;
    std::size_t last = first;
    while (last < endpoints_.size() && endpoints_[last].p == v) ++last;
    // Crossings at or before this vertex first (keys are clamped to no
    // later than either piece's end).
    while (!crossings_.empty() && !later(crossings_.top().key, v)) {
      const Crossing c = crossings_.top();
      crossings_.pop();
      now_ = c.key;
      crossing(c);
    }
    now_ = v;
    vertex(first, last);
    first = last;
  }
  touching = touching_;
  return area_ + caps_;
}

// Pieces of the vertex's group [first, last): those ending at v leave, those
// passing exactly through v are cut there, then those starting at v (and the
// cut ones' upper parts) enter.
void AreaSweep::vertex(std::size_t first, std::size_t last) {
  const Vec2 v = endpoints_[first].p;
  if (touches_at(first, last)) touching_ = true;
  collect_through(v);
  if (!through_.empty()) touching_ = true;
  for (std::size_t k = first; k < last; ++k)
    if (!endpoints_[k].start) remove_ending(endpoints_[k].piece, v);
  starting_.clear();
  for (const std::uint32_t id : through_) {
    Piece& p = pieces_[id];
    close(p, v);
    tree_.erase(p.at);
    p.lo = v;
    starting_.push_back(id);
  }
  for (std::size_t k = first; k < last; ++k)
    if (endpoints_[k].start) starting_.push_back(endpoints_[k].piece);
  insert_starting(v);
}

// Pieces on which v lies without ending there (found around v's place in the tree).
void AreaSweep::collect_through(Vec2 v) {
  through_.clear();
  auto on = [&](Tree::iterator it) {
    const Piece& p = pieces_[it->piece];
    return orient2d(p.lo, p.hi, v) == 0;
  };
  const auto place = tree_.lower_bound(v);
  for (auto it = place; it != tree_.end() && on(it); ++it)
    if (!(pieces_[it->piece].hi == v)) through_.push_back(it->piece);
  for (auto it = place; it != tree_.begin();) {
    --it;
    if (!on(it)) break;
    if (!(pieces_[it->piece].hi == v)) through_.push_back(it->piece);
  }
}

// A piece ending at v leaves the tree. Should rounding have left it on the
// wrong side of a neighbour that v is strictly beyond (a crossing placed
// slightly off), it is first moved past that neighbour, so that the
// windings stay consistent.
void AreaSweep::remove_ending(std::uint32_t id, Vec2 v) {
  Piece& p = pieces_[id];
  for (auto next = std::next(p.at); next != tree_.end(); next = std::next(p.at)) {
    const Piece& n = pieces_[next->piece];
    if (n.hi == v || orient2d(n.lo, n.hi, v) >= 0) break;
    swap_adjacent(p.at, next, v);
  }
  while (p.at != tree_.begin()) {
    const auto prev = std::prev(p.at);
    const Piece& n = pieces_[prev->piece];
    if (n.hi == v || orient2d(n.lo, n.hi, v) <= 0) break;
    swap_adjacent(prev, p.at, v);
  }
  close(p, v);
  const auto after = tree_.erase(p.at);
  p.active = false;
  if (after != tree_.end() && after != tree_.begin()) check_pair(std::prev(after));
}

void AreaSweep::insert_starting(Vec2 v) {
  for (const std::uint32_t id : starting_) {
    Piece& p = pieces_[id];
    p.at = tree_.insert(Slot{id});
    p.from = v;
    p.active = true;
    p.fresh = true;
  }
  // Windings left to right over each run of new pieces (one inserted later
  // may have landed left of an earlier one).
  auto fresh = [&](Tree::iterator it) { return pieces_[it->piece].fresh; };
  for (const std::uint32_t id : starting_) {
    if (!pieces_[id].fresh) continue;
    auto it = pieces_[id].at;
    while (it != tree_.begin() && fresh(std::prev(it))) --it;
    for (; it != tree_.end() && fresh(it); ++it) {
      Piece& p = pieces_[it->piece];
      const Piece* left = it == tree_.begin() ? nullptr : &pieces_[std::prev(it)->piece];
      p.w_minus = left ? left->w_minus - left->up : 0;
      p.fresh = false;
    }
  }
  for (const std::uint32_t id : starting_) {
    const auto at = pieces_[id].at;
    if (at != tree_.begin()) check_pair(std::prev(at));
    if (std::next(at) != tree_.end()) check_pair(at);
  }
}

// Schedules the crossing of `left` and its right neighbour if there is one ahead.
void AreaSweep::check_pair(Tree::iterator left) {
  const auto right = std::next(left);
  const Piece& l = pieces_[left->piece];
  const Piece& r = pieces_[right->piece];
  if (!crosses_ahead(l, r)) return;
  const Vec2 d = l.hi - l.lo, q = r.hi - r.lo;
  // (Nearly parallel pieces can cross with a cross product that rounds to
  // 0: then any point of the pair's common span serves.)
  double t = cross(r.lo - l.lo, q) / cross(d, q);
  t = std::isnan(t) ? 0.5 : std::clamp(t, 0.0, 1.0);
  const Vec2 at = l.lo + d * t;
  Vec2 key = later(now_, at) ? now_ : at;
  const Vec2 end = later(l.hi, r.hi) ? r.hi : l.hi;
  if (later(key, end)) key = end;
  crossings_.push({key, at, left->piece, right->piece});
}

void AreaSweep::crossing(const Crossing& c) {
  const Piece& l = pieces_[c.left];
  const Piece& r = pieces_[c.right];
  if (!l.active || !r.active || std::next(l.at) != r.at || !crosses_ahead(l, r)) return;
  touching_ = true;
  swap_adjacent(l.at, r.at, c.at);
}

void AreaSweep::swap_adjacent(Tree::iterator left, Tree::iterator right, Vec2 at) {
  Piece& l = pieces_[left->piece];
  Piece& r = pieces_[right->piece];
  close(l, at);
  close(r, at);
  r.w_minus = l.w_minus;
  l.w_minus = r.w_minus - r.up;
  std::swap(left->piece, right->piece);
  l.at = right;
  r.at = left;
  if (left != tree_.begin()) check_pair(std::prev(left));
  if (std::next(right) != tree_.end()) check_pair(right);
}

// Adds the run of p from p.from to `to`: where p bounds the nonzero region
// (exactly one side filled), the integral of x dy, and the cap's share.
void AreaSweep::close(Piece& p, Vec2 to) {
  const int w_plus = p.w_minus - p.up;
  const double dy = to.y - p.from.y;
  const double bound = static_cast<double>(fills(rule_, p.w_minus)) - static_cast<double>(fills(rule_, w_plus));
  area_ += bound * (0.5 * (p.from.x + to.x) - centre_x_) * dy;
  if (p.cap != 0.0 && p.dy > 0.0) {
    // Left of the contour's direction: the -x side when it runs upwards.
    const int left = p.up > 0 ? p.w_minus : w_plus, right = p.up > 0 ? w_plus : p.w_minus;
    caps_ += p.cap * (dy / p.dy) * (static_cast<double>(fills(rule_, left)) - static_cast<double>(fills(rule_, right)));
  }
  p.from = to;
}

// Whether the pieces with an end at this vertex meet other than as two
// consecutive, non-collinear pieces of one contour.
bool AreaSweep::touches_at(std::size_t first, std::size_t last) const {
  if (last - first > 2) return true;
  if (last - first < 2) return false;
  const Edge& e = (*edges_)[pieces_[endpoints_[first].piece].edge];
  const Edge& f = (*edges_)[pieces_[endpoints_[first + 1].piece].edge];
  if (e.contour != f.contour) return true;
  const std::size_t lo = std::min(e.index, f.index), hi = std::max(e.index, f.index);
  const bool consecutive = hi == lo + 1 || (lo == 0 && hi + 1 == (*contour_size_)[e.contour]);
  return !consecutive || (orient2d(e.a, e.b, f.a) == 0 && orient2d(e.a, e.b, f.b) == 0);
}

}  // namespace curvetext::detail
