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
    prepare_curve_edges();
    for (const auto& tri : mesh_.triangles) {
      interior(tri);
      remember_boundary_triangle(tri);
    }
    for (std::size_t i = 0; i < mesh_.curves.size(); ++i) curve(i);
    collect_fringe_edges();
    for (const FringeEdge& e : edges_) fringe(e);
  }

 private:
  Vec2 pt(std::uint32_t i) const { return mesh_.points[i]; }

  struct CurveEdge {
    int curve = -1;
    SharedCurveEdge edge = kChord;
  };

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

  // The hull edge each curved triangle shares with the interior mesh: the
  // chord of a convex curve, the legs of a concave one.
  void prepare_curve_edges() {
    for (std::size_t i = 0; i < mesh_.curves.size(); ++i) {
      const CurvedTriangle& ct = mesh_.curves[i];
      const int ci = static_cast<int>(i);
      for (std::uint32_t v : {ct.p0, ct.control, ct.p2}) curves_at_[v].push_back(ci);
      if (ct.convex) {
        curve_edge_[undirected_key(ct.p0, ct.p2)] = {ci, kChord};
      } else {
        curve_edge_[undirected_key(ct.p0, ct.control)] = {ci, kLegFromP0};
        curve_edge_[undirected_key(ct.control, ct.p2)] = {ci, kLegToP2};
      }
    }
  }

  static std::uint64_t undirected_key(std::uint32_t a, std::uint32_t b) { return key(std::min(a, b), std::max(a, b)); }

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
  void set_fade(Vertex& v, Vec2 p, Vec2 offset, const std::vector<int>& lines) const {
    for (std::size_t k = 0; k < 2 && k < lines.size(); ++k) {
      const LineFn& f = lines_[static_cast<std::size_t>(lines[k])];
      v.fade[k] = static_cast<float>(f(p));
      v.fade[k + 2] = static_cast<float>(dot(f.n, offset));
    }
  }

  void remember_boundary_triangle(const std::array<std::uint32_t, 3>& tri) {
    for (int e = 0; e < 3; ++e) {
      const std::uint32_t a = tri[static_cast<std::size_t>(e)], b = tri[static_cast<std::size_t>((e + 1) % 3)];
      auto it = line_index_.find(key(a, b));
      if (it == line_index_.end()) it = line_index_.find(key(b, a));
      if (it != line_index_.end()) boundary_triangle_[it->second] = tri;
    }
  }

  // The boundary lines an interior triangle fades by, in priority order:
  // its own boundary edges, then lines through its vertices (when safe).
  std::vector<int> interior_lines(const std::array<std::uint32_t, 3>& tri) const {
    const std::array<Vec2, 3> p{pt(tri[0]), pt(tri[1]), pt(tri[2])};
    std::vector<int> lines;
    auto add = [&](int line) {
      if (line >= 0 && std::find(lines.begin(), lines.end(), line) == lines.end()) lines.push_back(line);
    };
    for (int e = 0; e < 3; ++e) {
      const std::uint32_t a = tri[static_cast<std::size_t>(e)], b = tri[static_cast<std::size_t>((e + 1) % 3)];
      auto it = line_index_.find(key(a, b));
      if (it == line_index_.end()) it = line_index_.find(key(b, a));
      if (it != line_index_.end()) add(it->second);
    }
    // Boundary lines through a vertex of this triangle: a thin or shallow
    // triangle that touches a line only at a vertex still holds pixel centres
    // within a pixel of it (and at convex corners the product of both lines
    // is the corner coverage). Only lines whose half-plane and segment slab
    // contain the whole triangle are used, so a line never fades pixels away
    // from its own segment.
    for (int e = 0; e < 3; ++e) {
      auto it = corners_.find(tri[static_cast<std::size_t>(e)]);
      if (it == corners_.end()) continue;
      const Corner& c = it->second;
      if (c.count_in != 1 || c.count_out != 1) continue;
      if (safe_for(c.in, p)) add(c.in);
      if (safe_for(c.out, p)) add(c.out);
    }
    return lines;
  }

  // The hull edge of curve `ci` whose outer side holds all of `p` (the
  // chord of a convex curve, a leg of a concave one), if any: the side of
  // the curve an interior triangle touching it at a vertex is on.
  bool touching_edge(int ci, const std::array<Vec2, 3>& p, CurveEdge& out) const {
    const CurvedTriangle& ct = mesh_.curves[static_cast<std::size_t>(ci)];
    Bary g;
    if (!bary(ct, g)) return false;
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

  // Distance from x to the hull edge `ce` names (a segment).
  double hull_edge_distance(const CurveEdge& ce, Vec2 x) const {
    const CurvedTriangle& ct = mesh_.curves[static_cast<std::size_t>(ce.curve)];
    const Vec2 a = pt(ce.edge == kLegToP2 ? ct.control : ct.p0);
    const Vec2 b = pt(ce.edge == kLegFromP0 ? ct.control : ct.p2);
    const Vec2 d = b - a;
    const double len2 = dot(d, d);
    const double s = len2 > 0 ? std::clamp(dot(x - a, d) / len2, 0.0, 1.0) : 0.0;
    return distance(x, a + d * s);
  }

  void interior(const std::array<std::uint32_t, 3>& tri) {
    const std::array<Vec2, 3> p{pt(tri[0]), pt(tri[1]), pt(tri[2])};
    const std::vector<int> lines = interior_lines(tri);
    // Curved triangles across an edge of this one: the curve can come closer
    // than a pixel to this triangle's pixel centres (near the curve's ends,
    // and anywhere along flat curves), so full AA fades by it too.
    std::array<CurveEdge, 2> near_curves{};
    int curve_count = 0;
    auto has = [&](int ci) {
      for (int k = 0; k < curve_count; ++k)
        if (near_curves[static_cast<std::size_t>(k)].curve == ci) return true;
      return false;
    };
    for (int e = 0; e < 3; ++e) {
      const std::uint32_t a = tri[static_cast<std::size_t>(e)], b = tri[static_cast<std::size_t>((e + 1) % 3)];
      auto it = curve_edge_.find(undirected_key(a, b));
      if (it == curve_edge_.end()) continue;
      Bary g;
      if (!bary(mesh_.curves[static_cast<std::size_t>(it->second.curve)], g)) continue;
      curve_neighbours_[it->second.curve].push_back(lines);
      if (curve_count < 2 && !has(it->second.curve)) near_curves[static_cast<std::size_t>(curve_count++)] = it->second;
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
    std::vector<std::pair<double, CurveEdge>> touching;
    const Vec2 centroid = (p[0] + p[1] + p[2]) / 3.0;
    for (int e = 0; e < 3; ++e) {
      auto it = curves_at_.find(tri[static_cast<std::size_t>(e)]);
      if (it == curves_at_.end()) continue;
      for (int ci : it->second) {
        CurveEdge ce;
        if (has(ci) || !touching_edge(ci, p, ce)) continue;
        bool seen = false;
        for (const auto& t : touching) seen = seen || t.second.curve == ci;
        if (!seen) touching.emplace_back(hull_edge_distance(ce, centroid), ce);
      }
    }
    std::sort(touching.begin(), touching.end(),
              [](const auto& x, const auto& y) { return x.first < y.first; });
    for (const auto& t : touching) {
      if (curve_count >= 2) break;
      near_curves[static_cast<std::size_t>(curve_count++)] = t.second;
    }
    // Line slots: four in a_coef (two for kind 4, whose other two carry the
    // second curve), then two in a_fade. Shared boundary edges come first.
    const std::size_t coef_slots = curve_count == 2 ? 2 : 4;
    std::array<int, 4> slots{-1, -1, -1, -1};
    std::vector<int> fade;
    for (std::size_t k = 0; k < lines.size(); ++k) {
      if (k < coef_slots) slots[k] = lines[k];
      else fade.push_back(lines[k]);
    }
    const int kind = curve_count == 2 ? kNextToTwoCurves
                     : curve_count == 1 ? kNextToCurve
                     : !lines.empty()   ? kEdge
                                        : kSolid;
    for (int k = 0; k < 3; ++k) {
      const Vec2 x = p[static_cast<std::size_t>(k)];
      Vertex v = make(x, Vec2{}, kind);
      if (kind != kSolid) set_slots(v, x, Vec2{}, slots);
      set_fade(v, x, Vec2{}, fade);
      if (curve_count > 0) set_near_curves(v, x, near_curves, curve_count);
      out_.push_back(v);
    }
  }

  // Lines a curved triangle and its fringes fade by: those of the interior
  // triangles across its chord or legs whose half-plane and slab hold the
  // whole control triangle (so they bound the shape near the curve, e.g. the
  // other side of a serif thinner than a pixel).
  std::vector<int> curve_fade_lines(std::size_t ci) const {
    std::vector<int> out;
    const CurvedTriangle& ct = mesh_.curves[ci];
    const std::array<Vec2, 3> hull{pt(ct.p0), pt(ct.control), pt(ct.p2)};
    auto add = [&](int li) {
      if (li >= 0 && out.size() < 2 && std::find(out.begin(), out.end(), li) == out.end()) out.push_back(li);
    };
    // First the lines making a convex corner with the curve at its ends: the
    // corner pixel is covered by the intersection of both sides.
    for (const auto& [end, other] : {std::pair{ct.p0, ct.p2}, std::pair{ct.p2, ct.p0}}) {
      auto c = corners_.find(end);
      if (c == corners_.end() || c->second.count_in != 1 || c->second.count_out != 1) continue;
      for (int li : {c->second.in, c->second.out}) {
        if (!in_half_plane(li, hull)) continue;
        // The line's far end must be on the curve's filled side of its
        // tangent (the leg) at `end`: otherwise the corner is reflex.
        const auto& bl = mesh_.boundary_lines[static_cast<std::size_t>(li)];
        const Vec2 far = pt(bl[0] == end ? bl[1] : bl[0]);
        const Vec2 e = pt(end), ctrl = pt(ct.control);
        const double side_far = cross(ctrl - e, far - e);
        const double side_other = cross(ctrl - e, pt(other) - e);
        const bool filled_towards_other = ct.convex;
        if ((side_far * side_other > 0) == filled_towards_other) add(li);
      }
    }
    auto it = curve_neighbours_.find(static_cast<int>(ci));
    if (it == curve_neighbours_.end()) return out;
    for (const std::vector<int>& lines : it->second)
      for (int li : lines)
        if (safe_for(li, hull)) add(li);
    return out;
  }

  // True when all of `p` lies in the filled half-plane of `line`.
  bool in_half_plane(int line, const std::array<Vec2, 3>& p) const {
    const LineFn& f = lines_[static_cast<std::size_t>(line)];
    if (f.n == Vec2{}) return false;
    const auto& bl = mesh_.boundary_lines[static_cast<std::size_t>(line)];
    const double eps = 1e-9 * std::max(1.0, distance(pt(bl[0]), pt(bl[1])));
    for (const Vec2& x : p)
      if (f(x) < -eps) return false;
    return true;
  }

  // Writes the kind 3/4 curve data (see vertex_format.hpp) over the slots
  // that interior triangles leave unused. After set_slots.
  void set_near_curves(Vertex& v, Vec2 x, const std::array<CurveEdge, 2>& curves, int count) const {
    auto tau = [&](const CurveEdge& ce, float& t1, float& t2, float& w) {
      const CurvedTriangle& ct = mesh_.curves[static_cast<std::size_t>(ce.curve)];
      Bary g;
      bary(ct, g);
      t1 = static_cast<float>(g.tau1(x));
      t2 = static_cast<float>(g.tau2(x));
      w = static_cast<float>(ct.weight);
    };
    tau(curves[0], v.pos[2], v.pos[3], v.info[1]);
    v.info[2] = 0.0f;
    int codes = curves[0].edge;
    if (count == 2) {
      tau(curves[1], v.coef[2], v.coef[3], v.info[2]);
      codes += 3 * curves[1].edge;
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
    Vec2 grad1() const { return Vec2{(c - a).y, -(c - a).x} / area2; }
    Vec2 grad2() const { return Vec2{-(b - a).y, (b - a).x} / area2; }
  };

  bool bary(const CurvedTriangle& ct, Bary& out) const {
    out = Bary{pt(ct.p0), pt(ct.control), pt(ct.p2)};
    out.area2 = cross(out.b - out.a, out.c - out.a);
    const double scale = dot(out.b - out.a, out.b - out.a) + dot(out.c - out.a, out.c - out.a);
    return std::isfinite(out.area2) && std::fabs(out.area2) > 1e-12 * scale;
  }

  // True when an interior triangle lies across the chord of convex curve
  // `ct`, so the shape is solid beyond that chord (not, e.g., the other half
  // of a lens of two curves). After all interior().
  bool solid_beyond_chord(const CurvedTriangle& ct) const {
    if (!ct.convex) return false;
    auto it = curve_edge_.find(undirected_key(ct.p0, ct.p2));
    return it != curve_edge_.end() && curve_neighbours_.count(it->second.curve) > 0;
  }

  Vertex curve_vertex(const CurvedTriangle& ct, const Bary& g, Vec2 p, Vec2 offset) const {
    Vertex v = make(p, offset, kCurve);
    v.coef[0] = static_cast<float>(g.tau1(p));
    v.coef[1] = static_cast<float>(g.tau2(p));
    v.coef[2] = ct.convex ? 1.0f : -1.0f;
    v.coef[3] = solid_beyond_chord(ct) ? 1.0f : 0.0f;
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
    const std::vector<int> fade = curve_fade_lines(i);
    set_fade(v0, g.a, Vec2{}, fade);
    set_fade(v1, g.b, Vec2{}, fade);
    set_fade(v2, g.c, Vec2{}, fade);
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
      std::vector<int> lines{e.line};
      auto add = [&](int line) {
        if (line >= 0 && std::find(lines.begin(), lines.end(), line) == lines.end()) lines.push_back(line);
      };
      add(convex_partner(e.line, e.a));
      add(convex_partner(e.line, e.b));
      // A feature thinner than a pixel (a serif, a hairline): the pixels
      // whose centres fall in this fringe also overlap the opposite side of
      // the feature, so the fringe fades by the lines the interior triangle
      // behind it uses as well (all of them contain that triangle).
      auto behind = boundary_triangle_.find(e.line);
      if (behind != boundary_triangle_.end()) {
        for (int li : interior_lines(behind->second)) add(li);
      }
      // Three moving slots in a_coef (c3 has no derivative), two in a_fade.
      std::array<int, 4> slots{-1, -1, -1, -1};
      std::vector<int> fade;
      for (std::size_t k = 0; k < lines.size(); ++k) {
        if (k < 3) slots[k] = lines[k];
        else fade.push_back(lines[k]);
      }
      for (const auto& [p, o] : corners) {
        Vertex v = make(p, o, kEdge);
        set_slots(v, p, o, slots);
        set_fade(v, p, o, fade);
        out_.push_back(v);
      }
    } else {
      const CurvedTriangle& ct = mesh_.curves[static_cast<std::size_t>(e.curve)];
      Bary g;
      if (!bary(ct, g)) return;
      const std::vector<int> fade = curve_fade_lines(static_cast<std::size_t>(e.curve));
      for (const auto& [p, o] : corners) {
        Vertex v = curve_vertex(ct, g, p, o);
        set_fade(v, p, o, fade);
        out_.push_back(v);
      }
    }
  }

  const Mesh& mesh_;
  std::vector<Vertex>& out_;
  std::vector<LineFn> lines_;
  std::unordered_map<std::uint64_t, int> line_index_;
  std::unordered_map<std::uint32_t, Corner> corners_;
  std::unordered_map<std::uint64_t, CurveEdge> curve_edge_;
  // The curves whose hull has each point as a vertex.
  std::unordered_map<std::uint32_t, std::vector<int>> curves_at_;
  // Per curve, the line lists of the interior triangles sharing an edge with it.
  std::unordered_map<int, std::vector<std::vector<int>>> curve_neighbours_;
  // The interior triangle each boundary line is an edge of.
  std::unordered_map<int, std::array<std::uint32_t, 3>> boundary_triangle_;
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
