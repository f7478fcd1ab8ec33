// Bounded, checked mesh building on hostile and real-font input: tiny and
// huge coordinates, work budgets, and glyphs of Debian's fonts whose meshes
// (or whose reference areas) were wrong. Every build here either returns a
// mesh that passes check_mesh or throws curvetext::Error(Geometry).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "curvetext/curves.hpp"
#include "curvetext/error.hpp"
#include "curvetext/mesh.hpp"
#include "curvetext/outline.hpp"
#include "curvetext/tolerances.hpp"
#include "support/expect_error.hpp"
#include "tessellate/cleaning.hpp"
#include "tessellate/hull_separation.hpp"
#include "tessellate/resolve.hpp"
#include "tessellate/rings.hpp"
#include "tessellate/self_check.hpp"

namespace curvetext {
namespace {

// Outlines as text, one segment a line: "L", "Q" (weight 1) or "C", then the
// segment's points (start included) as x,y pairs (hex floats allowed);
// "contour" starts a contour.
Outline parse_outline(const std::string& text) {
  Outline outline;
  std::istringstream lines(text);
  std::string line;
  std::vector<Segment>* segments = nullptr;
  while (std::getline(lines, line)) {
    std::istringstream words(line);
    std::string kind;
    if (!(words >> kind)) continue;
    if (kind == "contour") {
      outline.contours().emplace_back();
      segments = &outline.contours().back().segments;
      continue;
    }
    std::vector<Vec2> points;
    for (std::string pair; words >> pair;) {
      const std::size_t comma = pair.find(',');
      points.push_back(
          {std::strtod(pair.substr(0, comma).c_str(), nullptr), std::strtod(pair.substr(comma + 1).c_str(), nullptr)});
    }
    if (kind == "L") segments->push_back(Segment::line(points[0], points[1]));
    if (kind == "Q") segments->push_back(Segment::conic(points[0], points[1], points[2]));
    if (kind == "C") segments->push_back(Segment::cubic(points[0], points[1], points[2], points[3]));
  }
  return outline;
}

// Builds and checks; returns the check (the build must not throw).
MeshCheck build_and_check(const Outline& outline, double tolerance) {
  const Mesh mesh = build_mesh(outline, {tolerance});
  MeshCheck check = check_mesh(mesh, to_quadratic_outline(outline, tolerance));
  for (const std::string& p : check.problems) ADD_FAILURE() << p;
  return check;
}

// A mesh that passes check_mesh, or Error(Geometry): nothing else may come
// out (no other exception, no mesh that breaks an invariant).
void expect_checked_or_refused(const Outline& outline, double tolerance) {
  try {
    const Mesh mesh = build_mesh(outline, {tolerance});
    const MeshCheck check = check_mesh(mesh, to_quadratic_outline(outline, tolerance));
    for (const std::string& p : check.problems) ADD_FAILURE() << p;
    EXPECT_TRUE(std::isfinite(check.area_outline));
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::Geometry) << e.what();
  }
}

// Two crossing contours near +-1e9 with subnormal (7.99e-315) and tiny
// (1e-300) coordinates, a cubic's control point among them. Before the
// coordinate rule, crossing resolution split without end (32 s, then
// std::bad_alloc under a 4 GiB cap); with the subnormals replaced by 0 it
// takes well under a millisecond.
const char* const kSubnormalBesideLarge = R"(
contour
 C -0x1.dcd65p+29,0x0p+0 -0x1.dcd65p+29,0x1.56e1fc2f8f359p-997 0x1.56e1fc2f8f359p-997,-0x1.dcd65p+29 0x1.56e1fc2f8f359p-997,0x0p+0
 L 0x1.56e1fc2f8f359p-997,0x0p+0 0x1.d84e0df389e1ap+29,0x1.56e1fc2f8f359p-997
 Q 0x1.d84e0df389e1ap+29,0x1.56e1fc2f8f359p-997 0x0p+0,0x1.dcd64ff8p+29 0x1.56e1fc2f8f359p-997,0x1.56e1fc2f8f359p-997
 L 0x1.56e1fc2f8f359p-997,0x1.56e1fc2f8f359p-997 -0x1.a6deb0276a33ep+29,0x1.dcd64ff8p+29
 L -0x1.a6deb0276a33ep+29,0x1.dcd64ff8p+29 0x0.0000060646c14p-1022,-0x1.bf144c4e646c9p+28
 L 0x0.0000060646c14p-1022,-0x1.bf144c4e646c9p+28 -0x1.dcd65p+29,0x0p+0
contour
 C 0x0.0000060646c14p-1022,0x0p+0 0x0p+0,-0x1.dcd65p+29 0x0p+0,0x0p+0 0x1.dcd64ff8p+29,0x1.dcd65p+29
 L 0x1.dcd64ff8p+29,0x1.dcd65p+29 0x0.0000060646c14p-1022,0x1.56e1fc2f8f359p-997
 Q 0x0.0000060646c14p-1022,0x1.56e1fc2f8f359p-997 0x1.bf5d55d07fe2ep+29,-0x1.dcd65p+29 -0x1.dcd65p+29,0x1.dcd65p+29
 L -0x1.dcd65p+29,0x1.dcd65p+29 0x0.0000060646c14p-1022,0x0p+0
)";

