// mesh_area and check_mesh: the invariants of DESIGN.md section 4, measured on
// a finished mesh. The outline's area is computed here from the outline alone
// (Green's theorem per contour, nesting by exact winding numbers of curved
// contours), not from anything the builder decided.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <string>
#include <utility>

#include "curvetext/curves.hpp"
#include "curvetext/mesh.hpp"
#include "curvetext/tolerances.hpp"
#include "tessellate/predicates.hpp"

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
    if (s.kind == Segment::Kind::Line && detail::point_on_segment(a, b, p)) on_curve = true;
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

// Points on a contour used to ask "where is this contour": its on-curve
// points and the middles of its pieces.
std::vector<Vec2> probe_points(const Contour& contour) {
  std::vector<Vec2> probes;
  for (const Segment& s : contour.segments) {
    probes.push_back(s.p[0]);
    probes.push_back(evaluate(s, 0.5));
  }
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
  std::snprintf(buf, sizeof buf, "(%.17g, %.17g)-(%.17g, %.17g)", mesh.points[a].x, mesh.points[a].y,
                mesh.points[b].x, mesh.points[b].y);
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

MeshCheck check_mesh(const Mesh& mesh, const Outline& quadratic_outline) {
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
  check.area_outline = nonzero_outline_area(quadratic_outline);
  check.area_rel_error = std::fabs(check.area_mesh - check.area_outline) /
                         std::max(std::fabs(check.area_outline), std::numeric_limits<double>::min());
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
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return boxes[a].min.x < boxes[b].min.x; });
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
  for (std::size_t oi = 0; oi < order.size(); ++oi) {
    const std::size_t i = order[oi];
    for (std::size_t oj = oi + 1; oj < order.size() && boxes[order[oj]].min.x <= boxes[i].max.x; ++oj) {
      const std::size_t j = order[oj];
      if (!faces[i].curved && !faces[j].curved) continue;
      if (!detail::boxes_overlap(boxes[i], boxes[j])) continue;
      if (!interiors_intersect(faces[i], faces[j])) continue;
      for (std::size_t k : {i, j}) {
        if (faces[k].curved && !curve_overlaps[k]) {
          curve_overlaps[k] = 1;
          ++check.hull_overlaps;
          add_problem(check, "curve " + std::to_string(faces[k].source) + " overlaps another face");
        }
      }
    }
  }
  return check;
}

}  // namespace curvetext
