// mesh_area and check_mesh: the invariants of docs/design.md section 4,
// measured on a finished mesh. The outline's area is computed here from the
// outline alone (Green's theorem per contour, nesting by exact winding numbers
// of curved contours; or, when contours cross or touch, a sweep over the
// flattened outline), not from anything the builder decided. Every search is
// O((n + k) log n), k the pairs found: the box-pair searches of
// check_box_pairs.hpp and the sweep of check_area_sweep.hpp.
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
#include "tessellate/check_area_sweep.hpp"
#include "tessellate/check_box_pairs.hpp"
#include "tessellate/predicates.hpp"
#include "tessellate/rings.hpp"
#include "tessellate/self_check.hpp"

namespace curvetext {
namespace {

using detail::orient2d;

// check_mesh's working memory, reused across its searches.
struct CheckScratch {
  detail::BoxPairSearch pairs;
  detail::AreaSweep sweep;
  std::vector<Box> boxes;
};

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

// The winding of `contour` around the first of `probes` that is not on it
// (0 when that probe is outside the contour's box).
int winding_around(const Contour& contour, const Box& box, const std::vector<Vec2>& probes) {
  for (const Vec2 p : probes) {
    if (p.x < box.min.x || p.x > box.max.x || p.y < box.min.y || p.y > box.max.y) break;
    bool on_curve = false;
    const int w = contour_winding(contour, p, on_curve);
    if (on_curve) continue;  // touching contours: ask another point
    return w;
  }
  return 0;
}

// Contours that do not touch: each adds its area where the winding across it
// changes from unfilled to filled (the others' winding around it, and its
// own added). Only contours whose boxes overlap can wind around each other.
double outline_area(const Outline& outline, FillRule rule, CheckScratch& scratch) {
  const auto& contours = outline.contours();
  const std::size_t n = contours.size();
  std::vector<double> area(n);
  std::vector<Box> box(n);
  std::vector<std::vector<Vec2>> probes(n);
  for (std::size_t i = 0; i < n; ++i) {
    Outline single;
    single.contours().push_back(contours[i]);
    box[i] = single.control_box();
    // The area about the contour's own corner: far from the origin, the
    // products of absolute coordinates round away a tiny contour's area
    // (a 1e-9 triangle at (1, 1)), which the mesh's triangles keep.
    for (Segment& s : single.contours()[0].segments)
      for (Vec2& p : s.p) p = p - box[i].min;
    area[i] = single.signed_area();
    probes[i] = probe_points(contours[i]);
  }
  std::vector<int> outside(n, 0);
  scratch.pairs.run(
      box, detail::BoxContact::Touching, [&](std::size_t i) { return area[i] != 0.0; },
      [&](std::size_t i, std::size_t j) {
        if (area[i] == 0.0 || area[j] == 0.0) return;
        outside[i] += winding_around(contours[j], box[j], probes[i]);
        outside[j] += winding_around(contours[i], box[i], probes[j]);
      });
  double total = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    if (area[i] == 0.0) continue;
    const int inside = outside[i] + (area[i] > 0 ? 1 : -1);
    total += (static_cast<double>(detail::fills(rule, inside)) - static_cast<double>(detail::fills(rule, outside[i]))) *
             std::fabs(area[i]);
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
  double cap;     // area between arc and chord, positive when bulging right
  Box box;        // of the chord
  Segment piece;  // the conic piece (kind Line for lines)
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
// whose hull overlaps another piece's hull, or whose chord overlaps
// another's. Returns the number marked.
std::size_t mark_contacts(const std::vector<std::vector<FlatEdge>>& contours, double fine_limit,
                          std::vector<std::vector<char>>& marks, CheckScratch& scratch) {
  struct Ref {
    std::size_t c, i;
  };
  std::vector<Ref> refs;
  std::vector<Box> boxes;
  for (std::size_t c = 0; c < contours.size(); ++c) {
    marks[c].assign(contours[c].size(), 0);
    for (std::size_t i = 0; i < contours[c].size(); ++i) {
      Box box = contours[c][i].box;
      if (contours[c][i].cap != 0.0) box.add(contours[c][i].piece.p[1]);
      refs.push_back({c, i});
      boxes.push_back(box);
    }
  }
  auto refinable = [&](std::size_t k) {
    const FlatEdge& e = contours[refs[k].c][refs[k].i];
    return std::fabs(e.cap) > fine_limit && e.depth < kMaxFineDepth;
  };
  std::size_t marked = 0;
  scratch.pairs.run(boxes, detail::BoxContact::Touching, refinable, [&](std::size_t x, std::size_t y) {
    const FlatEdge& e = contours[refs[x].c][refs[x].i];
    const FlatEdge& f = contours[refs[y].c][refs[y].i];
    Vec2 he[3], hf[3];
    const int ne = hull_of(e, he), nf = hull_of(f, hf);
    if (!detail::hulls_overlap(he, ne, hf, nf) && !chords_overlap(e, f)) return;
    for (const std::size_t k : {x, y}) {
      char& mark = marks[refs[k].c][refs[k].i];
      if (refinable(k) && !mark) {
        mark = 1;
        ++marked;
      }
    }
  });
  return marked;
}

// Halves the conic pieces in contact with other pieces until their caps are
// below `fine_limit` or the budget of pieces is spent.
void refine_contacts(std::vector<std::vector<FlatEdge>>& contours, double fine_limit, std::size_t budget,
                     CheckScratch& scratch) {
  std::vector<std::vector<char>> marks(contours.size());
  std::size_t total = 0;
  for (const auto& c : contours) total += c.size();
  while (total < budget) {
    const std::size_t marked = mark_contacts(contours, fine_limit, marks, scratch);
    if (marked == 0 || total + marked > budget) return;
    total += marked;
    for (std::size_t c = 0; c < contours.size(); ++c) {
      if (std::find(marks[c].begin(), marks[c].end(), 1) == marks[c].end()) continue;
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

// The outline flattened into chords with caps, pieces in contact refined.
std::vector<std::vector<FlatEdge>> flattened(const Outline& outline, CheckScratch& scratch) {
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
  refine_contacts(contours, kCapFineRelative * dot(diag, diag), kMaxFinePiecesPerPiece * coarse + 4096, scratch);
  return contours;
}

// Whether two flattened edges meet other than as consecutive, non-collinear
// pieces of one contour at their common end: what the sweep reports as
// touching (anything it reports is such a contact), found by testing the
// pairs of edges whose boxes meet. Unknown when those are too many for the
// scan (see BoxPairSearch), or an edge is not finite: then the sweep decides.
enum class Contact { None, Some, Unknown };

Contact edge_contacts(const std::vector<detail::AreaSweep::Edge>& edges, const std::vector<std::size_t>& contour_size,
                      CheckScratch& scratch) {
  auto finite = [](Vec2 p) { return std::isfinite(p.x) && std::isfinite(p.y); };
  scratch.boxes.assign(edges.size(), Box{});
  for (std::size_t i = 0; i < edges.size(); ++i) {
    if (!finite(edges[i].a) || !finite(edges[i].b)) return Contact::Unknown;
    scratch.boxes[i].add(edges[i].a);
    scratch.boxes[i].add(edges[i].b);
  }
  bool found = false;
  const bool scanned = scratch.pairs.scan_if_cheap(
      scratch.boxes, detail::BoxContact::Touching, [](std::size_t) { return true; },
      [&](std::size_t i, std::size_t j) {
        const detail::AreaSweep::Edge &e = edges[i], &f = edges[j];
        if (found || !detail::segments_intersect(e.a, e.b, f.a, f.b)) return;
        bool consecutive = false;
        if (e.contour == f.contour) {
          const std::size_t lo = std::min(e.index, f.index), hi = std::max(e.index, f.index);
          consecutive = hi == lo + 1 || (lo == 0 && hi + 1 == contour_size[e.contour]);
        }
        if (!consecutive || (orient2d(e.a, e.b, f.a) == 0 && orient2d(e.a, e.b, f.b) == 0)) found = true;
      });
  if (!scanned) return Contact::Unknown;
  return found ? Contact::Some : Contact::None;
}

// Area under `rule` by the sweep over the flattened outline; `crossing` is set
// when two edges meet other than as consecutive pieces of one contour (then
// only this method is right). Without a crossing NaN is returned (and the
// sweep skipped where a scan of the edges' box pairs shows there is none).
double swept_area(const Outline& outline, FillRule rule, bool& crossing, CheckScratch& scratch) {
  const std::vector<std::vector<FlatEdge>> contours = flattened(outline, scratch);
  std::vector<detail::AreaSweep::Edge> edges;
  std::vector<std::size_t> contour_size;
  std::size_t total = 0;
  for (const auto& c : contours) total += c.size();
  edges.reserve(total);
  for (const auto& c : contours) {
    for (std::size_t i = 0; i < c.size(); ++i) {
      edges.push_back(
          {c[i].a, c[i].b, c[i].cap, static_cast<std::uint32_t>(contour_size.size()), static_cast<std::uint32_t>(i)});
    }
    contour_size.push_back(c.size());
  }
  crossing = false;
  if (edge_contacts(edges, contour_size, scratch) == Contact::None) return std::numeric_limits<double>::quiet_NaN();
  const double area = scratch.sweep.run(edges, contour_size, rule, crossing);
  return crossing ? area : std::numeric_limits<double>::quiet_NaN();
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

// The faces, with their indices validated first so that the rest can trust them.
bool collect_faces(const Mesh& mesh, MeshCheck& check, std::vector<Face>& faces) {
  const std::size_t npoints = mesh.points.size();
  auto valid = [&](std::uint32_t i) { return i < npoints; };
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    const auto& t = mesh.triangles[i];
    if (!valid(t[0]) || !valid(t[1]) || !valid(t[2])) {
      add_problem(check, "triangle " + std::to_string(i) + " has an out-of-range vertex index");
      check.watertight = false;
      continue;
    }
    faces.push_back({t, false, i});
  }
  for (std::size_t i = 0; i < mesh.curves.size(); ++i) {
    const CurvedTriangle& c = mesh.curves[i];
    if (!valid(c.p0) || !valid(c.control) || !valid(c.p2)) {
      add_problem(check, "curve " + std::to_string(i) + " has an out-of-range vertex index");
      check.watertight = false;
      continue;
    }
    const bool ccw = orient2d(mesh.points[c.p0], mesh.points[c.control], mesh.points[c.p2]) >= 0;
    faces.push_back({ccw ? std::array{c.p0, c.control, c.p2} : std::array{c.p0, c.p2, c.control}, true, i});
  }
  for (const auto& b : mesh.boundary_lines) {
    if (!valid(b[0]) || !valid(b[1])) {
      add_problem(check, "boundary line with an out-of-range vertex index");
      return false;
    }
  }
  return true;
}

void check_area(const Mesh& mesh, const Outline& outline, FillRule rule, MeshCheck& check, CheckScratch& scratch) {
  check.area_mesh = mesh_area(mesh);
  // Contours that meet other than at vertices need the sweep; otherwise the
  // exact per-contour method (closed-form conic areas) is used.
  bool crossing = false;
  const double swept = swept_area(outline, rule, crossing, scratch);
  check.area_outline = crossing ? swept : outline_area(outline, rule, scratch);
  const Box control_box = outline.control_box();
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
}

void check_degenerate(const Mesh& mesh, const std::vector<Face>& faces, MeshCheck& check) {
  for (const Face& f : faces) {
    const int o = orient2d(mesh.points[f.v[0]], mesh.points[f.v[1]], mesh.points[f.v[2]]);
    if (o <= 0) {
      ++check.degenerate;
      add_problem(check, std::string(f.curved ? "curve " : "triangle ") + std::to_string(f.source) +
                             (o == 0 ? " has zero area" : " is clockwise"));
    }
  }
}

// Watertightness: the undirected edge multiset of all faces against the
// expected outline boundary.
void check_watertight(const Mesh& mesh, const std::vector<Face>& faces, MeshCheck& check) {
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
}

// Whether the interiors of two faces (triangles, counter-clockwise) meet:
// neither has an edge line with the whole other face on its outer side.
bool interiors_intersect(const Mesh& mesh, const Face& f, const Face& g) {
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
}

// Hull overlaps: each curved triangle against every other face whose open
// box meets its open box (interiors lie inside those; pairs of two straight
// faces are not searched).
void check_hull_overlaps(const Mesh& mesh, const std::vector<Face>& faces, MeshCheck& check, CheckScratch& scratch) {
  std::vector<Box> boxes(faces.size());
  for (std::size_t i = 0; i < faces.size(); ++i)
    for (int k = 0; k < 3; ++k) boxes[i].add(mesh.points[faces[i].v[k]]);
  std::vector<char> overlaps(faces.size(), 0);
  scratch.pairs.run(
      boxes, detail::BoxContact::Interiors, [&](std::size_t i) { return faces[i].curved; },
      [&](std::size_t i, std::size_t j) {
        if ((overlaps[i] || !faces[i].curved) && (overlaps[j] || !faces[j].curved)) return;
        if (!interiors_intersect(mesh, faces[i], faces[j])) return;
        for (const std::size_t k : {i, j})
          if (faces[k].curved) overlaps[k] = 1;
      });
  for (std::size_t i = 0; i < faces.size(); ++i) {
    if (!overlaps[i]) continue;
    ++check.hull_overlaps;
    add_problem(check, "curve " + std::to_string(faces[i].source) + " overlaps another face");
  }
}

enum class CheckDepth { Everything, FirstProblem };

MeshCheck check_mesh_of(const Mesh& mesh, const Outline& quadratic_outline, FillRule rule, CheckDepth depth) {
  MeshCheck check;
  CheckScratch scratch;
  std::vector<Face> faces;
  if (!collect_faces(mesh, check, faces)) return check;
  const bool stop = depth == CheckDepth::FirstProblem;
  check_area(mesh, quadratic_outline, rule, check, scratch);
  if (stop && !check.ok()) return check;
  check_degenerate(mesh, faces, check);
  if (stop && !check.ok()) return check;
  check_watertight(mesh, faces, check);
  if (stop && !check.ok()) return check;
  check_hull_overlaps(mesh, faces, check, scratch);
  return check;
}

MeshCheck check_mesh_to(const Mesh& mesh, const Outline& quadratic_outline, FillRule rule, CheckDepth depth) {
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
    return check_mesh_of(mesh, flush ? flushed : quadratic_outline, rule, depth);
  } catch (const std::bad_alloc&) {
    throw Error(ErrorCode::Geometry, "check_mesh: out of memory while checking the mesh");
  }
}

}  // namespace

MeshCheck check_mesh(const Mesh& mesh, const Outline& quadratic_outline, FillRule rule) {
  return check_mesh_to(mesh, quadratic_outline, rule, CheckDepth::Everything);
}

MeshCheck detail::self_check(const Mesh& mesh, const Outline& quadratic_outline, FillRule rule) {
  return check_mesh_to(mesh, quadratic_outline, rule, CheckDepth::FirstProblem);
}

}  // namespace curvetext