TEST(MeshLimits, SubnormalControlPointBesideLargeCoordinates) {
  const Outline outline = parse_outline(kSubnormalBesideLarge);
  const MeshCheck check = build_and_check(outline, 0.25);
  EXPECT_TRUE(check.ok());
  EXPECT_GT(check.area_outline, 0.0);
}

TEST(MeshLimits, TinyCoordinatesAreReadAsZero) {
  // The same triangle with and without coordinates below the flush
  // threshold (2^-64 of the largest, 1e9 here): the same mesh.
  auto triangle = [](double tiny) {
    Outline o;
    o.move_to({tiny, 0});
    o.line_to({1e9, tiny});
    o.cubic_to({1e9, 5e8}, {tiny, 1e9}, {0, 1e9});
    o.close();
    return o;
  };
  const Mesh flushed = build_mesh(triangle(7.99e-315), {0.25});
  const Mesh zero = build_mesh(triangle(0.0), {0.25});
  ASSERT_EQ(flushed.points.size(), zero.points.size());
  for (std::size_t i = 0; i < zero.points.size(); ++i) EXPECT_EQ(flushed.points[i], zero.points[i]);
  EXPECT_EQ(flushed.triangles, zero.triangles);
  // A coordinate above the threshold is kept.
  const Mesh kept = build_mesh(triangle(1e-3), {0.25});
  bool found = false;
  for (const Vec2 p : kept.points) found = found || p.x == 1e-3 || p.y == 1e-3;
  EXPECT_TRUE(found);
}

// Outlines drawn in tiny units keep their pieces: points are merged only when
// closer than a fraction of the outline's own size (the fuzz findings
// svg_path/triangle-1e-9-dropped and outline/empty-mesh-of-a-sliver, both
// meshed empty while their areas were 5e-19 and 5e-26).
TEST(MeshLimits, TinyOutlinesKeepTheirArea) {
  for (const double side : {1e-9, 1e-15, 1e-25}) {  // (below 1e-30 coordinates read as 0)
    Outline o;
    o.move_to({0, 0});
    o.line_to({side, 0});
    o.conic_to({side, side}, {0, side}, 0.7071067811865476);
    o.close();
    const MeshCheck check = build_and_check(o, 0.25);
    EXPECT_TRUE(check.ok()) << side;
    EXPECT_GT(check.area_mesh, 0.5 * side * side) << side;
  }
  const Outline sliver = parse_outline(R"(
contour
 L 0,0 -0x1p-50,0
 L -0x1p-50,0 0,0x1.008p-33
 L 0,0x1.008p-33 0,0
)");
  const MeshCheck check = build_and_check(sliver, 0.25);
  EXPECT_TRUE(check.ok());
  EXPECT_GT(check.area_mesh, 0.0);
}

// A conic whose weight is near 0 lies on its chord within the flatness
// tolerance: it is built as a line (a fuzz finding: weight 4.2e-309 gave a
// curved triangle of zero area after hull separation).
TEST(MeshLimits, ConicWithTinyWeightIsItsChord) {
  for (const double weight : {4.17744579392587e-309, 1e-20, 1e-12}) {
    Outline o;
    o.move_to({2, 0.5});
    o.line_to({100, 0});
    o.conic_to({0, 2}, {122, -15.375}, weight);
    o.close();
    const MeshCheck check = build_and_check(o, 0.25);
    EXPECT_TRUE(check.ok()) << weight;
    EXPECT_GT(check.area_mesh, 0.0) << weight;
  }
}

