// Small 2D vector type shared by curves, tessellation and fonts. Double
// precision: font units and shape coordinates are exact in it.
#pragma once

#include <cmath>

namespace curvetext {

struct Vec2 {
  double x = 0.0;
  double y = 0.0;

  friend constexpr Vec2 operator+(Vec2 a, Vec2 b) { return {a.x + b.x, a.y + b.y}; }
  friend constexpr Vec2 operator-(Vec2 a, Vec2 b) { return {a.x - b.x, a.y - b.y}; }
  friend constexpr Vec2 operator*(Vec2 a, double s) { return {a.x * s, a.y * s}; }
  friend constexpr Vec2 operator*(double s, Vec2 a) { return {a.x * s, a.y * s}; }
  friend constexpr Vec2 operator/(Vec2 a, double s) { return {a.x / s, a.y / s}; }
  // Both comparisons, combined without a branch (whether points coincide is
  // data-dependent; a short-circuit && is mispredicted often in mesh building).
  friend constexpr bool operator==(Vec2 a, Vec2 b) { return (a.x == b.x) & (a.y == b.y); }
};

constexpr double dot(Vec2 a, Vec2 b) { return a.x * b.x + a.y * b.y; }
constexpr double cross(Vec2 a, Vec2 b) { return a.x * b.y - a.y * b.x; }
inline double length(Vec2 a) { return std::hypot(a.x, a.y); }
inline double distance(Vec2 a, Vec2 b) { return length(a - b); }
constexpr Vec2 lerp(Vec2 a, Vec2 b, double t) { return a + (b - a) * t; }

struct Box {
  Vec2 min{+1e300, +1e300};
  Vec2 max{-1e300, -1e300};
  bool empty() const { return min.x > max.x || min.y > max.y; }
  void add(Vec2 p) {
    // (Selects rather than branches: compiled to min/max instructions. A NaN
    // coordinate leaves the box as it is.)
    min.x = p.x < min.x ? p.x : min.x;
    min.y = p.y < min.y ? p.y : min.y;
    max.x = p.x > max.x ? p.x : max.x;
    max.y = p.y > max.y ? p.y : max.y;
  }
};

}  // namespace curvetext
