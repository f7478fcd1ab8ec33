// Projective maps of the plane (rotation, non-uniform scale, skew, and the
// perspective view of a tilted plane) applied to framebuffer pixel
// coordinates after a Placement. Coverage stays right under any of them: the
// curve shader measures distances with screen-space derivatives.
#pragma once

#include <array>

#include "curvetext/export.hpp"
#include "curvetext/geometry.hpp"

namespace curvetext {

// Row-major 3x3 homogeneous matrix m: (x, y) -> (X / W, Y / W) with
// (X, Y, W) = m * (x, y, 1). Affine maps have the last row (0, 0, 1). A
// value type; the factories do not check their arguments (validate() does,
// and so does everything that draws with a transform).
struct CURVETEXT_API Transform {
  std::array<double, 9> m{1, 0, 0, 0, 1, 0, 0, 0, 1};

  static Transform translation(double dx, double dy);
  static Transform rotation(double degrees);  // clockwise on screen (y down)
  static Transform scale(double sx, double sy);
  static Transform skew(double x_degrees, double y_degrees);  // x += tan(ax) y, y += tan(ay) x
  // The plane turned by `degrees` about the horizontal axis y = 0 (top edge
  // towards the viewer for positive angles) and seen by a pinhole camera
  // `distance` pixels away whose focal length is `distance` (the axis keeps
  // its scale).
  static Transform perspective(double degrees, double distance);
  // The same map about the point c: T(c) * this * T(-c).
  Transform about(Vec2 c) const;
  // A 3D scene's plane z = 0 seen through a model-view-projection matrix, as
  // OpenGL and glm hold it (column-major: mvp[4 * column + row];
  // glm::value_ptr(m)), to the pixels of a viewport of width x height (y down
  // from its top-left). The input is (x, -y) for the plane's point (x, y, 0):
  // as a Placement's transform, the Placement's y-down pixels are the plane's
  // coordinates with y flipped, so text lies upright along the plane's +y
  // (Placement::on_plane does this). Throws Error(InvalidArgument) for a
  // non-finite entry or a viewport side that is not positive and finite.
  static Transform plane_to_viewport(const float mvp[16], double width, double height);
  // The depth of that plane as the pipeline computes it: normalized device
  // z = d[0] X + d[1] Y + d[2] at the viewport's pixel (X, Y) (y down from
  // its top-left); for a plane, z is affine in the pixel position. A plane
  // seen edge-on gives {0, 0, 0}. Throws as plane_to_viewport.
  static std::array<double, 3> plane_depth(const float mvp[16], double width, double height);

  bool is_identity() const;
  bool is_affine() const;
  double w(Vec2 p) const { return m[6] * p.x + m[7] * p.y + m[8]; }  // W at p
  Vec2 apply(Vec2 p) const;                                          // (X / W, Y / W); not finite where W is 0
  // Largest and smallest singular values of the map's Jacobian at p (pixels
  // out per pixel in).
  double largest_stretch(Vec2 p) const;
  double smallest_stretch(Vec2 p) const;

  // Throws Error(InvalidArgument) when an entry is NaN/inf or larger than
  // tolerance::kMaxTransformEntry, or the map is singular (|det| below
  // tolerance::kMinTransformDeterminant relative to the entries' scale).
  void validate() const;
};

// a after b.
CURVETEXT_API Transform operator*(const Transform& a, const Transform& b);

}  // namespace curvetext
