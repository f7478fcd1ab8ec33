// Packs a Mesh into the curve shaders' vertex format (see vertex_format.hpp).
//
// Every triangle of the mesh (interior triangles and curved triangles' control
// triangles) is drawn on its own, grown outward in the vertex shader by a
// pixel's reach, so that every pixel whose box touches it gets a fragment.
// Full antialiasing (shaders/area.frag.glsl) computes in that fragment the
// exact area of the pixel box inside the triangle (and, for a curved
// triangle, on the filled side of its arc) and adds it into a coverage
// buffer. The mesh tiles the nonzero union of the outline exactly (area
// identity, watertightness, separated hulls: docs/design.md section 4), so the
// sums are the pixels' coverage, whatever the triangles' shapes and however
// many meet in a pixel.
//
// Growing a triangle moves each edge outward by the dilation t; at a vertex
// the two moved edges meet at a miter, which at an acute corner runs far
// past the vertex, so there the corner is cut square (a bevel: two vertices,
// one more triangle) at the same reach along the corner's bisector. Packing
// only decides which corners are bevelled and writes each point's corner
// and edges; shaders/curve.vert.glsl computes where the point moves.
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include "core/tolerances.hpp"
#include "gpu/vertex_format.hpp"

namespace curvetext::gpu {
namespace {

// Whether the corner between edges d_in (arriving) and d_out (leaving) is
// bevelled: when the moved edges' unit normals have 1 + n_in . n_out =
// 1 + d_in . d_out / (|d_in| |d_out|) <= tolerance::kMinMiterDenominator,
// tested without square roots as d_in . d_out <= -m |d_in| |d_out| with
// m = 1 - kMinMiterDenominator > 0, squared. The vertex shader moves the
// points as told (a miter or a bevel is right either way near the limit).
bool bevelled(Vec2 d_in, Vec2 d_out, double len2_in, double len2_out) {
  constexpr double m = 1.0 - tolerance::kMinMiterDenominator;
  const double d = dot(d_in, d_out);
  return (d <= 0.0) & (d * d >= m * m * len2_in * len2_out);  // no branch: bevels come unpredictably
}

// Writes triangle p's polygon: one point per corner, two at a bevelled one,
// at dst (room for 6 vertices), numbered from `base`, and the fan's triangles
// (0, i, i + 1) at idx (room for 12 indices; all four possible triangles are
// written, the caller keeps the first n - 2). `side` is a VertexSide, w a
// curve's weight (0 for interior triangles). Returns the number of points
// (0 for a flat triangle, which covers nothing and whose barycentrics would
// be noise).
std::size_t emit(const std::array<Vec2, 3>& p, int side, float w, std::uint32_t base, Vertex* dst, std::uint32_t* idx) {
  const Vec2 e[3] = {p[1] - p[0], p[2] - p[1], p[0] - p[2]};  // edge k: p[k] -> p[k + 1]
  const double area2 = cross(e[0], p[2] - p[0]);
  const double len2[3] = {dot(e[0], e[0]), dot(e[1], e[1]), dot(e[2], e[2])};
  if (!(std::isfinite(area2) && std::fabs(area2) > 1e-12 * (len2[0] + len2[2]))) return 0;
  std::size_t n = 0;
#pragma GCC unroll 3
  for (int k = 0; k < 3; ++k) {
    const int arriving = (k + 2) % 3;
    // The edge back to the previous corner in the frame of the edge to the
    // next one: b = alpha a + beta perp(a). beta |a|^2 is the triangle's
    // doubled signed area, taken here in double: rebuilt in float from two
    // nearly parallel edges (a flat curved triangle) it would lose most of
    // its digits to cancellation, and the barycentrics' gradients with it.
    const Vec2 a = e[k], b = e[arriving] * -1.0;
    const double inv_len2 = 1.0 / len2[k];
    Vertex v;
    v.pos[0] = static_cast<float>(p[static_cast<std::size_t>(k)].x);
    v.pos[1] = static_cast<float>(p[static_cast<std::size_t>(k)].y);
    v.pos[2] = static_cast<float>(a.x);
    v.pos[3] = static_cast<float>(a.y);
    v.info[0] = static_cast<float>(dot(a, b) * inv_len2);
    v.info[1] = static_cast<float>(area2 * inv_len2);  // cross(a, b) = area2 at every corner
    v.info[3] = w;
    // Both points of a bevel are written, and the second kept only at a
    // bevel: which corners are bevelled follows the data, and a branch on it
    // is mispredicted often enough to cost more than the extra store. (The
    // code is computed in integers: a select between floats may be compiled
    // to a branch.)
    const int bevel = static_cast<int>(bevelled(e[arriving], e[k], len2[arriving], len2[k]));
    const int code = kSideStride * side + k + kPointStride * kBevelArriving * bevel;  // the miter, or a bevel's first
    v.info[2] = static_cast<float>(code);
    dst[n] = v;
    v.info[2] = static_cast<float>(code + kPointStride * (kBevelLeaving - kBevelArriving));
    dst[n + 1] = v;
    n += 1 + static_cast<std::size_t>(bevel);
  }
  static constexpr std::uint32_t kFan[12] = {0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 5};
  for (int j = 0; j < 12; ++j) idx[j] = base + kFan[j];
  return n;
}

}  // namespace

void pack_mesh(const Mesh& mesh, PackedMesh& out, PackScratch& scratch) {
  // Written into scratch with room for the most a triangle can grow into
  // (6 points, 4 fan triangles), then appended at once: `out` gets exactly
  // its vertices and indices, with no zero-filling or growth on the way.
  const std::size_t triangles = mesh.triangles.size() + mesh.curves.size();
  if (scratch.vertices.size() < 6 * triangles) scratch.vertices.resize(6 * triangles);
  if (scratch.indices.size() < 12 * triangles) scratch.indices.resize(12 * triangles);
  Vertex* const vertices = scratch.vertices.data();
  std::uint32_t* const indices = scratch.indices.data();
  const auto base = static_cast<std::uint32_t>(out.vertices.size());
  std::size_t nv = 0, ni = 0;
  auto add = [&](const std::array<Vec2, 3>& p, int side, float w) {
    const std::size_t n = emit(p, side, w, base + static_cast<std::uint32_t>(nv), vertices + nv, indices + ni);
    nv += n;
    ni += n >= 3 ? 3 * (n - 2) : 0;
  };
  for (const auto& tri : mesh.triangles)
    add({mesh.points[tri[0]], mesh.points[tri[1]], mesh.points[tri[2]]}, kInterior, 0.0f);
  const std::size_t interior = ni;
  for (const CurvedTriangle& ct : mesh.curves)
    add({mesh.points[ct.p0], mesh.points[ct.control], mesh.points[ct.p2]}, ct.convex ? kConvexCurve : kConcaveCurve,
        static_cast<float>(ct.weight));
  out.vertices.insert(out.vertices.end(), vertices, vertices + nv);
  const auto split = out.indices.begin() + static_cast<std::ptrdiff_t>(out.interior_indices);
  out.indices.insert(split, indices, indices + interior);
  out.indices.insert(out.indices.end(), indices + interior, indices + ni);
  out.interior_indices += interior;
}

void append_translated(const PackedMesh& in, Vec2 offset, PackedMesh& out) {
  const auto base = static_cast<std::uint32_t>(out.vertices.size());
  append_vertices_translated(in, offset, out);
  std::vector<std::uint32_t> interior(in.indices.begin(),
                                      in.indices.begin() + static_cast<std::ptrdiff_t>(in.interior_indices));
  for (std::uint32_t& i : interior) i += base;
  out.indices.insert(out.indices.begin() + static_cast<std::ptrdiff_t>(out.interior_indices), interior.begin(),
                     interior.end());
  out.interior_indices += interior.size();
  for (std::size_t k = in.interior_indices; k < in.indices.size(); ++k) out.indices.push_back(base + in.indices[k]);
}

void append_vertices_translated(const PackedMesh& in, Vec2 offset, PackedMesh& out) {
  // No exact reserve here: appended glyph by glyph, that would copy the
  // whole block per glyph. Callers that know the total reserve it once.
  for (Vertex v : in.vertices) {
    // Add in double so equal inputs stay equal after the shift.
    v.pos[0] = static_cast<float>(static_cast<double>(v.pos[0]) + offset.x);
    v.pos[1] = static_cast<float>(static_cast<double>(v.pos[1]) + offset.y);
    out.vertices.push_back(v);
  }
}

}  // namespace curvetext::gpu
