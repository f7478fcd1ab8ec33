// Packs a Mesh into the curve shader's vertex format (see vertex_format.hpp).
//
// Antialiasing of straight edges in `full` mode works on distances to
// boundary lines: a triangle knows the lines it must fade at, and fringe
// quads outside the boundary (dilated in the vertex shader) carry the
// outside part of the edge pixels. Two refinements over "each triangle knows
// its own boundary edges":
//  * Fringe quads meet at miter joins (the offset vertex of a boundary vertex
//    is shared bit-for-bit by both adjacent fringes), so at corners there is
//    neither a gap (missing coverage) nor an overlap (double blending).
//  * Triangles also receive the boundary lines through their vertices (when
//    safe, see interior()), and fringes the other line of a convex corner, so
//    corner pixels get the product of both edge coverages (exact for
//    perpendicular pixel-aligned edges) instead of whichever edge the pixel
//    centre happens to fall on, and shallow triangles fade near lines they
//    only touch at a vertex.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "curvetext/tolerances.hpp"
#include "gpu/vertex_format.hpp"

namespace curvetext::gpu {
namespace {

// Interior triangles knowing fewer boundary lines than this look for more
// up to this many triangles away (interior_lines).
constexpr std::size_t kMinKnownLines = 2;
constexpr int kLineSearchSteps = 3;

constexpr std::uint32_t kNoTriangle = 0xffffffffu;

Vec2 left_normal(Vec2 d) { return Vec2{-d.y, d.x}; }

// Signed distance to a boundary line, positive on the filled (left) side.
struct LineFn {
  Vec2 p{};
  Vec2 n{};  // unit inward normal
  double operator()(Vec2 x) const { return dot(n, x - p); }
};

// One slot of a kind-1 vertex: value at the base point and derivative per
// unit of dilation along the vertex's offset vector.
struct Slot {
  float c = kUnusedDistance;
  float dc = 0.0f;
};

struct Corner {
  // Boundary line arriving at / leaving this vertex (index into boundary_lines), -1 if none.
  int in = -1;
  int out = -1;
  int count_in = 0;
  int count_out = 0;
};

// A short list of indices without heap allocation: the line and curve lists
// of one triangle have a small fixed bound (3 edges + 2 lines per vertex).
struct IndexList {
  static constexpr std::size_t kCapacity = 16;
  std::array<int, kCapacity> items{};
  std::size_t count = 0;
  std::size_t size() const { return count; }
  bool empty() const { return count == 0; }
  int operator[](std::size_t k) const { return items[k]; }
  const int* begin() const { return items.data(); }
  const int* end() const { return items.data() + count; }
  bool contains(int v) const { return std::find(begin(), end(), v) != end(); }
  void push_back(int v) {
    if (count < kCapacity) items[count++] = v;
  }
};

// Per-vertex lists in compressed rows: the values of vertex v are
// values[start[v] .. start[v + 1]), in the order they were added.
template <class T>
struct VertexRows {
  std::vector<std::uint32_t> start;
  std::vector<T> values;
  // `add(emit)` must call emit(vertex, value) for every entry, identically on
  // both calls (one to count, one to fill).
  template <class Producer>
  void build(std::size_t vertex_count, Producer add) {
    start.assign(vertex_count + 2, 0);
    add([&](std::uint32_t v, const T&) { ++start[v + 2]; });
    for (std::size_t v = 2; v < start.size(); ++v) start[v] += start[v - 1];
    values.resize(start.back());
    add([&](std::uint32_t v, const T& value) { values[start[v + 1]++] = value; });
    start.pop_back();
  }
  const T* begin(std::uint32_t v) const { return values.data() + start[v]; }
  const T* end(std::uint32_t v) const { return values.data() + start[v + 1]; }
  std::size_t size(std::uint32_t v) const { return start[v + 1] - start[v]; }
};

// An edge of the outline along which a fringe quad is built: a boundary line,
// a leg of a convex curve's hull, or the chord of a concave curve.
struct FringeEdge {
  std::uint32_t a = 0, b = 0;
  Vec2 outward{};  // unit
  int line = -1;   // boundary line index, or -1 for curve fringes
  int curve = -1;  // curve index
};

// One per thread, reused across meshes: its arrays keep their capacity, so
// packing a glyph allocates nothing once they are warm.
class Packer {
 public:
  void run(const Mesh& mesh, std::vector<Vertex>& out) {
    mesh_ = &mesh;
    out_ = &out;
    lines_.clear();
    edges_.clear();
    out_->reserve(out_->size() + 3 * mesh_->triangles.size() + 15 * mesh_->curves.size() +
                  6 * mesh_->boundary_lines.size());
    prepare_lines();
    prepare_curve_edges();
    prepare_triangle_edges();
    triangle_lines_.resize(mesh_->triangles.size());
    for (std::size_t t = 0; t < mesh_->triangles.size(); ++t) {
      const auto& tri = mesh_->triangles[t];
      triangle_lines_[t] = interior_lines(static_cast<std::uint32_t>(t));
      interior(tri, triangle_lines_[t]);
      remember_boundary_triangle(edge_lines_[t], static_cast<std::uint32_t>(t));
    }
    group_curve_neighbours();
    // Per curve, once: its fade lines and whether the shape is solid beyond
    // its chord (each of its up to 15 vertices needs them).
    curve_fade_.resize(mesh_->curves.size());
    solid_beyond_.resize(mesh_->curves.size());
    for (std::size_t i = 0; i < mesh_->curves.size(); ++i) {
      curve_fade_[i] = curve_fade_lines(i);
      solid_beyond_[i] = solid_beyond_chord(mesh_->curves[i]);
    }
    for (std::size_t i = 0; i < mesh_->curves.size(); ++i) curve(i);
    collect_fringe_edges();
    for (const FringeEdge& e : edges_) fringe(e);
    mesh_ = nullptr;
    out_ = nullptr;
  }

 private:
  Vec2 pt(std::uint32_t i) const { return mesh_->points[i]; }

  struct CurveEdge {
    int curve = -1;
    SharedCurveEdge edge = kChord;
  };

