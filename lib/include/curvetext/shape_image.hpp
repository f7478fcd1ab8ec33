// A shape document (shapes.hpp) to an image through the renderer: for each
// shape in document order, its fill and its stroke (stroke.hpp) in its paint
// order, each one mesh, one DrawBatch and one draw in its own colour,
// blended source-over.
#pragma once

#include "curvetext/export.hpp"
#include "curvetext/image.hpp"
#include "curvetext/image_style.hpp"
#include "curvetext/renderer.hpp"
#include "curvetext/shapes.hpp"

namespace curvetext {

// Background, antialiasing, curve test, vbaa filter, blending, gamma, debug
// view and transform: ImageStyle (image_style.hpp), as for text. The
// transform is applied about the centre of the untransformed image (width x
// height), which then grows to the transformed bounding box. `auto` picks per
// shape from the larger side of its bounding box on screen (vbaa up to
// tolerance::kAutoVbaaMaxPx, full above).
struct ShapeImageOptions : ImageStyle {
  int width = 0;       // px; 0: from the document (or the view at `scale`)
  int height = 0;      // px
  double scale = 0.0;  // pixels per document unit; 0: fit the view into the image
};

struct ShapeImageLayout {
  int width = 0;                 // px, after the transform
  int height = 0;                // px
  Placement placement;           // document units (y-up) -> pixels (then placement.transform)
  double largest_stretch = 1.0;  // of placement.transform over the image
};

// The image's size and placement; no GL. The view (ShapeDocument::view, else
// the shapes' control box) is centred in the image. Throws
// Error(InvalidArgument) for an empty document, an empty view, a scale that
// is not positive and finite, an image side above
// tolerance::kMaxImageSidePx, or a transform that transform_frame refuses.
// Thread-safe (a pure function).
CURVETEXT_API ShapeImageLayout layout_shape_image(const ShapeDocument& doc, const ShapeImageOptions& options);

// Draws every shape in order with `renderer` into an offscreen ImageTarget
// (at layout's size) and returns it read back. Cubics and higher degrees
// are approximated within tolerance::kCubicApproximationPx at the drawn
// scale, stroke offsets within tolerance::kStrokeOffsetPx; device and
// hairline stroke widths are measured at the placement's scale times the
// transform's largest stretch. Needs the renderer's GL context current on
// the calling thread. Meshes are drawn relative to the view's centre (moved
// there in double). Throws Error(Geometry) for a shape the tessellator
// refuses (an opaque stroke whose union it refuses is meshed subpath by
// subpath instead: docs/strokes.md, limits) or one reaching more than
// tolerance::kMaxGpuCoordinatePx from the view's centre at the drawn scale
// (before anything is drawn), Error(InvalidArgument) for a gamma out of
// range or a size above the GL maximum, Error(Gl) when drawing fails.
CURVETEXT_API Image render_shape_image(Renderer& renderer, const ShapeDocument& doc, const ShapeImageLayout& layout,
                                       const ShapeImageOptions& options);

}  // namespace curvetext
