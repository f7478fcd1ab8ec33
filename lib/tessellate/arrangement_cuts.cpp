// Cut points of the arrangement (arrangement.hpp): snapped together, lines
// split at them, coincident edges merged.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "core/assert.hpp"
#include "core/tolerances.hpp"
#include "tessellate/arrangement.hpp"
#include "tessellate/columns.hpp"
#include "tessellate/positions.hpp"

namespace curvetext::detail {
namespace {

using Edge = ArrangementEdge;
using Cut = CutPoint;

bool by_x(Vec2 a, Vec2 b) { return a.x != b.x ? a.x < b.x : a.y < b.y; }

// The loose cut points (near no vertex) onto each other, in (x, y) order:
// each becomes the nearest earlier representative within eps (the last in
// that order among equally near ones), or a representative itself. (Only
// equal points compare equal here, and they snap alike: the result does not
// depend on the order of the cuts.) The representatives come in x order
// because the loose points do.
template <class NearestRepresentative>
void snap_loose(std::vector<Cut>& cuts, ResolveScratch& scratch, NearestRepresentative&& nearest_rep) {
  using Loose = ResolveScratch::LooseCut;
  std::vector<Loose>& loose = scratch.loose;
  std::sort(loose.begin(), loose.end(), [&](const Loose& a, const Loose& b) { return by_x(a.p, b.p); });
  scratch.representatives.clear();
  for (const Loose& l : loose) {
    Vec2 r;
    if (nearest_rep(l.p, r)) {
      cuts[l.cut].p = r;
    } else {
      scratch.representatives.push_back(l.p);
    }
  }
}

// With few cuts (the usual resolve), each looks for its vertex by scanning
// them as they are, which costs less than sorting them: the same vertex as
// snap_many_cuts finds (the nearest within eps, Chebyshev; the last in (x, y)
// order among equally near ones). Most cut points are crossings near no
// vertex: a branch-free count of the vertices within eps finds those first.
// The loose ones then meet each other in a scan too.
void snap_few_cuts(std::vector<Cut>& cuts, double eps, ResolveScratch& scratch) {
  const std::vector<Vec2>& vertices = scratch.vertices;
  const auto [xs, ys] = columns<2>(scratch.coordinates, vertices.size());
  for (std::size_t k = 0; k < vertices.size(); ++k) {
    xs[k] = vertices[k].x;
    ys[k] = vertices[k].y;
  }
  for (std::size_t k = 0; k < cuts.size(); ++k) {
    Cut& c = cuts[k];
    std::size_t near = 0;
    for (std::size_t v = 0; v < vertices.size(); ++v)
      near += static_cast<std::size_t>((std::fabs(xs[v] - c.p.x) <= eps) & (std::fabs(ys[v] - c.p.y) <= eps));
    if (near == 0) {
      scratch.loose.push_back({c.p, k});
      continue;
    }
    double best = eps;
    bool found = false;
    Vec2 nearest{};
    for (const Vec2 v : vertices) {
      const double d = std::max(std::fabs(v.x - c.p.x), std::fabs(v.y - c.p.y));
      if (d < best || (d == best && (!found || !by_x(v, nearest)))) {
        best = d;
        nearest = v;
        found = true;
      }
    }
    c.p = nearest;
  }
  snap_loose(cuts, scratch, [&](Vec2 p, Vec2& out) {
    double best = eps;
    bool found = false;
    for (const Vec2 r : scratch.representatives) {
      const double d = std::max(std::fabs(r.x - p.x), std::fabs(r.y - p.y));
      if (d <= best) {
        best = d;
        out = r;
        found = true;
      }
    }
    return found;
  });
}

// The nearest point within eps (Chebyshev) of p among those inserted, the
// greatest in (x, y) order among equally near ones. Points are kept in square
// cells of side eps, so a query reads the 3 x 3 cells around p whatever the
// outline's shape (a window over one sorted axis holds every point of a thin
// outline lying along the other). Cell keys may collide; distances decide.
class SnapGrid {
 public:
  SnapGrid(ResolveScratch::SnapCells& cells, double eps) : cells_(cells), eps_(eps), side_(eps > 0 ? eps : 1.0) {
    cells_.clear();
  }
  void insert(Vec2 p) { cells_[key(cell(p.x), cell(p.y))].push_back(p); }
  bool nearest(Vec2 p, Vec2& out) const {
    const std::int64_t cx = cell(p.x), cy = cell(p.y);
    double best = eps_;
    bool found = false;
    for (std::int64_t i = cx - 1; i <= cx + 1; ++i) {
      for (std::int64_t j = cy - 1; j <= cy + 1; ++j) {
        const auto it = cells_.find(key(i, j));
        if (it == cells_.end()) continue;
        for (const Vec2 v : it->second) {
          const double d = std::max(std::fabs(v.x - p.x), std::fabs(v.y - p.y));
          if (d < best || (d == best && (!found || by_x(out, v)))) {
            best = d;
            out = v;
            found = true;
          }
        }
      }
    }
    return found;
  }

