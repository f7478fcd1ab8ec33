#include "tessellate/triangulate.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <map>
#include <numeric>
#include <utility>
#include <vector>

#include "core/assert.hpp"
#include "tessellate/predicates.hpp"
#include "tessellate/rings.hpp"

namespace curvetext::detail {
namespace {

std::size_t prev_index(std::size_t i, std::size_t n) { return i == 0 ? n - 1 : i - 1; }
std::size_t next_index(std::size_t i, std::size_t n) { return i + 1 == n ? 0 : i + 1; }

// True when the direction from vertex `v` towards `target` points into the
// filled side at v, the filled side being left of prev->v and of v->next.
bool inside_cone(Vec2 prev, Vec2 v, Vec2 next, Vec2 target) {
  if (orient2d(prev, v, next) > 0) {  // convex corner: intersection of half-planes
    return orient2d(v, next, target) > 0 && orient2d(prev, v, target) > 0;
  }
  // reflex or straight corner: union of the half-planes
  return orient2d(v, next, target) > 0 || orient2d(prev, v, target) > 0;
}

// True when the bridge segment [o, h] meets the edge [p, q] anywhere other than
// at o or h themselves.
bool bridge_blocked_by(Vec2 o, Vec2 h, Vec2 p, Vec2 q) {
  const bool p_end = (p == o || p == h);
  const bool q_end = (q == o || q == h);
  if (p_end && q_end) return false;  // the edge joins the bridge's own endpoints
  if (p_end || q_end) {
    // Sharing an endpoint: only a collinear overlap counts.
    const Vec2 shared = p_end ? p : q;
    const Vec2 other = p_end ? q : p;
    const Vec2 far = (shared == o) ? h : o;
    return point_on_segment(o, h, other) || point_on_segment(shared, other, far);
  }
  return segments_intersect(o, h, p, q);
}

bool bridge_valid(const std::vector<Vec2>& outer, std::size_t oi, const std::vector<Vec2>& hole, std::size_t hi,
                  const std::vector<std::vector<Vec2>>& obstacles) {
  const Vec2 o = outer[oi];
  const Vec2 h = hole[hi];
  const std::size_t no = outer.size(), nh = hole.size();
  if (no >= 2 && !inside_cone(outer[prev_index(oi, no)], o, outer[next_index(oi, no)], h)) return false;
  if (nh >= 2 && !inside_cone(hole[prev_index(hi, nh)], h, hole[next_index(hi, nh)], o)) return false;
  Box bridge_box;
  bridge_box.add(o);
  bridge_box.add(h);
  auto loop_blocks = [&](const std::vector<Vec2>& loop) {
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const Vec2 p = loop[i], q = loop[next_index(i, loop.size())];
      if (std::max(p.x, q.x) < bridge_box.min.x || std::min(p.x, q.x) > bridge_box.max.x ||
          std::max(p.y, q.y) < bridge_box.min.y || std::min(p.y, q.y) > bridge_box.max.y)
        continue;
      if (bridge_blocked_by(o, h, p, q)) return true;
    }
    return false;
  };
  if (loop_blocks(outer)) return false;
  for (const auto& other : obstacles) {
    if (loop_blocks(other)) return false;
  }
  return true;
}

double squared_distance(Vec2 a, Vec2 b) { return dot(a - b, a - b); }

// Exact counter-clockwise angular order of the directions p->a and p->b
// (a, b != p), starting from the +x direction: first by half-plane (angles in
// [0, pi) before [pi, 2 pi)), then by orientation within a half-plane.
bool angle_less(Vec2 p, Vec2 a, Vec2 b) {
  auto upper = [&](Vec2 q) { return q.y > p.y || (q.y == p.y && q.x > p.x); };
  const bool ua = upper(a), ub = upper(b);
  if (ua != ub) return ua;
  return orient2d(p, a, b) > 0;
}

double loop_area(const std::vector<Vec2>& loop) {
  double area = 0.0;
  for (std::size_t i = 0; i < loop.size(); ++i) area += 0.5 * cross(loop[i], loop[next_index(i, loop.size())]);
  return area;
}

// Nonzero winding of a polygon loop around p, or Boundary when p is on it.
Where point_in_loop(const std::vector<Vec2>& loop, Vec2 p) {
  return point_in_polygon(
      loop.size(),
      [&](std::size_t i) {
        return std::pair{loop[i], loop[next_index(i, loop.size())]};
      },
      p);
}

// Whether the clockwise loop `hole` lies inside the counter-clockwise loop
// `outer`; the two may touch at vertices, so the first vertex of the hole off
// the outer decides (or, if every vertex is on it, an edge midpoint).
bool hole_inside(const std::vector<Vec2>& hole, const std::vector<Vec2>& outer) {
  for (const Vec2 p : hole) {
    const Where w = point_in_loop(outer, p);
    if (w != Where::Boundary) return w == Where::Inside;
  }
  for (std::size_t i = 0; i < hole.size(); ++i) {
    const Vec2 mid = 0.5 * (hole[i] + hole[next_index(i, hole.size())]);
    const Where w = point_in_loop(outer, mid);
    if (w != Where::Boundary) return w == Where::Inside;
  }
  return false;
}

}  // namespace

