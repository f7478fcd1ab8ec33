// The GPU vertex format of the curve shader (shaders/curve.*.glsl) and the
// packing of meshes into it. Private to the library; tests include it.
//
// Unindexed triangles, 4 vec4 per vertex (64 bytes):
//   a_pos  = (x, y, ox, oy)   position in outline units; (ox, oy) is the
//            direction a fringe vertex moves per outline unit of dilation t
//            (a miter vector at joins, so adjacent fringes share their edge
//            exactly), 0 for vertices that do not move.
//   a_coef = (c0, c1, c2, c3) affine values interpolated by the GPU.
//   a_info = (kind, w, dc0, dc1): kind 0 solid, 1 edge, 2 curve; w the conic
//            weight (kind 2) or dc2 (kind 1: the derivative of c2, which has
//            no other slot); dc0/dc1 the derivatives of c0/c1 per unit of t.
//   a_fade = (f0, f1, df0, df1): two more boundary lines (signed distances
//            as kind 1, with their derivatives per unit of t) that every
//            kind fades by in full AA: the far side of a feature thinner than
//            a pixel (a serif, a hairline) or the other line of a corner.
//            Unused slots hold kUnusedDistance.
// The vertex shader computes pos = xy + (ox,oy)*t, coef = a_coef + dc*t with
// t = fringe_px / px_per_unit (t = 0 unless antialiasing is `full`, which
// makes the fringe triangles zero-area so they produce no fragments).
//   kind 1: c0..c3 = signed distances (outline units, positive inside) to up
//           to four boundary lines (c3 only on vertices that never move: it
//           has no derivative slot); unused slots hold kUnusedDistance.
//   kind 2: c0 = tau1, c1 = tau2 (barycentrics of the control triangle,
//           p0 -> (1,0,0), control -> (0,1,0), p2 -> (0,0,1)), c2 = s (+1 the
//           chord side is filled, -1 the outer side), c3 = 1 where an
//           interior triangle lies across a convex curve's chord (the shape
//           is solid beyond it, over the chord's span), else 0.
//   kind 3, 4, 5: an interior triangle sharing an edge or a vertex with one
//           (3), two (4) or three (5) curved triangles, wholly beyond that curve's chord
//           (convex) or leg (concave) (full AA fades it near those curves, which can
//           be closer than a pixel to it). Such triangles never move, so the
//           offset and derivative slots are reused:
//             a_pos  = (x, y, tau1 A, tau2 A)  barycentrics of curve A's
//                      control triangle, extrapolated affinely to this vertex
//             a_coef = kind 3: four line distances as kind 1;
//                      kind 4: (line 0, line 1, tau1 B, tau2 B)
//             a_info = (kind, w A, w B, shared edges: edge A + 3 * edge B
//                      + 9 * edge C)
//             a_fade = kind 5: (tau1 C, tau2 C, w C, 0), as it never moves
//                      (a triangle spanning a stroke: the curve across an
//                      edge on the far side, and the two curves of a smooth
//                      join at a vertex on the near side, which a pixel
//                      centred by the join needs both of); else two lines
//           with edge 0 the chord (tau1 = 0; the curve is convex), 1 the leg
//           p0-control (tau2 = 0) and 2 the leg control-p2 (tau0 = 0) (both
//           concave). The shared edge determines the filled side.

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
  float fade[4];
};
static_assert(sizeof(Vertex) == 64, "the shader's attribute layout assumes 64-byte vertices");

enum VertexKind : int { kSolid = 0, kEdge = 1, kCurve = 2, kNextToCurve = 3, kNextToTwoCurves = 4,
                        kNextToThreeCurves = 5 };

// Which edge of a curve's control triangle an interior triangle shares.
enum SharedCurveEdge : int { kChord = 0, kLegFromP0 = 1, kLegToP2 = 2 };

// Added to a_info.x (the kind) of an interior triangle (kinds 0-4) whose two
// a_fade lines are the sides of a reflex corner at one of its vertices: the
// shape there is the union of their half-planes (shaders: add_union).
inline constexpr float kUnionFadeFlag = 0.25f;
// Added to a_info.x of an interior triangle (kinds 1 and 3) whose a_coef
// slots 2 and 3 are the sides of a second reflex corner (combined likewise).
inline constexpr float kUnionCoefFlag = 0.125f;

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
