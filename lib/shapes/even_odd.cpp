// Even-odd fill through the nonzero mesher: the boundary of the odd region,
// oriented with the region on its left, has winding 1 inside it and 0
// elsewhere, so its NONZERO fill is the region. build_mesh's crossing
// resolution makes that boundary (fill_boundary): the arrangement of all
// pieces, each piece's side windings, and the pieces with an odd side on
// exactly one side kept and traced into loops.
#include "curvetext/error.hpp"
#include "curvetext/mesh.hpp"
#include "curvetext/shapes.hpp"

namespace curvetext {

Outline even_odd_to_nonzero(const Outline& outline) {
  if (!outline.is_finite()) throw Error(ErrorCode::Geometry, "even-odd fill: the outline has non-finite values");
  for (const Contour& c : outline.contours())
    for (const Segment& s : c.segments)
      if (s.kind == Segment::Kind::Cubic)
        throw Error(ErrorCode::InvalidArgument, "even-odd fill: cubics must be replaced by conics first");
  return fill_boundary(outline, FillRule::EvenOdd);
}

}  // namespace curvetext
