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
#include <unordered_map>
#include <vector>

#include "gpu/vertex_format.hpp"

namespace curvetext::gpu {
namespace {

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

// An edge of the outline along which a fringe quad is built: a boundary line,
// a leg of a convex curve's hull, or the chord of a concave curve.
struct FringeEdge {
  std::uint32_t a = 0, b = 0;
  Vec2 outward{};  // unit
  int line = -1;   // boundary line index, or -1 for curve fringes
  int curve = -1;  // curve index
};

class Packer {
 public:
  Packer(const Mesh& mesh, std::vector<Vertex>& out) : mesh_(mesh), out_(out) {}

  void run() {
    prepare_lines();
    for (const auto& tri : mesh_.triangles) interior(tri);
    for (std::size_t i = 0; i < mesh_.curves.size(); ++i) curve(i);
    collect_fringe_edges();
    for (const FringeEdge& e : edges_) fringe(e);
  }

 private:
  Vec2 pt(std::uint32_t i) const { return mesh_.points[i]; }

  void prepare_lines() {
    lines_.reserve(mesh_.boundary_lines.size());
    for (std::size_t i = 0; i < mesh_.boundary_lines.size(); ++i) {
      const auto& bl = mesh_.boundary_lines[i];
      const Vec2 a = pt(bl[0]), b = pt(bl[1]);
      const double len = distance(a, b);
      LineFn f{a, len > 0 ? left_normal(b - a) / len : Vec2{}};
      lines_.push_back(f);
      if (len > 0) line_index_[key(bl[0], bl[1])] = static_cast<int>(i);
      Corner& ca = corners_[bl[0]];
      ca.out = static_cast<int>(i);
      ++ca.count_out;
      Corner& cb = corners_[bl[1]];
      cb.in = static_cast<int>(i);
      ++cb.count_in;
    }
  }

  static std::uint64_t key(std::uint32_t a, std::uint32_t b) {
    return (static_cast<std::uint64_t>(a) << 32) | b;
  }

  // The line that makes a convex corner with `line` at vertex v, if any.
  int convex_partner(int line, std::uint32_t v) const {
    auto it = corners_.find(v);
    if (it == corners_.end()) return -1;
    const Corner& c = it->second;
    if (c.count_in != 1 || c.count_out != 1) return -1;  // touching loops: ambiguous
    const auto& in = mesh_.boundary_lines[static_cast<std::size_t>(c.in)];
    const auto& out = mesh_.boundary_lines[static_cast<std::size_t>(c.out)];
    const Vec2 din = pt(in[1]) - pt(in[0]);
    const Vec2 dout = pt(out[1]) - pt(out[0]);
    if (cross(din, dout) <= 0) return -1;  // reflex or straight: the product rule would be wrong
    if (c.in == line) return c.out;
    if (c.out == line) return c.in;
    return -1;
  }

  // True when the whole triangle lies inside the half-plane of `line` and
  // projects within the segment, so the line's distance only fades pixels
  // that really are near that boundary segment.
  bool safe_for(int line, const std::array<Vec2, 3>& p) const {
    const auto& bl = mesh_.boundary_lines[static_cast<std::size_t>(line)];
    const Vec2 a = pt(bl[0]), b = pt(bl[1]);
    const Vec2 d = b - a;
    const double len2 = dot(d, d);
    const double eps = 1e-9 * std::max(1.0, std::sqrt(len2));
    for (const Vec2& x : p) {
      if (lines_[static_cast<std::size_t>(line)](x) < -eps) return false;
      const double s = dot(x - a, d);
      if (s < -eps * std::sqrt(len2) || s > len2 + eps * std::sqrt(len2)) return false;
    }
    return true;
  }

