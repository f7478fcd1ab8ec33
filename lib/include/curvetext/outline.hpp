// The outline model: closed contours made of lines, rational quadratic
// segments and cubics, in any unit (font units for glyphs). It describes any
// 2D shape, not only glyphs. The fill rule is nonzero winding over all
// contours. Cubics are kept as given; curves.hpp turns them into quadratics
// within a tolerance the caller states.
#pragma once

#include <cstdint>
#include <vector>

#include "curvetext/export.hpp"
#include "curvetext/geometry.hpp"

namespace curvetext {

// Which points an outline fills: winding number != 0 (NonZero) or odd
// (EvenOdd), as SVG's fill-rule.
enum class FillRule { NonZero, EvenOdd };

struct CURVETEXT_API Segment {
  enum class Kind : std::uint8_t { Line, Conic, Cubic };
  Kind kind = Kind::Line;
  // Line: p[0] -> p[1].  Conic: p[0], control p[1], p[2], middle weight
  // `weight` (end weights are 1; weight 1 is a parabola, < 1 an ellipse arc,
  // > 1 a hyperbola arc).  Cubic: p[0], p[1], p[2], p[3].
  Vec2 p[4];
  double weight = 1.0;

  static Segment line(Vec2 a, Vec2 b);
  static Segment conic(Vec2 a, Vec2 control, Vec2 b, double weight = 1.0);
  static Segment cubic(Vec2 a, Vec2 c1, Vec2 c2, Vec2 b);

  Vec2 start() const { return p[0]; }
  Vec2 end() const;
};

// A closed contour: segments[i].end() == segments[i+1].start(), and the last
// segment ends where the first starts.
struct Contour {
  std::vector<Segment> segments;
};

// A value type (copyable, movable). Values are not checked while building:
// is_finite() says whether they can be drawn, and build_mesh refuses those
// that cannot.
class CURVETEXT_API Outline {
 public:
  // Path builder. Every contour is closed: move_to() or close() closes the
  // current one with a line when its end is not its start. A drawing call
  // without move_to() starts a contour at the pen (the last point, else
  // (0,0)); zero-length lines are dropped.
  void move_to(Vec2 p);
  void line_to(Vec2 p);
  void conic_to(Vec2 control, Vec2 p, double weight = 1.0);
  void cubic_to(Vec2 c1, Vec2 c2, Vec2 p);
  void close();
  // Removes every contour. Their storage is kept for the contours added next,
  // so a caller that fills one Outline glyph after glyph allocates nothing
  // once warm.
  void clear();

  // The contours so far; the one still open gets its closing line at close()
  // or the next move_to(). Edits through the mutable overload must keep
  // every contour closed.
  const std::vector<Contour>& contours() const { return contours_; }
  std::vector<Contour>& contours() { return contours_; }
  bool empty() const;
  bool has_cubics() const;
  // Smallest box containing every point of every segment (control points too).
  Box control_box() const;
  // Exact signed area (Green's theorem; exact for lines, conics and cubics),
  // positive for counter-clockwise contours in a y-up frame.
  double signed_area() const;
  // False when any coordinate or weight is NaN/inf or any weight is <= 0.
  bool is_finite() const;

 private:
  std::vector<Contour> contours_;
  std::vector<Contour> spare_;  // cleared contours whose storage move_to reuses
  Vec2 start_{};
  Vec2 pen_{};
  bool open_ = false;
};

}  // namespace curvetext
