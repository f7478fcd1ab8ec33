// 2D shapes (paper Figures 2 and 5: CAD-like outlines with weights): a shape
// document is a list of shapes, each made of contours of rational Bezier
// pieces, with a fill (rule and colour) and optionally a stroke
// (stroke_style.hpp; stroke.hpp builds its region). Two inputs:
//  - JSON with NURBS curves (any degree, weights, knot vector) and lines
//    (docs/shapes/README.md gives the format);
//  - SVG path data (M L H V Q T C S A Z) and SVG documents (docs/svg.md).
// Exact where it can be: lines, quadratic NURBS/Beziers (rational or not) and
// SVG elliptical arcs become exact rational quadratics (docs/design.md section 3).
// Polynomial cubics use cubic_to_quadratics (curves.hpp); rational cubics and
// every degree >= 4 are approximated by conics within the caller's tolerance.
// No GL here: shape_image.hpp draws documents. Everything here is a value
// type or a pure function (thread-safe, export.hpp).
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "curvetext/color.hpp"
#include "curvetext/export.hpp"
#include "curvetext/outline.hpp"
#include "curvetext/paint.hpp"
#include "curvetext/stroke_style.hpp"
#include "curvetext/transform.hpp"

namespace curvetext {

// A rational Bezier piece of degree points.size() - 1 >= 1, in homogeneous
// form sum(w_i B_i(t) p_i) / sum(w_i B_i(t)). Every weight is > 0, except
// the middle weight of a quadratic, which may be 0 (the piece is its chord,
// docs/design.md section 3).
struct CURVETEXT_API RationalBezier {
  std::vector<Vec2> points;
  std::vector<double> weights;
  int degree() const { return static_cast<int>(points.size()) - 1; }
  bool is_polynomial() const;  // all weights equal
  static RationalBezier line(Vec2 a, Vec2 b);
  static RationalBezier conic(Vec2 a, Vec2 control, Vec2 b, double weight);
  static RationalBezier cubic(Vec2 a, Vec2 c1, Vec2 c2, Vec2 b);
};

// The point at t in [0, 1]; the curve must be valid (validate_nurbs's rules).
CURVETEXT_API Vec2 evaluate(const RationalBezier& curve, double t);
// De Casteljau in homogeneous coordinates: both halves are exact.
CURVETEXT_API std::pair<RationalBezier, RationalBezier> split(const RationalBezier& curve, double t);

// A contour: pieces[i] ends where pieces[i+1] starts. A fill always closes
// it, joining the last piece to the first by a line when it does not end
// there. `closed` is for strokes (stroke.hpp): a closed contour is stroked
// with a join where it starts (and its closing line, if any); an open one
// (an SVG subpath without Z) gets caps at both ends.
struct ShapeContour {
  std::vector<RationalBezier> pieces;
  bool closed = true;
};

// A shape's stroke: its style and its paint. stroke-opacity is the colour's
// alpha (multiplied in by the readers).
struct ShapeStroke {
  StrokeStyle style;
  Color color{0, 0, 0, 1};
  // Where the style's lengths are in a user space other than document units
  // (an SVG element's transform that scales unevenly or skews): the affine
  // map from it to document units. The stroke is then built in user space
  // and mapped (stroke_outline_mapped in stroke.hpp). Identity: document
  // units.
  Transform user_to_document;
};

// SVG paint-order for what shapes have: fill then stroke (the default), or
// stroke under the fill.
enum class PaintOrder { FillStroke, StrokeFill };

struct Shape {
  std::vector<ShapeContour> contours;
  FillRule fill_rule = FillRule::NonZero;
  Color color{0, 0, 0, 1};  // the fill's
  // Paints the fill instead of `color` when set; its from_outline maps
  // document coordinates (y-up) to the gradient's.
  std::optional<Gradient> gradient;
  bool filled = true;  // false: SVG fill="none"; the shape draws only its stroke
  std::optional<ShapeStroke> stroke;
  PaintOrder paint_order = PaintOrder::FillStroke;
  // Paints the stroke instead of its colour when set (as `gradient` the fill).
  std::optional<Gradient> stroke_gradient;
};

// Shapes drawn as one layer, then composited (SVG's group opacity and
// clip-path): shapes [begin, end) of the document are drawn into an
// offscreen layer, which is multiplied by the coverage of `clip` (when it
// has shapes: the union of their fills, colours unused) and composited
// source-over at `opacity`. Groups nest: two groups' ranges are disjoint or
// one holds the other.
struct ShapeGroup {
  std::size_t begin = 0, end = 0;
  float opacity = 1.0f;
  std::vector<Shape> clip;
};

// Coordinates are y-up (SVG's y-down input is mirrored when read).
struct ShapeDocument {
  std::vector<Shape> shapes;
  // Sorted by begin, a group before the groups it holds.
  std::vector<ShapeGroup> groups;
  // The region to draw, in document units, y-up. Empty: the control box of
  // every shape.
  Box view;
  // Intrinsic image size in pixels (SVG width/height, JSON "size"); 0 when
  // the document does not say.
  double width_px = 0.0;
  double height_px = 0.0;
};

// --- NURBS ----------------------------------------------------------------------
// A NURBS curve: degree p >= 1, n + 1 = points.size() >= p + 1 control points,
// weights (empty = all 1), and n + p + 2 knots, non-decreasing, with interior
// multiplicity <= p. Clamped or not: the curve is the part over
// [knots[p], knots[n + 1]].
struct Nurbs {
  int degree = 0;
  std::vector<Vec2> points;
  std::vector<double> weights;
  std::vector<double> knots;
};

// Throws Error(InvalidArgument) naming the problem (bad degree, counts, knot
// order or multiplicity, NaN/inf/huge values, weights <= 0 except 0 at an
// interior point of degree 2; nurbs_to_beziers refuses a 0 that lands on a
// piece's end and turns a piece whose middle weight is 0 into its chord).
CURVETEXT_API void validate_nurbs(const Nurbs& curve);

// Exact conversion into rational Bezier pieces of the same degree, one per
// non-empty knot span of the domain. Each piece's control points are the
// blossoms (polar values) of the span's end knots: the same points Boehm's
// knot insertion gives after raising every knot to multiplicity p, computed
// in homogeneous coordinates (so rational curves stay exact).
CURVETEXT_API std::vector<RationalBezier> nurbs_to_beziers(const Nurbs& curve);

// Largest absolute coordinate accepted anywhere in shape input (document
// units). Beyond it double precision leaves too few bits for 1/16 px at any
// useful zoom, and squared lengths approach overflow.
inline constexpr double kMaxShapeCoordinate = 1e9;
// Degree above which NURBS input is refused (the homogeneous de Casteljau and
// blossoms are O(p^2) per piece; nothing real needs more).
inline constexpr int kMaxNurbsDegree = 16;

// --- Lines and conics -------------------------------------------------------------
// Appends lines and conics for `curve`: exact for degree 1 and 2 (conics
// normalised to end weights 1, w = w1 / sqrt(w0 w2)); polynomial cubics
// through cubic_to_quadratics(tolerance); rational cubics and degree >= 4 by
// adaptive subdivision, each piece replaced by the conic with the same end
// points and end tangents through the piece's midpoint, accepted when the
// estimated distance (first-order implicit distance at 33 sample points per
// piece, with a 1.5x safety factor) is <= tolerance.
// `tolerance` is in document units. Throws Error(InvalidArgument) for a piece
// with fewer than 2 points, a weight count that differs, or a tolerance that
// is not positive; Error(Geometry) when that would need more than
// kMaxConicsPerCurve pieces.
CURVETEXT_API void append_quadratics(const RationalBezier& curve, double tolerance, std::vector<Segment>& out);
inline constexpr int kMaxConicsPerCurve = 4096;

// The shape's contours as lines and conics (see append_quadratics, whose
// errors it throws).
CURVETEXT_API Outline shape_outline(const Shape& shape, double tolerance);

// An outline whose NONZERO fill is the shape's fill: the shape's own outline
// for FillRule::NonZero; for EvenOdd, even_odd_to_nonzero of it. Throws the
// errors of both.
CURVETEXT_API Outline fill_outline(const Shape& shape, double tolerance);

// Re-expresses the even-odd fill of an outline of lines and conics as an
// outline whose nonzero fill is the same region. Every segment is split
// where it crosses or touches another (or itself); each piece is then
// oriented so that the side with odd winding is on its left, and the pieces
// are chained into closed contours. Exact in the geometry (pieces of conics
// are exact sub-conics); the crossing points are computed in double
// precision (relative error ~1e-12 of the outline's size). O(n^2) box tests
// for n segments. Pieces between the same two points along the same curve
// cancel in pairs; segments overlapping only in part (collinear lines, arcs
// of one circle) are not resolved: fill_boundary (mesh.hpp) with
// FillRule::EvenOdd does that, in O((n + k) log n), through build_mesh's
// crossing resolution. Throws
// Error(InvalidArgument) for an outline with cubics, Error(Geometry) for
// non-finite values.
CURVETEXT_API Outline even_odd_to_nonzero(const Outline& outline);

// --- Input ------------------------------------------------------------------------
// Every reader checks every value (finite, within kMaxShapeCoordinate,
// weights as validate_nurbs says) and throws Error(InvalidArgument) naming
// the problem, with "line L, column C" for JSON syntax errors.
// The JSON format of docs/shapes/README.md (NURBS curves and lines).
CURVETEXT_API ShapeDocument parse_shape_json(std::string_view text);
// SVG path data in its own coordinates (no mirroring). Arcs become exact conics.
CURVETEXT_API std::vector<ShapeContour> parse_svg_path(std::string_view d);
// An SVG document: the static subset icons and drawings use (docs/svg.md):
// shapes and paths, transforms, viewBox, <use>/<symbol>/<defs>, the CSS
// cascade of <style> sheets, style and presentation attributes, colours,
// gradients, strokes, opacity and clip paths (ShapeGroup), markers. Every
// part it does not draw (filters, masks, text, ...) is refused by name with
// its line and column, never dropped.
struct SvgOptions {
  // The value of `currentColor` where the document does not set `color`
  // (icon themes leave it to the toolkit: its text colour).
  Color current_color{0, 0, 0, 1};
};
CURVETEXT_API ShapeDocument parse_svg(std::string_view text, const SvgOptions& options);
CURVETEXT_API ShapeDocument parse_svg(std::string_view text);
// By extension: .json or .svg (any case). Throws Error(Io) when unreadable,
// Error(InvalidArgument) for another extension, and the readers' errors
// prefixed with the path.
CURVETEXT_API ShapeDocument read_shape_file(const std::string& path, const SvgOptions& options);
CURVETEXT_API ShapeDocument read_shape_file(const std::string& path);

}  // namespace curvetext
