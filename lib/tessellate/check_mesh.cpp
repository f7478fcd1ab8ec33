// mesh_area and check_mesh: the invariants of DESIGN.md section 4, measured on
// a finished mesh. The outline's area is computed here from the outline alone
// (Green's theorem per contour, nesting by exact winding numbers of curved
// contours), not from anything the builder decided.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <new>
#include <string>
#include <utility>
#include <vector>

#include "curvetext/curves.hpp"
#include "curvetext/error.hpp"
#include "curvetext/mesh.hpp"
#include "core/tolerances.hpp"
#include "tessellate/predicates.hpp"
#include "tessellate/rings.hpp"

namespace curvetext {
namespace {

using detail::orient2d;

double triangle_area(Vec2 a, Vec2 b, Vec2 c) { return 0.5 * cross(b - a, c - a); }

// Winding number of p around one closed contour of lines and conics. The
// contour is its chord polygon plus, per conic, the closed loop "arc then
// chord back"; that loop winds +1 around the points between chord and arc
// when the arc bulges right of the chord, -1 when it bulges left. `on_curve`
// is set when p lies on a straight piece or (numerically) on an arc.
int contour_winding(const Contour& contour, Vec2 p, bool& on_curve) {
  int winding = 0;
  on_curve = false;
  for (const Segment& s : contour.segments) {
    const Vec2 a = s.p[0], b = s.end();
    // On a line, or on a conic's chord: the chord polygon's count and the
    // cap's then disagree about which side p is on (p on the chord of a
    // cap it lies in counts twice), so the caller asks another point.
    if (detail::point_on_segment(a, b, p)) on_curve = true;
    if (a.y <= p.y) {
      if (b.y > p.y && orient2d(a, b, p) > 0) ++winding;
    } else if (b.y <= p.y && orient2d(a, b, p) < 0) {
      --winding;
    }
    if (s.kind != Segment::Kind::Conic) continue;
    const Vec2 c = s.p[1];
    const double area = triangle_area(a, c, b);
    if (area == 0.0 || detail::point_in_triangle(a, c, b, p) == detail::Where::Outside) continue;
    // Barycentric coordinates (tau0 at a, tau1 at the control point, tau2 at
    // b); the conic is tau1^2 = 4 w^2 tau0 tau2, the chord side negative.
    const double t0 = triangle_area(p, c, b) / area;
    const double t1 = triangle_area(a, p, b) / area;
    const double t2 = triangle_area(a, c, p) / area;
    const double f = t1 * t1 - 4.0 * s.weight * s.weight * t0 * t2;
    if (std::fabs(f) <= 1e-12) on_curve = true;
    if (f < 0.0) winding += orient2d(a, b, c) < 0 ? 1 : -1;
  }
  return winding;
}

// Points on a contour used to ask "where is this contour": the middles of
// its pieces, then its on-curve points. Middles first: contours that touch
// (a serif's tip on a neighbouring stroke) meet at on-curve points, where
// "inside" is decided by rounding.
std::vector<Vec2> probe_points(const Contour& contour) {
  std::vector<Vec2> probes;
  for (const Segment& s : contour.segments) probes.push_back(evaluate(s, 0.5));
  for (const Segment& s : contour.segments) probes.push_back(s.p[0]);
  return probes;
}

double nonzero_outline_area(const Outline& outline) {
  const auto& contours = outline.contours();
  const std::size_t n = contours.size();
  std::vector<double> area(n);
  std::vector<Box> box(n);
  std::vector<std::vector<Vec2>> probes(n);
  for (std::size_t i = 0; i < n; ++i) {
    Outline single;
    single.contours().push_back(contours[i]);
    area[i] = single.signed_area();
    box[i] = single.control_box();
    probes[i] = probe_points(contours[i]);
  }
  double total = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    if (area[i] == 0.0) continue;
    int outside = 0;
    for (std::size_t j = 0; j < n; ++j) {
      if (j == i || area[j] == 0.0) continue;
      for (const Vec2 p : probes[i]) {
        if (p.x < box[j].min.x || p.x > box[j].max.x || p.y < box[j].min.y || p.y > box[j].max.y) break;
        bool on_curve = false;
        const int w = contour_winding(contours[j], p, on_curve);
        if (on_curve) continue;  // touching contours: ask another point
        outside += w;
        break;
      }
    }
    const int inside = outside + (area[i] > 0 ? 1 : -1);
    total += (static_cast<double>(inside != 0) - static_cast<double>(outside != 0)) * std::fabs(area[i]);
  }
  return total;
}

// --- Reference area for crossing outlines -------------------------------------
//
// Independent of the mesh builder's crossing resolver: the outline is
// flattened (each conic halved recursively into 2^k pieces until a piece's
// cap, the area between arc and chord, is at most kCapRelative * diag^2, diag
// the outline's box diagonal), and the nonzero area of the polygon is
// integrated exactly by a slab sweep: between consecutive event heights
// (vertices and crossings) the covered width is linear in y, so width at the
// slab's middle times its height is exact. Each piece's cap is then added
// back with the sign given by the windings on its two sides in that slab:
// cap * ([w_left != 0] - [w_right != 0]). That is exact unless another piece
// enters the cap. So pieces whose control triangle (which holds the cap)
// overlaps another piece's hull are halved further, until their caps are at
// most kCapFineRelative * diag^2 (a piece at a crossing always stays in
// contact); what remains wrong is below that per crossing, ~1e-15 of diag^2,
// far inside kAreaIdentityRelative of the area floor (1e-6 of diag^2).
// Curved pieces with a horizontal chord are halved (a horizontal chord spans
// no slab).
constexpr double kCapRelative = 1e-8;
constexpr double kCapFineRelative = 1e-15;
constexpr int kMaxCoarseDepth = 9;                  // 512 pieces per conic at most
constexpr int kMaxFineDepth = 40;                   // near contacts
constexpr std::size_t kMaxFinePiecesPerPiece = 64;  // refinement budget, per coarse piece

struct FlatEdge {
  Vec2 a, b;
  double cap;                          // area between arc and chord, positive when bulging right
  Box box;                             // of the chord
  std::size_t contour = 0, index = 0;  // position in the flattened contour
  Segment piece;                       // the conic piece (kind Line for lines)
  int depth = 0;
};

FlatEdge flat_edge(const Segment& s, int depth) {
  FlatEdge e;
  e.a = s.p[0];
  e.b = s.end();
  // Area between arc and chord, positive when the arc bulges right of
  // p0 -> p2 (the formula ring_area uses; conic_chord_area's sign is not
  // relied on here).
  e.cap =
      s.kind == Segment::Kind::Conic ? conic_area_ratio(s.weight) * 0.5 * cross(s.p[1] - s.p[0], s.p[2] - s.p[0]) : 0.0;
  e.box.add(e.a);
  e.box.add(e.b);
  e.piece = s;
  e.depth = depth;
  return e;
}

void flatten_conic(const Segment& s, double cap_limit, int depth, std::vector<FlatEdge>& out) {
  FlatEdge e = flat_edge(s, depth);
  // A horizontal chord spans no slab, so its cap would be lost: split it.
  const bool horizontal = e.a.y == e.b.y && e.cap != 0.0;
  if (depth >= kMaxCoarseDepth || (std::fabs(e.cap) <= cap_limit && !horizontal)) {
    out.push_back(e);
    return;
  }
  const auto halves = split(s, 0.5);
  flatten_conic(halves.first, cap_limit, depth + 1, out);
  flatten_conic(halves.second, cap_limit, depth + 1, out);
}

// The hull of a flattened piece: its chord, or a conic piece's control triangle.
int hull_of(const FlatEdge& e, Vec2* hull) {
  hull[0] = e.a;
  if (e.cap == 0.0) {
    hull[1] = e.b;
    return 2;
  }
  hull[1] = e.piece.p[1];
  hull[2] = e.b;
  return 3;
}

// Chords on one line that share more than a point: the slab sweep would put
// an artificial winding between them (zero width), which a cap on either
// side would take for its own.
bool chords_overlap(const FlatEdge& e, const FlatEdge& f) {
  if (orient2d(e.a, e.b, f.a) != 0 || orient2d(e.a, e.b, f.b) != 0) return false;
  auto inside = [](Vec2 a, Vec2 b, Vec2 p) { return detail::point_on_segment(a, b, p) && p != a && p != b; };
  return inside(e.a, e.b, f.a) || inside(e.a, e.b, f.b) || inside(f.a, f.b, e.a) || inside(f.a, f.b, e.b) ||
         (e.a == f.a && e.b == f.b) || (e.a == f.b && e.b == f.a);
}

// One round of refinement: marks the conic pieces (caps above `fine_limit`)
// whose hull overlaps another piece's hull, or whose chord overlaps another's. Returns the number marked.
std::size_t mark_contacts(const std::vector<std::vector<FlatEdge>>& contours, double fine_limit,
                          std::vector<std::vector<char>>& marks) {
  struct Ref {
    Box box;
    std::size_t c, i;
  };
  std::vector<Ref> refs;
  for (std::size_t c = 0; c < contours.size(); ++c) {
    marks[c].assign(contours[c].size(), 0);
    for (std::size_t i = 0; i < contours[c].size(); ++i) {
      Ref r{contours[c][i].box, c, i};
      if (contours[c][i].cap != 0.0) r.box.add(contours[c][i].piece.p[1]);
      refs.push_back(r);
    }
  }
  std::sort(refs.begin(), refs.end(), [](const Ref& x, const Ref& y) { return x.box.min.x < y.box.min.x; });
  auto refinable = [&](const Ref& r) {
    const FlatEdge& e = contours[r.c][r.i];
    return std::fabs(e.cap) > fine_limit && e.depth < kMaxFineDepth;
  };
  std::size_t marked = 0;
  for (std::size_t x = 0; x < refs.size(); ++x) {
    for (std::size_t y = x + 1; y < refs.size() && refs[y].box.min.x <= refs[x].box.max.x; ++y) {
      const Ref& r = refs[x];
      const Ref& q = refs[y];
      if (!refinable(r) && !refinable(q)) continue;
      if (!detail::boxes_overlap(r.box, q.box)) continue;
      Vec2 hr[3], hq[3];
      const int nr = hull_of(contours[r.c][r.i], hr), nq = hull_of(contours[q.c][q.i], hq);
      if (!detail::hulls_overlap(hr, nr, hq, nq) && !chords_overlap(contours[r.c][r.i], contours[q.c][q.i])) continue;
      for (const Ref* t : {&r, &q}) {
        if (refinable(*t) && !marks[t->c][t->i]) {
          marks[t->c][t->i] = 1;
          ++marked;
        }
      }
    }
  }
  return marked;
}

// Halves the conic pieces in contact with other pieces until their caps are
// below `fine_limit` or the budget of pieces is spent.
void refine_contacts(std::vector<std::vector<FlatEdge>>& contours, double fine_limit, std::size_t budget) {
  std::vector<std::vector<char>> marks(contours.size());
  std::size_t total = 0;
  for (const auto& c : contours) total += c.size();
  while (total < budget) {
    const std::size_t marked = mark_contacts(contours, fine_limit, marks);
    if (marked == 0 || total + marked > budget) return;
    total += marked;
    for (std::size_t c = 0; c < contours.size(); ++c) {
      std::vector<FlatEdge> refined;
      refined.reserve(contours[c].size());
      for (std::size_t i = 0; i < contours[c].size(); ++i) {
        const FlatEdge& e = contours[c][i];
        if (!marks[c][i]) {
          refined.push_back(e);
          continue;
        }
        const auto halves = split(e.piece, 0.5);
        refined.push_back(flat_edge(halves.first, e.depth + 1));
        refined.push_back(flat_edge(halves.second, e.depth + 1));
      }
      contours[c] = std::move(refined);
    }
  }
}

// Nonzero area by the slab sweep; `crossing` is set when two edges meet other
// than as consecutive pieces of one contour (then only this method is right).
// Without a crossing the sweep is skipped (its work is the number of edges
// times the edges a slab crosses, quadratic for a comb) and NaN returned.
double swept_nonzero_area(const Outline& outline, bool& crossing) {
  const Box cb = outline.control_box();
  const Vec2 diag = cb.max - cb.min;
  const double cap_limit = kCapRelative * dot(diag, diag);
  std::vector<std::vector<FlatEdge>> contours;
  for (const Contour& c : outline.contours()) {
    std::vector<FlatEdge>& flat = contours.emplace_back();
    for (const Segment& s : c.segments) {
      if (s.kind == Segment::Kind::Conic) {
        flatten_conic(s, cap_limit, 0, flat);
      } else {
        flat.push_back(flat_edge(s, 0));
      }
    }
    flat.erase(std::remove_if(flat.begin(), flat.end(), [](const FlatEdge& e) { return e.a == e.b; }), flat.end());
  }
  std::size_t coarse = 0;
  for (const auto& c : contours) coarse += c.size();
  refine_contacts(contours, kCapFineRelative * dot(diag, diag), kMaxFinePiecesPerPiece * coarse + 4096);
  std::vector<FlatEdge> edges;
  std::vector<std::size_t> contour_size;
  for (const auto& c : contours) {
    for (std::size_t i = 0; i < c.size(); ++i) {
      edges.push_back(c[i]);
      edges.back().contour = contour_size.size();
      edges.back().index = i;
    }
    contour_size.push_back(c.size());
  }
  // Events: end points and crossing heights.
  std::vector<double> ys;
  for (const FlatEdge& e : edges) {
    ys.push_back(e.a.y);
    ys.push_back(e.b.y);
  }
  crossing = false;
  {
    std::vector<std::size_t> order(edges.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(),
              [&](std::size_t x, std::size_t y) { return edges[x].box.min.x < edges[y].box.min.x; });
    for (std::size_t oi = 0; oi < order.size(); ++oi) {
      const FlatEdge& e = edges[order[oi]];
      for (std::size_t oj = oi + 1; oj < order.size() && edges[order[oj]].box.min.x <= e.box.max.x; ++oj) {
        const FlatEdge& f = edges[order[oj]];
        if (!detail::boxes_overlap(e.box, f.box)) continue;
        if (detail::segments_cross_properly(e.a, e.b, f.a, f.b)) {
          crossing = true;
          const Vec2 r = e.b - e.a, q = f.b - f.a;
          // (Nearly parallel edges can cross with a cross product that
          // rounds to 0: then any height of the pair's common span serves.)
          double t = cross(f.a - e.a, q) / cross(r, q);
          t = std::isnan(t) ? 0.5 : std::clamp(t, 0.0, 1.0);
          ys.push_back(e.a.y + r.y * t);
          continue;
        }
        if (crossing || !detail::segments_intersect(e.a, e.b, f.a, f.b)) continue;
        // Any contact other than consecutive pieces of one contour meeting at
        // their common end: the per-contour method below cannot be trusted
        // (a contour touching itself may have lobes of both orientations).
        bool consecutive = false;
        if (e.contour == f.contour) {
          const std::size_t lo = std::min(e.index, f.index), hi = std::max(e.index, f.index);
          consecutive = hi == lo + 1 || (lo == 0 && hi + 1 == contour_size[e.contour]);
        }
        if (!consecutive || (orient2d(e.a, e.b, f.a) == 0 && orient2d(e.a, e.b, f.b) == 0)) crossing = true;
      }
    }
  }
  if (!crossing) return std::numeric_limits<double>::quiet_NaN();
  std::sort(ys.begin(), ys.end());
  ys.erase(std::unique(ys.begin(), ys.end()), ys.end());
  std::vector<std::size_t> by_min(edges.size());
  for (std::size_t i = 0; i < by_min.size(); ++i) by_min[i] = i;
  std::sort(by_min.begin(), by_min.end(),
            [&](std::size_t x, std::size_t y) { return edges[x].box.min.y < edges[y].box.min.y; });
  std::vector<std::size_t> active;
  struct Hit {
    double x;
    int dir;
    std::size_t edge;
  };
  std::vector<Hit> hits;
  double area = 0.0, caps = 0.0;
  std::size_t next = 0;
  for (std::size_t k = 0; k + 1 < ys.size(); ++k) {
    const double y0 = ys[k], y1 = ys[k + 1], ym = 0.5 * (y0 + y1), dy = y1 - y0;
    while (next < by_min.size() && edges[by_min[next]].box.min.y <= y0) active.push_back(by_min[next++]);
    active.erase(std::remove_if(active.begin(), active.end(), [&](std::size_t i) { return edges[i].box.max.y <= y0; }),
                 active.end());
    hits.clear();
    for (const std::size_t i : active) {
      const FlatEdge& e = edges[i];
      if (e.box.max.y < y1) continue;
      const double t = (ym - e.a.y) / (e.b.y - e.a.y);
      hits.push_back({e.a.x + (e.b.x - e.a.x) * t, e.b.y > e.a.y ? 1 : -1, i});
    }
    std::sort(hits.begin(), hits.end(), [](const Hit& p, const Hit& q) { return p.x < q.x; });
    int w = 0;
    double width = 0.0;
    for (std::size_t h = 0; h < hits.size(); ++h) {
      const int before = w;
      w += hits[h].dir;
      if (w != 0 && h + 1 < hits.size()) width += hits[h + 1].x - hits[h].x;
      const FlatEdge& e = edges[hits[h].edge];
      if (e.cap == 0.0) continue;
      // Left of an upward edge is the -x side (before it in the scan).
      const int left = hits[h].dir > 0 ? before : w, right = hits[h].dir > 0 ? w : before;
      const double share = dy / (e.box.max.y - e.box.min.y);
      caps += e.cap * share * (static_cast<double>(left != 0) - static_cast<double>(right != 0));
    }
    area += width * dy;
  }
  return area + caps;
}

struct Face {
  std::array<std::uint32_t, 3> v;  // counter-clockwise when not degenerate
  bool curved;
  std::size_t source;  // index in triangles or curves
};

void add_problem(MeshCheck& check, const std::string& line) {
  constexpr std::size_t kMaxProblems = 20;
  if (check.problems.size() < kMaxProblems) {
    check.problems.push_back(line);
  } else if (check.problems.size() == kMaxProblems) {
    check.problems.push_back("... (more problems not listed)");
  }
}

std::string edge_name(const Mesh& mesh, std::uint32_t a, std::uint32_t b) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "(%.17g, %.17g)-(%.17g, %.17g)", mesh.points[a].x, mesh.points[a].y, mesh.points[b].x,
                mesh.points[b].y);
  return buf;
}

}  // namespace

