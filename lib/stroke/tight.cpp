// Strokes wider than a curve's radius of curvature: the inner side's normals
// reach past their centre of curvature, where the side sweeps backwards (the
// offset curve loops back). One loop per side would then let forward and
// backward sweeps of the same points cancel (a circle of radius 3 stroked 10
// wide would keep a hole of radius 2). Here each piece's half of the sweep is
// cut where the normals pass their centres (the evolute) into loops that
// each sweep one way, every loop oriented counter-clockwise, so that their
// nonzero union is the stroke region (docs/strokes.md, the model).
#include <algorithm>
#include <cmath>

#include "curvetext/curves.hpp"
#include "stroke/stroke_parts.hpp"

namespace curvetext::stroke {

namespace {

// Points on the evolute polyline between a piece's two normals (its interior
// boundary between loops; where it lies exactly does not change their union).
constexpr int kEvolutePoints = 16;
// Samples of a conic's curvature when looking for where it crosses 1 / h.
constexpr int kCurvatureSamples = 64;
// A crossing within this parameter of a piece's start is the one it was cut at.
constexpr double kCrossingSkip = 1e-6;

double signed_area(const std::vector<Segment>& loop) {
  double a = 0.0;
  for (const Segment& s : loop) {
    a += 0.5 * cross(s.p[0], s.end());
    if (s.kind == Segment::Kind::Conic) a -= conic_chord_area(s);
  }
  return a;
}

void close_and_orient(std::vector<Segment>& loop, std::vector<std::vector<Segment>>& out) {
  if (loop.empty()) return;
  for (const Segment& s : loop)
    for (const Vec2& p : s.p)
      if (!std::isfinite(p.x) || !std::isfinite(p.y)) return;  // a degenerate piece's evolute
  if (!(loop.back().end() == loop.front().p[0])) loop.push_back(Segment::line(loop.back().end(), loop.front().p[0]));
  if (signed_area(loop) < 0.0) {
    std::reverse(loop.begin(), loop.end());
    for (Segment& s : loop) s = reversed(s);
  }
  out.push_back(std::move(loop));
}

void line_to(std::vector<Segment>& loop, Vec2 p) {
  const Vec2 from = loop.empty() ? p : loop.back().end();
  if (!(from == p)) loop.push_back(Segment::line(from, p));
}

// Appends `side` reversed (its pieces backwards) to the loop.
void append_reversed(std::vector<Segment>& loop, const std::vector<Segment>& side) {
  for (auto it = side.rbegin(); it != side.rend(); ++it) {
    line_to(loop, it->end());
    loop.push_back(reversed(*it));
  }
}

Vec2 centre_of_curvature(const Segment& s, double t) {
  const double k = curvature(s, t);
  return evaluate(s, t) + left_normal(unit(derivative(s, t))) / k;
}

// The sweep of normals from 0 to d along q, with the offset fitted.
void half_loop(const Segment& q, double d, double tol, Budget& budget, std::vector<std::vector<Segment>>& out) {
  std::vector<Segment> offset, loop{q};
  append_offset(q, d, tol, budget, offset);
  if (offset.empty()) return;
  line_to(loop, offset.back().end());
  append_reversed(loop, offset);
  close_and_orient(loop, out);
}

// Normals from 0 to d along q reach past their centres of curvature all
// along q: one loop from q to the evolute, one from the evolute to the offset.
void split_loops(const Segment& q, double d, double tol, Budget& budget, std::vector<std::vector<Segment>>& out) {
  std::vector<Vec2> evolute;
  for (int i = 0; i <= kEvolutePoints; ++i) evolute.push_back(centre_of_curvature(q, double(i) / kEvolutePoints));
  std::vector<Segment> near{q};
  for (int i = kEvolutePoints; i >= 0; --i) line_to(near, evolute[static_cast<std::size_t>(i)]);
  close_and_orient(near, out);
  std::vector<Segment> offset, far;
  append_offset(q, d, tol, budget, offset);
  for (const Vec2& e : evolute) line_to(far, e);
  if (far.empty()) far.push_back(Segment::line(evolute.front(), evolute.front()));
  line_to(far, offset.back().end());
  append_reversed(far, offset);
  far.erase(std::remove_if(far.begin(), far.end(),
                           [](const Segment& s) { return s.p[0] == s.end() && s.kind == Segment::Kind::Line; }),
            far.end());
  close_and_orient(far, out);
}

// The first t in (0, 1) where |curvature| crosses 1 / h, or 1.
double next_crossing(const Segment& q, double h) {
  auto g = [&](double t) { return std::abs(curvature(q, t)) * h - 1.0; };
  // (Not from 0 itself: q may start at the crossing found before.)
  double prev = g(kCrossingSkip);
  for (int i = 1; i <= kCurvatureSamples; ++i) {
    const double t = double(i) / kCurvatureSamples, v = g(t);
    if ((prev < 0.0) != (v < 0.0)) {
      double lo = t - 1.0 / kCurvatureSamples, hi = t;
      for (int k = 0; k < 50; ++k) {
        const double m = 0.5 * (lo + hi);
        ((g(m) < 0.0) == (prev < 0.0) ? lo : hi) = m;
      }
      return 0.5 * (lo + hi);
    }
    prev = v;
  }
  return 1.0;
}

}  // namespace

double curvature(const Segment& s, double t) {
  if (s.kind == Segment::Kind::Line) return 0.0;
  constexpr double kStep = 1e-6;
  const double lo = std::max(0.0, t - kStep), hi = std::min(1.0, t + kStep);
  const Vec2 d1 = derivative(s, t), d2 = (derivative(s, hi) - derivative(s, lo)) / (hi - lo);
  const double l = length(d1);
  return l > 0.0 ? cross(d1, d2) / (l * l * l) : 0.0;
}

bool tighter_than(const Segment& s, double h) {
  if (s.kind == Segment::Kind::Line) return false;
  for (int i = 0; i <= kCurvatureSamples; ++i)
    if (std::abs(curvature(s, double(i) / kCurvatureSamples)) * h >= 1.0) return true;
  return false;
}

void append_sweep_loops(const Segment& s, double h, double tol, Budget& budget,
                        std::vector<std::vector<Segment>>& out) {
  for (double d : {h, -h}) {
    const bool inner = s.kind == Segment::Kind::Conic && d * curvature(s, 0.5) > 0.0;
    if (!inner || !tighter_than(s, h)) {
      half_loop(s, d, tol, budget, out);
      continue;
    }
    // Pieces between the points where the radius of curvature crosses h.
    Segment rest = s;
    for (int guard = 0; guard < 8; ++guard) {
      const double t = next_crossing(rest, h);
      const Segment piece = t < 1.0 ? split(rest, t).first : rest;
      if (std::abs(curvature(piece, 0.5)) * h > 1.0)
        split_loops(piece, d, tol, budget, out);
      else
        half_loop(piece, d, tol, budget, out);
      if (t >= 1.0) break;
      rest = split(rest, t).second;
    }
  }
}

void append_wedge(Vec2 p, const std::vector<Segment>& join, std::vector<std::vector<Segment>>& out) {
  if (join.empty()) return;
  std::vector<Segment> loop{Segment::line(p, join.front().p[0])};
  loop.insert(loop.end(), join.begin(), join.end());
  close_and_orient(loop, out);
}

}  // namespace curvetext::stroke
