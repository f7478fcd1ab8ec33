// Where SVG places markers on a path: its vertices and the directions
// orient="auto" gives them (svg_reader.hpp).
#include <cmath>
#include <numbers>

#include "svg_reader.hpp"

namespace curvetext::svg {

namespace {

// The direction a piece leaves its start and reaches its end (the first and
// last control points apart from the end points); nullopt for a point.
std::optional<Vec2> start_direction(const RationalBezier& b) {
  for (std::size_t i = 1; i < b.points.size(); ++i)
    if (!(b.points[i] == b.points[0])) return b.points[i] - b.points[0];
  return std::nullopt;
}
std::optional<Vec2> end_direction(const RationalBezier& b) {
  const Vec2 end = b.points.back();
  for (std::size_t i = b.points.size() - 1; i-- > 0;)
    if (!(b.points[i] == end)) return end - b.points[i];
  return std::nullopt;
}

// SVG's auto orientation: the bisector of the directions in and out, one of
// them where the other is missing, 0 without either; and each alone.
MarkerVertex vertex(Vec2 at, std::optional<Vec2> in, std::optional<Vec2> out) {
  if (!in) in = out;
  if (!out) out = in;
  if (!in) return {at, 0.0, 0.0, 0.0};
  const double a = std::atan2(in->y, in->x), b = std::atan2(out->y, out->x);
  double d = b - a;
  if (d > std::numbers::pi) d -= 2 * std::numbers::pi;
  if (d <= -std::numbers::pi) d += 2 * std::numbers::pi;
  return {at, a + 0.5 * d, a, b};
}

}  // namespace

std::vector<MarkerVertex> marker_vertices(const std::vector<ShapeContour>& contours) {
  std::vector<MarkerVertex> out;
  for (const ShapeContour& c : contours) {
    if (c.pieces.empty()) continue;
    std::vector<RationalBezier> segs = c.pieces;
    const Vec2 start = segs.front().points.front();
    if (c.closed && !(segs.back().points.back() == start))
      segs.push_back(RationalBezier::line(segs.back().points.back(), start));  // the closing segment
    // A closed subpath's first and last vertex take its closing segment in and its first segment out.
    const std::optional<Vec2> closing_in = c.closed ? end_direction(segs.back()) : std::nullopt;
    out.push_back(vertex(start, closing_in, start_direction(segs.front())));
    for (std::size_t k = 1; k < segs.size(); ++k)
      out.push_back(vertex(segs[k].points.front(), end_direction(segs[k - 1]), start_direction(segs[k])));
    const std::optional<Vec2> last_out = c.closed ? start_direction(segs.front()) : std::nullopt;
    out.push_back(vertex(segs.back().points.back(), end_direction(segs.back()), last_out));
  }
  return out;
}

}  // namespace curvetext::svg
