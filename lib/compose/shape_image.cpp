// Shape documents to images: one mesh and one draw call per shape, in order,
// blended source-over (the renderer draws one colour per batch).
#include "curvetext/shape_image.hpp"

#include "curvetext/shape_drawing.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

#include "curvetext/error.hpp"
#include "curvetext/mesh.hpp"
#include "curvetext/stroke.hpp"
#include "curvetext/tolerances.hpp"
#include "compose/check_style.hpp"
#include "core/format.hpp"
#include "gpu/layers.hpp"

namespace curvetext {

namespace {

// Pixels of the longer side when neither the document nor the caller sizes
// the image.
constexpr double kDefaultLongSidePx = 512.0;

// How far a stroke in user units reaches past its path's control box: half
// its width, times the miter limit for miter joins (a miter's tip) or
// sqrt(2) for square caps (a corner). Device-pixel widths are not known
// before the scale is, and are left out.
double stroke_reach(const Shape& s) {
  if (!s.stroke || s.stroke->style.width_unit != StrokeWidthUnit::User || !(s.stroke->style.width > 0.0)) return 0.0;
  const StrokeStyle& st = s.stroke->style;
  double k = st.cap == LineCap::Square ? std::sqrt(2.0) : 1.0;
  if (st.join == LineJoin::Miter || st.join == LineJoin::MiterClip || st.join == LineJoin::Arcs)
    k = std::max(k, std::max(1.0, st.miter_limit));
  // A stroke built in a user space reaches as far as the map stretches it.
  const double reach = 0.5 * st.width * k * s.stroke->user_to_document.largest_stretch({0.0, 0.0});
  return std::isfinite(reach) ? reach : 0.0;
}

Box shape_box(const Shape& s) {
  Box box;
  for (const ShapeContour& c : s.contours)
    for (const RationalBezier& b : c.pieces)
      for (Vec2 p : b.points) box.add(p);
  const double r = stroke_reach(s);
  if (!box.empty() && r > 0.0) {
    box.add(box.min - Vec2{r, r});
    box.add(box.max + Vec2{r, r});
  }
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

namespace {

// One mesh to draw, in its colour.
struct Layer {
  Mesh mesh;
  Color color;
  std::size_t shape;
  const Gradient* gradient = nullptr;  // the fill's, instead of `color`
  bool overlaps = false;               // meshed in parts whose triangles overlap (a stroke's fallback)
};

// `part` added to `all` (its vertices renumbered after all's).
void append_mesh(Mesh& all, const Mesh& part) {
  const auto base = static_cast<std::uint32_t>(all.points.size());
  all.points.insert(all.points.end(), part.points.begin(), part.points.end());
  for (auto t : part.triangles) all.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  for (CurvedTriangle c : part.curves) {
    c.p0 += base;
    c.control += base;
    c.p2 += base;
    all.curves.push_back(c);
  }
  for (auto l : part.boundary_lines) all.boundary_lines.push_back({l[0] + base, l[1] + base});
}

// The shape's fill and stroke meshes in paint order (docs/strokes.md).
void shape_layers(const Shape& shape, std::size_t index, double tolerance, double px_per_unit, Vec2 centre,
                  double scale, std::vector<Layer>& out) {
  MeshOptions mo;
  mo.cubic_tolerance = tolerance;
  auto fill = [&] {
    if (shape.filled)
      out.push_back({relative_to(build_mesh(fill_outline(shape, tolerance), mo), centre, scale), shape.color, index,
                     shape.gradient ? &*shape.gradient : nullptr});
  };
  auto stroke = [&] {
    if (!shape.stroke) return;
    // docs/design.md section 8: offsets within tolerance::kStrokeOffsetPx at the drawn scale.
    const double stroke_tolerance = tolerance::kStrokeOffsetPx / px_per_unit;
    const Outline o = stroke_outline_mapped(shape.contours, shape.stroke->style, shape.stroke->user_to_document,
                                            stroke_tolerance, px_per_unit);
    if (o.empty()) return;
    const Gradient* gradient = shape.stroke_gradient ? &*shape.stroke_gradient : nullptr;
    try {
      out.push_back({relative_to(build_mesh(o, mo), centre, scale), shape.stroke->color, index, gradient});
    } catch (const Error& e) {
      // docs/strokes.md, limits: where the mesher's budget refuses the union
      // of many crossing subpaths, a stroke is meshed subpath by subpath
      // (and a subpath whose union is refused too, loop by loop: each loop
      // of a stroke outline is a region of its own) into one mesh whose
      // triangles overlap. The offscreen AA modes sum its coverage and
      // clamp it, so it draws the same pixels but for the antialiased edges
      // where parts cross; the single-pass modes would blend a translucent
      // one twice there, and refuse it (ShapeDrawing::draw).
      if (e.code() != ErrorCode::Geometry) throw;
      Mesh all;
      for (const ShapeContour& c : shape.contours) {
        const Outline one = stroke_outline_mapped({c}, shape.stroke->style, shape.stroke->user_to_document,
                                                  stroke_tolerance, px_per_unit);
        if (one.empty()) continue;
        try {
          append_mesh(all, build_mesh(one, mo));
        } catch (const Error& again) {
          if (again.code() != ErrorCode::Geometry) throw;
          for (const Contour& loop : one.contours()) {
            Outline single;
            single.contours().push_back(loop);
            append_mesh(all, build_mesh(single, mo));
          }
        }
      }
      out.push_back({relative_to(std::move(all), centre, scale), shape.stroke->color, index, gradient, true});
    }
  };
  if (shape.paint_order == PaintOrder::StrokeFill) {
    stroke();
    fill();
  } else {
    fill();
    stroke();
  }
}

}  // namespace

// --- ShapeDrawing ---------------------------------------------------------------

namespace {

// Throws Error(InvalidArgument) for groups outside the document, out of
// order, overlapping without nesting, or with an opacity outside [0, 1].
void check_groups(const ShapeDocument& doc) {
  if (doc.groups.size() > tolerance::kMaxShapeGroups)
    throw Error(ErrorCode::InvalidArgument, "more than " + std::to_string(tolerance::kMaxShapeGroups) +
                                                " shape groups (opacity, clip paths), each an offscreen pass");
  std::vector<std::size_t> ends;  // of the groups holding the current one
  std::size_t last_begin = 0;
  for (const ShapeGroup& g : doc.groups) {
    if (g.begin > g.end || g.end > doc.shapes.size() || g.begin < last_begin || !(g.opacity >= 0.0f) ||
        !(g.opacity <= 1.0f))
      throw Error(ErrorCode::InvalidArgument,
                  "a shape group must hold shapes [begin, end) of the document in order, with an opacity in [0, 1]");
    while (!ends.empty() && ends.back() <= g.begin) ends.pop_back();
    if (!ends.empty() && g.end > ends.back())
      throw Error(ErrorCode::InvalidArgument,
                  "shape groups must nest (two groups overlap without one holding the other)");
    ends.push_back(g.end);
    if (ends.size() > tolerance::kMaxShapeGroupDepth)
      throw Error(ErrorCode::InvalidArgument, "shape groups (opacity, clip paths) nested deeper than " +
                                                  std::to_string(tolerance::kMaxShapeGroupDepth));
    last_begin = g.begin;
  }
}

}  // namespace

struct ShapeDrawing::Layer {
  DrawBatch batch;
  Color color;
  double side = 0.0;                 // the shape's larger side, document units (for `auto`)
  std::optional<Gradient> gradient;  // from the mesh's units (relative to the centre)
  std::size_t shape = 0;             // its index in the document (for groups)
  bool overlaps = false;             // triangles overlap: translucent paint needs an offscreen AA mode
};

struct ShapeDrawing::Groups {
  struct Group {
    std::size_t begin = 0, end = 0;
    float opacity = 1.0f;
    bool clipped = false;     // multiplied by a clip's coverage (clip may be empty: nothing shows)
    std::vector<Layer> clip;  // fills drawn white into the clip's coverage mask
  };
  std::vector<Group> list;
  gpu::LayerPrograms programs;
};

ShapeDrawing::ShapeDrawing() : layers_(std::make_unique<std::vector<Layer>>()), groups_(std::make_unique<Groups>()) {}
ShapeDrawing::ShapeDrawing(ShapeDrawing&&) noexcept = default;
ShapeDrawing& ShapeDrawing::operator=(ShapeDrawing&&) noexcept = default;
ShapeDrawing::~ShapeDrawing() = default;

std::size_t ShapeDrawing::layer_count() const { return layers_->size(); }

ShapeDrawing ShapeDrawing::from_document(const ShapeDocument& doc, double px_per_unit) {
  if (!std::isfinite(px_per_unit) || !(px_per_unit > 0.0))
    throw Error(ErrorCode::InvalidArgument,
                "pixels per unit must be positive and finite, got " + detail::format_number_exact(px_per_unit));
  ShapeDrawing d;
  d.px_per_unit_ = px_per_unit;
  const Box view = doc.view.empty() ? content_box(doc) : doc.view;
  if (!view.empty()) d.centre_ = 0.5 * (view.min + view.max);
  // docs/design.md section 3: 1/16 px at the scale drawn, in document units.
  const double tolerance = tolerance::kCubicApproximationPx / px_per_unit;
  check_groups(doc);
  // Meshes first: geometry errors surface before anything is uploaded.
  std::vector<::curvetext::Layer> layers;
  for (std::size_t i = 0; i < doc.shapes.size(); ++i)
    shape_layers(doc.shapes[i], i, tolerance, px_per_unit, d.centre_, px_per_unit, layers);
  for (const ::curvetext::Layer& l : layers) {
    if (l.mesh.empty()) continue;
    const Box b = shape_box(doc.shapes[l.shape]);
    Layer out{DrawBatch::from_mesh(l.mesh),
              l.color,
              b.empty() ? 0.0 : std::max(b.max.x - b.min.x, b.max.y - b.min.y),
              std::nullopt,
              l.shape,
              l.overlaps};
    if (l.gradient) {
      // The mesh is relative to the centre: the gradient's map from
      // document coordinates moved with it.
      out.gradient = *l.gradient;
      out.gradient->from_outline = out.gradient->from_outline * Transform::translation(d.centre_.x, d.centre_.y);
    }
    d.layers_->push_back(std::move(out));
  }
  for (const ShapeGroup& g : doc.groups) {
    Groups::Group out{g.begin, g.end, g.opacity, !g.clip.empty(), {}};
    for (const Shape& c : g.clip) {
      // The clip's geometry only: its fill, in white, is the coverage.
      Shape fill = c;
      fill.filled = true;
      fill.stroke.reset();
      fill.gradient.reset();
      std::vector<::curvetext::Layer> parts;
      shape_layers(fill, 0, tolerance, px_per_unit, d.centre_, px_per_unit, parts);
      const Box b = shape_box(fill);
      for (const ::curvetext::Layer& p : parts)
        if (!p.mesh.empty())
          out.clip.push_back(Layer{DrawBatch::from_mesh(p.mesh), Color{1, 1, 1, 1},
                                   b.empty() ? 0.0 : std::max(b.max.x - b.min.x, b.max.y - b.min.y), std::nullopt, 0});
    }
    d.groups_->list.push_back(std::move(out));
  }
  return d;
}

void ShapeDrawing::draw(Renderer& renderer, const Placement& at, const DrawOptions& options) const {
  Placement moved = at;
  moved.origin_x += at.scale * centre_.x;
  moved.origin_y -= at.scale * centre_.y;
  auto draw_one = [&](const Layer& l) {
    DrawOptions d = options;
    d.color = l.color;
    d.antialiasing = resolve_antialiasing(options.antialiasing, l.side * px_per_unit_);
    d.gradient = l.gradient ? &*l.gradient : nullptr;
    if (l.overlaps && (l.color.a < 1.0f || l.gradient) &&
        (d.antialiasing == AntiAliasing::None || d.antialiasing == AntiAliasing::Curves))
      throw Error(ErrorCode::InvalidArgument,
                  "a translucent stroke meshed in overlapping parts (the mesher refused its union) is drawn with "
                  "antialiasing full, vbaa or msaa only");
    renderer.draw(l.batch, moved, d);
  };
  const std::vector<Groups::Group>& groups = groups_->list;
  if (groups.empty()) {
    for (const Layer& l : *layers_) draw_one(l);
    return;
  }
  // Groups open (outer first) as their first mesh comes and close when a
  // mesh past their end does; groups without meshes are never opened.
  gpu::LayerStack stack(groups_->programs);
  std::vector<const Groups::Group*> open;
  auto close_before = [&](std::size_t shape) {
    while (!open.empty() && open.back()->end <= shape) {
      const Groups::Group& g = *open.back();
      if (g.clipped) {
        stack.push();
        for (const Layer& c : g.clip) draw_one(c);
        stack.apply_mask();
      }
      stack.pop(g.opacity);
      open.pop_back();
    }
  };
  std::size_t next = 0;
  for (const Layer& l : *layers_) {
    close_before(l.shape);
    for (; next < groups.size() && groups[next].begin <= l.shape; ++next)
      if (groups[next].end > l.shape) {
        stack.push();
        open.push_back(&groups[next]);
      }
    draw_one(l);
  }
  close_before(static_cast<std::size_t>(-1));
}

Image render_shape_image(Renderer& renderer, const ShapeDocument& doc, const ShapeImageLayout& layout,
                         const ShapeImageOptions& options) {
  const ShapeDrawing drawing = ShapeDrawing::from_document(doc, layout.placement.scale * layout.largest_stretch);
  DrawOptions draw = draw_options(options, Color{0, 0, 0, 1}, 0.0);
  draw.antialiasing = options.antialiasing;  // `auto` is resolved per shape by the drawing
  ImageTarget target;
  target.begin(layout.width, layout.height, options.background, options.blending);
  drawing.draw(renderer, layout.placement, draw);
  return target.read_pixels();
}

}  // namespace curvetext
