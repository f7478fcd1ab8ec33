// build_mesh's check of its own mesh before it returns one from the general
// path: check_mesh's invariants, stopping at the first stage that finds a
// problem, since one problem is enough to refuse the mesh (and the last
// stage, the hull-overlap search, is the slowest).
#pragma once

#include "curvetext/mesh.hpp"
#include "curvetext/outline.hpp"

namespace curvetext::detail {

// The first of check_mesh's problems, in check_mesh's order (areas, degenerate
// faces, watertightness, hull overlaps); empty when the mesh passes.
MeshCheck self_check(const Mesh& mesh, const Outline& quadratic_outline, FillRule rule);

}  // namespace curvetext::detail
