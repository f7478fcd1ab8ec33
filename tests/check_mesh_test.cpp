// check_mesh's searches: the box-pair search against all pairs, the crossing
// reference area's sweep against areas known in closed form and against a
// slab-by-slab integration, and check_mesh on shapes where its searches used
// to be quadratic.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <set>
#include <utility>
#include <vector>

#include "curvetext/curves.hpp"
#include "curvetext/mesh.hpp"
#include "tessellate/check_area_sweep.hpp"
#include "tessellate/check_box_pairs.hpp"

namespace curvetext {
namespace {

using detail::AreaSweep;
using detail::BoxContact;
using detail::BoxPairSearch;

std::set<std::pair<std::size_t, std::size_t>> searched(BoxPairSearch& search, const std::vector<Box>& boxes,
                                                       BoxContact contact, const std::vector<char>& keyed) {
  std::set<std::pair<std::size_t, std::size_t>> pairs;
  search.run(
      boxes, contact, [&](std::size_t i) { return keyed[i] != 0; },
      [&](std::size_t i, std::size_t j) {
        EXPECT_NE(i, j);
        EXPECT_TRUE(pairs.insert({std::min(i, j), std::max(i, j)}).second) << "pair reported twice";
      });
  return pairs;
}

std::set<std::pair<std::size_t, std::size_t>> all_pairs(const std::vector<Box>& boxes, BoxContact contact,
                                                        const std::vector<char>& keyed) {
  std::set<std::pair<std::size_t, std::size_t>> pairs;
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    for (std::size_t j = i + 1; j < boxes.size(); ++j) {
      const Box &a = boxes[i], &b = boxes[j];
      // Open boxes: a flat box has no interior and meets nothing.
      const bool meet = contact == BoxContact::Touching
                            ? a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y && b.min.y <= a.max.y
                            : std::max(a.min.x, b.min.x) < std::min(a.max.x, b.max.x) &&
                                  std::max(a.min.y, b.min.y) < std::min(a.max.y, b.max.y) && a.min.x < a.max.x &&
                                  b.min.x < b.max.x && a.min.y < a.max.y && b.min.y < b.max.y;
      if (meet && (keyed[i] || keyed[j])) pairs.insert({i, j});
    }
  }
  return pairs;
}

// Both methods (the scan and the sweep), and the choice between them.
TEST(CheckMesh, BoxPairSearchFindsEveryPairOnce) {
  for (const auto method : {BoxPairSearch::Method::Auto, BoxPairSearch::Method::Scan, BoxPairSearch::Method::Sweep}) {
    std::mt19937 random(7);
    // Coordinates on a small grid, so that boxes share bounds and touch.
    std::uniform_int_distribution<int> coordinate(0, 40), length(0, 12), coin(0, 3);
    BoxPairSearch search;  // reused: its scratch must not leak between runs
    search.set_method(method);
    for (int round = 0; round < 40; ++round) {
      std::vector<Box> boxes(60 + round);
      std::vector<char> keyed(boxes.size());
      for (std::size_t i = 0; i < boxes.size(); ++i) {
        const Vec2 p{static_cast<double>(coordinate(random)), static_cast<double>(coordinate(random))};
        boxes[i].add(p);
        // Long boxes along both axes, flat ones, points.
        const int shape = coin(random);
        boxes[i].add(p + Vec2{shape == 1 ? 30.0 : length(random), shape == 2 ? 30.0 : length(random)});
        keyed[i] = round % 2 == 0 || coin(random) == 0;
      }
      for (const BoxContact contact : {BoxContact::Touching, BoxContact::Interiors})
        EXPECT_EQ(searched(search, boxes, contact, keyed), all_pairs(boxes, contact, keyed)) << round;
    }
  }
}

// The scan is taken only while the pairs it would meet are few per box: a
// comb's teeth beside one box spanning them all is cheap, n boxes all
// overlapping in x (a fan) is not, and there nothing is reported; with no
// box keyed there is nothing to search.
TEST(CheckMesh, BoxPairScanOnlyWhereCheap) {
  std::vector<Box> teeth, fan;
  for (int i = 0; i < 4000; ++i) {
    Box tooth, blade;
    tooth.add({10.0 * i, 1});
    tooth.add({10.0 * i + 4, 1000});
    const double y = i;
    blade.add({0, y});
    blade.add({40000.0 - y, y + 2.0});
    teeth.push_back(tooth);
    fan.push_back(blade);
  }
  Box base;
  base.add({0, 0});
  base.add({40000, 1});
  teeth.push_back(base);
  BoxPairSearch search;
  std::size_t pairs = 0;
  auto all = [](std::size_t) { return true; };
  auto count = [&](std::size_t, std::size_t) { ++pairs; };
  EXPECT_TRUE(search.scan_if_cheap(teeth, BoxContact::Touching, all, count));
  EXPECT_EQ(pairs, 4000u);  // the base touches every tooth; teeth 6 apart do not touch
  pairs = 0;
  EXPECT_FALSE(search.scan_if_cheap(fan, BoxContact::Touching, all, count));
  EXPECT_EQ(pairs, 0u);
  search.run(fan, BoxContact::Touching, all, count);  // by the sweep: each blade meets its two neighbours on each side
  EXPECT_EQ(pairs, 2u * 4000 - 3);
  // No box keyed (a mesh without curved faces): nothing to search, at no cost.
  pairs = 0;
  EXPECT_TRUE(search.scan_if_cheap(
      fan, BoxContact::Touching, [](std::size_t) { return false; }, count));
  EXPECT_EQ(pairs, 0u);
}

// Teeth standing on a fan's base touch it along one line: as open boxes, no pair.
TEST(CheckMesh, BoxesThatOnlyTouchAreNoPairOfInteriors) {
  std::vector<Box> boxes;
  for (int i = 0; i < 300; ++i) {
    Box fan, tooth;
    fan.add({0, 0});
    fan.add({10.0 * i + 10, 1});
    tooth.add({10.0 * i, 1});
    tooth.add({10.0 * i + 4, 1000});
    boxes.push_back(fan);
    boxes.push_back(tooth);
  }
  std::vector<char> keyed(boxes.size(), 0);
  for (std::size_t i = 1; i < boxes.size(); i += 2) keyed[i] = 1;  // the teeth (a mesh's curved faces)
  BoxPairSearch search;
  EXPECT_TRUE(searched(search, boxes, BoxContact::Interiors, keyed).empty());
  EXPECT_EQ(searched(search, boxes, BoxContact::Touching, keyed).size(),
            all_pairs(boxes, BoxContact::Touching, keyed).size());
}

struct Polygon {
  std::vector<AreaSweep::Edge> edges;
  std::vector<std::size_t> sizes;
  void add(const std::vector<Vec2>& points) {
    for (std::size_t i = 0; i < points.size(); ++i) {
      edges.push_back({points[i], points[(i + 1) % points.size()], 0.0, static_cast<std::uint32_t>(sizes.size()),
                       static_cast<std::uint32_t>(i)});
    }
    sizes.push_back(points.size());
  }
  double area(bool& touching, FillRule rule = FillRule::NonZero) {
    AreaSweep sweep;
    return sweep.run(edges, sizes, rule, touching);
  }
};

TEST(CheckMesh, SweptAreaOfShapesKnownInClosedForm) {
  struct Case {
    const char* name;
    std::vector<std::vector<Vec2>> contours;
    double area;
    bool touching;
  };
  const std::vector<Case> cases = {
      {"square", {{{0, 0}, {2, 0}, {2, 2}, {0, 2}}}, 4, false},
      {"clockwise square", {{{0, 0}, {0, 2}, {2, 2}, {2, 0}}}, 4, false},
      {"two overlapping squares", {{{0, 0}, {2, 0}, {2, 2}, {0, 2}}, {{1, 1}, {3, 1}, {3, 3}, {1, 3}}}, 7, true},
      {"square with a hole", {{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {{1, 1}, {1, 3}, {3, 3}, {3, 1}}}, 12, false},
      {"square drawn twice, one reversed",
       {{{0, 0}, {2, 0}, {2, 2}, {0, 2}}, {{0, 0}, {0, 2}, {2, 2}, {2, 0}}},
       0,
       true},
      {"bow tie", {{{0, 0}, {2, 2}, {2, 0}, {0, 2}}}, 2, true},
      {"vertex on another's edge", {{{0, 0}, {2, 0}, {2, 2}, {0, 2}}, {{2, 1}, {3, 0}, {3, 2}}}, 5, true},
      {"contour through another's vertex",
       {{{0, 0}, {2, 0}, {2, 2}, {0, 2}}, {{1, -1}, {3, 1}, {1, 3}, {-1, 1}}},
       8,
       true},
      {"horizontal bar across a tooth",
       {{{0, 0}, {1, 0}, {1, 10}, {0, 10}}, {{-1, 4}, {2, 4}, {2, 5}, {-1, 5}}},
       12,
       true},
      {"triangle", {{{0, 0}, {4, 0}, {0, 3}}}, 6, false},
  };
  for (const Case& c : cases) {
    Polygon p;
    for (const auto& contour : c.contours) p.add(contour);
    bool touching = false;
    EXPECT_NEAR(p.area(touching), c.area, 1e-12) << c.name;
    EXPECT_EQ(touching, c.touching) << c.name;
  }
}

// The same sweep under the even-odd rule: the windings 2 of a bow tie drawn
// twice, of nested squares drawn alike and of a pentagram's centre are not
// filled.
TEST(CheckMesh, SweptAreaUnderTheEvenOddRule) {
  struct Case {
    const char* name;
    std::vector<std::vector<Vec2>> contours;
    double nonzero, even_odd;
  };
  const double pi = std::numbers::pi;
  std::vector<Vec2> star;
  for (int k = 0; k < 5; ++k)
    star.push_back({std::cos((90 + 144 * k) * pi / 180), std::sin((90 + 144 * k) * pi / 180)});
  const double ri = std::cos(2 * pi / 5) / std::cos(pi / 5);
  const double star_area = 10 * 0.5 * ri * std::sin(pi / 5), pentagon = 2.5 * ri * ri * std::sin(2 * pi / 5);
  const std::vector<Case> cases = {
      {"two overlapping squares", {{{0, 0}, {2, 0}, {2, 2}, {0, 2}}, {{1, 1}, {3, 1}, {3, 3}, {1, 3}}}, 7, 6},
      {"nested squares drawn alike", {{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {{1, 1}, {3, 1}, {3, 3}, {1, 3}}}, 16, 12},
      {"pentagram", {star}, star_area, star_area - pentagon},
  };
  for (const Case& c : cases) {
    Polygon p;
    for (const auto& contour : c.contours) p.add(contour);
    bool touching = false;
    EXPECT_NEAR(p.area(touching), c.nonzero, 1e-12) << c.name;
    EXPECT_NEAR(p.area(touching, FillRule::EvenOdd), c.even_odd, 1e-12) << c.name;
  }
}

// Nonzero area by slabs: between consecutive event heights, the covered
// width at the slab's middle times its height (quadratic, for small inputs).
double slab_area(const Polygon& p) {
  std::vector<double> ys;
  for (const auto& e : p.edges) {
    ys.push_back(e.a.y);
    ys.push_back(e.b.y);
  }
  for (const auto& e : p.edges) {
    for (const auto& f : p.edges) {
      const Vec2 r = e.b - e.a, q = f.b - f.a;
      const double d = cross(r, q);
      if (d == 0) continue;
      const double t = cross(f.a - e.a, q) / d, u = cross(f.a - e.a, r) / d;
      if (t > 0 && t < 1 && u > 0 && u < 1) ys.push_back(e.a.y + r.y * t);
    }
  }
  std::sort(ys.begin(), ys.end());
  double area = 0;
  for (std::size_t k = 0; k + 1 < ys.size(); ++k) {
    const double y = 0.5 * (ys[k] + ys[k + 1]);
    std::vector<std::pair<double, int>> hits;
    for (const auto& e : p.edges) {
      if ((e.a.y < y) == (e.b.y < y)) continue;
      hits.push_back({e.a.x + (e.b.x - e.a.x) * (y - e.a.y) / (e.b.y - e.a.y), e.b.y > e.a.y ? 1 : -1});
    }
    std::sort(hits.begin(), hits.end());
    int w = 0;
    for (std::size_t h = 0; h + 1 < hits.size(); ++h) {
      w += hits[h].second;
      if (w != 0) area += (hits[h + 1].first - hits[h].first) * (ys[k + 1] - ys[k]);
    }
  }
  return area;
}

TEST(CheckMesh, SweptAreaOfRandomPolygonsMatchesSlabs) {
  std::mt19937 random(11);
  std::uniform_int_distribution<int> grid(0, 12), count(3, 9), contours(1, 3);
  for (int round = 0; round < 1000; ++round) {
    Polygon p;
    const int n = contours(random);
    for (int c = 0; c < n; ++c) {
      std::vector<Vec2> points(count(random));
      // Grid points: shared vertices, vertices on edges, collinear and horizontal edges.
      for (Vec2& q : points) q = {static_cast<double>(grid(random)), static_cast<double>(grid(random))};
      p.add(points);
    }
    bool touching = false;
    EXPECT_NEAR(p.area(touching), slab_area(p), 1e-9) << round;
  }
}

// The comb crossed by a bar, a case where slab-by-slab integration is
// quadratic: every tooth is crossed twice, and each crossing changes the
// windings beside it.
TEST(CheckMesh, SweptAreaOfACombCrossedByABar) {
  const int n = 20000;
  Polygon p;
  std::vector<Vec2> comb = {{0, 0}};
  for (int i = 0; i < n; ++i) {
    const double x = i * 10.0, h = 1000.0 + i;
    comb.insert(comb.end(), {{x + 2, h}, {x + 4, h}, {x + 4, 1}, {x + 10, 1}});
  }
  comb.push_back({n * 10.0, 0});
  p.add(comb);
  p.add({{-5, 500}, {n * 10.0 + 5, 500}, {n * 10.0 + 5, 501}, {-5, 501}});
  // The comb alone is a simple polygon (clockwise; the bar counter-clockwise,
  // so where they overlap the winding is 0: outside).
  double comb_area = 0;
  for (std::size_t i = 0; i < comb.size(); ++i) comb_area -= 0.5 * cross(comb[i], comb[(i + 1) % comb.size()]);
  const double bar_area = n * 10.0 + 10;
  // The bar's overlap with the teeth: at height y a tooth covers 4 units
  // less its leaning left edge's offset; integrated over y in [500, 501].
  double overlap = 4 - 2 * 500.5 / 1000.0;  // the first tooth leans from (0, 0)
  for (int i = 1; i < n; ++i) overlap += 4 - 2 * (500.5 - 1) / (1000.0 + i - 1);
  const double expected = comb_area + bar_area - 2 * overlap;
  bool touching = false;
  EXPECT_NEAR(p.area(touching), expected, 1e-9 * expected);
  EXPECT_TRUE(touching);
}

// Long spikes around a centre: the edges' boxes overlap in x by the
// thousand, too many pairs for the scan, so whether contours touch is left
// to the sweep. Alone the star touches nothing (the exact per-contour area);
// with a ring crossing every spike the sweep's area is the reference. Both
// must agree with the mesh.
TEST(CheckMesh, ContactsOfManyLongEdgesAreLeftToTheSweep) {
  const int spikes = 1000;
  const double pi = 3.141592653589793;
  Outline star;
  double star_area = 0;
  std::vector<Vec2> points;
  for (int i = 0; i < 2 * spikes; ++i) {
    const double a = pi * i / spikes, r = i % 2 == 0 ? 1000.0 : 10.0;
    points.push_back({r * std::cos(a), r * std::sin(a)});
  }
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (i == 0) {
      star.move_to(points[i]);
    } else {
      star.line_to(points[i]);
    }
    star_area += 0.5 * cross(points[i], points[(i + 1) % points.size()]);
  }
  star.close();
  const MeshCheck alone = check_mesh(build_mesh(star, {}), star);
  EXPECT_TRUE(alone.ok()) << alone.problems.front();
  EXPECT_NEAR(alone.area_outline, star_area, 1e-12 * star_area);

  Outline crossed = star;
  for (int i = 0; i < 64; ++i) {  // a ring of radius 500..510 (outer contour only), crossing every spike
    const double a = 2 * pi * i / 64;
    if (i == 0) {
      crossed.move_to({510 * std::cos(a), 510 * std::sin(a)});
    } else {
      crossed.line_to({510 * std::cos(a), 510 * std::sin(a)});
    }
  }
  crossed.close();
  const MeshCheck both = check_mesh(build_mesh(crossed, {}), crossed);
  EXPECT_TRUE(both.ok()) << both.problems.front();
  EXPECT_GT(both.area_outline, star_area);  // the union: more than the star alone, less than the sum
  EXPECT_LT(both.area_outline, star_area + 64 * 0.5 * 510 * 510 * std::sin(2 * pi / 64));
}

}  // namespace
}  // namespace curvetext
