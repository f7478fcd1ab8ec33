// The GPU vertex format of the curve shaders (shaders/curve.vert.glsl with
// curve.frag.glsl or area.frag.glsl) and the packing of meshes into it.
// Private to the library; tests include it.
//
// Unindexed triangles, 3 vec4 per vertex (48 bytes). Every interior triangle
// and every curved triangle's control triangle of the mesh is one polygon of
// 3 to 6 vertices (its grown outline, lib/gpu/pack.cpp), drawn as a fan:
//   a_pos  = (x, y, ox, oy)   position in outline units of one of the
//            triangle's own vertices; (ox, oy) the direction it moves per
//            outline unit of dilation t (edges move out by t).
//   a_coef = (tau1, tau2, s, 0): the triangle's affine barycentrics at (x, y)
//            (its vertices 0 -> (0, 0), 1 -> (1, 0), 2 -> (0, 1); for a curved
//            triangle p0, control, p2); s = +1 a curve filled on its chord's
//            side (convex), -1 beyond its arc (concave), 0 interior.
//   a_info = (kind, w, dtau1, dtau2): kind 0 interior, 2 curved; w the conic
//            weight; the barycentrics' change per unit of t along (ox, oy).
// The vertex shader computes pos = xy + (ox, oy) t, tau = tau + dtau t with
// t = u_fringe_px / (pixels per outline unit): 0 for the single-pass modes
// (the triangles as they are; a bevel's extra vertices coincide), a pixel's
// reach for full antialiasing.

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
static_assert(sizeof(Vertex) == 48, "the shaders' attribute layout assumes 48-byte vertices");
inline constexpr unsigned kVertexAttributes = 3;  // vec4 each

enum VertexKind : int { kSolid = 0, kCurve = 2 };

// Appends the packed triangles (interior and curved) of `mesh`.
void pack_mesh(const Mesh& mesh, std::vector<Vertex>& out);
inline std::vector<Vertex> pack_mesh(const Mesh& mesh) {
  std::vector<Vertex> out;
  pack_mesh(mesh, out);
  return out;
}

// Appends `in` translated by `offset` (outline units). Barycentrics are
// translation invariant, so only positions change.
void append_translated(const std::vector<Vertex>& in, Vec2 offset, std::vector<Vertex>& out);

}  // namespace curvetext::gpu
