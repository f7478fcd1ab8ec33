// Packs a Mesh into the curve shaders' vertex format (see vertex_format.hpp).
//
// Every triangle of the mesh (interior triangles and curved triangles' control
// triangles) is drawn on its own, grown outward in the vertex shader by a
// pixel's reach, so that every pixel whose box touches it gets a fragment.
// Full antialiasing (shaders/area.frag.glsl) computes in that fragment the
// exact area of the pixel box inside the triangle (and, for a curved
// triangle, on the filled side of its arc) and adds it into a coverage
// buffer. The mesh tiles the nonzero union of the outline exactly (area
// identity, watertightness, separated hulls: DESIGN.md section 4), so the
// sums are the pixels' coverage, whatever the triangles' shapes and however
// many meet in a pixel.
//
// Growing a triangle moves each edge outward by the dilation t; at a vertex
// the two moved edges meet at a miter, which at an acute corner runs far
// past the vertex, so there the corner is cut square (a bevel: two vertices,
// one more triangle) at the same reach along the corner's bisector.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "curvetext/tolerances.hpp"
#include "gpu/vertex_format.hpp"

namespace curvetext::gpu {
namespace {

// Unit vector along d; the squared length is finite for every triangle that
// reaches here (bary_of rejects the others), so no hypot is needed.
Vec2 unit(Vec2 d) {
  const double len2 = dot(d, d);
  return len2 > 0 ? d * (1.0 / std::sqrt(len2)) : Vec2{};
}

// Affine barycentric coordinates (tau1, tau2) of a triangle (a, b, c):
// tau1 is b's weight, tau2 c's (a -> (0, 0), b -> (1, 0), c -> (0, 1)).
struct Bary {
  Vec2 grad1{}, grad2{};
  bool ok = false;
};

Bary bary_of(Vec2 a, Vec2 b, Vec2 c) {
  Bary g;
  const double area2 = cross(b - a, c - a);
  const double scale = dot(b - a, b - a) + dot(c - a, c - a);
  // A flat triangle covers nothing; its barycentrics would be noise.
  if (!(std::isfinite(area2) && std::fabs(area2) > 1e-12 * scale)) return g;
  const double inv = 1.0 / area2;
  g.grad1 = Vec2{(c - a).y, -(c - a).x} * inv;
  g.grad2 = Vec2{-(b - a).y, (b - a).x} * inv;
  g.ok = true;
  return g;
}

// Left uninitialised (no member initialisers): emit fills the ones it uses.
struct Corner {
  int vertex;  // 0, 1, 2: which triangle vertex the point moves from
  double ox, oy;  // its offset per unit of dilation
};
Corner corner(std::size_t vertex, Vec2 offset) { return {static_cast<int>(vertex), offset.x, offset.y}; }

// The grown triangle as a convex polygon of 3 to 6 points, in order. Each
// edge moves outward by 1 (times t); see the file comment for the bevels.
int grown_polygon(const std::array<Vec2, 3>& p, std::array<Corner, 6>& out) {
  const double orientation = cross(p[1] - p[0], p[2] - p[0]) > 0 ? 1.0 : -1.0;
  std::array<Vec2, 3> along{};   // unit direction of edge k: p[k] -> p[k + 1]
  std::array<Vec2, 3> normal{};  // its outward normal
  for (std::size_t k = 0; k < 3; ++k) {
    along[k] = unit(p[(k + 1) % 3] - p[k]);
    normal[k] = Vec2{along[k].y, -along[k].x} * orientation;
  }
  int count = 0;
  for (std::size_t k = 0; k < 3; ++k) {
    const std::size_t arriving = (k + 2) % 3;
    const Vec2 na = normal[arriving];  // edge arriving at p[k]
    const Vec2 nb = normal[k];         // edge leaving p[k]
    const double denom = 1.0 + dot(na, nb);
    if (denom > tolerance::kMinMiterDenominator) {
      out[static_cast<std::size_t>(count++)] = corner(k, (na + nb) * (1.0 / denom));
      continue;
    }
    // Bevel: the points of both moved edges at distance 1 from p[k] along
    // the outward bisector u.
    const Vec2 ea = along[arriving];  // along the arriving edge, onward
    const Vec2 eb = along[k] * -1.0;  // along the leaving edge, backward
    const Vec2 u = unit(ea + eb);
    const double ua = dot(u, ea), ub = dot(u, eb);
    if (!(ua > 1e-9 && ub > 1e-9)) return 0;  // a needle with no width: nothing to draw
    out[static_cast<std::size_t>(count++)] = corner(k, na + ea * ((1.0 - dot(u, na)) / ua));
    out[static_cast<std::size_t>(count++)] = corner(k, nb + eb * ((1.0 - dot(u, nb)) / ub));
  }
  return count;
}

// Writes triangle p grown as above: its polygon's points at dst (room for 6
// vertices), numbered from `base`, and the fan's triangles (0, i, i + 1) at
// idx (room for 12 indices). `side` is a VertexSide, w a curve's weight (0
// for interior triangles). Returns the number of points (0 when the triangle
// has no width).
std::size_t emit(const std::array<Vec2, 3>& p, const Bary& g, int side, float w, std::uint32_t base, Vertex* dst,
                 std::uint32_t* idx) {
  std::array<Corner, 6> poly;
  const int count = grown_polygon(p, poly);
  if (count < 3) return 0;
  const std::size_t n = static_cast<std::size_t>(count);
  for (std::size_t i = 0; i < n; ++i) {
    const Corner& c = poly[i];
    const auto k = static_cast<std::size_t>(c.vertex);
    Vertex v;
    v.pos[0] = static_cast<float>(p[k].x);
    v.pos[1] = static_cast<float>(p[k].y);
    v.pos[2] = static_cast<float>(c.ox);
    v.pos[3] = static_cast<float>(c.oy);
    v.info[0] = static_cast<float>(c.vertex + kSideStride * side);
    v.info[1] = w;
    v.info[2] = static_cast<float>(g.grad1.x * c.ox + g.grad1.y * c.oy);
    v.info[3] = static_cast<float>(g.grad2.x * c.ox + g.grad2.y * c.oy);
    dst[i] = v;
  }
  for (std::uint32_t t = 0; t + 2 < n; ++t) {
    idx[3 * t] = base;
    idx[3 * t + 1] = base + t + 1;
    idx[3 * t + 2] = base + t + 2;
  }
  return n;
}

}  // namespace

void pack_mesh(const Mesh& mesh, PackedMesh& out) {
  // Written into scratch with room for the most a triangle can grow into
  // (6 points, 4 fan triangles), then appended at once: `out` gets exactly
  // its vertices and indices, with no zero-filling or growth on the way.
  thread_local std::vector<Vertex> vertex_scratch;
  thread_local std::vector<std::uint32_t> index_scratch;
  const std::size_t triangles = mesh.triangles.size() + mesh.curves.size();
  if (vertex_scratch.size() < 6 * triangles) vertex_scratch.resize(6 * triangles);
  if (index_scratch.size() < 12 * triangles) index_scratch.resize(12 * triangles);
  Vertex* const vertices = vertex_scratch.data();
  std::uint32_t* const indices = index_scratch.data();
  const auto base = static_cast<std::uint32_t>(out.vertices.size());
  std::size_t nv = 0, ni = 0;
  auto add = [&](const std::array<Vec2, 3>& p, int side, float w) {
    const Bary g = bary_of(p[0], p[1], p[2]);
    if (!g.ok) return;
    const std::size_t n = emit(p, g, side, w, base + static_cast<std::uint32_t>(nv), vertices + nv, indices + ni);
    nv += n;
    ni += n >= 3 ? 3 * (n - 2) : 0;
  };
  for (const auto& tri : mesh.triangles)
    add({mesh.points[tri[0]], mesh.points[tri[1]], mesh.points[tri[2]]}, kInterior, 0.0f);
  for (const CurvedTriangle& ct : mesh.curves)
    add({mesh.points[ct.p0], mesh.points[ct.control], mesh.points[ct.p2]}, ct.convex ? kConvexCurve : kConcaveCurve,
        static_cast<float>(ct.weight));
  out.vertices.insert(out.vertices.end(), vertices, vertices + nv);
  out.indices.insert(out.indices.end(), indices, indices + ni);
}

void append_translated(const PackedMesh& in, Vec2 offset, PackedMesh& out) {
  const auto base = static_cast<std::uint32_t>(out.vertices.size());
  out.vertices.reserve(out.vertices.size() + in.vertices.size());
  for (Vertex v : in.vertices) {
    // Add in double so equal inputs stay equal after the shift.
    v.pos[0] = static_cast<float>(static_cast<double>(v.pos[0]) + offset.x);
    v.pos[1] = static_cast<float>(static_cast<double>(v.pos[1]) + offset.y);
    out.vertices.push_back(v);
  }
  out.indices.reserve(out.indices.size() + in.indices.size());
  for (std::uint32_t i : in.indices) out.indices.push_back(base + i);
}

}  // namespace curvetext::gpu