namespace {

// No position occurs twice among all loop vertices: checked on a sorted copy.
bool positions_repeat(const std::vector<Vec2>& outer, const std::vector<std::vector<Vec2>>& holes,
                      std::vector<std::pair<double, double>>& sorted) {
  sorted.clear();
  for (const Vec2 p : outer) sorted.emplace_back(p.x, p.y);
  for (const auto& hole : holes) {
    for (const Vec2 p : hole) sorted.emplace_back(p.x, p.y);
  }
  std::sort(sorted.begin(), sorted.end());
  return std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end();
}

std::vector<PolygonLoops> unchanged_loops(std::vector<Vec2>&& outer, std::vector<std::vector<Vec2>>&& holes) {
  std::vector<PolygonLoops> unchanged(1);
  unchanged[0].outer = std::move(outer);
  unchanged[0].holes = std::move(holes);
  return unchanged;
}

// Every loop vertex is a node; prev/next link the nodes of each loop.
struct LoopNodes {
  std::vector<Vec2> pos;
  std::vector<std::size_t> prev, next;

  void add_loop(const std::vector<Vec2>& loop) {
    const std::size_t first = pos.size();
    for (std::size_t i = 0; i < loop.size(); ++i) {
      // Zero-length edges have no direction to sort by; they carry nothing.
      if (pos.size() > first && loop[i] == pos.back()) continue;
      if (i + 1 == loop.size() && pos.size() > first && loop[i] == pos[first]) continue;
      pos.push_back(loop[i]);
    }
    const std::size_t count = pos.size() - first;
    for (std::size_t k = 0; k < count; ++k) {
      prev.push_back(first + prev_index(k, count));
      next.push_back(first + next_index(k, count));
    }
  }
};

// link[c]: having arrived at node c's position along c's incoming edge, the
// walk leaves along link[c]'s outgoing edge. At a shared vertex the filled
// side of an arrival lies clockwise of its incoming ray (it is on the left of
// the travel), so the departure that keeps the filled corner free of other
// edges is the first outgoing ray clockwise from the incoming ray. Around a
// vertex where non-crossing loops touch, incoming and outgoing rays
// alternate, so that is the next ray clockwise; skipping outgoing rays
// already taken only matters for garbage input, and keeps link a bijection.
// `by_position`: the nodes sorted by position.
std::vector<std::size_t> relink(const LoopNodes& g, const std::vector<std::size_t>& by_position) {
  const std::vector<Vec2>& pos = g.pos;
  const std::size_t n = pos.size();
  std::vector<std::size_t> link(n);
  std::iota(link.begin(), link.end(), std::size_t{0});
  struct Ray {
    Vec2 to;
    std::size_t node;
    bool outgoing;
  };
  std::vector<Ray> rays;
  std::vector<char> taken;
  std::vector<std::size_t> nodes;
  for (std::size_t first = 0; first < n;) {
    // The nodes at one position, in increasing node order.
    std::size_t last = first + 1;
    while (last < n && pos[by_position[last]] == pos[by_position[first]]) ++last;
    nodes.assign(by_position.begin() + static_cast<std::ptrdiff_t>(first),
                 by_position.begin() + static_cast<std::ptrdiff_t>(last));
    first = last;
    if (nodes.size() < 2) continue;
    const Vec2 p = pos[nodes.front()];
    rays.clear();
    for (std::size_t c : nodes) {
      rays.push_back({pos[g.prev[c]], c, false});
      rays.push_back({pos[g.next[c]], c, true});
    }
    std::stable_sort(rays.begin(), rays.end(), [&](const Ray& a, const Ray& b) { return angle_less(p, a.to, b.to); });
    taken.assign(rays.size(), 0);
    for (std::size_t i = 0; i < rays.size(); ++i) {
      if (rays[i].outgoing) continue;
      for (std::size_t step = 1; step < rays.size(); ++step) {
        const std::size_t j = (i + rays.size() - step) % rays.size();  // clockwise from ray i
        if (rays[j].outgoing && !taken[j]) {
          taken[j] = 1;
          link[rays[i].node] = rays[j].node;
          break;
        }
      }
    }
  }
  return link;
}

// Each hole to the innermost of the outers around it (smallest outers first).
std::vector<PolygonLoops> assign_holes(std::vector<std::vector<Vec2>>&& outers,
                                       std::vector<std::vector<Vec2>>&& new_holes) {
  std::vector<double> areas;
  for (const auto& loop : outers) areas.push_back(loop_area(loop));
  std::vector<std::size_t> order(outers.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return areas[a] < areas[b]; });
  std::vector<PolygonLoops> polygons(outers.size());
  for (std::size_t i = 0; i < outers.size(); ++i) polygons[i].outer = std::move(outers[i]);
  for (auto& hole : new_holes) {
    std::size_t home = order.back();  // garbage (no outer around it): the largest
    if (polygons.size() > 1) {
      for (std::size_t k : order) {
        if (hole_inside(hole, polygons[k].outer)) {
          home = k;
          break;
        }
      }
    }
    polygons[home].holes.push_back(std::move(hole));
  }
  return polygons;
}

}  // namespace

