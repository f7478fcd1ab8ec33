// A shape document (shapes.hpp: SVG or NURBS JSON) ready to draw into the
// application's own framebuffer, frame after frame, as TextBlock draws text:
// every shape's fill and stroke meshed once for a scale on screen, each one
// DrawBatch, drawn in paint order in its own colour or gradient with one
// call. render_shape_image draws through it.
#pragma once

#include <cstddef>
#include <memory>

#include "curvetext/export.hpp"
#include "curvetext/geometry.hpp"
#include "curvetext/renderer.hpp"
#include "curvetext/shapes.hpp"

namespace curvetext {

// Owns GL buffers as DrawBatch does: the context (or one sharing with it)
// current when it is built must be current when it is drawn or destroyed.
// Not thread-safe: one thread (and its context) at a time. Holds no
// reference to the document.
class CURVETEXT_API ShapeDrawing {
 public:
  // `px_per_unit`: pixels per document unit on screen (a Placement's scale
  // times its transform's largest stretch), which sets the tolerance of
  // cubic approximations (tolerance::kCubicApproximationPx) and of stroke
  // offsets (tolerance::kStrokeOffsetPx), device-pixel stroke widths, and
  // `auto` antialiasing per shape (from its size on screen). Meshes are
  // stored relative to the centre of the document's view (else of its
  // shapes), so float32 keeps 1/16 px up to tolerance::kMaxGpuCoordinatePx
  // from it. Throws Error(InvalidArgument) for a scale that is not positive
  // and finite, Error(Geometry) for a shape the tessellator or stroker
  // refuses or one reaching beyond that distance, and DrawBatch's errors.
  static ShapeDrawing from_document(const ShapeDocument& doc, double px_per_unit);

  ShapeDrawing(ShapeDrawing&&) noexcept;
  ShapeDrawing& operator=(ShapeDrawing&&) noexcept;
  ~ShapeDrawing();

  // Draws every shape with `at` mapping document units (y up) to the bound
  // framebuffer's viewport pixels as Renderer::draw does (x_px = at.scale x
  // + at.origin_x, y_px = at.origin_y - at.scale y, then at.transform), with
  // at's depth, depth offset and depth test. Each shape in its own colour
  // or gradient (options.color is not used); groups (ShapeGroup) drawn into
  // offscreen layers the size of the bound viewport, multiplied by their
  // clip's coverage and composited at their opacity (those composites are
  // not depth-tested); antialiasing (`auto` resolved
  // per shape), curve mode, vbaa filter, gamma and the debug view from
  // `options`. Draw at the scale it was built for. Renderer::draw's GL state
  // contract holds. Throws as Renderer::draw.
  void draw(Renderer& renderer, const Placement& at, const DrawOptions& options) const;

  // Meshes drawn (fills and strokes that are not empty).
  std::size_t layer_count() const;
  double px_per_unit() const { return px_per_unit_; }

 private:
  struct Layer;
  struct Groups;  // layered groups (ShapeGroup): ranges, opacities, clip meshes, the compositing program
  ShapeDrawing();
  std::unique_ptr<std::vector<Layer>> layers_;
  std::unique_ptr<Groups> groups_;
  Vec2 centre_{0, 0};
  double px_per_unit_ = 1.0;
};

}  // namespace curvetext
