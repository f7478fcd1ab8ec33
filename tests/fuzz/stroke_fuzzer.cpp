// Stroke styles and paths -> stroke_outline -> the outline's invariants
// (and, for small outlines when the mode asks, build_mesh and the mesh's). The input is a style (join, cap, width unit,
// width, miter limit, dash array, offset, pathLength, tolerance: any doubles, through fuzz_support.hpp's Input::number)
// and then path operations making open or closed contours of lines, conics and cubics.
#include <algorithm>
#include <vector>

#include "curvetext/stroke.hpp"
#include "curvetext/tolerances.hpp"
#include "fuzz_support.hpp"

namespace {

constexpr int kMaxOperations = 64;  // keeps each input's work small
constexpr std::size_t kMaxDashes = 16;
// Outlines above this many segments are not meshed (the mesher has its own
// fuzz target; this one is about the stroker).
constexpr std::size_t kMaxMeshedSegments = 64;

// One call site for Input::number: GCC 12 inlining it at each of many
// sites warns (-Wstringop-overflow) about raw_double's byte loop.
[[gnu::noinline]] double number(curvetext::fuzz::Input& in) { return in.number(); }

curvetext::Vec2 point(curvetext::fuzz::Input& in) {
  const double x = number(in);
  return {x, number(in)};
}

curvetext::StrokeStyle read_style(curvetext::fuzz::Input& in) {
  using namespace curvetext;
  StrokeStyle st;
  const std::uint8_t kinds = in.byte();
  st.join = static_cast<LineJoin>(kinds % 5);
  st.cap = static_cast<LineCap>((kinds / 5) % 3);
  st.width_unit = static_cast<StrokeWidthUnit>((kinds / 15) % 3);
  st.width = number(in);
  if (kinds & 0x80) st.miter_limit = number(in);
  const std::size_t dashes = in.byte() % (kMaxDashes + 1);
  for (std::size_t i = 0; i < dashes; ++i) st.dashes.push_back(number(in));
  if (dashes > 0) {
    st.dash_offset = number(in);
    if (in.byte() & 1) st.path_length = number(in);
  }
  return st;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace curvetext;
  fuzz::Input in(data, size);
  const StrokeStyle style = read_style(in);
  const std::uint8_t mode = in.byte();
  // A tolerance relative to the path (most inputs) or any number.
  const double any_tolerance = mode & 1 ? number(in) : 0.0;
  const double px_per_unit = mode & 2 ? number(in) : 1.0;
  std::vector<ShapeContour> path;
  Vec2 pen{};
  double reach = 0.0;
  for (int op = 0; op < kMaxOperations && !in.empty(); ++op) {
    const std::uint8_t kind = in.byte();
    if (path.empty() || kind % 6 == 0) {
      path.push_back({});
      path.back().closed = kind & 0x40;
      if (kind % 6 == 0) pen = point(in);
      continue;
    }
    std::vector<RationalBezier>& pieces = path.back().pieces;
    if (kind % 6 <= 2) {
      const Vec2 p = point(in);
      pieces.push_back(RationalBezier::line(pen, p));
      pen = p;
    } else if (kind % 6 <= 4) {
      const Vec2 c = point(in), p = point(in);
      pieces.push_back(RationalBezier::conic(pen, c, p, kind & 0x80 ? number(in) : 1.0));
      pen = p;
    } else {
      const Vec2 c1 = point(in), c2 = point(in), p = point(in);
      pieces.push_back(RationalBezier::cubic(pen, c1, c2, p));
      pen = p;
    }
    for (const Vec2 q : pieces.back().points) reach = std::max({reach, std::abs(q.x), std::abs(q.y)});
  }
  const double tolerance = mode & 1 ? any_tolerance : std::max(reach, 1.0) * (mode & 4 ? 1e-4 : 1e-2);
  Outline outline;
  try {
    outline = stroke_outline(path, style, tolerance, px_per_unit);
  } catch (const Error&) {
    return 0;
  }
  // The stroker's own invariants: closed contours of finite points (for
  // input the stroker accepts, whose coordinates are bounded), within its
  // segment budget, with a winding that is nowhere negative (every loop
  // sweeps counter-clockwise), so a total signed area >= 0.
  std::size_t segments = 0;
  double reach_out = 0.0;
  for (const Contour& c : outline.contours()) {
    segments += c.segments.size();
    if (c.segments.empty()) fuzz::fail("empty contour");
    for (std::size_t i = 0; i + 1 < c.segments.size(); ++i)
      if (!(c.segments[i].end() == c.segments[i + 1].start())) fuzz::fail("contour not continuous");
    if (!(c.segments.back().end() == c.segments.front().start())) fuzz::fail("contour not closed");
    for (const Segment& s : c.segments)
      for (const Vec2& p : s.p) reach_out = std::max({reach_out, std::abs(p.x), std::abs(p.y)});
  }
  if (segments > tolerance::kMaxStrokeSegments) fuzz::fail("stroke over its segment budget");
  if (!outline.is_finite()) fuzz::fail("stroke not finite");
  if (outline.signed_area() < -1e-9 * std::max(1.0, reach_out * reach_out)) fuzz::fail("negative stroke area");
  // Meshing: small outlines only (build_mesh has its own target, and its
  // self-check spends seconds under ASan on arcs lying on each other, which
  // round caps and dots make: corpus/stroke/*-meshed replay three).
  if (segments > kMaxMeshedSegments || !(mode & 16)) return 0;
  fuzz::mesh_and_check(outline, 0.25, false);
  return 0;
}
