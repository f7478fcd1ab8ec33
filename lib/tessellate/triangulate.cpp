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

namespace {

// The flips' edge table: every edge of the triangles with the faces on its
// sides, the shared ones stacked as candidates (in triangle order), the
// constrained ones marked fixed.
void index_edges(const std::vector<std::array<std::uint32_t, 3>>& triangles, const std::vector<EdgeKey>& constrained,
                 TriangulateScratch& scratch) {
  EdgeTable& edges = scratch.edges;
  std::vector<EdgeKey>& stack = scratch.flip_stack;
  edges.reset(3 * triangles.size());
  stack.clear();
  stack.reserve(3 * triangles.size());
  for (std::uint32_t t = 0; t < triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const EdgeKey key = edge_key(triangles[t][k], triangles[t][(k + 1) % 3]);
      EdgeTable::Faces& e = edges.at(key);
      if (e.count < 2) e.face[e.count] = t;
      ++e.count;
      if (e.count == 2) stack.push_back(key);  // candidates in triangle order
    }
  }
  // Constrained edges are marked once in the table instead of being looked up
  // in `constrained` for every candidate popped from the stack.
  // Those not in the mesh (possible after remove_folds or a fallback ear)
  // are the only ones a flip could create: fixed edges never flip, so the
  // others are never removed and re-created. Kept apart (sorted, usually
  // empty) so that a new edge is looked up there instead of in all of them.
  std::vector<EdgeKey>& missing = scratch.missing;
  missing.clear();
  for (const EdgeKey& key : constrained) {
    if (EdgeTable::Faces* e = edges.find(key)) {
      e->fixed = true;
    } else {
      missing.push_back(key);
    }
  }
}

}  // namespace

void delaunay_flips(const std::vector<Vec2>& points, std::vector<std::array<std::uint32_t, 3>>& triangles,
                    const std::vector<EdgeKey>& constrained, TriangulateScratch& scratch) {
  index_edges(triangles, constrained, scratch);
  EdgeTable& edges = scratch.edges;
  std::vector<EdgeKey>& stack = scratch.flip_stack;
  const std::vector<EdgeKey>& missing = scratch.missing;
  // Lawson's algorithm terminates with exact predicates; ours are not exact
  // (incircle_sign falls back to long double near zero), so the flip count is capped to guarantee an end.
  std::size_t flips_left = 16 * triangles.size() + 64;
  auto opposite = [&](const std::array<std::uint32_t, 3>& t, std::uint32_t u, std::uint32_t v) {
    for (int k = 0; k < 3; ++k) {
      if (t[k] != u && t[k] != v) return t[k];
    }
    return t[0];
  };
  auto has_directed = [](const std::array<std::uint32_t, 3>& t, std::uint32_t u, std::uint32_t v) {
    for (int k = 0; k < 3; ++k) {
      if (t[k] == u && t[(k + 1) % 3] == v) return true;
    }
    return false;
  };
  // Returns the edge's entry (null if none).
  auto replace_face = [&](EdgeKey key, std::uint32_t from, std::uint32_t to) {
    EdgeTable::Faces* e = edges.find(key);
    if (!e) return e;
    for (int k = 0; k < 2; ++k) {
      if (e->face[k] == from) {
        e->face[k] = to;
        break;
      }
    }
    return e;
  };
  // An edge that is fixed or not shared by two triangles stays so: popping
  // it would do nothing, so it is not pushed.
  auto flippable = [](const EdgeTable::Faces* e) { return e && e->count == 2 && !e->fixed; };
  while (!stack.empty() && flips_left > 0) {
    const EdgeKey key = stack.back();
    stack.pop_back();
    EdgeTable::Faces* e = edges.find(key);
    if (!e || e->count != 2 || e->fixed) continue;
    std::uint32_t t1 = e->face[0], t2 = e->face[1];
    std::uint32_t a = key.first, b = key.second;
    if (!has_directed(triangles[t1], a, b)) std::swap(a, b);
    if (!has_directed(triangles[t1], a, b) || !has_directed(triangles[t2], b, a)) continue;
    const std::uint32_t c = opposite(triangles[t1], a, b);
    const std::uint32_t d = opposite(triangles[t2], a, b);
    if (c == d) continue;
    const Vec2 pa = points[a], pb = points[b], pc = points[c], pd = points[d];
    if (orient2d(pa, pd, pc) <= 0 || orient2d(pd, pb, pc) <= 0) continue;  // quad not strictly convex
    if (incircle_sign(pa, pb, pc, pd) <= 0) continue;
    const EdgeKey cd = edge_key(c, d);
    if (edges.find(cd)) continue;  // would duplicate an existing edge
    triangles[t1] = {a, d, c};
    triangles[t2] = {d, b, c};
    e->count = 0;                               // edge a-b is gone
    EdgeTable::Faces& new_edge = edges.at(cd);  // may move the table: e is not used below
    new_edge.face[0] = t1;
    new_edge.face[1] = t2;
    new_edge.count = 2;
    new_edge.fixed = !missing.empty() && std::binary_search(missing.begin(), missing.end(), cd);
    const bool push_ad = flippable(replace_face(edge_key(a, d), t2, t1));
    const bool push_bc = flippable(replace_face(edge_key(b, c), t1, t2));
    --flips_left;
    if (push_ad) stack.push_back(edge_key(a, d));
    stack.push_back(edge_key(d, b));
    if (push_bc) stack.push_back(edge_key(b, c));
    stack.push_back(edge_key(c, a));
  }
}

