// The GPU vertex format of the curve shaders (shaders/curve.vert.glsl with
// curve.frag.glsl or area.frag.glsl) and the packing of meshes into it.
// Private to the library; tests include it.
//
// Indexed triangles, 2 vec4 per vertex (32 bytes). Every interior triangle
// and every curved triangle's control triangle of the mesh is one polygon of
// 3 to 6 vertices (its outline grown by the dilation t, lib/gpu/pack.cpp),
// each vertex stored once and the polygon drawn as a fan of indexed triangles.
// A vertex carries its corner of the triangle and that corner's two edges,
// from which the vertex shader grows it:
//   a_pos  = (x, y, ax, ay): position in outline units of the triangle's
//            corner k; (ax, ay) = corner k + 1 - corner k (the edge leaving it).
//   a_info = (alpha, beta, code, w): the edge back to the previous corner,
//            b = corner k - 1 - corner k, in the frame of a: b = alpha a +
//            beta perp(a) with perp(a) = (-ay, ax), so beta |a|^2 is the
//            triangle's doubled signed area (taken in double: from two float
//            edges of a flat triangle it would cancel to noise); w the conic
//            weight (0 interior); code = k + 3 side + 9 point (a small whole
//            number): k 0, 1, 2 the corner (p0, p1, p2 of the triangle; for a
//            curved triangle p0, control, p2), with affine barycentrics
//            (tau1, tau2) (0, 0), (1, 0), (0, 1) there; side 0 interior, 1 a
//            curve filled on its chord's side (convex, s = +1), 2 filled beyond
//            its arc (concave, s = -1); point 0 the corner's miter, 1 and 2 the
//            points of a bevel on the arriving and on the leaving edge (a
//            corner sharper than about 29 degrees, see pack.cpp).
// The vertex shader decodes code, moves the point by t along its miter or
// bevel direction (computed from the two edges) and its barycentrics with it,
// with t = u_fringe_px / (pixels per outline unit): 0 for the single-pass
// modes (the triangles as they are; a bevel's two points coincide), a pixel's
// reach for full antialiasing. The edges are differences taken in double
// before rounding, so they are exact to float precision wherever the block
// sits; the positions are shared bit for bit by neighbouring triangles.
//
// Indices are 32-bit here; a batch uploads them as 16-bit when it has at most
// 65,536 vertices (the GLES2 floor), else as 32-bit where the context has
// them (GLES3, desktop GL, OES_element_index_uint), else expands the
// triangles into plain vertex arrays.

#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "curvetext/geometry.hpp"
#include "curvetext/mesh.hpp"

namespace curvetext::gpu {

struct Vertex {
  float pos[4];
  float info[4];
};
static_assert(sizeof(Vertex) == 32, "the shaders' attribute layout assumes 32-byte vertices");
inline constexpr unsigned kVertexAttributes = 2;  // vec4 each

// a_info.z = corner + kSideStride * side + kPointStride * point.
enum VertexSide : int { kInterior = 0, kConvexCurve = 1, kConcaveCurve = 2 };
enum VertexPoint : int { kMiter = 0, kBevelArriving = 1, kBevelLeaving = 2 };
inline constexpr int kSideStride = 3;
inline constexpr int kPointStride = 9;

// Vertices a 16-bit index reaches (a batch's index width; see above).
inline constexpr std::size_t kMaxShortIndexedVertices = 65536;

// Vertices and the triangles over them (3 indices each, counter-clockwise or
// not: the shaders do not cull).
struct PackedMesh {
  std::vector<Vertex> vertices;
  // The interior triangles' indices first, [0, interior_indices), then the
  // curved triangles': full antialiasing draws them with two programs.
  std::vector<std::uint32_t> indices;
  std::size_t interior_indices = 0;

  bool empty() const { return indices.empty(); }
  // Bytes in a vertex buffer and an index buffer of the width a batch of
  // this many vertices uploads (16-bit up to 65,536 vertices, else 32-bit).
  std::size_t gpu_bytes() const {
    return vertices.size() * sizeof(Vertex) + indices.size() * (vertices.size() <= kMaxShortIndexedVertices ? 2 : 4);
  }
  // Bytes this object holds in CPU memory (the glyph cache's budget).
  std::size_t memory_bytes() const { return vertices.size() * sizeof(Vertex) + indices.size() * sizeof(std::uint32_t); }
};

// Room pack_mesh writes a mesh's polygons into before appending them at once;
// reused from call to call, its storage grows to the largest mesh packed.
struct PackScratch {
  std::vector<Vertex> vertices;
  std::vector<std::uint32_t> indices;
};

// Appends the packed triangles (interior and curved) of `mesh`, keeping the
// interior triangles' indices ahead of the curved ones'.
void pack_mesh(const Mesh& mesh, PackedMesh& out, PackScratch& scratch);
inline void pack_mesh(const Mesh& mesh, PackedMesh& out) {
  PackScratch scratch;
  pack_mesh(mesh, out, scratch);
}
inline PackedMesh pack_mesh(const Mesh& mesh) {
  PackedMesh out;
  pack_mesh(mesh, out);
  return out;
}

// Appends `in` translated by `offset` (outline units), its indices moved past
// the vertices already in `out`, interior ones ahead of curved ones (which
// moves out's curved indices: a block of many glyphs is assembled in two
// passes instead, lib/gpu/batch.cpp). Barycentrics are translation invariant, so
// only positions change.
void append_translated(const PackedMesh& in, Vec2 offset, PackedMesh& out);
// Only the vertices of `in`, translated (no indices).
void append_vertices_translated(const PackedMesh& in, Vec2 offset, PackedMesh& out);

}  // namespace curvetext::gpu
