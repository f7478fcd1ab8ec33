// Shared by the shape document targets: every shape's mesh at the tolerance
// render_shape_image uses (1/16 px at the document's drawn scale).
#pragma once

#include "curvetext/shape_image.hpp"
#include "curvetext/shapes.hpp"
#include "curvetext/tolerances.hpp"
#include "fuzz_support.hpp"

namespace curvetext::fuzz {

inline void shape_meshes(const ShapeDocument& doc) {
  ShapeImageLayout layout;
  try {
    layout = layout_shape_image(doc, {});
  } catch (const Error&) {
    return;
  }
  const double tolerance = tolerance::kCubicApproximationPx / (layout.placement.scale * layout.largest_stretch);
  for (const Shape& shape : doc.shapes) {
    Outline outline;
    try {
      outline = fill_outline(shape, tolerance);
    } catch (const Error&) {
      continue;
    }
    mesh_and_check(outline, tolerance, true);
  }
}

}  // namespace curvetext::fuzz