// A conic whose weight is so large that its shoulder is within the flatness
// tolerance of its control point is built as its two legs (a fuzz finding:
// weight 7.8e143 split into a curved triangle of zero area).
TEST(MeshLimits, ConicWithHugeWeightIsItsLegs) {
  for (const double weight : {7.773885550103301e+143, 1e30, 1e300}) {
    Outline o;
    o.move_to({-0.125, 0});
    o.conic_to({-0.0625, -31.9375}, {0, -1}, weight);
    o.close();
    o.move_to({119, -168.625});
    o.line_to({0, 0});
    o.close();
    const MeshCheck check = build_and_check(o, 0.25);
    EXPECT_TRUE(check.ok()) << weight;
    EXPECT_GT(check.area_mesh, 0.0) << weight;
  }
}

// A path that runs over itself n times: its n copies of each edge all meet,
// n^2 / 2 pairs. Hull separation pairs lines only with conics (two lines
// have no hull to separate) and stops looking at pairs of lines at their
// first crossing; the crossing resolver merges the copies into one edge
// each. 16,384 runs (65,536 segments) are built; before, hull separation
// tested the n^2 / 2 pairs of lines and refused from 1,024 runs on with
// Error(Geometry) ("pair tests").
namespace {

Outline retraced_square(int runs, bool back_and_forth) {
  Outline o;
  o.move_to({0, 0});
  for (int k = 0; k < runs; ++k) {
    if (back_and_forth && k % 2 == 1) {
      o.line_to({0, 1000});
      o.line_to({1000, 1000});
      o.line_to({1000, 0});
    } else {
      o.line_to({1000, 0});
      o.line_to({1000, 1000});
      o.line_to({0, 1000});
    }
    o.line_to({0, 0});
  }
  o.close();
  return o;
}

}  // namespace

TEST(MeshLimits, RetracedPathIsBuilt) {
  for (const int runs : {300, 16384}) {
    SCOPED_TRACE(runs);
    // Winding `runs` inside: the nonzero fill is the square.
    const MeshCheck check = build_and_check(retraced_square(runs, false), 0.25);
    EXPECT_TRUE(check.ok());
    EXPECT_DOUBLE_EQ(check.area_mesh, 1e6);
    EXPECT_DOUBLE_EQ(check.area_outline, 1e6);
  }
  // Run forward and back in turn: winding 0 inside, nothing to fill.
  const Mesh empty = build_mesh(retraced_square(16384, true));
  EXPECT_TRUE(empty.empty());
}

// A circle of 4 conics run `laps` times, as one contour or as one contour
// per lap; with `alternate`, every other lap runs backwards.
Outline retraced_circle(int laps, bool one_contour, bool alternate) {
  Outline o;
  const double w = std::sqrt(0.5), r = 1000;
  for (int k = 0; k < laps; ++k) {
    const double s = alternate && k % 2 ? -1 : 1;
    if (k == 0 || !one_contour) o.move_to({r, 0});
    o.conic_to({r, s * r}, {0, s * r}, w);
    o.conic_to({-r, s * r}, {-r, 0}, w);
    o.conic_to({-r, -s * r}, {0, -s * r}, w);
    o.conic_to({r, -s * r}, {r, 0}, w);
    if (!one_contour) o.close();
  }
  o.close();
  return o;
}

// Identical conics all meet, and hull separation would test their n^2 / 2
// pairs (1,024 laps stopped at its pair-test budget): cleaning folds equal
// rings into one with a count, which the crossing resolver's windings take.
TEST(MeshLimits, RetracedConicsAreBuilt) {
  const double disc = std::numbers::pi * 1e6;
  MeshOptions even_odd;
  even_odd.fill_rule = FillRule::EvenOdd;
  for (const bool one_contour : {true, false}) {
    SCOPED_TRACE(one_contour ? "one contour" : "a contour per lap");
    EXPECT_NEAR(mesh_area(build_mesh(retraced_circle(1024, one_contour, false))), disc, 1e-9 * disc);
    EXPECT_TRUE(build_mesh(retraced_circle(1024, one_contour, true)).empty());
    EXPECT_TRUE(build_mesh(retraced_circle(1024, one_contour, false), even_odd).empty());
    EXPECT_NEAR(mesh_area(build_mesh(retraced_circle(1023, one_contour, false), even_odd)), disc, 1e-9 * disc);
  }
  // Beside another contour the count matters: a disc run 300 times with a
  // smaller one run once backwards inside it leaves winding 299 there
  // (filled under nonzero), a disc run once would leave 0 (a hole).
  Outline ring = retraced_circle(300, false, false);
  ring.move_to({500, 0});
  ring.conic_to({500, -500}, {0, -500}, std::sqrt(0.5));
  ring.conic_to({-500, -500}, {-500, 0}, std::sqrt(0.5));
  ring.conic_to({-500, 500}, {0, 500}, std::sqrt(0.5));
  ring.conic_to({500, 500}, {500, 0}, std::sqrt(0.5));
  ring.close();
  EXPECT_NEAR(mesh_area(build_mesh(ring)), disc, 1e-9 * disc);
  Outline holed = retraced_circle(1, false, false);
  holed.contours().push_back(ring.contours().back());
  EXPECT_NEAR(mesh_area(build_mesh(holed)), 0.75 * disc, 1e-9 * disc);
}