std::vector<PolygonLoops> relink_touching_loops(std::vector<Vec2> outer, std::vector<std::vector<Vec2>> holes,
                                                TriangulateScratch& scratch) {
  // Quick exit for the usual case: no position occurs twice among all loop
  // vertices (then none does among the nodes below, a subset), without
  // building the node lists.
  if (!positions_repeat(outer, holes, scratch.relink_sorted))
    return unchanged_loops(std::move(outer), std::move(holes));
  LoopNodes g;
  g.add_loop(outer);
  for (const auto& hole : holes) g.add_loop(hole);
  const std::vector<Vec2>& pos = g.pos;
  const std::size_t n = pos.size();

  // Loops that share no vertex (the usual case) are returned as they are.
  std::vector<std::size_t> by_position(n);
  std::iota(by_position.begin(), by_position.end(), std::size_t{0});
  auto position_less = [&](std::size_t i, std::size_t j) {
    return pos[i].x < pos[j].x || (pos[i].x == pos[j].x && (pos[i].y < pos[j].y || (pos[i].y == pos[j].y && i < j)));
  };
  std::sort(by_position.begin(), by_position.end(), position_less);
  bool touching = false;
  for (std::size_t k = 1; k < n && !touching; ++k) touching = pos[by_position[k]] == pos[by_position[k - 1]];
  if (!touching) return unchanged_loops(std::move(outer), std::move(holes));
  const std::vector<std::size_t> link = relink(g, by_position);

  // next[link[.]] is a permutation of the nodes: its cycles are the new loops.
  std::vector<std::vector<Vec2>> outers, new_holes;
  std::vector<char> visited(n, 0);
  for (std::size_t s = 0; s < n; ++s) {
    if (visited[s]) continue;
    std::vector<Vec2> loop;
    for (std::size_t cur = s; !visited[cur]; cur = g.next[link[cur]]) {
      visited[cur] = 1;
      loop.push_back(pos[cur]);
    }
    if (loop.size() < 3) continue;  // a back-and-forth between two points: no area
    const double area = loop_area(loop);
    if (area > 0.0) {
      outers.push_back(std::move(loop));
    } else if (area < 0.0) {
      new_holes.push_back(std::move(loop));
    }
  }
  // Not a region with the filled side on the left: left to the fallbacks.
  if (outers.empty()) return unchanged_loops(std::move(outer), std::move(holes));
  return assign_holes(std::move(outers), std::move(new_holes));
}