// Meshes of up to this many points find twins in a direct table of n^2
// 16-bit entries (128 KiB at most); larger ones hash.
constexpr std::size_t kDirectVertices = 256;

namespace {

// Half-edge h = 4 t + k (k < 3: a shift and a mask instead of a division)
// runs from triangles[t][k] to triangles[t][k + 1]; twin[h] is the half-edge
// running back on the other triangle, or -1.
constexpr std::uint32_t kNext[3] = {1, 2, 0}, kPrev[3] = {2, 0, 1};

// twin[h] for h = a -> b is the half-edge b -> a, found by a table lookup
// without branches (whether an edge has a twin, inner or boundary, comes in
// no predictable order; mispredicted branches cost more here than the
// arithmetic). Up to kDirectVertices points the table is indexed directly by
// the pair; larger meshes hash it.
void find_twins(std::size_t n, const std::vector<std::array<std::uint32_t, 3>>& triangles,
                TriangulateScratch& scratch) {
  const std::size_t m = triangles.size();
  std::vector<std::int32_t>& twin = scratch.twin;
  twin.assign(4 * m, -1);
  if (n <= kDirectVertices && 4 * m < 0xffff) {  // (h + 1 fits in 16 bits)
    // Entry a * n + b holds h + 1 for h = a -> b, 0 for none. Every entry
    // written is reset before returning, so the table is all zero between
    // calls and is never cleared as a whole.
    std::vector<std::uint16_t>& direct = scratch.direct;
    if (direct.size() < n * n) direct.assign(n * n, 0);
    for (std::uint32_t t = 0; t < m; ++t)
      for (std::uint32_t k = 0; k < 3; ++k)
        direct[triangles[t][k] * n + triangles[t][kNext[k]]] = static_cast<std::uint16_t>(4 * t + k + 1);
    for (std::uint32_t t = 0; t < m; ++t)
      for (std::uint32_t k = 0; k < 3; ++k)
        twin[4 * t + k] = static_cast<std::int32_t>(direct[triangles[t][kNext[k]] * n + triangles[t][k]]) - 1;
    for (std::uint32_t t = 0; t < m; ++t)
      for (std::uint32_t k = 0; k < 3; ++k) direct[triangles[t][k] * n + triangles[t][kNext[k]]] = 0;
  } else {
    // Open addressing on the directed pair, at most a quarter full, so that a
    // probe rarely goes past its first slot.
    constexpr std::uint64_t kEmptyKey = ~std::uint64_t{0};            // all bits set: filled by memset
    std::vector<std::uint64_t>& keys = scratch.twin_keys;             // a << 32 | b, or kEmptyKey
    std::vector<std::int32_t>& half_edges = scratch.twin_half_edges;  // the half-edge of each key
    int bits = 4;
    while ((std::size_t{1} << bits) < 12 * m) ++bits;
    const std::size_t mask = (std::size_t{1} << bits) - 1;
    keys.resize(mask + 1);
    half_edges.resize(mask + 1);
    std::memset(keys.data(), 0xff, keys.size() * sizeof(std::uint64_t));
    // Each end multiplied by its own odd constant (one product of the packed
    // key would put keys with nearby ends in nearby slots).
    auto slot_of = [&](std::uint32_t a, std::uint32_t b) {
      return static_cast<std::size_t>((a * 0x9e3779b97f4a7c15ull ^ b * 0xc2b2ae3d27d4eb4full) >> (64 - bits));
    };
    for (std::uint32_t t = 0; t < m; ++t) {
      for (std::uint32_t k = 0; k < 3; ++k) {
        const std::uint32_t a = triangles[t][k], b = triangles[t][kNext[k]];
        std::size_t slot = slot_of(a, b);
        while (keys[slot] != kEmptyKey) slot = (slot + 1) & mask;
        keys[slot] = std::uint64_t{a} << 32 | b;
        half_edges[slot] = static_cast<std::int32_t>(4 * t + k);
      }
    }
    for (std::uint32_t t = 0; t < m; ++t) {
      for (std::uint32_t k = 0; k < 3; ++k) {
        const std::uint32_t a = triangles[t][kNext[k]], b = triangles[t][k];
        const std::uint64_t key = std::uint64_t{a} << 32 | b;
        std::size_t slot = slot_of(a, b);
        while ((keys[slot] != key) & (keys[slot] != kEmptyKey)) slot = (slot + 1) & mask;
        const std::int32_t found = -static_cast<std::int32_t>(keys[slot] == key);  // all ones or zero
        twin[4 * t + k] = (half_edges[slot] & found) | ~found;                     // the twin or -1
      }
    }
  }
}

}  // namespace