  void prepare_lines() {
    const std::size_t n = mesh_->points.size();
    corners_.assign(n, Corner{});
    lines_.reserve(mesh_->boundary_lines.size());
    slabs_.clear();
    slabs_.reserve(mesh_->boundary_lines.size());
    for (std::size_t i = 0; i < mesh_->boundary_lines.size(); ++i) {
      const auto& bl = mesh_->boundary_lines[i];
      const Vec2 a = pt(bl[0]), b = pt(bl[1]);
      const double len = distance(a, b);
      LineFn f{a, len > 0 ? left_normal(b - a) / len : Vec2{}};
      lines_.push_back(f);
      LineSlab slab;
      slab.d = b - a;
      slab.len2 = dot(slab.d, slab.d);
      slab.len = std::sqrt(slab.len2);
      slab.eps = 1e-9 * std::max(1.0, slab.len);
      slab.slack = slab.eps * slab.len;
      slab.half_plane_eps = 1e-9 * std::max(1.0, len);
      slabs_.push_back(slab);
      Corner& ca = corners_[bl[0]];
      ca.out = static_cast<int>(i);
      ++ca.count_out;
      Corner& cb = corners_[bl[1]];
      cb.in = static_cast<int>(i);
      ++cb.count_in;
    }
    lines_from_.build(n, [&](auto emit) {
      for (std::size_t i = 0; i < mesh_->boundary_lines.size(); ++i) {
        if (lines_[i].n == Vec2{}) continue;  // zero length: not an edge of anything
        emit(mesh_->boundary_lines[i][0], static_cast<int>(i));
      }
    });
    boundary_triangle_.assign(mesh_->boundary_lines.size(), {});
    has_boundary_triangle_.assign(mesh_->boundary_lines.size(), 0);
  }

  // The boundary line a->b or, failing that, b->a (the latest added of
  // several equal ones), or -1.
  int line_between(std::uint32_t a, std::uint32_t b) const {
    for (std::uint32_t from : {a, b}) {
      const std::uint32_t to = from == a ? b : a;
      int found = -1;
      for (const int* it = lines_from_.begin(from); it != lines_from_.end(from); ++it) {
        if (mesh_->boundary_lines[static_cast<std::size_t>(*it)][1] == to) found = *it;
      }
      if (found >= 0) return found;
    }
    return -1;
  }

  // The curve hull edge between a and b (the latest added), or null.
  const CurveEdge* curve_edge_between(std::uint32_t a, std::uint32_t b) const {
    const std::uint32_t lo = std::min(a, b), hi = std::max(a, b);
    const CurveEdge* found = nullptr;
    for (const auto* it = curve_edges_.begin(lo); it != curve_edges_.end(lo); ++it) {
      if (it->first == hi) found = &it->second;
    }
    return found;
  }

  // The hull edge each curved triangle shares with the interior mesh: the
  // chord of a convex curve, the legs of a concave one.
  void prepare_curve_edges() {
    const std::size_t n = mesh_->points.size();
    barys_.resize(mesh_->curves.size());
    bary_ok_.resize(mesh_->curves.size());
    for (std::size_t i = 0; i < mesh_->curves.size(); ++i) bary_ok_[i] = compute_bary(mesh_->curves[i], barys_[i]);
    curves_at_.build(n, [&](auto emit) {
      for (std::size_t i = 0; i < mesh_->curves.size(); ++i) {
        const CurvedTriangle& ct = mesh_->curves[i];
        for (std::uint32_t v : {ct.p0, ct.control, ct.p2}) emit(v, static_cast<int>(i));
      }
    });
    curve_edges_.build(n, [&](auto emit) {
      auto add = [&](std::uint32_t a, std::uint32_t b, CurveEdge ce) {
        emit(std::min(a, b), std::pair<std::uint32_t, CurveEdge>{std::max(a, b), ce});
      };
      for (std::size_t i = 0; i < mesh_->curves.size(); ++i) {
        const CurvedTriangle& ct = mesh_->curves[i];
        const int ci = static_cast<int>(i);
        if (ct.convex) {
          add(ct.p0, ct.p2, {ci, kChord});
        } else {
          add(ct.p0, ct.control, {ci, kLegFromP0});
          add(ct.control, ct.p2, {ci, kLegToP2});
        }
      }
    });
    has_neighbour_.assign(mesh_->curves.size(), 0);
    neighbour_lines_.clear();
  }

  // Per curve, in order, the lines of the interior triangles across its edges.
  void group_curve_neighbours() {
    neighbour_rows_.build(mesh_->curves.size(), [&](auto emit) {
      for (const auto& [ci, li] : neighbour_lines_) emit(static_cast<std::uint32_t>(ci), li);
    });
  }

  // The line that makes a convex corner with `line` at vertex v, if any.
  int convex_partner(int line, std::uint32_t v) const {
    const Corner& c = corners_[v];
    if (c.count_in != 1 || c.count_out != 1) return -1;  // touching loops: ambiguous
    const auto& in = mesh_->boundary_lines[static_cast<std::size_t>(c.in)];
    const auto& out = mesh_->boundary_lines[static_cast<std::size_t>(c.out)];
    const Vec2 din = pt(in[1]) - pt(in[0]);
    const Vec2 dout = pt(out[1]) - pt(out[0]);
    if (cross(din, dout) <= 0) return -1;  // reflex or straight: the product rule would be wrong
    if (c.in == line) return c.out;
    if (c.out == line) return c.in;
    return -1;
  }

  // True when the whole triangle lies inside the half-plane of `line` and,
  // along the line, within the segment or past an end only where that is
  // harmless, so the line's distance fades pixels that really are near that
  // boundary: within a 45-degree cone past the end (see below), or where the
  // next edge stays in the half-plane (a convex or straight join: the end
  // cap of a slanted stroke). Without this the triangles of a hairline or a
  // thin frame, which reach past the far side's ends, knew only one side and
  // took its coverage alone (about twice the ink).
  bool safe_for(int line, const std::array<Vec2, 3>& p) const {
    const auto& bl = mesh_->boundary_lines[static_cast<std::size_t>(line)];
    const LineFn& f = lines_[static_cast<std::size_t>(line)];
    const LineSlab& l = slabs_[static_cast<std::size_t>(line)];
    for (const Vec2& x : p) {
      const double inside = f(x);
      if (inside < -l.eps) return false;
      const double s = dot(x - f.p, l.d);
      // Past an end by no more than x lies inside the line (a 45-degree
      // cone from the end; a half-plane, so the triangle's vertices decide)
      // and a tenth of the line's length: only pixels near that end can be
      // faded by the line's extension, where the outline turns anyway.
      if (s < -l.slack) {
        if (-s / l.len <= std::min(inside, tolerance::kFadePastEndFraction * l.len)) continue;
        if (!past_end_ok(line, corners_[bl[0]].in, bl[0], corners_[bl[0]].count_in, x)) return false;
      } else if (s > l.len2 + l.slack) {
        if ((s - l.len2) / l.len <= std::min(inside, tolerance::kFadePastEndFraction * l.len)) continue;
        if (!past_end_ok(line, corners_[bl[1]].out, bl[1], corners_[bl[1]].count_out, x)) return false;
      }
    }
    return true;
  }