double mesh_area(const Mesh& mesh) {
  double area = 0.0;
  for (const auto& t : mesh.triangles) area += triangle_area(mesh.points[t[0]], mesh.points[t[1]], mesh.points[t[2]]);
  for (const CurvedTriangle& c : mesh.curves) {
    const double hull = std::fabs(triangle_area(mesh.points[c.p0], mesh.points[c.control], mesh.points[c.p2]));
    const double ratio = conic_area_ratio(c.weight);
    area += (c.convex ? ratio : 1.0 - ratio) * hull;
  }
  return area;
}

namespace {

MeshCheck check_mesh_of(const Mesh& mesh, const Outline& quadratic_outline) {
  MeshCheck check;
  const std::uint32_t npoints = static_cast<std::uint32_t>(mesh.points.size());
  auto valid_index = [&](std::uint32_t i) { return i < npoints; };

  // Faces, with index validation first so the rest can trust the indices.
  std::vector<Face> faces;
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    const auto& t = mesh.triangles[i];
    if (!valid_index(t[0]) || !valid_index(t[1]) || !valid_index(t[2])) {
      add_problem(check, "triangle " + std::to_string(i) + " has an out-of-range vertex index");
      check.watertight = false;
      continue;
    }
    faces.push_back({t, false, i});
  }
  for (std::size_t i = 0; i < mesh.curves.size(); ++i) {
    const CurvedTriangle& c = mesh.curves[i];
    if (!valid_index(c.p0) || !valid_index(c.control) || !valid_index(c.p2)) {
      add_problem(check, "curve " + std::to_string(i) + " has an out-of-range vertex index");
      check.watertight = false;
      continue;
    }
    const bool ccw = orient2d(mesh.points[c.p0], mesh.points[c.control], mesh.points[c.p2]) >= 0;
    faces.push_back({ccw ? std::array{c.p0, c.control, c.p2} : std::array{c.p0, c.p2, c.control}, true, i});
  }
  for (const auto& b : mesh.boundary_lines) {
    if (!valid_index(b[0]) || !valid_index(b[1])) {
      add_problem(check, "boundary line with an out-of-range vertex index");
      return check;
    }
  }