// A stroke's outline (tests/fixtures/strokes/mesh_reproducers/
// retraced_line_empty_mesh.path): one contour round a capsule, then round
// its straight part again, through several vertices twice. Resolved unsplit
// it lost its whole fill (an empty mesh, no error); its loops resolve right.
TEST(MeshLimits, RingThroughItsVerticesTwiceKeepsItsFill) {
  Outline o;
  o.move_to({5.9241724601467469, 730.93026379988987});
  o.line_to({-0.49998068921386973, 0.0043943615262937762});
  o.conic_to({-0.50437505070742294, -0.49558632396242958}, {-0.0043943652514402288, -0.4999806891811292},
             0.70710678382072556);
  o.conic_to({0.49558632020454257, -0.50437505439982888}, {0.49998068914838861, -0.0043943689765866805},
             0.70710678382072556);
  o.line_to({9.499980689213869, 1023.9956056384738});
  o.conic_to({9.5043750507073668, 1024.4955863239625}, {9.0043943652513843, 1024.499980689181}, 0.70710678382072556);
  o.conic_to({8.5044136797954017, 1024.5043750543998}, {8.5000193108516129, 1024.0043943689766}, 0.70710678382072556);
  o.line_to({5.9241724601467478, 730.93026379988987});
  o.line_to({6.9241338385744875, 730.9214750768374});
  o.line_to({9.499980689213869, 1023.9956056384738});
  o.line_to({9, 1024});
  o.line_to({8.500019310786131, 1024.0043943615262});
  o.line_to({-0.49998068921386973, 0.0043943615262937771});
  o.line_to({0, 0});
  o.line_to({0.49998068921386973, -0.0043943615262937762});
  o.line_to({6.9241338385744866, 730.9214750768374});
  o.line_to({5.9241724601467469, 730.93026379988987});
  o.close();
  const double area = 1024.824948;  // check_mesh's reference area of the outline
  const Mesh mesh = build_mesh(o);
  EXPECT_NEAR(mesh_area(mesh), area, 1e-6);
  EXPECT_TRUE(check_mesh(mesh, o).ok());
  EXPECT_NEAR(fill_boundary(o, FillRule::NonZero).signed_area(), area, 1e-6);
}

// Hull separation halves a nearly straight arc until its last piece's
// control point lies exactly on the piece's chord: that piece is a line, not
// a curved triangle of zero area (a fuzz finding, from the outline below and
// from an SVG path with coordinates of 1e-200 read as 0).
// build_mesh's own check stops at the first stage that finds a problem (one
// is enough to refuse the mesh, and the hull-overlap search after the others
// is the slowest); check_mesh reports every stage. A circle's mesh with every
// face doubled: its area is twice the outline's, its edges are used by four
// faces, and its curved triangles overlap their copies.
TEST(MeshLimits, SelfCheckStopsAtTheFirstProblem) {
  const Outline disc = retraced_circle(1, true, false);
  Mesh doubled = build_mesh(disc);
  const std::size_t triangles = doubled.triangles.size(), curves = doubled.curves.size();
  for (std::size_t i = 0; i < triangles; ++i) doubled.triangles.push_back(doubled.triangles[i]);
  for (std::size_t i = 0; i < curves; ++i) doubled.curves.push_back(doubled.curves[i]);
  const MeshCheck all = check_mesh(doubled, disc);
  const MeshCheck first = detail::self_check(doubled, disc, FillRule::NonZero);
  ASSERT_FALSE(first.ok());
  for (const std::string& p : first.problems) EXPECT_EQ(p.rfind("area identity", 0), 0u) << p;
  EXPECT_GT(all.hull_overlaps, 0);
  EXPECT_FALSE(all.watertight);
  EXPECT_GT(all.problems.size(), first.problems.size());
}

