// The GPU vertex format of the curve shader (shaders/curve.*.glsl) and the
// packing of meshes into it. Private to the library; tests include it.
//
// Unindexed triangles, 3 vec4 per vertex (48 bytes):
//   a_pos  = (x, y, ox, oy)   position in outline units; (ox, oy) is the
//            direction a fringe vertex moves per outline unit of dilation t
//            (a miter vector at joins, so adjacent fringes share their edge
//            exactly), 0 for vertices that do not move.
//   a_coef = (c0, c1, c2, c3) affine values interpolated by the GPU.
//   a_info = (kind, w, dc0, dc1): kind 0 solid, 1 edge, 2 curve; w the conic
//            weight (kind 2) or dc2 (kind 1: the derivative of c2, which has
//            no other slot); dc0/dc1 the derivatives of c0/c1 per unit of t.
// The vertex shader computes pos = xy + (ox,oy)*t, coef = a_coef + dc*t with
// t = fringe_px / px_per_unit (t = 0 unless antialiasing is `full`, which
// makes the fringe triangles zero-area so they produce no fragments).
//   kind 1: c0..c3 = signed distances (outline units, positive inside) to up
//           to four boundary lines (c3 only on vertices that never move: it
//           has no derivative slot); unused slots hold kUnusedDistance.
//   kind 2: c0 = tau1, c1 = tau2 (barycentrics of the control triangle,
//           p0 -> (1,0,0), control -> (0,1,0), p2 -> (0,0,1)), c2 = s (+1 the
//           chord side is filled, -1 the outer side).
#pragma once

#include <cstddef>
#include <vector>

#include "curvetext/geometry.hpp"
#include "curvetext/mesh.hpp"

namespace curvetext::gpu {

struct Vertex {
  float pos[4];
  float coef[4];
  float info[4];
};
static_assert(sizeof(Vertex) == 48, "the shader's attribute layout assumes 48-byte vertices");

enum VertexKind : int { kSolid = 0, kEdge = 1, kCurve = 2 };

// A constant distance far inside: its screen gradient is 0, which the shader
// reads as "no edge in this slot".
inline constexpr float kUnusedDistance = 1e6f;

// Appends the packed triangles (interior, curved, and fringes) of `mesh`.
void pack_mesh(const Mesh& mesh, std::vector<Vertex>& out);
inline std::vector<Vertex> pack_mesh(const Mesh& mesh) {
  std::vector<Vertex> out;
  pack_mesh(mesh, out);
  return out;
}

// Appends `in` translated by `offset` (outline units). Distances and
// barycentrics are translation invariant, so only positions change.
void append_translated(const std::vector<Vertex>& in, Vec2 offset, std::vector<Vertex>& out);

}  // namespace curvetext::gpu