  // For x past the end v of `line`: true when the outline goes on at v with
  // one edge (`next`, the only boundary line joining `line` there, or else
  // the only curve with an end at v) that stays inside the half-plane of
  // `line` (a convex or straight join), and x projects within that edge's
  // chord, so x is no farther past the end than the edge reaches.
  bool past_end_ok(int line, int next, std::uint32_t v, int count, Vec2 x) const {
    const double eps = slabs_[static_cast<std::size_t>(line)].half_plane_eps;
    const LineFn& f = lines_[static_cast<std::size_t>(line)];
    const Vec2 near = pt(v);
    Vec2 far{};
    if (next < 0 && count == 0) {
      // The outline goes on with a curve (a rounded corner): the one curve
      // with an end at v, whose hull must lie in the half-plane.
      int found = -1;
      for (const int* it = curves_at_.begin(v); it != curves_at_.end(v); ++it) {
        const CurvedTriangle& ct = mesh_->curves[static_cast<std::size_t>(*it)];
        if (ct.p0 != v && ct.p2 != v) continue;
        if (found >= 0) return false;
        found = *it;
      }
      if (found < 0) return false;
      const CurvedTriangle& ct = mesh_->curves[static_cast<std::size_t>(found)];
      if (f(pt(ct.control)) < -eps) return false;
      far = pt(ct.p0 == v ? ct.p2 : ct.p0);
    } else {
      if (next < 0 || count != 1 || next == line) return false;
      const auto& nb = mesh_->boundary_lines[static_cast<std::size_t>(next)];
      far = pt(nb[0] == v ? nb[1] : nb[0]);
    }
    if (f(far) < -eps) return false;
    const Vec2 e = far - near;
    const double e2 = dot(e, e);
    const double s = dot(x - near, e);
    const double slack = 1e-9 * std::max(1.0, e2);
    return s >= -slack && s <= e2 + slack;
  }

  static Vertex make(Vec2 p, Vec2 offset, int kind) {
    Vertex v{};
    v.pos[0] = static_cast<float>(p.x);
    v.pos[1] = static_cast<float>(p.y);
    v.pos[2] = static_cast<float>(offset.x);
    v.pos[3] = static_cast<float>(offset.y);
    v.info[0] = static_cast<float>(kind);
    v.fade[0] = kUnusedDistance;
    v.fade[1] = kUnusedDistance;
    return v;
  }

  // Fills the distance slots of a kind-1 vertex. Slot 3 has no derivative
  // slot, so only vertices that never move (interior triangles) may use it.
  void set_slots(Vertex& v, Vec2 p, Vec2 offset, const std::array<int, 4>& slot_lines) const {
    std::array<Slot, 4> s{};
    for (int k = 0; k < 4; ++k) {
      const int li = slot_lines[static_cast<std::size_t>(k)];
      if (li < 0) continue;
      const LineFn& f = lines_[static_cast<std::size_t>(li)];
      s[static_cast<std::size_t>(k)] = Slot{static_cast<float>(f(p)), static_cast<float>(dot(f.n, offset))};
    }
    v.coef[0] = s[0].c;
    v.coef[1] = s[1].c;
    v.coef[2] = s[2].c;
    v.coef[3] = s[3].c;
    v.info[1] = s[2].dc;  // kind 1 has no weight: this slot carries dc2
    v.info[2] = s[0].dc;
    v.info[3] = s[1].dc;
  }

  // Fills the two a_fade slots with `lines` (at most two; others ignored).
  void set_fade(Vertex& v, Vec2 p, Vec2 offset, const IndexList& lines) const {
    for (std::size_t k = 0; k < 2 && k < lines.size(); ++k) {
      const LineFn& f = lines_[static_cast<std::size_t>(lines[k])];
      v.fade[k] = static_cast<float>(f(p));
      v.fade[k + 2] = static_cast<float>(dot(f.n, offset));
    }
  }

  void remember_boundary_triangle(const std::array<int, 3>& edge_lines, std::uint32_t t) {
    for (const int line : edge_lines) {
      if (line < 0) continue;
      boundary_triangle_[static_cast<std::size_t>(line)] = t;
      has_boundary_triangle_[static_cast<std::size_t>(line)] = 1;
    }
  }