TEST(MeshLimits, FlatPiecesOfSplitConicsAreLines) {
  Outline o;
  o.move_to({0.0625, -1});
  o.conic_to({0, 0}, {0, -1}, 2.875);
  o.conic_to({0, 3.843069862341508e-09}, {15.9375, -32}, 1.0);
  o.line_to({46, 0});
  o.close();
  const MeshCheck check = build_and_check(o, 0.25);
  EXPECT_TRUE(check.ok());
  EXPECT_EQ(check.degenerate, 0u);
}

// A hairpin conic (weight 14) whose second leg lies along the line that
// closes the contour: halving it rounds the child's control point a hair
// across that line, and hull separation must test the child against its ring
// neighbour again (a fuzz finding: curve 3 overlapped another face).
TEST(MeshLimits, HairpinConicClosedAlongItsLeg) {
  Outline o;
  o.move_to({0, 0});
  o.conic_to({0, -9}, {36, 0}, 8);
  o.conic_to({0, 0}, {11.75, -0.00024412572383880615}, 14.0);
  o.close();
  const MeshCheck check = build_and_check(o, 0.25);
  EXPECT_TRUE(check.ok());
  EXPECT_EQ(check.hull_overlaps, 0u);
}

TEST(MeshLimits, CoordinatesBeyondTheLimitAreRefused) {
  // 1e160: the outline's area (and orient2d's products) overflow to infinity.
  for (const double big : {2 * tolerance::kMaxMeshCoordinate, 1e160}) {
    Outline o;
    o.move_to({0, 0});
    o.line_to({big, 0});
    o.line_to({0, big});
    o.close();
    try {
      (void)build_mesh(o);
      ADD_FAILURE() << "no error for coordinate " << big;
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), ErrorCode::Geometry);
      EXPECT_NE(std::string(e.what()).find("beyond the largest accepted"), std::string::npos) << e.what();
    }
    // check_mesh reports it instead of comparing infinite areas.
    EXPECT_FALSE(check_mesh(Mesh{}, o).ok());
  }
}

// A star polygon whose edges cross each other many times.
std::vector<detail::Ring> star_rings(int points, int step) {
  detail::Ring ring;
  for (int k = 0; k < points; ++k) {
    const double angle = 2.0 * 3.141592653589793 * (k * step % points) / points;
    detail::Piece piece;
    piece.a = {1000.0 * std::cos(angle), 1000.0 * std::sin(angle)};
    ring.push_back(piece);
  }
  return {ring};
}

TEST(MeshLimits, CrossingResolutionStopsAtItsWorkBudget) {
  const std::vector<detail::Ring> rings = star_rings(31, 13);  // 31 edges, hundreds of crossings
  detail::RingPool pool;
  detail::ResolveScratch scratch;
  EXPECT_FALSE(
      detail::resolve_crossings(rings, {}, detail::HullState::NotSeparated, FillRule::NonZero, SIZE_MAX, pool, scratch)
          .empty());
  try {
    (void)detail::resolve_crossings(rings, {}, detail::HullState::NotSeparated, FillRule::NonZero, 40, pool, scratch);
    ADD_FAILURE() << "no error past the budget";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::Geometry);
    EXPECT_NE(std::string(e.what()).find("work budget"), std::string::npos) << e.what();
  }
}

TEST(MeshLimits, HullSeparationStopsAtItsWorkBudget) {
  // Two overlapping circles: hull separation splits their conics where they
  // cross, more pieces than a budget of 9 allows.
  Outline o;
  for (const double cx : {0.0, 1.5}) {
    const double w = std::sqrt(0.5);
    o.move_to({cx + 1, 0});
    o.conic_to({cx + 1, 1}, {cx, 1}, w);
    o.conic_to({cx - 1, 1}, {cx - 1, 0}, w);
    o.conic_to({cx - 1, -1}, {cx, -1}, w);
    o.conic_to({cx + 1, -1}, {cx + 1, 0}, w);
    o.close();
  }
  std::vector<detail::Ring> rings;
  detail::RingPool pool;
  detail::CleanScratch clean_scratch;
  ASSERT_TRUE(detail::clean_rings(o, 0.25, 1e-12, rings, pool, clean_scratch));
  detail::HullScratch hull_scratch;
  EXPECT_THROW(detail::separate_hulls(rings, detail::CrossingSplits::Split, 9, hull_scratch, pool), Error);
  // Within the real budget the mesh is built and checked.
  const MeshCheck check = build_and_check(o, 0.25);
  EXPECT_TRUE(check.ok());
}

