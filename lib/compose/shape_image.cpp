// Shape documents to images: one mesh and one draw call per shape, in order,
// blended source-over (the renderer draws one colour per batch).
#include "curvetext/shape_image.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "curvetext/error.hpp"
#include "curvetext/mesh.hpp"
#include "curvetext/tolerances.hpp"
#include "compose/check_style.hpp"
#include "core/format.hpp"

namespace curvetext {

namespace {

// Pixels of the longer side when neither the document nor the caller sizes
// the image.
constexpr double kDefaultLongSidePx = 512.0;

Box shape_box(const Shape& s) {
  Box box;
  for (const ShapeContour& c : s.contours)
    for (const RationalBezier& b : c.pieces)
      for (Vec2 p : b.points) box.add(p);
  return box;
}

Box content_box(const ShapeDocument& doc) {
  Box box;
  for (const Shape& s : doc.shapes) {
    const Box b = shape_box(s);
    if (!b.empty()) {
      box.add(b.min);
      box.add(b.max);
    }
  }
  return box;
}

// The larger side of the shape's control polygon box on screen, in pixels:
// what `auto` picks by (as text by its pixels per em).
double on_screen_size(const Shape& shape, const ShapeImageLayout& layout) {
  const Box b = shape_box(shape);
  if (b.empty()) return 0.0;
  return std::max(b.max.x - b.min.x, b.max.y - b.min.y) * layout.placement.scale * layout.largest_stretch;
}

int image_side(double v, const char* what) {
  if (!std::isfinite(v) || v < 1.0 || v > tolerance::kMaxImageSidePx)
    throw Error(ErrorCode::InvalidArgument, std::string("the image ") + what + " would be " +
                                                detail::format_number_exact(v) + " px; it must be from 1 to " +
                                                std::to_string(static_cast<int>(tolerance::kMaxImageSidePx)));
  return static_cast<int>(v);
}

}  // namespace

ShapeImageLayout layout_shape_image(const ShapeDocument& doc, const ShapeImageOptions& options) {
  Box view = doc.view;
  if (view.empty()) view = content_box(doc);
  if (view.empty()) throw Error(ErrorCode::InvalidArgument, "the shape document draws nothing (no shapes)");
  double vw = view.max.x - view.min.x, vh = view.max.y - view.min.y;
  // A view of zero width or height (a single horizontal line) gets the other
  // side, so that scales stay finite.
  if (!(vw > 0.0) && !(vh > 0.0)) throw Error(ErrorCode::InvalidArgument, "the shapes have no extent");
  if (!(vw > 0.0)) vw = vh;
  if (!(vh > 0.0)) vh = vw;

  if (options.scale != 0.0 && (!std::isfinite(options.scale) || options.scale <= 0.0))
    throw Error(ErrorCode::InvalidArgument,
                "scale must be a positive number, got " + detail::format_number_exact(options.scale));
  if (options.width < 0 || options.height < 0) throw Error(ErrorCode::InvalidArgument, "image size must be positive");

  double w = options.width, h = options.height, s = options.scale;
  if (s > 0.0) {
    if (w == 0) w = std::ceil(vw * s);
    if (h == 0) h = std::ceil(vh * s);
  } else {
    if (w == 0 || h == 0) {
      if (doc.width_px > 0 && doc.height_px > 0) {
        w = doc.width_px;
        h = doc.height_px;
      } else {
        const double k = kDefaultLongSidePx / std::max(vw, vh);
        w = std::ceil(vw * k);
        h = std::ceil(vh * k);
      }
    }
    s = std::min(w / vw, h / vh);
  }
  ShapeImageLayout layout;
  layout.width = image_side(w, "width");
  layout.height = image_side(h, "height");
  // The view centred in the image (SVG's default xMidYMid meet).
  layout.placement.scale = s;
  layout.placement.origin_x = 0.5 * (layout.width - s * vw) - s * view.min.x;
  layout.placement.origin_y = 0.5 * (layout.height - s * vh) + s * view.max.y;
  if (!std::isfinite(layout.placement.origin_x) || !std::isfinite(layout.placement.origin_y) ||
      std::abs(layout.placement.origin_x) > 1e12 || std::abs(layout.placement.origin_y) > 1e12)
    throw Error(ErrorCode::InvalidArgument, "the view is too far from the origin at this scale");
  const ImageFrame frame = transform_frame(layout.width, layout.height, options.transform);
  layout.width = frame.width;
  layout.height = frame.height;
  layout.placement.transform = frame.transform;
  layout.largest_stretch = frame.largest_stretch;
  return layout;
}

namespace {

// The document point drawn at the image's centre (before the transform).
Vec2 view_centre(const ShapeImageLayout& layout) {
  const Placement& p = layout.placement;
  return {(0.5 * layout.width - p.origin_x) / p.scale, (p.origin_y - 0.5 * layout.height) / p.scale};
}

// `mesh` moved by -centre (in double, before the GPU's float32), or
// Error(Geometry) where a vertex then lies beyond what float32 places within
// 1/16 px (tolerance::kMaxGpuCoordinatePx at `scale` px per unit).
Mesh relative_to(Mesh mesh, Vec2 centre, double scale) {
  double reach = 0.0;
  for (Vec2& p : mesh.points) {
    p = p - centre;
    reach = std::max({reach, std::abs(p.x), std::abs(p.y)});
  }
  if (reach * scale > tolerance::kMaxGpuCoordinatePx) {
    throw Error(ErrorCode::Geometry, "a shape reaches " + detail::format_number(reach * scale) +
                                         " px from the view's centre at this scale; the GPU's float32 places "
                                         "geometry within 1/16 px only within " +
                                         detail::format_number(tolerance::kMaxGpuCoordinatePx) +
                                         " px (crop the shape to the view or draw it smaller)");
  }
  return mesh;
}

}  // namespace

Image render_shape_image(Renderer& renderer, const ShapeDocument& doc, const ShapeImageLayout& layout,
                         const ShapeImageOptions& options) {
  // docs/design.md section 3: 1/16 px at the scale drawn, in document units.
  const double tolerance = tolerance::kCubicApproximationPx / (layout.placement.scale * layout.largest_stretch);
  // Meshes first: geometry errors surface before anything is drawn.
  // Each mesh relative to the view's centre, the placement moved to match.
  const Vec2 centre = view_centre(layout);
  std::vector<Mesh> meshes;
  for (const Shape& shape : doc.shapes) {
    MeshOptions mo;
    mo.cubic_tolerance = tolerance;
    meshes.push_back(relative_to(build_mesh(fill_outline(shape, tolerance), mo), centre,
                                 layout.placement.scale * layout.largest_stretch));
  }
  Placement placement = layout.placement;
  placement.origin_x += placement.scale * centre.x;
  placement.origin_y -= placement.scale * centre.y;
  check_coverage_gamma(options.gamma);
  ImageTarget target;
  target.begin(layout.width, layout.height, options.background, options.blending);
  for (std::size_t i = 0; i < meshes.size(); ++i) {
    if (meshes[i].empty()) continue;
    DrawBatch batch = DrawBatch::from_mesh(meshes[i]);
    DrawOptions draw = draw_options(options, doc.shapes[i].color, on_screen_size(doc.shapes[i], layout));
    // The mesh is relative to the view's centre: the gradient's map from
    // document coordinates moved with it.
    std::optional<Gradient> gradient = doc.shapes[i].gradient;
    if (gradient) {
      gradient->from_outline = gradient->from_outline * Transform::translation(centre.x, centre.y);
      draw.gradient = &*gradient;
    }
    renderer.draw(batch, placement, draw);
  }
  return target.read_pixels();
}

}  // namespace curvetext