  // The boundary lines an interior triangle fades by, in priority order:
  // its own boundary edges, then lines through its vertices (when safe).
  // `edge_lines`: line_between() of the edges (0, 1), (1, 2), (2, 0).
  // Per triangle edge (k: tri[k] -> tri[k + 1]), computed once per mesh:
  // the boundary line along it (line_between, or -1) and, for edges that are
  // not boundary lines, the triangle across it (kNoTriangle if none; in a
  // triangulation two triangles share an inner edge, and were there more,
  // the next one by index is taken). Sorting the inner edges by their end
  // points pairs them up.
  void prepare_triangle_edges() {
    const auto& tris = mesh_->triangles;
    edge_lines_.resize(tris.size());
    across_.assign(tris.size(), {kNoTriangle, kNoTriangle, kNoTriangle});
    seen_.assign(tris.size(), 0);
    stamp_ = 0;
    inner_edges_.clear();
    for (std::size_t t = 0; t < tris.size(); ++t) {
      const auto& tri = tris[t];
      edge_lines_[t] = {line_between(tri[0], tri[1]), line_between(tri[1], tri[2]), line_between(tri[2], tri[0])};
      for (std::uint32_t k = 0; k < 3; ++k) {
        if (edge_lines_[t][k] >= 0) continue;
        const std::uint32_t a = tri[k], b = tri[(k + 1) % 3];
        const std::uint64_t key = (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
        inner_edges_.emplace_back(key, static_cast<std::uint32_t>(3 * t + k));
      }
    }
    std::sort(inner_edges_.begin(), inner_edges_.end());
    for (std::size_t i = 0; i < inner_edges_.size();) {
      std::size_t j = i + 1;
      while (j < inner_edges_.size() && inner_edges_[j].first == inner_edges_[i].first) ++j;
      for (std::size_t q = i; q < j; ++q) {
        const std::uint32_t half = inner_edges_[q].second;
        const std::uint32_t other = inner_edges_[q + 1 < j ? q + 1 : i].second;
        if (other != half) across_[half / 3][half % 3] = other / 3;
      }
      i = j;
    }
  }

  IndexList interior_lines(std::uint32_t t) const {
    const auto& tri = mesh_->triangles[t];
    const std::array<Vec2, 3> p{pt(tri[0]), pt(tri[1]), pt(tri[2])};
    IndexList lines;
    auto add = [&](int line) {
      if (line >= 0 && !lines.contains(line)) lines.push_back(line);
    };
    for (const int line : edge_lines_[t]) add(line);
    // Boundary lines through a vertex of this triangle: a thin or shallow
    // triangle that touches a line only at a vertex still holds pixel centres
    // within a pixel of it (and at convex corners the product of both lines
    // is the corner coverage). Only lines whose half-plane and segment slab
    // contain the whole triangle are used, so a line never fades pixels away
    // from its own segment.
    for (int e = 0; e < 3; ++e) {
      const Corner& c = corners_[tri[static_cast<std::size_t>(e)]];
      if (c.count_in != 1 || c.count_out != 1) continue;
      if (safe_for(c.in, p)) add(c.in);
      if (safe_for(c.out, p)) add(c.out);
    }
    // A triangle that knows fewer than two lines takes the nearest safe
    // boundary edges of the triangles up to kLineSearchSteps steps across its
    // inner edges: at small sizes a pixel centred in it reaches them (a
    // serif's top a third of a pixel above a triangle between its brackets).
    // quality_bench full, 8/10/12/16/24 px edge: 0.0286/0.0250/0.0114/0.0104/
    // 0.0057 without, 0.0288/0.0211/0.0106/0.0093/0.0048 with.
    if (lines.size() < kMinKnownLines) {
      // Breadth-first over triangle indices; seen_[u] == stamp marks the
      // triangles already in the ring.
      std::array<std::uint32_t, 16> ring{};
      std::size_t ring_count = 0, frontier_begin = 0;
      const std::uint32_t stamp = ++stamp_;
      ring[ring_count++] = t;
      seen_[t] = stamp;
      for (int step = 0; step < kLineSearchSteps; ++step) {
        const std::size_t frontier_end = ring_count;
        for (std::size_t r = frontier_begin; r < frontier_end; ++r) {
          const std::uint32_t cur = ring[r];
          for (std::uint32_t e = 0; e < 3; ++e) {
            if (edge_lines_[cur][e] >= 0) continue;
            const std::uint32_t other = across_[cur][e];
            if (other != kNoTriangle && seen_[other] != stamp && ring_count < ring.size()) {
              seen_[other] = stamp;
              ring[ring_count++] = other;
            }
          }
        }
        frontier_begin = frontier_end;
      }
      std::array<std::pair<double, int>, 24> found{};
      std::size_t found_count = 0;
      for (std::size_t r = 1; r < ring_count; ++r) {
        for (int k = 0; k < 3; ++k) {
          const int line = edge_lines_[ring[r]][static_cast<std::size_t>(k)];
          if (line < 0 || lines.contains(line) || found_count == found.size()) continue;
          bool dup = false;
          for (std::size_t q = 0; q < found_count; ++q) dup = dup || found[q].second == line;
          if (dup || !safe_for(line, p)) continue;
          double dmin = 1e300;
          for (const Vec2& x : p) dmin = std::min(dmin, std::fabs(lines_[static_cast<std::size_t>(line)](x)));
          found[found_count++] = {dmin, line};
        }
      }
      std::sort(found.begin(), found.begin() + static_cast<std::ptrdiff_t>(found_count));
      for (std::size_t q = 0; q < found_count && lines.size() < kMinKnownLines; ++q) add(found[q].second);
    }
    return lines;
  }

  // The hull edge of curve `ci` whose outer side holds all of `p` (the
  // chord of a convex curve, a leg of a concave one), if any: the side of
  // the curve an interior triangle touching it at a vertex is on.
  bool touching_edge(int ci, const std::array<Vec2, 3>& p, CurveEdge& out) const {
    const CurvedTriangle& ct = mesh_->curves[static_cast<std::size_t>(ci)];
    const Bary* hull = bary(ci);
    if (!hull) return false;
    const Bary& g = *hull;
    // Barycentrics are relative to the hull, so a fixed tolerance suits.
    const double eps = 1e-9;
    auto all_outside = [&](auto coord) {
      for (const Vec2& x : p)
        if (coord(x) > eps) return false;
      return true;
    };
    if (ct.convex) {
      if (!all_outside([&](Vec2 x) { return g.tau1(x); })) return false;
      out = CurveEdge{ci, kChord};
      return true;
    }
    if (all_outside([&](Vec2 x) { return g.tau2(x); })) {
      out = CurveEdge{ci, kLegFromP0};
      return true;
    }
    if (all_outside([&](Vec2 x) { return 1.0 - g.tau1(x) - g.tau2(x); })) {
      out = CurveEdge{ci, kLegToP2};
      return true;
    }
    return false;
  }

  // Squared distance from x to the hull edge `ce` names (a segment): only
  // compared, so no square root (std::hypot was ~1.5% of mesh preparation).
  double hull_edge_distance2(const CurveEdge& ce, Vec2 x) const {
    const CurvedTriangle& ct = mesh_->curves[static_cast<std::size_t>(ce.curve)];
    const Vec2 a = pt(ce.edge == kLegToP2 ? ct.control : ct.p0);
    const Vec2 b = pt(ce.edge == kLegFromP0 ? ct.control : ct.p2);
    const Vec2 d = b - a;
    const double len2 = dot(d, d);
    const double s = len2 > 0 ? std::clamp(dot(x - a, d) / len2, 0.0, 1.0) : 0.0;
    const Vec2 off = x - (a + d * s);
    return dot(off, off);
  }

  void interior(const std::array<std::uint32_t, 3>& tri, const IndexList& lines) {
    const std::array<Vec2, 3> p{pt(tri[0]), pt(tri[1]), pt(tri[2])};
    // Curved triangles across an edge of this one: the curve can come closer
    // than a pixel to this triangle's pixel centres (near the curve's ends,
    // and anywhere along flat curves), so full AA fades by it too.
    std::array<CurveEdge, 3> near_curves{};
    int curve_count = 0;
    auto has = [&](int ci) {
      for (int k = 0; k < curve_count; ++k)
        if (near_curves[static_cast<std::size_t>(k)].curve == ci) return true;
      return false;
    };
    for (int e = 0; e < 3; ++e) {
      const std::uint32_t a = tri[static_cast<std::size_t>(e)], b = tri[static_cast<std::size_t>((e + 1) % 3)];
      const CurveEdge* ce = curve_edge_between(a, b);
      if (!ce || !bary_ok_[static_cast<std::size_t>(ce->curve)]) continue;
      has_neighbour_[static_cast<std::size_t>(ce->curve)] = 1;
      for (int li : lines) neighbour_lines_.emplace_back(ce->curve, li);
      if (curve_count < 3 && !has(ce->curve)) near_curves[static_cast<std::size_t>(curve_count++)] = *ce;
    }
    // Curves that touch this triangle only at a vertex, as lines through a
    // vertex (interior_lines): at small sizes triangles are smaller than a
    // pixel, and the pixel centred here may overlap a curve of a neighbouring
    // triangle (the other side of a thin curved stroke, a bowl's end). Only
    // curves whose chord / leg has the whole triangle on its outer side, so
    // the shader's "this side of the edge is filled" holds.
    // Of several, the nearest to the triangle's centroid (distance to the
    // hull's edge on the triangle's side) come first: they are the likeliest
    // to cross the pixels centred in it.
    std::vector<std::pair<double, CurveEdge>>& touching = touching_scratch_;
    touching.clear();
    const Vec2 centroid = (p[0] + p[1] + p[2]) / 3.0;
    for (int e = 0; e < 3 && curve_count < 3; ++e) {  // three across edges: no slot left
      const std::uint32_t vertex = tri[static_cast<std::size_t>(e)];
      for (const int* it = curves_at_.begin(vertex); it != curves_at_.end(vertex); ++it) {
        const int ci = *it;
        CurveEdge ce;
        if (has(ci) || !touching_edge(ci, p, ce)) continue;
        bool seen = false;
        for (const auto& t : touching) seen = seen || t.second.curve == ci;
        if (!seen) touching.emplace_back(hull_edge_distance2(ce, centroid), ce);
      }
    }
    std::sort(touching.begin(), touching.end(),
              [](const auto& x, const auto& y) { return x.first < y.first; });
    for (const auto& t : touching) {
      if (curve_count >= 3) break;
      near_curves[static_cast<std::size_t>(curve_count++)] = t.second;
    }
    // A third curve takes kind 5's a_fade, so only where no line needs it.
    if (curve_count == 3 && lines.size() > 2) curve_count = 2;
    // Line slots: four in a_coef (two for kinds 4 and 5, whose other two
    // carry the second curve), then two in a_fade (none for kind 5, whose
    // a_fade carries the third curve). Shared boundary edges come first.
    const std::size_t coef_slots = curve_count >= 2 ? 2 : 4;
    std::array<int, 4> slots{-1, -1, -1, -1};
    IndexList fade;
    // A reflex corner at a vertex: the shape there is the union of the two
    // sides' half-planes (the triangle lies in the cone of the corner's
    // interior angle), and pixels centred in the triangle near the corner
    // need both, also where the triangle knows one side as a line (the
    // union replaces it). The pair takes the a_fade slots with
    // kUnionFadeFlag; the shader removes the part of the pixel in the wedge
    // outside both sides. quality_bench full, pixels off by > 0.15 at
    // 24-384 px: 344 -> 312 with one pair (when the sides were unknown),
    // 301 -> 284 taking it also where a side was known, once the shader
    // combined boundaries exactly (before that it made 10 px edges worse).
    std::array<int, 2> pair{-1, -1};
    // A second reflex corner (a sliver spanning a stem between the two inner
    // corners of a crossbar) takes a_coef's last two slots, when the known
    // lines fit in the first two, flagged kUnionCoefFlag (328 -> 307 pixels
    // off by > 0.15 at 24-384 px).
    std::array<int, 2> pair2{-1, -1};
    if (curve_count < 3) {
      for (std::uint32_t vertex : tri) {
        std::array<int, 2> c{};
        if (!reflex_pair(vertex, c) ||
            !short_of_far_end(c[0], vertex, p) || !short_of_far_end(c[1], vertex, p))
          continue;
        std::size_t others = 0;  // the lines left for the line slots
        for (int li : lines)
          if (li != c[0] && li != c[1] && li != pair[0] && li != pair[1]) ++others;
        if (pair[0] < 0) {
          if (others <= coef_slots) pair = c;
        } else if (pair2[0] < 0 && coef_slots == 4 && others <= 2) {
          pair2 = c;
        }
      }
    }
    std::size_t used = 0;
    const std::size_t line_slots = pair2[0] >= 0 ? 2 : coef_slots;
    for (std::size_t k = 0; k < lines.size(); ++k) {
      if (lines[k] == pair[0] || lines[k] == pair[1] || lines[k] == pair2[0] || lines[k] == pair2[1]) continue;
      if (used < line_slots) slots[used++] = lines[k];
      else if (curve_count < 3) fade.push_back(lines[k]);
    }
    if (pair2[0] >= 0) {
      slots[2] = pair2[0];
      slots[3] = pair2[1];
    }
    if (pair[0] >= 0) {
      fade = IndexList{};
      fade.push_back(pair[0]);
      fade.push_back(pair[1]);
    }
    const int kind = curve_count == 3 ? kNextToThreeCurves
                     : curve_count == 2 ? kNextToTwoCurves
                     : curve_count == 1 ? kNextToCurve
                     : !lines.empty() || pair[0] >= 0 ? kEdge
                                                       : kSolid;
    for (int k = 0; k < 3; ++k) {
      const Vec2 x = p[static_cast<std::size_t>(k)];
      Vertex v = make(x, Vec2{}, kind);
      if (kind != kSolid) set_slots(v, x, Vec2{}, slots);
      set_fade(v, x, Vec2{}, fade);
      if (curve_count > 0) set_near_curves(v, x, near_curves, curve_count);
      if (pair[0] >= 0) v.info[0] += kUnionFadeFlag;
      if (pair2[0] >= 0) v.info[0] += kUnionCoefFlag;
      out_->push_back(v);
    }
  }

  // True when no point of `p` projects past the end of `line` away from
  // `corner` (its other end): beyond that end the outline may turn back, and
  // the union of a reflex corner's sides would cut the shape there (a thin
  // CJK stroke past the far end of a corner's side drew a line of pixels 0.34
  // too light). Past the corner itself the other side covers.
  bool short_of_far_end(int line, std::uint32_t corner, const std::array<Vec2, 3>& p) const {
    const auto& bl = mesh_->boundary_lines[static_cast<std::size_t>(line)];
    const Vec2 c = pt(corner), far = pt(bl[0] == corner ? bl[1] : bl[0]);
    const Vec2 d = far - c;
    const LineSlab& l = slabs_[static_cast<std::size_t>(line)];
    for (const Vec2& x : p)
      if (dot(x - c, d) > l.len2 + l.slack) return false;
    return true;
  }

  // The two lines of a reflex corner at v (arriving, leaving), or false.
  bool reflex_pair(std::uint32_t v, std::array<int, 2>& pair) const {
    const Corner& c = corners_[v];
    if (c.count_in != 1 || c.count_out != 1 || c.in == c.out) return false;
    if (lines_[static_cast<std::size_t>(c.in)].n == Vec2{} || lines_[static_cast<std::size_t>(c.out)].n == Vec2{})
      return false;
    const auto& in = mesh_->boundary_lines[static_cast<std::size_t>(c.in)];
    const auto& out = mesh_->boundary_lines[static_cast<std::size_t>(c.out)];
    if (!(cross(pt(in[1]) - pt(in[0]), pt(out[1]) - pt(out[0])) < 0)) return false;
    pair = {c.in, c.out};
    return true;
  }

  // Lines a curved triangle and its fringes fade by: those of the interior
  // triangles across its chord or legs whose half-plane and slab hold the
  // whole control triangle (so they bound the shape near the curve, e.g. the
  // other side of a serif thinner than a pixel).
  IndexList curve_fade_lines(std::size_t ci) const {
    IndexList out;
    const CurvedTriangle& ct = mesh_->curves[ci];
    const std::array<Vec2, 3> hull{pt(ct.p0), pt(ct.control), pt(ct.p2)};
    auto add = [&](int li) {
      if (li >= 0 && out.size() < 2 && !out.contains(li)) out.push_back(li);
    };
    // First the lines making a convex corner with the curve at its ends: the
    // corner pixel is covered by the intersection of both sides.
    for (const auto& [end, other] : {std::pair{ct.p0, ct.p2}, std::pair{ct.p2, ct.p0}}) {
      const Corner& c = corners_[end];
      if (c.count_in != 1 || c.count_out != 1) continue;
      for (int li : {c.in, c.out}) {
        if (!in_half_plane(li, hull)) continue;
        // The line's far end must be on the curve's filled side of its
        // tangent (the leg) at `end`: otherwise the corner is reflex.
        const auto& bl = mesh_->boundary_lines[static_cast<std::size_t>(li)];
        const Vec2 far = pt(bl[0] == end ? bl[1] : bl[0]);
        const Vec2 e = pt(end), ctrl = pt(ct.control);
        const double side_far = cross(ctrl - e, far - e);
        const double side_other = cross(ctrl - e, pt(other) - e);
        const bool filled_towards_other = ct.convex;
        if ((side_far * side_other > 0) == filled_towards_other) add(li);
      }
    }
    const auto c = static_cast<std::uint32_t>(ci);
    for (const int* li = neighbour_rows_.begin(c); li != neighbour_rows_.end(c); ++li)
      if (safe_for(*li, hull)) add(*li);
    return out;
  }

  // True when all of `p` lies in the filled half-plane of `line`.
  bool in_half_plane(int line, const std::array<Vec2, 3>& p) const {
    const LineFn& f = lines_[static_cast<std::size_t>(line)];
    if (f.n == Vec2{}) return false;
    const double eps = slabs_[static_cast<std::size_t>(line)].half_plane_eps;
    for (const Vec2& x : p)
      if (f(x) < -eps) return false;
    return true;
  }

  // Writes the kind 3-5 curve data (see vertex_format.hpp) over the slots
  // that interior triangles leave unused. After set_slots.
  void set_near_curves(Vertex& v, Vec2 x, const std::array<CurveEdge, 3>& curves, int count) const {
    auto tau = [&](const CurveEdge& ce, float& t1, float& t2, float& w) {
      const CurvedTriangle& ct = mesh_->curves[static_cast<std::size_t>(ce.curve)];
      const Bary& g = barys_[static_cast<std::size_t>(ce.curve)];
      t1 = static_cast<float>(g.tau1(x));
      t2 = static_cast<float>(g.tau2(x));
      w = static_cast<float>(ct.weight);
    };
    tau(curves[0], v.pos[2], v.pos[3], v.info[1]);
    v.info[2] = 0.0f;
    int codes = curves[0].edge;
    if (count >= 2) {
      tau(curves[1], v.coef[2], v.coef[3], v.info[2]);
      codes += 3 * curves[1].edge;
    }
    if (count == 3) {
      tau(curves[2], v.fade[0], v.fade[1], v.fade[2]);
      v.fade[3] = 0.0f;
      codes += 9 * curves[2].edge;
    }
    v.info[3] = static_cast<float>(codes);
  }

  // Affine barycentric coordinates (tau1, tau2) of a control triangle and
  // their gradients; false for a degenerate hull.
  struct Bary {
    Vec2 a, b, c;
    double area2 = 0.0;
    double tau1(Vec2 x) const { return cross(x - a, c - a) / area2; }
    double tau2(Vec2 x) const { return cross(b - a, x - a) / area2; }
    // Filled in by compute_bary (divisions done once per curve): the
    // gradients of tau1 and tau2, and (tau1, tau2) at a, b and c.
    Vec2 grad1{}, grad2{};
    std::array<std::array<double, 2>, 3> at_vertex{};
  };

  // Computed once per curve (compute_bary) and looked up.
  // Null for a degenerate hull.
  const Bary* bary(int ci) const {
    return bary_ok_[static_cast<std::size_t>(ci)] ? &barys_[static_cast<std::size_t>(ci)] : nullptr;
  }

  bool compute_bary(const CurvedTriangle& ct, Bary& out) const {
    out = Bary{pt(ct.p0), pt(ct.control), pt(ct.p2)};
    out.area2 = cross(out.b - out.a, out.c - out.a);
    const double scale = dot(out.b - out.a, out.b - out.a) + dot(out.c - out.a, out.c - out.a);
    if (!(std::isfinite(out.area2) && std::fabs(out.area2) > 1e-12 * scale)) return false;
    out.grad1 = Vec2{(out.c - out.a).y, -(out.c - out.a).x} / out.area2;
    out.grad2 = Vec2{-(out.b - out.a).y, (out.b - out.a).x} / out.area2;
    const Vec2 corners[3] = {out.a, out.b, out.c};
    for (int k = 0; k < 3; ++k) out.at_vertex[static_cast<std::size_t>(k)] = {out.tau1(corners[k]), out.tau2(corners[k])};
    return true;
  }

  // True when an interior triangle lies across the chord of convex curve
  // `ct`, so the shape is solid beyond that chord (not, e.g., the other half
  // of a lens of two curves). After all interior().
  bool solid_beyond_chord(const CurvedTriangle& ct) const {
    if (!ct.convex) return false;
    const CurveEdge* ce = curve_edge_between(ct.p0, ct.p2);
    return ce && has_neighbour_[static_cast<std::size_t>(ce->curve)];
  }

  // `ci`: the index of `ct`; p is its hull vertex number `k` (0: p0, 1:
  // control, 2: p2).
  Vertex curve_vertex(std::size_t ci, const CurvedTriangle& ct, const Bary& g, int k, Vec2 offset) const {
    const Vec2 p = k == 0 ? g.a : k == 1 ? g.b : g.c;
    Vertex v = make(p, offset, kCurve);
    v.coef[0] = static_cast<float>(g.at_vertex[static_cast<std::size_t>(k)][0]);
    v.coef[1] = static_cast<float>(g.at_vertex[static_cast<std::size_t>(k)][1]);
    v.coef[2] = ct.convex ? 1.0f : -1.0f;
    v.coef[3] = solid_beyond_[ci] ? 1.0f : 0.0f;
    v.info[1] = static_cast<float>(ct.weight);
    v.info[2] = static_cast<float>(dot(g.grad1, offset));
    v.info[3] = static_cast<float>(dot(g.grad2, offset));
    return v;
  }

  void curve(std::size_t i) {
    const CurvedTriangle& ct = mesh_->curves[i];
    const Bary* hull = bary(static_cast<int>(i));
    if (!hull) return;  // a flat hull has no area to draw
    const Bary& g = *hull;
    // Exact hull barycentrics (not recomputed) so the corners are crisp.
    Vertex v0 = curve_vertex(i, ct, g, 0, Vec2{});
    Vertex v1 = curve_vertex(i, ct, g, 1, Vec2{});
    Vertex v2 = curve_vertex(i, ct, g, 2, Vec2{});
    v0.coef[0] = 0.0f; v0.coef[1] = 0.0f;
    v1.coef[0] = 1.0f; v1.coef[1] = 0.0f;
    v2.coef[0] = 0.0f; v2.coef[1] = 1.0f;
    const IndexList& fade = curve_fade_[i];
    set_fade(v0, g.a, Vec2{}, fade);
    set_fade(v1, g.b, Vec2{}, fade);
    set_fade(v2, g.c, Vec2{}, fade);
    out_->push_back(v0);
    out_->push_back(v1);
    out_->push_back(v2);
  }

  static Vec2 outward_normal(Vec2 a, Vec2 b, Vec2 away_from) {
    const Vec2 d = b - a;
    const double len = length(d);
    if (!(len > 0)) return Vec2{};
    Vec2 n = left_normal(d) / len;
    if (dot(n, away_from - a) > 0) n = n * -1.0;
    return n;
  }

  void collect_fringe_edges() {
    for (std::size_t i = 0; i < mesh_->boundary_lines.size(); ++i) {
      const auto& bl = mesh_->boundary_lines[i];
      const LineFn& f = lines_[i];
      if (f.n == Vec2{}) continue;
      edges_.push_back(FringeEdge{bl[0], bl[1], f.n * -1.0, static_cast<int>(i), -1});
    }
    for (std::size_t i = 0; i < mesh_->curves.size(); ++i) {
      const CurvedTriangle& ct = mesh_->curves[i];
      const int ci = static_cast<int>(i);
      const Bary* hull = bary(ci);
      if (!hull) continue;
      const Bary& g = *hull;
      if (ct.convex) {
        // Outside the shape lies beyond the hull's legs.
        edges_.push_back(FringeEdge{ct.p0, ct.control, outward_normal(g.a, g.b, g.c), -1, ci});
        edges_.push_back(FringeEdge{ct.control, ct.p2, outward_normal(g.b, g.c, g.a), -1, ci});
      } else {
        // Outside is the chord side; beyond the chord for curves flatter than the fringe.
        edges_.push_back(FringeEdge{ct.p0, ct.p2, outward_normal(g.a, g.c, g.b), -1, ci});
      }
    }
    incident_.assign(mesh_->points.size(), Incident{});
    for (std::size_t i = 0; i < edges_.size(); ++i) {
      incident_[edges_[i].a].add(static_cast<int>(i));
      incident_[edges_[i].b].add(static_cast<int>(i));
    }
  }

  // Offset vector of fringe edge `e` at its vertex v: the miter of the two
  // fringe edges meeting there (distance 1 from both edges' lines), so both
  // fringes use the same offset vertex. Falls back to the edge's own normal
  // where the join is ambiguous or too sharp.
  Vec2 offset_at(const FringeEdge& e, std::uint32_t v) const {
    const Incident& inc = incident_[v];
    if (inc.count != 2) return e.outward;
    const FringeEdge& e0 = edges_[static_cast<std::size_t>(inc.first[0])];
    const FringeEdge& e1 = edges_[static_cast<std::size_t>(inc.first[1])];
    const Vec2 o0 = e0.outward, o1 = e1.outward;
    const Vec2 sum{o0.x + o1.x, o0.y + o1.y};  // symmetric: both edges compute the same bits
    const double denom = 1.0 + (o0.x * o1.x + o0.y * o1.y);
    // |miter| = sqrt(2/denom); beyond 4 (normals ~150 degrees apart) the
    // spike would be long and thin: keep the own normal instead.
    if (!(denom > 0.125)) return e.outward;
    return sum / denom;
  }

  void fringe(const FringeEdge& e) {
    const Vec2 a = pt(e.a), b = pt(e.b);
    const Vec2 oa = offset_at(e, e.a), ob = offset_at(e, e.b);
    // Quad a, b, b', a' as triangles (a, b, b') and (a, b', a'); the offset
    // vertices share base positions with a and b and move only when t > 0.
    // Four distinct vertices, each computed once and emitted in that order.
    const std::array<std::pair<Vec2, Vec2>, 4> corners{std::pair{a, Vec2{}}, std::pair{b, Vec2{}},
                                                       std::pair{b, ob}, std::pair{a, oa}};
    std::array<Vertex, 4> quad;
    auto emit = [&] {
      for (const int k : {0, 1, 2, 0, 2, 3}) out_->push_back(quad[static_cast<std::size_t>(k)]);
    };
    if (e.line >= 0) {
      IndexList lines;
      lines.push_back(e.line);
      auto add = [&](int line) {
        if (line >= 0 && !lines.contains(line)) lines.push_back(line);
      };
      add(convex_partner(e.line, e.a));
      add(convex_partner(e.line, e.b));
      // A feature thinner than a pixel (a serif, a hairline): the pixels
      // whose centres fall in this fringe also overlap the opposite side of
      // the feature, so the fringe fades by the lines the interior triangle
      // behind it uses as well (all of them contain that triangle).
      const auto line = static_cast<std::size_t>(e.line);
      if (has_boundary_triangle_[line]) {
        for (int li : triangle_lines_[boundary_triangle_[line]]) add(li);
      }
      // Three moving slots in a_coef (c3 has no derivative), two in a_fade.
      std::array<int, 4> slots{-1, -1, -1, -1};
      IndexList fade;
      for (std::size_t k = 0; k < lines.size(); ++k) {
        if (k < 3) slots[k] = lines[k];
        else fade.push_back(lines[k]);
      }
      for (std::size_t k = 0; k < 4; ++k) {
        const auto& [p, o] = corners[k];
        Vertex& v = quad[k];
        v = make(p, o, kEdge);
        set_slots(v, p, o, slots);
        set_fade(v, p, o, fade);
      }
      emit();
    } else {
      const CurvedTriangle& ct = mesh_->curves[static_cast<std::size_t>(e.curve)];
      const Bary* hull = bary(e.curve);
      if (!hull) return;
      const Bary& g = *hull;
      const IndexList& fade = curve_fade_[static_cast<std::size_t>(e.curve)];
      // The edge's ends are vertices of the curve's hull.
      auto hull_vertex = [&](std::uint32_t v) { return v == ct.p0 ? 0 : v == ct.control ? 1 : 2; };
      const int ka = hull_vertex(e.a), kb = hull_vertex(e.b);
      for (std::size_t k = 0; k < 4; ++k) {
        const auto& [p, o] = corners[k];
        quad[k] = curve_vertex(static_cast<std::size_t>(e.curve), ct, g, k == 0 || k == 3 ? ka : kb, o);
        set_fade(quad[k], p, o, fade);
      }
      emit();
    }
  }

  const Mesh* mesh_ = nullptr;
  std::vector<Vertex>* out_ = nullptr;
  // Fringe edges at a vertex: how many, and the first two.
  struct Incident {
    int count = 0;
    std::array<int, 2> first{-1, -1};
    void add(int edge) {
      if (count < 2) first[static_cast<std::size_t>(count)] = edge;
      ++count;
    }
  };

  std::vector<LineFn> lines_;
  // Per boundary line, the constants of safe_for and in_half_plane.
  struct LineSlab {
    Vec2 d{};             // b - a
    double len2 = 0.0;    // |d|^2
    double len = 0.0;     // sqrt(len2)
    double eps = 0.0;     // 1e-9 * max(1, |d|): distance slack
    double slack = 0.0;   // eps * |d|: slack of the projection dot(x - a, d)
    double half_plane_eps = 0.0;
  };
  std::vector<LineSlab> slabs_;
  std::vector<Corner> corners_;            // per point
  VertexRows<int> lines_from_;             // per point: boundary lines starting there
  // Per lower vertex of a curve hull edge: (upper vertex, edge).
  VertexRows<std::pair<std::uint32_t, CurveEdge>> curve_edges_;
  std::vector<std::array<int, 3>> edge_lines_;  // per triangle edge: line_between()
  mutable std::vector<std::uint32_t> seen_;  // per triangle: interior_lines' search stamp
  mutable std::uint32_t stamp_ = 0;
  std::vector<std::array<std::uint32_t, 3>> across_;  // per triangle edge: see prepare_triangle_edges
  std::vector<std::pair<std::uint64_t, std::uint32_t>> inner_edges_;  // scratch of prepare_triangle_edges
  VertexRows<int> curves_at_;              // per point: curves whose hull has it as a vertex
  std::vector<Bary> barys_;                // per curve
  std::vector<char> bary_ok_;              // per curve: hull not degenerate
  // The lines of the interior triangles across each curve's edges, as
  // (curve, line) in the order met, then grouped per curve.
  std::vector<std::pair<int, int>> neighbour_lines_;
  VertexRows<int> neighbour_rows_;
  std::vector<char> has_neighbour_;        // per curve: an interior triangle across its edge
  // The interior triangle (index) each boundary line is an edge of.
  std::vector<std::uint32_t> boundary_triangle_;
  std::vector<IndexList> triangle_lines_;  // per triangle: interior_lines()
  std::vector<IndexList> curve_fade_;      // per curve: curve_fade_lines()
  std::vector<char> solid_beyond_;         // per curve: solid_beyond_chord()
  std::vector<char> has_boundary_triangle_;
  std::vector<FringeEdge> edges_;
  std::vector<Incident> incident_;         // per point
  std::vector<std::pair<double, CurveEdge>> touching_scratch_;
};

}  // namespace

void pack_mesh(const Mesh& mesh, std::vector<Vertex>& out) {
  thread_local Packer packer;
  packer.run(mesh, out);
}

void append_translated(const std::vector<Vertex>& in, Vec2 offset, std::vector<Vertex>& out) {
  out.reserve(out.size() + in.size());
  for (Vertex v : in) {
    // Add in double so equal inputs stay equal after the shift (watertightness).
    v.pos[0] = static_cast<float>(static_cast<double>(v.pos[0]) + offset.x);
    v.pos[1] = static_cast<float>(static_cast<double>(v.pos[1]) + offset.y);
    out.push_back(v);
  }
}

}  // namespace curvetext::gpu
