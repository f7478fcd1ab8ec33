#include "curvetext/image_style.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "curvetext/error.hpp"
#include "curvetext/geometry.hpp"
#include "curvetext/tolerances.hpp"
#include "compose/check_style.hpp"
#include "core/format.hpp"

namespace curvetext {

namespace {

// Refuses a transform that squashes the w x h image into a sliver: the
// transformed corners' quadrilateral is thinner (area over longest side)
// than tolerance::kMinTransformedImagePx, and less than half as thick as
// the image was.
void check_squash(const Transform& t, double w, double h) {
  const Vec2 c[4] = {t.apply({0, 0}), t.apply({w, 0}), t.apply({w, h}), t.apply({0, h})};
  double twice_area = 0.0, longest = 0.0;
  for (int i = 0; i < 4; ++i) {
    twice_area += cross(c[i], c[(i + 1) % 4]);
    longest = std::max(longest, distance(c[i], c[(i + 1) % 4]));
  }
  const double thickness = std::abs(twice_area) / 2.0 / longest;
  if (thickness < tolerance::kMinTransformedImagePx && thickness < std::min(w, h) / 2.0)
    throw Error(ErrorCode::InvalidArgument,
                "the transform squashes the " + detail::format_number(w) + "x" + detail::format_number(h) +
                    " px image into a sliver " + detail::format_number(thickness) + " px thick (at least " +
                    detail::format_number(tolerance::kMinTransformedImagePx) + " px must remain): it would look empty");
}

}  // namespace

void check_coverage_gamma(double gamma) {
  if (!std::isfinite(gamma) || gamma < tolerance::kMinCoverageGamma || gamma > tolerance::kMaxCoverageGamma) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "gamma must be a number from %g to %g, got %g", tolerance::kMinCoverageGamma,
                  tolerance::kMaxCoverageGamma, gamma);
    throw Error(ErrorCode::InvalidArgument, buf);
  }
}

AntiAliasing resolve_antialiasing(AntiAliasing aa, double on_screen_px) {
  if (aa != AntiAliasing::Auto) return aa;
  // bench/quality_bench: vbaa's edge error is below full's at every size
  // from 8 to 384 px; above, nothing was measured and the offscreen texture
  // grows with the square of the size.
  return on_screen_px <= tolerance::kAutoVbaaMaxPx ? AntiAliasing::Vbaa : AntiAliasing::Full;
}

AntiAliasing resolve_antialiasing(AntiAliasing aa, double on_screen_px, const Renderer& renderer,
                                  const DrawBatch& batch, const Placement& placement) {
  if (aa == AntiAliasing::Auto && renderer.draws_from_bands(batch, placement)) return AntiAliasing::Full;
  return resolve_antialiasing(aa, on_screen_px);
}

DrawOptions draw_options(const ImageStyle& style, Color color, double on_screen_px) {
  check_coverage_gamma(style.gamma);
  DrawOptions draw;
  draw.color = color;
  draw.antialiasing = resolve_antialiasing(style.antialiasing, on_screen_px);
  draw.curve_mode = style.curve_mode;
  draw.vbaa_ring = style.vbaa_ring;
  draw.gamma = style.gamma;
  draw.debug = style.debug;
  return draw;
}

ImageFrame transform_frame(double w, double h, const Transform& transform) {
  ImageFrame frame;
  frame.width = static_cast<int>(std::ceil(w));
  frame.height = static_cast<int>(std::ceil(h));
  if (transform.is_identity()) return frame;
  transform.validate();
  const Transform t = transform.about({w / 2.0, h / 2.0});
  Box box;
  double stretch = 0.0;
  for (Vec2 c : {Vec2{0, 0}, Vec2{w, 0}, Vec2{0, h}, Vec2{w, h}}) {
    const double cw = t.w(c) / t.m[8];
    if (!(cw > tolerance::kMinPerspectiveW))
      throw Error(ErrorCode::InvalidArgument,
                  "the transform puts part of the image behind the viewer (use a smaller perspective angle or a larger "
                  "distance)");
    box.add(t.apply(c));
    stretch = std::max(stretch, t.largest_stretch(c));
  }
  check_squash(t, w, h);
  // Rounding of cos/sin (a rotation by 90 degrees) must not add a pixel.
  constexpr double kSlack = 1e-7;
  const double tw = std::ceil(box.max.x - box.min.x - kSlack), th = std::ceil(box.max.y - box.min.y - kSlack);
  if (!(tw >= 1.0 && th >= 1.0) || tw > tolerance::kMaxImageSidePx || th > tolerance::kMaxImageSidePx)
    throw Error(ErrorCode::InvalidArgument, "the transformed image would be " + detail::format_number(tw) + "x" +
                                                detail::format_number(th) + " px; the largest side allowed is " +
                                                std::to_string(static_cast<int>(tolerance::kMaxImageSidePx)));
  frame.width = static_cast<int>(tw);
  frame.height = static_cast<int>(th);
  frame.transform = Transform::translation(-box.min.x, -box.min.y) * t;
  frame.largest_stretch = stretch;
  return frame;
}

}  // namespace curvetext