  // Area identity.
  check.area_mesh = mesh_area(mesh);
  // Contours that meet other than at vertices need the sweep; otherwise the
  // exact per-contour method (closed-form conic areas) is used.
  bool crossing = false;
  const double swept = swept_nonzero_area(quadratic_outline, crossing);
  check.area_outline = crossing ? swept : nonzero_outline_area(quadratic_outline);
  const Box control_box = quadratic_outline.control_box();
  const Vec2 diagonal = control_box.empty() ? Vec2{} : control_box.max - control_box.min;
  const double floor = tolerance::kAreaIdentityFloorOfBox * dot(diagonal, diagonal);
  check.area_rel_error = std::fabs(check.area_mesh - check.area_outline) /
                         std::max({std::fabs(check.area_outline), floor, std::numeric_limits<double>::min()});
  if (!(check.area_rel_error <= tolerance::kAreaIdentityRelative)) {
    char buf[200];
    std::snprintf(buf, sizeof buf, "area identity: mesh %.17g vs outline %.17g (relative error %.3g)", check.area_mesh,
                  check.area_outline, check.area_rel_error);
    add_problem(check, buf);
  }

  // Degenerate faces.
  for (const Face& f : faces) {
    const int o = orient2d(mesh.points[f.v[0]], mesh.points[f.v[1]], mesh.points[f.v[2]]);
    if (o <= 0) {
      ++check.degenerate;
      add_problem(check, std::string(f.curved ? "curve " : "triangle ") + std::to_string(f.source) +
                             (o == 0 ? " has zero area" : " is clockwise"));
    }
  }

