#include "curvetext/outline.hpp"

#include <cmath>

#include "curvetext/curves.hpp"

namespace curvetext {

Segment Segment::line(Vec2 a, Vec2 b) {
  Segment s;
  s.kind = Kind::Line;
  s.p[0] = a;
  s.p[1] = b;
  return s;
}

Segment Segment::conic(Vec2 a, Vec2 control, Vec2 b, double weight) {
  Segment s;
  s.kind = Kind::Conic;
  s.p[0] = a;
  s.p[1] = control;
  s.p[2] = b;
  s.weight = weight;
  return s;
}

Segment Segment::cubic(Vec2 a, Vec2 c1, Vec2 c2, Vec2 b) {
  Segment s;
  s.kind = Kind::Cubic;
  s.p[0] = a;
  s.p[1] = c1;
  s.p[2] = c2;
  s.p[3] = b;
  return s;
}

Vec2 Segment::end() const {
  switch (kind) {
    case Kind::Line:
      return p[1];
    case Kind::Conic:
      return p[2];
    case Kind::Cubic:
      return p[3];
  }
  return p[1];
}

void Outline::move_to(Vec2 p) {
  close();
  if (!spare_.empty()) {
    contours_.push_back(std::move(spare_.back()));
    spare_.pop_back();
  } else {
    contours_.emplace_back();
    // Glyph contours have tens of segments: start with room for a few dozen
    // rather than growing one segment at a time (1, 2, 4, ... reallocations).
    contours_.back().segments.reserve(32);
  }
  start_ = pen_ = p;
  open_ = true;
}

void Outline::clear() {
  for (Contour& contour : contours_) {
    contour.segments.clear();
    spare_.push_back(std::move(contour));
  }
  contours_.clear();
  start_ = pen_ = Vec2{};
  open_ = false;
}

namespace {

// Appends a segment of `kind` starting at `start` and returns it for its
// other points. Segments are written field by field where they are stored,
// not built in a temporary and copied: the copy reads the temporary back in
// 16-byte loads over the 1-byte store of its kind, which the CPU cannot
// forward from its store buffer (a stall of a dozen cycles or more per load;
// measured: line_to, conic_to and cubic_to were 40% of loading a glyph's
// outline when they copied).
Segment& append(std::vector<Segment>& segments, Segment::Kind kind, Vec2 start) {
  Segment& s = segments.emplace_back();
  s.kind = kind;
  s.p[0] = start;
  return s;
}

}  // namespace

void Outline::line_to(Vec2 p) {
  if (!open_) move_to(pen_);
  if (p == pen_) return;  // a zero-length line adds nothing to the fill
  append(contours_.back().segments, Segment::Kind::Line, pen_).p[1] = p;
  pen_ = p;
}

void Outline::conic_to(Vec2 control, Vec2 p, double weight) {
  if (!open_) move_to(pen_);
  Segment& s = append(contours_.back().segments, Segment::Kind::Conic, pen_);
  s.p[1] = control;
  s.p[2] = p;
  s.weight = weight;
  pen_ = p;
}

void Outline::cubic_to(Vec2 c1, Vec2 c2, Vec2 p) {
  if (!open_) move_to(pen_);
  Segment& s = append(contours_.back().segments, Segment::Kind::Cubic, pen_);
  s.p[1] = c1;
  s.p[2] = c2;
  s.p[3] = p;
  pen_ = p;
}

void Outline::close() {
  if (!open_) return;
  if (!(pen_ == start_)) append(contours_.back().segments, Segment::Kind::Line, pen_).p[1] = start_;
  if (contours_.back().segments.empty()) {
    spare_.push_back(std::move(contours_.back()));
    contours_.pop_back();
  }
  pen_ = start_;
  open_ = false;
}

bool Outline::empty() const {
  for (const Contour& c : contours_)
    if (!c.segments.empty()) return false;
  return true;
}

bool Outline::has_cubics() const {
  for (const Contour& c : contours_)
    for (const Segment& s : c.segments)
      if (s.kind == Segment::Kind::Cubic) return true;
  return false;
}

static int point_count(const Segment& s) {
  switch (s.kind) {
    case Segment::Kind::Line:
      return 2;
    case Segment::Kind::Conic:
      return 3;
    case Segment::Kind::Cubic:
      return 4;
  }
  return 2;
}

Box Outline::control_box() const {
  Box box;
  for (const Contour& c : contours_)
    for (const Segment& s : c.segments)
      for (int i = 0; i < point_count(s); ++i) box.add(s.p[i]);
  return box;
}

// Green's theorem, A = 1/2 * closed integral of (x dy - y dx), piece by piece.
static double green_integral(const Segment& s) {
  switch (s.kind) {
    case Segment::Kind::Line:
      return 0.5 * cross(s.p[0], s.p[1]);
    case Segment::Kind::Conic:
      // Chord term plus the arc's contribution relative to its chord, which
      // is the negative of conic_chord_area's loop (that loop runs back along
      // the arc, the contour runs forward along it).
      return 0.5 * cross(s.p[0], s.p[2]) - conic_chord_area(s);
    case Segment::Kind::Cubic: {
      // x(t) y'(t) - y(t) x'(t) is a polynomial of degree 5: three-point
      // Gauss-Legendre quadrature integrates it exactly.
      static constexpr double kNodes[3] = {-0.7745966692414834, 0.0, 0.7745966692414834};
      static constexpr double kWeights[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
      const Vec2 a = s.p[0], b = s.p[1], c = s.p[2], d = s.p[3];
      double sum = 0.0;
      for (int i = 0; i < 3; ++i) {
        const double t = 0.5 * (kNodes[i] + 1.0), u = 1.0 - t;
        const Vec2 pt = a * (u * u * u) + b * (3 * u * u * t) + c * (3 * u * t * t) + d * (t * t * t);
        const Vec2 dt = (b - a) * (3 * u * u) + (c - b) * (6 * u * t) + (d - c) * (3 * t * t);
        sum += kWeights[i] * cross(pt, dt);
      }
      return 0.5 * 0.5 * sum;  // 0.5 from Green, 0.5 from mapping [-1,1] onto [0,1]
    }
  }
  return 0.0;
}

double Outline::signed_area() const {
  double area = 0.0;
  for (const Contour& c : contours_)
    for (const Segment& s : c.segments) area += green_integral(s);
  return area;
}

bool Outline::is_finite() const {
  // x * 0 is 0 (or -0) for finite x and NaN for an infinity or a NaN, and a
  // NaN stays in the sum: one test at the end instead of one per coordinate.
  double zero = 0.0;
  bool weights_ok = true;
  for (const Contour& c : contours_)
    for (const Segment& s : c.segments) {
      for (int i = 0; i < point_count(s); ++i) zero += s.p[i].x * 0.0 + s.p[i].y * 0.0;
      if (s.kind == Segment::Kind::Conic) weights_ok = weights_ok && std::isfinite(s.weight) && s.weight > 0.0;
    }
  return zero == 0.0 && weights_ok;
}

}  // namespace curvetext