  static Vertex make(Vec2 p, Vec2 offset, int kind) {
    Vertex v{};
    v.pos[0] = static_cast<float>(p.x);
    v.pos[1] = static_cast<float>(p.y);
    v.pos[2] = static_cast<float>(offset.x);
    v.pos[3] = static_cast<float>(offset.y);
    v.info[0] = static_cast<float>(kind);
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

  static void add_unique(std::array<int, 4>& slots, int& n, int line, int max_slots) {
    if (line < 0 || n >= max_slots) return;
    for (int k = 0; k < n; ++k)
      if (slots[static_cast<std::size_t>(k)] == line) return;
    slots[static_cast<std::size_t>(n++)] = line;
  }

  void interior(const std::array<std::uint32_t, 3>& tri) {
    const std::array<Vec2, 3> p{pt(tri[0]), pt(tri[1]), pt(tri[2])};
    // Four slots: a thin rectangle meshed as two triangles needs all four of
    // its lines in each triangle for the corner pixels.
    std::array<int, 4> slots{-1, -1, -1, -1};
    int n = 0;
    for (int e = 0; e < 3; ++e) {
      const std::uint32_t a = tri[static_cast<std::size_t>(e)], b = tri[static_cast<std::size_t>((e + 1) % 3)];
      auto it = line_index_.find(key(a, b));
      if (it == line_index_.end()) it = line_index_.find(key(b, a));
      if (it != line_index_.end()) add_unique(slots, n, it->second, 4);
    }
    // Boundary lines through a vertex of this triangle: a thin or shallow
    // triangle that touches a line only at a vertex still holds pixel centres
    // within a pixel of it (and at convex corners the product of both lines
    // is the corner coverage). Only lines whose half-plane and segment slab
    // contain the whole triangle are used, so a line never fades pixels away
    // from its own segment.
    for (int e = 0; e < 3 && n < 4; ++e) {
      auto it = corners_.find(tri[static_cast<std::size_t>(e)]);
      if (it == corners_.end()) continue;
      const Corner& c = it->second;
      if (c.count_in != 1 || c.count_out != 1) continue;
      if (safe_for(c.in, p)) add_unique(slots, n, c.in, 4);
      if (safe_for(c.out, p)) add_unique(slots, n, c.out, 4);
    }
    for (int k = 0; k < 3; ++k) {
      Vertex v = make(p[static_cast<std::size_t>(k)], Vec2{}, n > 0 ? kEdge : kSolid);
      if (n > 0) set_slots(v, p[static_cast<std::size_t>(k)], Vec2{}, slots);
      out_.push_back(v);
    }
  }

  // Affine barycentric coordinates (tau1, tau2) of a control triangle and
  // their gradients; false for a degenerate hull.
  struct Bary {
    Vec2 a, b, c;
    double area2 = 0.0;
    double tau1(Vec2 x) const { return cross(x - a, c - a) / area2; }
    double tau2(Vec2 x) const { return cross(b - a, x - a) / area2; }
    Vec2 grad1() const { return Vec2{(c - a).y, -(c - a).x} / area2; }
    Vec2 grad2() const { return Vec2{-(b - a).y, (b - a).x} / area2; }
  };

  bool bary(const CurvedTriangle& ct, Bary& out) const {
    out = Bary{pt(ct.p0), pt(ct.control), pt(ct.p2)};
    out.area2 = cross(out.b - out.a, out.c - out.a);
    const double scale = dot(out.b - out.a, out.b - out.a) + dot(out.c - out.a, out.c - out.a);
    return std::isfinite(out.area2) && std::fabs(out.area2) > 1e-12 * scale;
  }

  Vertex curve_vertex(const CurvedTriangle& ct, const Bary& g, Vec2 p, Vec2 offset) const {
    Vertex v = make(p, offset, kCurve);
    v.coef[0] = static_cast<float>(g.tau1(p));
    v.coef[1] = static_cast<float>(g.tau2(p));
    v.coef[2] = ct.convex ? 1.0f : -1.0f;
    v.coef[3] = 0.0f;
    v.info[1] = static_cast<float>(ct.weight);
    v.info[2] = static_cast<float>(dot(g.grad1(), offset));
    v.info[3] = static_cast<float>(dot(g.grad2(), offset));
    return v;
  }

  void curve(std::size_t i) {
    const CurvedTriangle& ct = mesh_.curves[i];
    Bary g;
    if (!bary(ct, g)) return;  // a flat hull has no area to draw
    // Exact hull barycentrics (not recomputed) so the corners are crisp.
    Vertex v0 = curve_vertex(ct, g, g.a, Vec2{});
    Vertex v1 = curve_vertex(ct, g, g.b, Vec2{});
    Vertex v2 = curve_vertex(ct, g, g.c, Vec2{});
    v0.coef[0] = 0.0f; v0.coef[1] = 0.0f;
    v1.coef[0] = 1.0f; v1.coef[1] = 0.0f;
    v2.coef[0] = 0.0f; v2.coef[1] = 1.0f;
    out_.push_back(v0);
    out_.push_back(v1);
    out_.push_back(v2);
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
    for (std::size_t i = 0; i < mesh_.boundary_lines.size(); ++i) {
      const auto& bl = mesh_.boundary_lines[i];
      const LineFn& f = lines_[i];
      if (f.n == Vec2{}) continue;
      edges_.push_back(FringeEdge{bl[0], bl[1], f.n * -1.0, static_cast<int>(i), -1});
    }
    for (std::size_t i = 0; i < mesh_.curves.size(); ++i) {
      const CurvedTriangle& ct = mesh_.curves[i];
      Bary g;
      if (!bary(ct, g)) continue;
      const int ci = static_cast<int>(i);
      if (ct.convex) {
        // Outside the shape lies beyond the hull's legs.
        edges_.push_back(FringeEdge{ct.p0, ct.control, outward_normal(g.a, g.b, g.c), -1, ci});
        edges_.push_back(FringeEdge{ct.control, ct.p2, outward_normal(g.b, g.c, g.a), -1, ci});
      } else {
        // Outside is the chord side; beyond the chord for curves flatter than the fringe.
        edges_.push_back(FringeEdge{ct.p0, ct.p2, outward_normal(g.a, g.c, g.b), -1, ci});
      }
    }
    for (std::size_t i = 0; i < edges_.size(); ++i) {
      incident_[edges_[i].a].push_back(static_cast<int>(i));
      incident_[edges_[i].b].push_back(static_cast<int>(i));
    }
  }

  // Offset vector of fringe edge `e` at its vertex v: the miter of the two
  // fringe edges meeting there (distance 1 from both edges' lines), so both
  // fringes use the same offset vertex. Falls back to the edge's own normal
  // where the join is ambiguous or too sharp.
  Vec2 offset_at(const FringeEdge& e, std::uint32_t v) const {
    auto it = incident_.find(v);
    if (it == incident_.end() || it->second.size() != 2) return e.outward;
    const FringeEdge& e0 = edges_[static_cast<std::size_t>(it->second[0])];
    const FringeEdge& e1 = edges_[static_cast<std::size_t>(it->second[1])];
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
    const std::array<std::pair<Vec2, Vec2>, 6> corners{
        std::pair{a, Vec2{}}, std::pair{b, Vec2{}}, std::pair{b, ob},
        std::pair{a, Vec2{}}, std::pair{b, ob},     std::pair{a, oa}};
    if (e.line >= 0) {
      std::array<int, 4> slots{e.line, -1, -1, -1};
      int n = 1;
      add_unique(slots, n, convex_partner(e.line, e.a), 3);
      add_unique(slots, n, convex_partner(e.line, e.b), 3);
      for (const auto& [p, o] : corners) {
        Vertex v = make(p, o, kEdge);
        set_slots(v, p, o, slots);
        out_.push_back(v);
      }
    } else {
      const CurvedTriangle& ct = mesh_.curves[static_cast<std::size_t>(e.curve)];
      Bary g;
      if (!bary(ct, g)) return;
      for (const auto& [p, o] : corners) out_.push_back(curve_vertex(ct, g, p, o));
    }
  }

  const Mesh& mesh_;
  std::vector<Vertex>& out_;
  std::vector<LineFn> lines_;
  std::unordered_map<std::uint64_t, int> line_index_;
  std::unordered_map<std::uint32_t, Corner> corners_;
  std::vector<FringeEdge> edges_;
  std::unordered_map<std::uint32_t, std::vector<int>> incident_;
};

}  // namespace

void pack_mesh(const Mesh& mesh, std::vector<Vertex>& out) {
  Packer(mesh, out).run();
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
