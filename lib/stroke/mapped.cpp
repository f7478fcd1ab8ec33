// Strokes whose style is in a user space an affine map takes to document
// units (stroke.hpp, stroke_outline_mapped).
#include <cmath>

#include "curvetext/error.hpp"
#include "curvetext/stroke.hpp"

namespace curvetext {

namespace {

Vec2 apply_affine(const Transform& t, Vec2 p) {
  return {t.m[0] * p.x + t.m[1] * p.y + t.m[2], t.m[3] * p.x + t.m[4] * p.y + t.m[5]};
}

Transform affine_inverse(const Transform& t) {
  const double a = t.m[0], c = t.m[1], e = t.m[2], b = t.m[3], d = t.m[4], f = t.m[5];
  const double k = 1.0 / (a * d - b * c);
  Transform inv;
  inv.m = {d * k, -c * k, (c * f - d * e) * k, -b * k, a * k, (b * e - a * f) * k, 0.0, 0.0, 1.0};
  return inv;
}

}  // namespace

Outline stroke_outline_mapped(const std::vector<ShapeContour>& contours, const StrokeStyle& style,
                              const Transform& user_to_document, double tolerance, double px_per_unit) {
  if (style.width_unit != StrokeWidthUnit::User || user_to_document.is_identity())
    return stroke_outline(contours, style, tolerance, px_per_unit);
  user_to_document.validate();
  if (!user_to_document.is_affine())
    throw Error(ErrorCode::InvalidArgument, "a stroke's user space must be an affine map of the document's");
  const Transform back = affine_inverse(user_to_document);
  std::vector<ShapeContour> user = contours;
  for (ShapeContour& c : user)
    for (RationalBezier& piece : c.pieces)
      for (Vec2& p : piece.points) p = apply_affine(back, p);
  // An affine map's stretch is the same everywhere.
  const double stretch = user_to_document.largest_stretch({0.0, 0.0});
  Outline out = stroke_outline(user, style, tolerance / stretch, px_per_unit * stretch);
  for (Contour& c : out.contours())
    for (Segment& s : c.segments)
      for (Vec2& p : s.p) p = apply_affine(user_to_document, p);
  return out;
}

}  // namespace curvetext
