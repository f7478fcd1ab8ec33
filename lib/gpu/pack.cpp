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

#if defined(__SSE2__)
#include <emmintrin.h>  // part of every x86-64 CPU
#endif

namespace curvetext::gpu {
namespace {

// Writes triangle p grown as above: its polygon's points at dst (room for 6
// vertices), numbered from `base`, and the fan's triangles (0, i, i + 1) at
// idx (room for 12 indices). `side` is a VertexSide, w a curve's weight (0
// for interior triangles). Returns the number of points (0 for a flat
// triangle, which covers nothing).
std::size_t emit(const std::array<Vec2, 3>& p, int side, float w, std::uint32_t base, Vertex* dst, std::uint32_t* idx) {
  const Vec2 e[3] = {p[1] - p[0], p[2] - p[1], p[0] - p[2]};  // edge k: p[k] -> p[k + 1]
  const double area2 = cross(e[0], p[2] - p[0]);
  const double len2[3] = {dot(e[0], e[0]), dot(e[1], e[1]), dot(e[2], e[2])};
  // A flat triangle covers nothing, and its barycentrics would be noise.
  if (!(std::isfinite(area2) && std::fabs(area2) > 1e-12 * (len2[0] + len2[2]))) return 0;
  // Gradients of the affine barycentrics (tau1, tau2): p[1]'s weight and
  // p[2]'s (p[0] -> (0, 0), p[1] -> (1, 0), p[2] -> (0, 1)).
  const double inv = 1.0 / area2;
  const Vec2 grad1 = Vec2{-e[2].y, e[2].x} * inv;
  const Vec2 grad2 = Vec2{-e[0].y, e[0].x} * inv;
#if defined(__SSE2__)
  const __m128d g1 = _mm_setr_pd(grad1.x, grad1.y), g2 = _mm_setr_pd(grad2.x, grad2.y);
#endif
  const double orientation = area2 > 0 ? 1.0 : -1.0;
  Vec2 along[3], normal[3];  // unit direction of edge k and its outward normal
  for (int k = 0; k < 3; ++k) {
    along[k] = e[k] * (1.0 / std::sqrt(len2[k]));
    normal[k] = Vec2{along[k].y, -along[k].x} * orientation;
  }
  std::size_t n = 0;
  const float code_base = static_cast<float>(kSideStride * side);
  auto put = [&](int k, Vec2 offset) {
    Vertex& v = dst[n++];
#if defined(__SSE2__)
    // Pairs of doubles to pairs of floats in one step each: the same
    // products, sums and roundings as the scalar code below, fewer steps.
    const __m128d o = _mm_setr_pd(offset.x, offset.y);
    const __m128d position = _mm_setr_pd(p[static_cast<std::size_t>(k)].x, p[static_cast<std::size_t>(k)].y);
    _mm_storeu_ps(v.pos, _mm_movelh_ps(_mm_cvtpd_ps(position), _mm_cvtpd_ps(o)));
    const __m128d m1 = _mm_mul_pd(g1, o), m2 = _mm_mul_pd(g2, o);
    const __m128d dtau = _mm_add_pd(_mm_unpacklo_pd(m1, m2), _mm_unpackhi_pd(m1, m2));
    _mm_storeu_ps(v.info, _mm_movelh_ps(_mm_setr_ps(code_base + static_cast<float>(k), w, 0.0f, 0.0f), _mm_cvtpd_ps(dtau)));
#else
    v.pos[0] = static_cast<float>(p[static_cast<std::size_t>(k)].x);
    v.pos[1] = static_cast<float>(p[static_cast<std::size_t>(k)].y);
    v.pos[2] = static_cast<float>(offset.x);
    v.pos[3] = static_cast<float>(offset.y);
    v.info[0] = code_base + static_cast<float>(k);
    v.info[1] = w;
    v.info[2] = static_cast<float>(grad1.x * offset.x + grad1.y * offset.y);
    v.info[3] = static_cast<float>(grad2.x * offset.x + grad2.y * offset.y);
#endif
  };
#pragma GCC unroll 3
  for (int k = 0; k < 3; ++k) {
    const int arriving = (k + 2) % 3;
    const Vec2 na = normal[arriving], nb = normal[k];  // of the edges arriving at and leaving p[k]
    const double denom = 1.0 + dot(na, nb);
    if (denom > tolerance::kMinMiterDenominator) {
      put(k, (na + nb) * (1.0 / denom));  // the miter
      continue;
    }
    // Bevel: the points of both moved edges at distance 1 from p[k] along
    // the outward bisector u = (ea + eb) / |ea + eb| of the unit vectors ea
    // (along the arriving edge, onward) and eb (along the leaving edge,
    // backward). With c = ea . eb = -na . nb, |ea + eb| = sqrt(2 (1 + c)) and
    // u . ea = u . eb = (1 + c) / |ea + eb|; a point na + ea s on the moved
    // arriving edge is at distance 1 along u when s = (|ea + eb| - eb . na) /
    // (1 + c), and likewise on the leaving edge. 1 + c = 2 - denom >= 1.875 here.
    const Vec2 ea = along[arriving], eb = along[k] * -1.0;
    const double one_plus_c = 2.0 - denom;
    const double bisector_length = std::sqrt(2.0 * one_plus_c);
    const double inv_one_plus_c = 1.0 / one_plus_c;
    put(k, na + ea * ((bisector_length - dot(eb, na)) * inv_one_plus_c));
    put(k, nb + eb * ((bisector_length - dot(ea, nb)) * inv_one_plus_c));
  }
  // The fan (0, 1, 2), (0, 2, 3), ...: all four possible triangles are
  // written (idx has room), the caller keeps the first n - 2.
  static constexpr std::uint32_t kFan[12] = {0, 1, 2, 0, 2, 3, 0, 3, 4, 0, 4, 5};
  for (int j = 0; j < 12; ++j) idx[j] = base + kFan[j];
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
    const std::size_t n = emit(p, side, w, base + static_cast<std::uint32_t>(nv), vertices + nv, indices + ni);
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