 private:
  std::int64_t cell(double v) const { return static_cast<std::int64_t>(std::floor(v / side_)); }
  static std::uint64_t key(std::int64_t i, std::int64_t j) {
    return static_cast<std::uint64_t>(i) * 0x9E3779B97F4A7C15ull ^ static_cast<std::uint64_t>(j);
  }
  ResolveScratch::SnapCells& cells_;
  double eps_;
  double side_;
};

// Many cuts: the vertices in a SnapGrid, each cut looked up there. First onto
// existing vertices (all of them, whatever the order of discovery), then the
// remaining cut points onto each other.
void snap_many_cuts(std::vector<Cut>& cuts, double eps, ResolveScratch& scratch) {
  SnapGrid vertices(scratch.vertex_cells, eps);
  for (const Vec2 v : scratch.vertices) vertices.insert(v);
  for (std::size_t k = 0; k < cuts.size(); ++k) {
    Vec2 v;
    if (vertices.nearest(cuts[k].p, v)) {
      cuts[k].p = v;
    } else {
      scratch.loose.push_back({cuts[k].p, k});
    }
  }
  SnapGrid representatives(scratch.representative_cells, eps);
  snap_loose(cuts, scratch, [&](Vec2 p, Vec2& out) {
    if (representatives.nearest(p, out)) return true;
    representatives.insert(p);
    return false;
  });
}

// Crossing points computed from different pairs of lines through one point
// differ in their last bits; left apart they make slivers and zero-length
// loops. Cut points closer than the merge distance to an end point of any
// edge become that end point, and to each other the first of them (the merge
// distance is 1e-12 of the outline's size or largest coordinate, far above the
// rounding error of a crossing of lines that are not nearly parallel).
void snap_cuts(const std::vector<Edge>& edges, std::vector<Cut>& cuts, ResolveScratch& scratch) {
  std::vector<Vec2>& vertices = scratch.vertices;
  vertices.clear();
  Box all;
  for (const Edge& e : edges) {
    vertices.push_back(e.a);
    vertices.push_back(e.b);
    all.add(e.a);
    all.add(e.b);
  }
  const double extent = std::max(all.max.x - all.min.x, all.max.y - all.min.y);
  const double largest =
      std::max({std::fabs(all.min.x), std::fabs(all.min.y), std::fabs(all.max.x), std::fabs(all.max.y)});
  const double eps = tolerance::kMergeDistanceRelative * std::max(extent, largest);
  scratch.loose.clear();
  if (cuts.size() <= 16) {
    snap_few_cuts(cuts, eps, scratch);
  } else {
    snap_many_cuts(cuts, eps, scratch);
  }
}

}  // namespace

// Splits line edges at the cut points found on them (line_pair_cuts), after
// snapping the points together (snap_cuts). The pieces of a split edge are
// fresh; other edges keep their flag. Returns true when some edge was split.
bool split_at_cuts(std::vector<Edge>& edges, std::vector<Cut>& cuts, ResolveScratch& scratch) {
  if (cuts.empty()) return false;
  std::vector<Vec2>& along = scratch.along;
  std::vector<Edge>& next = scratch.split_edges;
  snap_cuts(edges, cuts, scratch);
  // Each edge's cuts together, in the order found.
  std::stable_sort(cuts.begin(), cuts.end(), [](const Cut& a, const Cut& b) { return a.edge < b.edge; });
  next.clear();
  next.reserve(edges.size() + cuts.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < edges.size(); ++i) {
    if (k == cuts.size() || cuts[k].edge != i) {
      next.push_back(edges[i]);
      continue;
    }
    const Edge& e = edges[i];
    const Vec2 dir = e.b - e.a;
    along.clear();
    for (; k < cuts.size() && cuts[k].edge == i; ++k) along.push_back(cuts[k].p);
    std::sort(along.begin(), along.end(), [&](Vec2 p, Vec2 q) { return dot(p - e.a, dir) < dot(q - e.a, dir); });
    along.erase(std::unique(along.begin(), along.end()), along.end());
    Vec2 from = e.a;
    along.push_back(e.b);
    for (const Vec2 p : along) {
      if (p == from) continue;
      Edge piece = e;
      piece.a = from;
      piece.b = p;
      piece.box = edge_box(piece);
      piece.fresh = true;
      next.push_back(piece);
      from = p;
    }
  }
  edges.swap(next);
  return true;
}

// Coincident edges become one with the sum of their directed counts; edges
// whose count cancels (a contour running back over another) disappear. Each
// edge is directed from its smaller end and looked up in a hash table of the
// edges kept so far: the merged edges come in the order of their first
// occurrence.
void merge_coincident(const std::vector<Edge>& edges, std::vector<Edge>& merged, std::vector<std::int32_t>& slots) {
  auto same_key = [](const Edge& e, const Edge& f) {
    return e.a == f.a && e.b == f.b && e.conic == f.conic &&
           (!e.conic || (e.control == f.control && e.weight == f.weight));
  };
  merged.clear();
  merged.reserve(edges.size());
  const int bits = position_table_bits(edges.size());
  slots.assign(std::size_t{1} << bits, -1);
  const std::size_t mask = (std::size_t{1} << bits) - 1;
  for (const Edge& e0 : edges) {
    Edge e = e0;
    if (std::make_pair(e.b.x, e.b.y) < std::make_pair(e.a.x, e.a.y)) {
      std::swap(e.a, e.b);
      e.count = -e.count;
    }
    if (e.a == e.b) continue;
    std::size_t slot = (position_hash(canonical(e.a), bits) ^ position_hash(canonical(e.b), bits) * 3) & mask;
    for (;; slot = (slot + 1) & mask) {
      const std::int32_t k = slots[slot];
      if (k < 0) {
        slots[slot] = static_cast<std::int32_t>(merged.size());
        merged.push_back(e);
        break;
      }
      if (same_key(merged[static_cast<std::size_t>(k)], e)) {
        merged[static_cast<std::size_t>(k)].count += e.count;
        break;
      }
    }
  }
  merged.erase(std::remove_if(merged.begin(), merged.end(), [](const Edge& e) { return e.count == 0; }), merged.end());
}

}  // namespace curvetext::detail