void delaunay_flips_manifold(const std::vector<Vec2>& points, std::vector<std::array<std::uint32_t, 3>>& triangles,
                             TriangulateScratch& scratch) {
  const std::size_t m = triangles.size();
  if (m < 2) return;
  find_twins(points.size(), triangles, scratch);
  std::vector<std::int32_t>& twin = scratch.twin;
  std::vector<std::uint32_t>& stack = scratch.manifold_stack;
  // Every inner edge once (from its first side), written without a branch.
  stack.resize(4 * m);
  std::size_t inner = 0;
  for (std::uint32_t h = 0; h < 4 * m; ++h) {
    stack[inner] = h;
    inner += static_cast<std::size_t>(twin[h] > static_cast<std::int32_t>(h));
  }
  stack.resize(inner);
  auto link = [&](std::uint32_t h, std::int32_t other) {
    twin[h] = other;
    if (other >= 0) twin[static_cast<std::size_t>(other)] = static_cast<std::int32_t>(h);
  };
  std::size_t flips_left = 16 * m + 64;  // as in delaunay_flips
  while (!stack.empty() && flips_left > 0) {
    const std::uint32_t h = stack.back();
    stack.pop_back();
    const std::int32_t g = twin[h];
    // Every twin found runs between the same two points; a half-edge that
    // occurs twice (a non-manifold input: never from the sweep) can leave
    // the pairs one-sided, and those are never flipped.
    if (g < 0 || twin[static_cast<std::size_t>(g)] != static_cast<std::int32_t>(h)) continue;
    const std::uint32_t t1 = h >> 2, k1 = h & 3, t2 = static_cast<std::uint32_t>(g) >> 2,
                        k2 = static_cast<std::uint32_t>(g) & 3;
    const std::uint32_t a = triangles[t1][k1], b = triangles[t1][kNext[k1]], c = triangles[t1][kPrev[k1]];
    const std::uint32_t d = triangles[t2][kPrev[k2]];
    if (c == d) continue;
    const Vec2 pa = points[a], pb = points[b], pc = points[c], pd = points[d];
    // (The incircle test first: most edges of the sweep's triangulation are
    // already locally Delaunay, and it rejects them in one test.)
    if (incircle_sign(pa, pb, pc, pd) <= 0) continue;
    if (orient2d(pa, pd, pc) <= 0 || orient2d(pd, pb, pc) <= 0) continue;  // quad not strictly convex
    const std::int32_t bc = twin[4 * t1 + kNext[k1]], ca = twin[4 * t1 + kPrev[k1]];
    const std::int32_t ad = twin[4 * t2 + kNext[k2]], db = twin[4 * t2 + kPrev[k2]];
    triangles[t1] = {a, d, c};
    triangles[t2] = {d, b, c};
    link(4 * t1 + 0, ad);
    link(4 * t1 + 1, static_cast<std::int32_t>(4 * t2 + 2));
    link(4 * t1 + 2, ca);
    link(4 * t2 + 0, db);
    link(4 * t2 + 1, bc);
    --flips_left;
    for (const std::uint32_t e : {4 * t1 + 0, 4 * t1 + 2, 4 * t2 + 0, 4 * t2 + 1})
      if (twin[e] >= 0) stack.push_back(e);
  }
}

}  // namespace curvetext::detail