  // Watertightness: undirected edge multiset of all faces against the
  // expected outline boundary.
  struct EdgeUse {
    int faces = 0;
    int direction = 0;  // +1 per use low->high, -1 per use high->low
    int boundary = 0;   // expected uses by the outline boundary
  };
  std::map<std::pair<std::uint32_t, std::uint32_t>, EdgeUse> edges;
  auto use_face_edge = [&](std::uint32_t a, std::uint32_t b) {
    EdgeUse& e = edges[{std::min(a, b), std::max(a, b)}];
    ++e.faces;
    e.direction += a < b ? 1 : -1;
  };
  auto expect_boundary = [&](std::uint32_t a, std::uint32_t b) { ++edges[{std::min(a, b), std::max(a, b)}].boundary; };
  for (const Face& f : faces) {
    for (int k = 0; k < 3; ++k) use_face_edge(f.v[k], f.v[(k + 1) % 3]);
  }
  for (const auto& b : mesh.boundary_lines) expect_boundary(b[0], b[1]);
  for (const CurvedTriangle& c : mesh.curves) {
    if (c.convex) {
      expect_boundary(c.p0, c.control);
      expect_boundary(c.control, c.p2);
    } else {
      expect_boundary(c.p0, c.p2);
    }
  }
  for (const auto& [key, e] : edges) {
    std::string why;
    if (e.faces == 0) {
      why = "outline boundary edge used by no face";
    } else if (e.faces > 2) {
      why = "edge used by " + std::to_string(e.faces) + " faces";
    } else if (e.faces == 2 && e.direction != 0) {
      why = "edge used twice in the same direction (overlapping faces)";
    } else if (e.faces == 1 && e.boundary != 1) {
      why = e.boundary == 0 ? "edge used by one face but not on the outline (crack)"
                            : "boundary edge listed " + std::to_string(e.boundary) + " times";
    } else if (e.faces == 2 && e.boundary != 0 && e.boundary != 2) {
      why = "outline boundary edge inside the mesh";
    }
    if (!why.empty()) {
      check.watertight = false;
      add_problem(check, why + ": " + edge_name(mesh, key.first, key.second));
    }
  }

