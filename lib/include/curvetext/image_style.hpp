// What single lines (text_image.hpp), paragraphs (paragraph_image.hpp) and
// shape documents (shape_image.hpp) share when drawn to an image: antialiasing,
// curve test, vbaa filter, blending, coverage gamma, the debug view and a
// projective transform of the whole image. One place turns them into
// DrawOptions and into the transformed image frame, so the three paths
// behave alike.
#pragma once

#include "curvetext/color.hpp"
#include "curvetext/export.hpp"
#include "curvetext/renderer.hpp"
#include "curvetext/transform.hpp"

namespace curvetext {

struct ImageStyle {
  Color background{1, 1, 1, 1};  // straight alpha, sRGB
  AntiAliasing antialiasing = AntiAliasing::Full;
  CurveMode curve_mode = CurveMode::Exact;
  // vbaa's filter ring (DrawOptions::vbaa_ring): 0 a box filter (default).
  float vbaa_ring = 0.0f;
  // Blending of the framebuffer (ImageTarget::begin), coverage gamma and the
  // debug view (DrawOptions::gamma, DrawOptions::debug).
  Blending blending = Blending::Srgb;
  float gamma = 1.0f;
  bool debug = false;
  // Applied about the centre of the untransformed image; the image then
  // becomes the bounding box of the transformed one (ceil of its size), so
  // nothing is cut off. Identity: the untransformed image exactly.
  Transform transform;
};

// `auto` for a block whose characteristic size on screen is `on_screen_px`
// (text: pixels per em times the transform's largest stretch; shapes: the
// larger side of the shape's bounding box on screen): vbaa up to
// tolerance::kAutoVbaaMaxPx, full above (bench/quality_bench). Other modes
// are returned as they are. Thread-safe.
CURVETEXT_API AntiAliasing resolve_antialiasing(AntiAliasing aa, double on_screen_px);
// The same for `batch` drawn by `renderer` under `placement`: `auto` is full
// where the renderer draws the batch in one pass from its curve bands
// (Renderer::draws_from_bands: there full's edge error is at or below
// vbaa's at every size measured, and it draws without an offscreen pass),
// else as above. The renderer's context must be current.
CURVETEXT_API AntiAliasing resolve_antialiasing(AntiAliasing aa, double on_screen_px, const Renderer& renderer,
                                                const DrawBatch& batch, const Placement& placement);

// The style's DrawOptions for one block drawn in `color` (auto resolved for
// `on_screen_px`). Throws Error(InvalidArgument) for a gamma that is not
// finite or is outside [tolerance::kMinCoverageGamma, kMaxCoverageGamma].
CURVETEXT_API DrawOptions draw_options(const ImageStyle& style, Color color, double on_screen_px);

// A width x height image under `transform` about its centre.
struct ImageFrame {
  int width = 0;                 // px
  int height = 0;                // px
  Transform transform;           // untransformed image pixels -> final image pixels
  double largest_stretch = 1.0;  // of `transform` over the image (for levels of detail)
};

// Identity: the same size (ceil) and transform. Otherwise the transformed
// image's bounding box, moved to the origin. Throws Error(InvalidArgument) for
// an invalid transform (Transform::validate), one that puts a corner behind
// the viewer, one that squashes the image into a sliver thinner than
// tolerance::kMinTransformedImagePx, or a side above
// tolerance::kMaxImageSidePx.
CURVETEXT_API ImageFrame transform_frame(double width, double height, const Transform& transform);

}  // namespace curvetext