std::vector<Vec2> bridge_holes(std::vector<Vec2> outer, std::vector<std::vector<Vec2>> holes) {
  // Holes are joined left to right (as earcut does) so that a hole's bridge
  // usually finds the container directly to its left.
  auto leftmost = [](const std::vector<Vec2>& loop) {
    std::size_t best = 0;
    for (std::size_t i = 1; i < loop.size(); ++i) {
      if (loop[i].x < loop[best].x || (loop[i].x == loop[best].x && loop[i].y < loop[best].y)) best = i;
    }
    return best;
  };
  holes.erase(std::remove_if(holes.begin(), holes.end(), [](const auto& h) { return h.empty(); }), holes.end());
  std::sort(holes.begin(), holes.end(),
            [&](const auto& a, const auto& b) { return a[leftmost(a)].x < b[leftmost(b)].x; });

  for (std::size_t k = 0; k < holes.size(); ++k) {
    const std::vector<Vec2>& hole = holes[k];
    if (outer.empty()) {
      outer = hole;
      continue;
    }
    // The other holes not yet joined are obstacles (joined ones are in outer).
    std::vector<std::vector<Vec2>> obstacles(holes.begin() + static_cast<std::ptrdiff_t>(k), holes.end());

    std::vector<std::size_t> outer_order(outer.size());
    std::size_t found_o = outer.size(), found_h = 0;
    const std::size_t first_h = leftmost(hole);
    // Candidate hole vertices: the leftmost against every outer vertex, then
    // the others against their nearest few only, which bounds the work.
    constexpr std::size_t kNearCandidates = 8;
    for (std::size_t step = 0; step < hole.size() && found_o == outer.size(); ++step) {
      const std::size_t hi = (first_h + step) % hole.size();
      std::iota(outer_order.begin(), outer_order.end(), std::size_t{0});
      const Vec2 h = hole[hi];
      const std::size_t limit = step == 0 ? outer.size() : std::min(kNearCandidates, outer.size());
      std::partial_sort(
          outer_order.begin(), outer_order.begin() + static_cast<std::ptrdiff_t>(limit), outer_order.end(),
          [&](std::size_t a, std::size_t b) { return squared_distance(outer[a], h) < squared_distance(outer[b], h); });
      for (std::size_t c = 0; c < limit; ++c) {
        if (outer[outer_order[c]] == h || bridge_valid(outer, outer_order[c], hole, hi, obstacles)) {
          found_o = outer_order[c];
          found_h = hi;
          break;
        }
      }
    }
    if (found_o == outer.size()) {
      // Garbage input (the hole is not inside, or crosses): join at the closest
      // pair anyway; check_mesh will report the result.
      double best = 1e308;
      for (std::size_t i = 0; i < outer.size(); ++i) {
        for (std::size_t j = 0; j < hole.size(); ++j) {
          const double d = squared_distance(outer[i], hole[j]);
          if (d < best) best = d, found_o = i, found_h = j;
        }
      }
    }
    std::vector<Vec2> merged;
    merged.reserve(outer.size() + hole.size() + 2);
    merged.insert(merged.end(), outer.begin(), outer.begin() + static_cast<std::ptrdiff_t>(found_o) + 1);
    const bool touching = outer[found_o] == hole[found_h];
    // A hole touching its container at a vertex is joined at that pinch point
    // without a zero-length bridge.
    for (std::size_t j = touching ? 1 : 0; j <= hole.size(); ++j) {
      merged.push_back(hole[(found_h + j) % hole.size()]);
    }
    if (!touching) merged.push_back(outer[found_o]);
    merged.insert(merged.end(), outer.begin() + static_cast<std::ptrdiff_t>(found_o) + 1, outer.end());
    outer = std::move(merged);
  }
  return outer;
}

namespace {

// A candidate ear (a, b, c) with the boxes its tests skip by.
struct Ear {
  std::size_t ia, ib, ic;
  Vec2 corners[3];                                // a, b, c
  double min_x, max_x, min_y, max_y;              // the triangle's box
  double ac_min_x, ac_max_x, ac_min_y, ac_max_y;  // the diagonal's box
};

// Ear clipping of one loop (ear_clip): the loop as a linked list over
// `loop`'s indices, the live edges for the ear tests, the work spent.
class EarClipper {
 public:
  EarClipper(const std::vector<Vec2>& loop, std::vector<std::array<Vec2, 3>>& triangles, TriangulateScratch& scratch,
             std::size_t max_visits)
      : loop_(loop),
        triangles_(triangles),
        prev_(scratch.ear_prev),
        next_(scratch.ear_next),
        live_(scratch.live),
        max_visits_(max_visits) {}

  bool run();