// Nearly parallel pieces (a cubic that runs out along a line and back) cross
// with a cross product that rounds to 0: no NaN crossing point, in the
// mesher or in check_mesh's reference area.
const char* const kNearlyParallel = R"(
contour
 L -0x1.3acddb517114cp+28,0x1.b72db2c509d5p+28 0x0p+0,0x0p+0
 C 0x0p+0,0x0p+0 0x0p+0,0x0p+0 0x1.adb76f4e41facp+28,-0x1.d944a984b3cf8p+28 0x0p+0,0x0p+0
 L 0x0p+0,0x0p+0 0x1.dcd64ff8p+29,0x1.dcd65p+29
 Q 0x1.dcd64ff8p+29,0x1.dcd65p+29 -0x1.8bdf331f35092p+28,0x1.b2a86d3e309cep+29 0x0p+0,0x1.10aba7a1f067p+27
 L 0x0p+0,0x1.10aba7a1f067p+27 -0x1.3acddb517114cp+28,0x1.b72db2c509d5p+28
)";

TEST(MeshLimits, NearlyParallelCrossingsGiveNoNaN) {
  const Outline outline = parse_outline(kNearlyParallel);
  expect_checked_or_refused(outline, 0.25);
  const Outline quadratic = to_quadratic_outline(outline, 0.25);
  EXPECT_TRUE(std::isfinite(check_mesh(Mesh{}, quadratic).area_outline));
}

// FreeSerif.otf (fonts-freefont-otf) glyph 7987: a rounded box with eleven
// slots. The probe check_mesh used to place the last slot lay exactly on the
// chord of the box's corner curve, where the chord polygon and the curve's
// cap both counted it: the slot was taken as nested twice, and a right mesh
// was reported 7.7% short of its area at 16 and 64 px/em.
const char* const kFreeSerif7987 = R"(
contour
 L 771,-119 771,688
 C 771,688 771,736 748,760 703,760
 L 703,760 92,760
 C 92,760 47,760 24,736 24,688
 L 24,688 24,-119
 C 24,-119 24,-167 47,-191 92,-191
 L 92,-191 703,-191
 C 703,-191 748,-191 771,-167 771,-119
contour
 C 754,-119 754,-150 743,-168 720,-173
 L 720,-173 720,742
 C 720,742 743,737 754,719 754,688
 L 754,688 754,-119
contour
 L 686,-175 652,-175
 L 652,-175 652,743
 L 652,743 686,743
 L 686,743 686,-175
contour
 L 618,-175 584,-175
 L 584,-175 584,743
 L 584,743 618,743
 L 618,743 618,-175
contour
 L 550,-175 516,-175
 L 516,-175 516,743
 L 516,743 550,743
 L 550,743 550,-175
contour
 L 482,-175 448,-175
 L 448,-175 448,743
 L 448,743 482,743
 L 482,743 482,-175
contour
 L 415,-175 380,-175
 L 380,-175 380,743
 L 380,743 415,743
 L 415,743 415,-175
contour
 L 347,-175 312,-175
 L 312,-175 312,743
 L 312,743 347,743
 L 347,743 347,-175
contour
 L 279,-175 245,-175
 L 245,-175 245,743
 L 245,743 279,743
 L 279,743 279,-175
contour
 L 211,-175 177,-175
 L 177,-175 177,743
 L 177,743 211,743
 L 211,743 211,-175
contour
 L 143,-175 109,-175
 L 109,-175 109,743
 L 109,743 143,743
 L 143,743 143,-175
contour
 C 75,-173 52,-169 41,-151 41,-119
 L 41,-119 41,688
 C 41,688 41,718 52,736 75,741
 L 75,741 75,-173
)";