  // Hull overlaps: each curved triangle against every other face.
  std::vector<Box> boxes(faces.size());
  std::vector<std::size_t> order(faces.size());
  for (std::size_t i = 0; i < faces.size(); ++i) {
    for (int k = 0; k < 3; ++k) boxes[i].add(mesh.points[faces[i].v[k]]);
    order[i] = i;
  }
  // The scans below run along the axis where the boxes overlap less: the one
  // whose summed box extents are the smaller share of the mesh's extent (a
  // comb's fan triangles span its width, its teeth not its height).
  Box all;
  double sum_x = 0.0, sum_y = 0.0;
  for (const Box& b : boxes) {
    all.add(b.min);
    all.add(b.max);
    sum_x += b.max.x - b.min.x;
    sum_y += b.max.y - b.min.y;
  }
  const bool along_y = sum_y * (all.max.x - all.min.x) < sum_x * (all.max.y - all.min.y);
  auto lo = [&](std::size_t k) { return along_y ? boxes[k].min.y : boxes[k].min.x; };
  auto hi = [&](std::size_t k) { return along_y ? boxes[k].max.y : boxes[k].max.x; };
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return lo(a) < lo(b); });
  std::vector<char> curve_overlaps(faces.size(), 0);
  auto interiors_intersect = [&](const Face& f, const Face& g) {
    Vec2 p[3], q[3];
    for (int k = 0; k < 3; ++k) {
      p[k] = mesh.points[f.v[k]];
      q[k] = mesh.points[g.v[k]];
    }
    auto separated = [](const Vec2* t, const Vec2* other) {
      const int o = orient2d(t[0], t[1], t[2]);
      if (o == 0) return true;
      for (int k = 0; k < 3; ++k) {
        bool all_outside = true;
        for (int m = 0; m < 3 && all_outside; ++m) all_outside = orient2d(t[k], t[(k + 1) % 3], other[m]) * o <= 0;
        if (all_outside) return true;
      }
      return false;
    };
    return !separated(p, q) && !separated(q, p);
  };
  auto test_pair = [&](std::size_t i, std::size_t j) {
    if (!detail::boxes_overlap(boxes[i], boxes[j]) || !interiors_intersect(faces[i], faces[j])) return;
    for (std::size_t k : {i, j}) {
      if (faces[k].curved && !curve_overlaps[k]) {
        curve_overlaps[k] = 1;
        ++check.hull_overlaps;
        add_problem(check, "curve " + std::to_string(faces[k].source) + " overlaps another face");
      }
    }
  };
  // Only pairs with a curved face are tested, so the scans start from curved
  // faces: each one forward over all faces whose boxes start within its
  // range, and each straight face over the curved faces whose boxes start
  // within its own (a long straight face, such as a fan's, meets few curves;
  // scanning all faces from it would make a comb's check quadratic).
  std::vector<std::size_t> curved_order;
  for (const std::size_t i : order)
    if (faces[i].curved) curved_order.push_back(i);
  for (std::size_t oi = 0; oi < order.size(); ++oi) {
    const std::size_t i = order[oi];
    if (faces[i].curved) {
      for (std::size_t oj = oi + 1; oj < order.size() && lo(order[oj]) <= hi(i); ++oj) test_pair(i, order[oj]);
      continue;
    }
    auto c = std::lower_bound(curved_order.begin(), curved_order.end(), lo(i),
                              [&](std::size_t k, double v) { return lo(k) < v; });
    for (; c != curved_order.end() && lo(*c) <= hi(i); ++c) test_pair(*c, i);
  }
  return check;
}

}  // namespace

MeshCheck check_mesh(const Mesh& mesh, const Outline& quadratic_outline) {
  try {
    // The outline as build_mesh reads it (tiny coordinates as 0), so that
    // the areas compared are of the same outline.
    Outline flushed;
    double largest = 0.0;
    const bool flush = detail::flush_tiny_coordinates(quadratic_outline, flushed, largest);
    if (largest > tolerance::kMaxMeshCoordinate) {
      MeshCheck check;
      add_problem(check, "outline coordinates beyond the largest build_mesh accepts");
      return check;
    }
    return check_mesh_of(mesh, flush ? flushed : quadratic_outline);
  } catch (const std::bad_alloc&) {
    throw Error(ErrorCode::Geometry, "check_mesh: out of memory while checking the mesh");
  }
}

}  // namespace curvetext