 private:
  void spend(std::size_t work) {
    visits_ += work;
    if (visits_ > max_visits_) work_budget_exceeded("ear clipping", visits_, max_visits_);
  }
  void unlink(std::size_t i);
  std::size_t drop_repeats();
  bool is_ear(std::size_t ia, std::size_t ib, std::size_t ic);
  bool blocks(const Ear& ear, std::size_t p, const LiveEdges::Entry& e) const;
  std::size_t clip_any(std::size_t cur);

  const std::vector<Vec2>& loop_;
  std::vector<std::array<Vec2, 3>>& triangles_;
  std::vector<std::uint32_t>& prev_;
  std::vector<std::uint32_t>& next_;
  LiveEdges& live_;
  const std::size_t max_visits_;
  std::size_t visits_ = 0;
  std::size_t remaining_ = 0;
  bool tracking_ = false;  // `live_` is filled after the first clean-up
  bool clean_ = true;
};

void EarClipper::unlink(std::size_t i) {
  next_[prev_[i]] = next_[i];
  prev_[next_[i]] = prev_[i];
  --remaining_;
  if (tracking_) {
    live_.erase(static_cast<std::uint32_t>(i));
    live_.set(prev_[i], loop_[prev_[i]], loop_[next_[i]]);  // the edge that replaces i's two
  }
}

// Consecutive repeats (possible after bridging) carry no area: dropped.
// Returns where the clipping starts.
std::size_t EarClipper::drop_repeats() {
  const std::size_t n = loop_.size();
  std::size_t start = 0;
  for (std::size_t guard = 0; guard < n && remaining_ > 2; ++guard) {
    const std::size_t i = start;
    if (loop_[i] == loop_[next_[i]]) {
      start = next_[i];
      unlink(i);
    } else {
      start = next_[i];
    }
  }
  return start;
}

bool EarClipper::is_ear(std::size_t ia, std::size_t ib, std::size_t ic) {
  const Vec2 a = loop_[ia], b = loop_[ib], c = loop_[ic];
  if (orient2d(a, b, c) <= 0) return false;
  spend(live_.entries().size());
  const Ear ear{ia,
                ib,
                ic,
                {a, b, c},
                std::min({a.x, b.x, c.x}),
                std::max({a.x, b.x, c.x}),
                std::min({a.y, b.y, c.y}),
                std::max({a.y, b.y, c.y}),
                std::min(a.x, c.x),
                std::max(a.x, c.x),
                std::min(a.y, c.y),
                std::max(a.y, c.y)};
  // The new edge a-c must leave a and c into the filled side of their own
  // corners (at a repeated vertex only one of the copies' wedges is right)
  // and meet no loop edge except at a or c. A diagonal that coincides with
  // the edge beside it closes a lobe at a repeated vertex; that is fine.
  const Vec2 before_a = loop_[prev_[ia]], after_c = loop_[next_[ic]];
  if (before_a != c && !inside_cone(before_a, a, b, c)) return false;
  if (after_c != a && !inside_cone(b, c, after_c, a)) return false;
  // Every other vertex p of the loop and its edge p -> next[p]: the edge
  // must not meet the diagonal, the vertex must not lie in the triangle. The
  // diagonal lies in the triangle's box, so edges and vertices outside it
  // are skipped without predicates.
  for (const LiveEdges::Entry& e : live_.entries()) {
    if (e.x1 < ear.min_x || e.x0 > ear.max_x || e.y1 < ear.min_y || e.y0 > ear.max_y) continue;
    if (e.p == ia || e.p == ib || e.p == ic) continue;
    if (blocks(ear, e.p, e)) return false;
  }
  return true;
}

// Whether vertex p, or its edge p -> next[p] (live entry e), blocks the ear.
bool EarClipper::blocks(const Ear& ear, std::size_t p, const LiveEdges::Entry& e) const {
  const Vec2 a = ear.corners[0], b = ear.corners[1], c = ear.corners[2];
  const Vec2 pp = loop_[p];
  const bool p_outside_box = pp.x < ear.min_x || pp.x > ear.max_x || pp.y < ear.min_y || pp.y > ear.max_y;
  // An edge can only meet the diagonal inside the diagonal's own box (a
  // subset of the triangle's): an exact test that skips most predicates.
  if (!(e.x1 < ear.ac_min_x || e.x0 > ear.ac_max_x || e.y1 < ear.ac_min_y || e.y0 > ear.ac_max_y) &&
      bridge_blocked_by(a, c, pp, loop_[next_[p]]))
    return true;
  if (p_outside_box) return false;
  int corner = -1;
  for (int k = 0; k < 3; ++k) {
    if (pp == ear.corners[k]) corner = k;
  }
  if (corner < 0) {
    // Any other vertex in the closed triangle blocks (strictness avoids
    // T-junctions and zero-area triangles). point_in_triangle(a, b, c, pp) !=
    // Outside, with orient2d(a, b, c) > 0 known from the top of is_ear.
    return orient2d(a, b, pp) >= 0 && orient2d(b, c, pp) >= 0 && orient2d(c, a, pp) >= 0;
  }
  // A repeat of a corner (bridge or pinch vertex): its edges must not enter
  // the triangle from that corner.
  const Vec2 v = ear.corners[corner];
  const Vec2 x = ear.corners[(corner + 1) % 3];
  const Vec2 y = ear.corners[(corner + 2) % 3];
  for (std::size_t q : {std::size_t{prev_[p]}, std::size_t{next_[p]}}) {
    const Vec2 qq = loop_[q];
    if (qq == a || qq == b || qq == c) continue;  // along a triangle edge
    const int ox = orient2d(v, x, qq), oy = orient2d(v, y, qq);
    if (ox > 0 && oy < 0) return true;
    if (ox == 0 && dot(qq - v, x - v) > 0) return true;
    if (oy == 0 && dot(qq - v, y - v) > 0) return true;
  }
  return false;
}

// A full turn without an ear: the loop is not weakly simple. Best effort:
// clip the first strictly convex corner, or drop a vertex, so that every
// iteration removes one vertex and the loop terminates. Returns where to go
// on.
std::size_t EarClipper::clip_any(std::size_t cur) {
  clean_ = false;
  spend(remaining_);
  std::size_t pick = cur;
  bool convex_found = false;
  for (std::size_t i = 0, p = cur; i < remaining_; ++i, p = next_[p]) {
    if (orient2d(loop_[prev_[p]], loop_[p], loop_[next_[p]]) > 0) {
      pick = p;
      convex_found = true;
      break;
    }
  }
  if (convex_found) triangles_.push_back({loop_[prev_[pick]], loop_[pick], loop_[next_[pick]]});
  const std::size_t next = next_[pick];
  unlink(pick);
  return next;
}

bool EarClipper::run() {
  const std::size_t n = loop_.size();
  if (n < 3) return n == 0;
  if (n >= 0xffffffffu) return false;  // indices are 32-bit
  prev_.resize(n);
  next_.resize(n);
  live_.reset(n);
  for (std::size_t i = 0; i < n; ++i) {
    prev_[i] = static_cast<std::uint32_t>(prev_index(i, n));
    next_[i] = static_cast<std::uint32_t>(next_index(i, n));
  }
  remaining_ = n;
  const std::size_t start = drop_repeats();
  std::uint32_t p = static_cast<std::uint32_t>(start);
  for (std::size_t k = 0; k < remaining_; ++k, p = next_[p]) live_.set(p, loop_[p], loop_[next_[p]]);
  tracking_ = true;
  std::size_t cur = start;
  std::size_t stall = 0;
  while (remaining_ > 3) {
    CURVETEXT_ASSERT(prev_[next_[cur]] == cur && next_[prev_[cur]] == cur);  // cur is still linked
    const std::size_t a = prev_[cur], c = next_[cur];
    if (is_ear(a, cur, c)) {
      triangles_.push_back({loop_[a], loop_[cur], loop_[c]});
      unlink(cur);
      // Closing a lobe at a repeated vertex leaves two copies side by side.
      if (remaining_ > 3 && loop_[a] == loop_[c]) unlink(c);
      cur = next_[c];
      stall = 0;
      continue;
    }
    cur = c;
    if (++stall < remaining_) continue;
    cur = clip_any(cur);
    stall = 0;
  }
  if (remaining_ == 3) {
    const std::size_t a = prev_[cur], c = next_[cur];
    const int o = orient2d(loop_[a], loop_[cur], loop_[c]);
    if (o > 0) {
      triangles_.push_back({loop_[a], loop_[cur], loop_[c]});
    } else if (o < 0) {
      clean_ = false;
    }
  }
  return clean_;
}

}  // namespace

bool ear_clip(const std::vector<Vec2>& loop, std::vector<std::array<Vec2, 3>>& triangles, TriangulateScratch& scratch,
              std::size_t max_visits) {
  return EarClipper(loop, triangles, scratch, max_visits).run();
}

}  // namespace curvetext::detail