TEST(MeshLimits, FreeSerifGlyph7987) {
  const Outline outline = parse_outline(kFreeSerif7987);
  // 1000 units per em at 16 and 64 px/em (lod.hpp).
  for (const double tolerance : {3.90625, 0.9765625}) {
    const MeshCheck check = build_and_check(outline, tolerance);
    EXPECT_TRUE(check.ok());
    EXPECT_DOUBLE_EQ(check.area_outline, 363705.25);  // the contours' signed areas add up to it
  }
}

// NotoSerifCJK-Regular.ttc (fonts-noto-cjk) glyph 64501 (every face): two
// strokes share the vertices (-184, 183) and (-248, 184), one running
// straight between them and the other through (-241, 184), just past that
// line: the strokes overlap in a lens of 3.5 units^2 that no edge test sees
// (nothing crosses). Meshed as separate, the lens was covered twice (an edge
// of three faces). Rings meeting at vertices now go through the crossing
// resolver, which merges the strokes.
const char* const kNotoSerifCjk64501 = R"(
contour
 L -386,20 -432,79
 C -432,79 -417,114 -408,150 -404,184
 C -404,184 -404,188 -404,193 -404,198
 C -404,198 -404,204 -406,209 -412,212
 C -412,212 -427,220 -458,229 -479,232
 C -479,232 -486,234 -490,232 -492,230
 L -492,230 -502,210
 C -502,210 -488,203 -474,191 -470,181
 C -470,181 -478,103 -514,9 -571,-70
 C -571,-70 -574,-73 -573,-77 -569,-80
 L -569,-80 -555,-91
 C -555,-91 -552,-92 -547,-91 -543,-87
 C -543,-87 -504,-48 -473,-4 -450,40
 L -450,40 -384,-62
 C -384,-62 -380,-67 -374,-73 -369,-74
 C -369,-74 -362,-77 -350,-74 -345,-66
 C -345,-66 -343,-62 -342,-58 -343,-50
 C -343,-50 -345,-38 -350,-15 -356,-1
 L -356,-1 -386,20
contour
 L -184,183 -175,210
 C -175,210 -173,215 -173,218 -177,221
 C -177,221 -182,226 -197,233 -206,237
 C -206,237 -209,239 -217,239 -220,237
 L -220,237 -242,225
 C -242,225 -264,223 -312,222 -330,222
 C -330,222 -344,222 -363,222 -377,225
 L -377,225 -384,213
 C -384,213 -385,211 -385,208 -382,205
 C -382,205 -370,193 -353,181 -338,173
 C -338,173 -330,177 -312,181 -303,181
 C -303,181 -294,183 -265,184 -248,184
 L -248,184 -184,183
contour
 C -205,-89 -194,-52 -186,10 -186,51
 L -186,51 -184,183
 L -184,183 -241,184
 L -241,184 -248,184
 L -248,184 -248,35
 C -248,35 -248,0 -246,-56 -242,-89
 L -242,-89 -205,-89
contour
 C -603,-91 -592,-54 -585,9 -585,49
 L -585,49 -583,174
 L -583,174 -574,201
 C -574,201 -572,205 -572,209 -576,212
 C -576,212 -581,216 -596,224 -604,227
 C -604,227 -608,229 -615,229 -619,227
 L -619,227 -641,216
 C -641,216 -662,214 -711,213 -728,213
 C -728,213 -742,213 -762,213 -776,215
 L -776,215 -783,203
 C -783,203 -783,201 -783,199 -780,195
 C -780,195 -769,183 -752,171 -736,163
 C -736,163 -728,167 -710,171 -701,171
 C -701,171 -693,173 -663,174 -647,174
 L -647,174 -640,174
 L -640,174 -647,174
 L -647,174 -647,33
 C -647,33 -647,-1 -645,-57 -641,-91
 L -641,-91 -603,-91
)";

TEST(MeshLimits, NotoSerifCjkGlyph64501) {
  const MeshCheck check = build_and_check(parse_outline(kNotoSerifCjk64501), 3.90625);
  EXPECT_TRUE(check.ok());
  EXPECT_NEAR(check.area_outline, 74615.5, 1e-6);
}

// NotoSerifCJK-Bold.ttc glyph 34689: a teardrop whose tip (734, 663) lies
// on the curve of the stroke above it. check_mesh probed the teardrop at
// that tip first, found it inside the stroke by rounding, and took the
// whole teardrop as nested (2% of area error on a right mesh); it now asks
// the middles of pieces first.
const char* const kNotoSerifCjkBold34689 = R"(
contour
 L 734,663 726,657
 C 726,657 747,636 769,597 772,563
 C 772,563 848,508 927,651 734,663
