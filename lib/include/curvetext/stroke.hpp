// Strokes as fills: a path (shapes.hpp contours, open or closed) and a
// StrokeStyle (stroke_style.hpp) become an Outline whose NONZERO fill is the
// stroke region, meshed by build_mesh (mesh.hpp) like any fill. The outline
// is a set of closed loops (the offset sides of each subpath or dash with its
// joins and caps; piece by piece where the stroke is wider than a curve's
// radius of curvature), all oriented so that the region they sweep has
// winding of one sign; they overlap each other at inner joins, cusps and
// where the path crosses itself, and build_mesh's nonzero union resolves
// that.
//
// What is exact: lines and their offsets; round joins and round caps (circle
// arcs as rational quadratics); the offsets of circular arcs (the concentric
// arc); miter, bevel and square geometry. Approximated within `tolerance`
// (the sampled Hausdorff distance between the fitted conics and the true
// offset curve, subdividing until it holds): offsets of every other conic;
// cubics and higher degrees are first turned into conics within half the
// tolerance and their offsets fitted within the other half. Dash ends lie at
// the arc length the pattern asks for within tolerance::kStrokeDashLengthOfTolerance
// times `tolerance` (numerical integration). docs/strokes.md has the model and
// its limits.
//
// Units: the path's units (document units for shapes), tolerance included.
// Device and hairline widths (StrokeWidthUnit) are converted with
// `px_per_unit`, the scale the stroke will be drawn at (for an anisotropic
// or projective transform, its largest stretch: the stroke is then at most
// that wide on screen).
//
// Errors: Error(InvalidArgument) for a tolerance or px_per_unit that is not
// positive and finite, a tolerance below
// tolerance::kMinStrokeToleranceRelative of the path's reach, a non-finite
// width, miter limit, dash value, dash offset or pathLength, or a path the
// shape readers would refuse (append_quadratics' errors);
// Error(Geometry) when the stroke would need more than
// tolerance::kMaxStrokeSegments segments (a dash pattern of millions of
// dashes, a width far beyond the path's size at a tiny tolerance): bounded
// time and memory, never a partial outline.
// Thread safety: stroke_outline is a pure function; a Stroker serves one call
// at a time (separate Strokers on separate threads).
#pragma once

#include <cstddef>
#include <vector>

#include "curvetext/export.hpp"
#include "curvetext/outline.hpp"
#include "curvetext/shapes.hpp"
#include "curvetext/stroke_style.hpp"
#include "curvetext/tolerances.hpp"
#include "curvetext/transform.hpp"

namespace curvetext {

// The width in the path's units: style.width for User, style.width /
// px_per_unit for Device, 1 / px_per_unit for Hairline. 0 when nothing is
// stroked (width <= 0, except for hairlines).
CURVETEXT_API double stroke_width_in_units(const StrokeStyle& style, double px_per_unit);

// Device-pixel and hairline widths depend on the scale a stroke is drawn
// at. To zoom without rebuilding every frame, build at stroke_build_scale()
// and rebuild only when it changes: scales are cut into geometric buckets
// of ratio (1 + 2 tolerance_px / w)^2 (w the width in device pixels), each
// built at its geometric middle, so that a stroke drawn anywhere in its
// bucket is within tolerance_px per side of the width asked for (1/64 px
// and a 1 px width: a bucket per 6.3% of zoom, 11 rebuilds per doubling).
// User widths return px_per_unit unchanged (they never need a rebuild for
// their width). Throws Error(InvalidArgument) for a px_per_unit or
// tolerance_px that is not positive and finite. Pure function.
CURVETEXT_API double stroke_build_scale(const StrokeStyle& style, double px_per_unit,
                                        double tolerance_px = tolerance::kStrokeOffsetPx);

// Strokes paths, keeping its scratch memory (the flattened path, the two
// offset sides, the dash being built) between calls, so that stroking many
// paths reuses it (strokes wider than a curve's radius of curvature still
// allocate their loops). A value: copies share nothing.
class CURVETEXT_API Stroker {
 public:
  // Appends the loops of the stroke of `contours` to `out` (see the header
  // comment for units, exactness and errors). A ShapeContour with
  // closed == false gets caps at its ends; a closed one gets a join where it
  // starts. On an error `out` is left as it was.
  void stroke(const std::vector<ShapeContour>& contours, const StrokeStyle& style, double tolerance, double px_per_unit,
              Outline& out);

 private:
  struct Run;                          // the state of one call (stroker.cpp)
  std::vector<Segment> path_;          // every subpath as lines and conics
  std::vector<std::size_t> subpaths_;  // where each subpath starts in path_, and path_.size()
  std::vector<unsigned char> closed_;  // per subpath
  std::vector<double> lengths_;        // arc length of each segment of path_
  std::vector<Segment> piece_;         // one dash being built
  std::vector<Segment> first_dash_;    // a closed subpath's first dash, joined to its last
  std::vector<Segment> right_;         // the right side of what is outlined, forward
  std::vector<Segment> left_;          // its left side, forward (added reversed)
  std::vector<Segment> cap_;           // a cap, join or dot
  Outline staged_;                     // the call's loops until it succeeds
};

// A Stroker's stroke into a new Outline.
CURVETEXT_API Outline stroke_outline(const std::vector<ShapeContour>& contours, const StrokeStyle& style,
                                     double tolerance, double px_per_unit = 1.0);

// The stroke of `contours` (document units) whose style is in a user space
// that `user_to_document` (affine and invertible: an SVG element's transform
// that scales unevenly or skews) maps into document units, as SVG defines
// strokes: the contours are mapped back into user space, stroked there, and
// the stroke's outline mapped forward. Both maps are exact (affine maps keep
// lines lines and conics conics), so the width varies with direction as the
// map says. The offsets are fitted within tolerance / (the map's largest
// stretch) in user space, so within `tolerance` after the map. Device and
// hairline widths are not user-space lengths: they are stroked in document
// units as stroke_outline does. Throws stroke_outline's errors and
// Error(InvalidArgument) for a map that is not affine, finite and invertible
// (Transform::validate).
CURVETEXT_API Outline stroke_outline_mapped(const std::vector<ShapeContour>& contours, const StrokeStyle& style,
                                            const Transform& user_to_document, double tolerance,
                                            double px_per_unit = 1.0);

}  // namespace curvetext