contour
 L 876,818 822,743
 L 822,743 750,743
 L 750,743 750,816
 C 750,816 770,819 775,826 777,836
 L 777,836 634,849
 L 634,849 634,743
 L 634,743 527,743
 L 527,743 535,714
 L 535,714 634,714
 L 634,714 634,648
 L 634,648 656,648
 C 656,648 697,648 750,666 750,673
 L 750,673 750,714
 L 750,714 947,714
 C 947,714 961,714 971,719 974,730
 C 974,730 937,766 876,818 876,818
contour
 L 419,817 366,743
 L 366,743 347,743
 L 347,743 347,816
 C 347,816 366,819 371,826 373,836
 L 373,836 231,849
 L 231,849 231,743
 L 231,743 34,743
 L 34,743 42,714
 L 42,714 231,714
 L 231,714 231,640
 L 231,640 252,640
 C 252,640 294,640 347,658 347,665
 L 347,665 347,714
 L 347,714 486,714
 C 486,714 500,714 510,719 512,730
 C 512,730 478,766 419,817 419,817
contour
 L 306,556 263,482
 L 263,482 263,599
 C 263,599 287,603 297,612 299,627
 L 299,627 151,640
 L 151,640 151,479
 L 151,479 37,479
 L 37,479 45,451
 L 45,451 151,451
 L 151,451 151,286
 L 151,286 37,264
 L 37,264 85,129
 C 85,129 96,132 107,143 111,156
 L 111,156 151,180
 L 151,180 151,44
 C 151,44 151,34 147,30 133,30
 C 133,30 118,30 48,35 48,35
 L 48,35 48,21
 C 48,21 86,14 102,2 113,-14
 C 113,-14 124,-31 127,-57 129,-92
 C 129,-92 248,-82 263,-39 263,39
 L 263,39 263,249
 C 263,249 308,279 345,304 373,324
 L 373,324 371,335
 L 371,335 263,310
 L 263,310 263,451
 L 263,451 358,451
 C 358,451 372,451 381,456 384,467
 C 384,467 358,502 306,556 306,556
contour
 L 503,161 503,268
 L 503,268 590,268
 L 590,268 590,161
 L 590,161 503,161
contour
 L 891,608 847,534
 L 847,534 703,534
 L 703,534 703,600
 C 703,600 727,603 735,613 737,625
 L 737,625 590,640
 L 590,640 590,534
 L 590,534 359,534
 L 359,534 367,505
 L 367,505 590,505
 L 590,505 590,427
 L 590,427 509,427
 L 509,427 396,473
 L 396,473 396,-82
 L 396,-82 413,-82
 C 413,-82 458,-82 503,-57 503,-46
 L 503,-46 503,132
 L 503,132 590,132
 L 590,132 590,-85
 L 590,-85 612,-85
 C 612,-85 654,-85 703,-61 703,-50
 L 703,-50 703,132
 L 703,132 793,132
 L 793,132 793,52
 C 793,52 793,41 790,36 777,36
 C 777,36 763,36 722,39 722,39
 L 722,39 722,25
 C 722,25 750,20 762,7 770,-7
 C 770,-7 777,-23 780,-48 780,-80
 C 780,-80 889,-71 903,-30 903,41
 L 903,41 903,380
 C 903,380 923,384 938,392 944,400
 L 944,400 833,484
 L 833,484 783,427
 L 783,427 703,427
 L 703,427 703,505
 L 703,505 942,505
 C 942,505 956,505 965,510 968,521
 C 968,521 941,555 891,608 891,608
contour
 L 703,161 703,268
 L 703,268 793,268
 L 793,268 793,161
 L 793,161 703,161
contour
 L 503,297 503,398
 L 503,398 590,398
 L 590,398 590,297
 L 590,297 503,297
contour
 L 703,297 703,398
 L 703,398 793,398
 L 793,398 793,297
 L 793,297 703,297
)";

TEST(MeshLimits, NotoSerifCjkBoldGlyph34689) {
  const MeshCheck check = build_and_check(parse_outline(kNotoSerifCjkBold34689), 3.90625);
  EXPECT_TRUE(check.ok());
}

}  // namespace
}  // namespace curvetext
