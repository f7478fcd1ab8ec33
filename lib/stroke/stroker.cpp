// The stroker: subpaths as lines and conics, dashed, each dash or subpath
// outlined as its two offset sides with joins and caps (docs/strokes.md).
#include <algorithm>
#include <cmath>
#include <string>

#include "curvetext/curves.hpp"
#include "curvetext/error.hpp"
#include "curvetext/stroke.hpp"
#include "core/format.hpp"
#include "core/tolerances.hpp"
#include "stroke/stroke_parts.hpp"

namespace curvetext {

using namespace stroke;

double stroke_width_in_units(const StrokeStyle& style, double px_per_unit) {
  if (!(px_per_unit > 0.0) || !std::isfinite(px_per_unit))
    throw Error(ErrorCode::InvalidArgument,
                "px_per_unit must be positive and finite, got " + detail::format_number_exact(px_per_unit));
  if (!std::isfinite(style.width))
    throw Error(ErrorCode::InvalidArgument,
                "stroke width must be finite, got " + detail::format_number_exact(style.width));
  switch (style.width_unit) {
    case StrokeWidthUnit::User:
      return std::max(0.0, style.width);
    case StrokeWidthUnit::Device:
      return std::max(0.0, style.width) / px_per_unit;
    case StrokeWidthUnit::Hairline:
      return 1.0 / px_per_unit;
  }
  return 0.0;
}

namespace {

void check_finite(double v, const char* what) {
  if (!std::isfinite(v))
    throw Error(ErrorCode::InvalidArgument,
                std::string(what) + " must be finite, got " + detail::format_number_exact(v));
}

// SVG's dash rules: no dashes for an empty array, a negative value or a zero
// sum; an odd count repeated; lengths and offset scaled by pathLength.
bool dash_pattern(const StrokeStyle& style, double total_length, DashPattern& out) {
  out.lengths.clear();
  double sum = 0.0;
  for (double v : style.dashes) {
    check_finite(v, "a dash length");
    if (v < 0.0) return false;
    sum += v;
  }
  check_finite(style.dash_offset, "the dash offset");
  check_finite(style.path_length, "pathLength");
  if (style.dashes.empty() || !(sum > 0.0) || !std::isfinite(sum)) return false;
  const double scale = style.path_length > 0.0 ? total_length / style.path_length : 1.0;
  out.lengths.assign(style.dashes.begin(), style.dashes.end());
  if (out.lengths.size() % 2 == 1) out.lengths.insert(out.lengths.end(), style.dashes.begin(), style.dashes.end());
  for (double& v : out.lengths) v *= scale;
  const double period = (style.dashes.size() % 2 == 1 ? 2.0 : 1.0) * sum * scale;
  if (!(period > 0.0) || !std::isfinite(period)) return false;
  out.phase = std::fmod(style.dash_offset * scale, period);
  if (out.phase < 0.0) out.phase += period;
  return true;
}

// A conic whose control point lies on its chord's line: lines through the
// point where it turns back, if it does.
void flat_conic(const Segment& c, std::vector<Segment>& out) {
  const Vec2 dir = c.p[2] - c.p[0];
  const double l2 = dot(dir, dir), k = l2 > 0.0 ? dot(c.p[1] - c.p[0], dir) / l2 : 0.0;
  if (k >= 0.0 && k <= 1.0) {
    out.push_back(Segment::line(c.p[0], c.p[2]));
    return;
  }
  // The extreme of its projection on the chord (or on the leg for a
  // closed one), found by ternary search (the projection is unimodal).
  const Vec2 axis = l2 > 0.0 ? dir : c.p[1] - c.p[0];
  const double sign = k > 1.0 || l2 == 0.0 ? 1.0 : -1.0;
  double lo = 0.0, hi = 1.0;
  for (int i = 0; i < 100; ++i) {
    const double m1 = lo + (hi - lo) / 3.0, m2 = hi - (hi - lo) / 3.0;
    if (sign * dot(evaluate(c, m1), axis) < sign * dot(evaluate(c, m2), axis))
      lo = m1;
    else
      hi = m2;
  }
  const Vec2 turn = evaluate(c, 0.5 * (lo + hi));
  out.push_back(Segment::line(c.p[0], turn));
  out.push_back(Segment::line(turn, c.p[2]));
}

bool zero_length(const Segment& s, double eps) {
  const double d = distance(s.p[0], s.end());
  return s.kind == Segment::Kind::Line ? d <= eps : d <= eps && distance(s.p[0], s.p[1]) <= eps;
}

}  // namespace

// The state of one Stroker::stroke call.
struct Stroker::Run {
  explicit Run(Stroker& owner) : k(owner) {}
  Stroker& k;
  double h = 0.5;    // half width, path units
  double tol = 1.0;  // offset fitting tolerance, path units
  double len_tol = 0.1;
  double eps = 0.0;   // zero length
  double snap = 0.0;  // gaps and pieces below this are closed and dropped (path units)
  Vec2 pen;           // the end of what emit() has added
  LineCap cap = LineCap::Butt;
  JoinStyle join;
  Budget budget;
  DashPattern dashes;
  bool dashed = false;

  void add_segment(Segment s);
  void flatten(const ShapeContour& c);
  void emit(const std::vector<Segment>& side, bool reverse);
  void side_of(const Segment* first, const Segment* last, bool closed, double d, std::vector<Segment>& side);
  void sides(const Segment* first, const Segment* last, bool closed);
  void outline_open(const Segment* first, const Segment* last);
  void outline_closed(const Segment* first, const Segment* last);
  void emit_dot(Vec2 p, Vec2 t);
  void dash(std::size_t first, std::size_t last, bool closed);
  void add_part(std::size_t i, double from, double to);
  void finish_dash(bool into_first);
};

void Stroker::Run::add_segment(Segment s) {
  // Pieces shorter than `snap` (cubic splits near inflections make some)
  // would only add slivers: dropped, the next one starting where the path is.
  if (zero_length(s, snap)) return;
  if (!k.path_.empty() && k.path_.size() > k.subpaths_.back() && distance(k.path_.back().end(), s.p[0]) <= snap)
    s.p[0] = k.path_.back().end();
  if (!k.path_.empty() && k.path_.size() > k.subpaths_.back() && !(k.path_.back().end() == s.p[0]) &&
      distance(k.path_.back().end(), s.p[0]) > eps)
    k.path_.push_back(Segment::line(k.path_.back().end(), s.p[0]));  // a gap between pieces
  if (s.kind == Segment::Kind::Conic &&
      std::abs(cross(s.p[1] - s.p[0], s.p[2] - s.p[0])) <=
          tolerance::kConicFlatnessRelative *
              std::max(dot(s.p[1] - s.p[0], s.p[1] - s.p[0]), dot(s.p[2] - s.p[0], s.p[2] - s.p[0]))) {
    std::vector<Segment> lines;
    flat_conic(s, lines);
    for (const Segment& l : lines)
      if (!zero_length(l, eps)) k.path_.push_back(l);
    return;
  }
  k.path_.push_back(s);
}

// One contour into path_ as a subpath; a contour of zero length (a point)
// becomes its dot right away (SVG: caps drawn for zero-length subpaths).
void Stroker::Run::flatten(const ShapeContour& c) {
  if (c.pieces.empty()) return;
  k.subpaths_.push_back(k.path_.size());
  std::vector<Segment>& segs = k.cap_;
  for (const RationalBezier& piece : c.pieces) {
    segs.clear();
    append_quadratics(piece, 0.5 * tol, segs);
    for (const Segment& s : segs) add_segment(s);
  }
  const std::size_t first = k.subpaths_.back();
  if (k.path_.size() == first) {
    k.subpaths_.pop_back();
    emit_dot(c.pieces.front().points.front(), {1.0, 0.0});  // SVG: along the x axis
    return;
  }
  if (c.closed && distance(k.path_.back().end(), k.path_[first].p[0]) > eps)
    k.path_.push_back(Segment::line(k.path_.back().end(), k.path_[first].p[0]));
  k.closed_.push_back(c.closed ? 1 : 0);
}

void Stroker::Run::emit(const std::vector<Segment>& side, bool reverse) {
  Outline& o = k.staged_;
  const std::size_t n = side.size();
  budget.spend(n);
  for (std::size_t j = 0; j < n; ++j) {
    const Segment s = reverse ? reversed(side[n - 1 - j]) : side[j];
    // Gaps and pieces below `snap` (rounding where offsets meet, joins of
    // nearly tangent pieces) are closed rather than drawn as slivers.
    if (distance(pen, s.p[0]) > snap) o.line_to(pen = s.p[0]);
    if (distance(pen, s.end()) <= snap && (s.kind == Segment::Kind::Line || distance(pen, s.p[1]) <= snap)) continue;
    if (s.kind == Segment::Kind::Line)
      o.line_to(s.p[1]);
    else
      o.conic_to(s.p[1], s.p[2], s.weight);
    pen = s.end();
  }
}

namespace {

// Where the inner offsets of two lines cross inside both (then the side
// runs from one to the other there, instead of pivoting through the path
// point, which would only add two crossing slivers for the mesher).
bool inner_crossing(const Segment& a, const Segment& b, Vec2& x) {
  const Vec2 da = a.p[1] - a.p[0], db = b.p[1] - b.p[0];
  const double den = cross(da, db);
  if (!(std::abs(den) > 0.0)) return false;
  const double u = cross(b.p[0] - a.p[0], db) / den, v = cross(b.p[0] - a.p[0], da) / den;
  if (!(u > 0.0 && u <= 1.0 && v >= 0.0 && v < 1.0)) return false;
  x = a.p[0] + da * u;
  return true;
}

}  // namespace

// One side (offset `d`) of [first, last) with its joins (and the join from
// the last segment to the first when closed) into `side`.
void Stroker::Run::side_of(const Segment* first, const Segment* last, bool closed, double d,
                           std::vector<Segment>& side) {
  side.clear();
  bool trim = false;  // the next offset starts at `cut`
  Vec2 cut;
  const double sign = d < 0.0 ? -1.0 : 1.0;
  for (const Segment* s = first; s != last; ++s) {
    const std::size_t at = side.size();
    append_offset(*s, d, tol, budget, side);
    if (trim && side[at].kind == Segment::Kind::Line) side[at].p[0] = cut;
    trim = false;
    const Segment* next = s + 1 != last ? s + 1 : closed ? first : nullptr;
    if (!next) break;
    const Vec2 p = s->end(), t0 = end_tangent(*s), t1 = start_tangent(*next);
    if (s->kind == Segment::Kind::Line && next->kind == Segment::Kind::Line && !outer_side(t0, t1, sign)) {
      const Vec2 n = left_normal(t1) * d;
      if (inner_crossing(side.back(), Segment::line(next->p[0] + n, next->p[1] + n), cut)) {
        side.back().p[1] = cut;
        trim = next != first;
        if (next == first) side.front().p[0] = cut;
        continue;
      }
    }
    append_join(p, t0, t1, end_curvature(*s, true), end_curvature(*next, false), sign, join, side);
  }
}

void Stroker::Run::sides(const Segment* first, const Segment* last, bool closed) {
  side_of(first, last, closed, -h, k.right_);
  side_of(first, last, closed, h, k.left_);
}

void Stroker::Run::outline_open(const Segment* first, const Segment* last) {
  sides(first, last, false);
  Outline& o = k.staged_;
  o.move_to(pen = k.right_.front().p[0]);
  emit(k.right_, false);
  k.cap_.clear();
  append_cap((last - 1)->end(), end_tangent(*(last - 1)), h, cap, k.cap_);
  emit(k.cap_, false);
  emit(k.left_, true);
  k.cap_.clear();
  append_cap(first->p[0], start_tangent(*first) * -1.0, h, cap, k.cap_);
  emit(k.cap_, false);
  o.close();
}

void Stroker::Run::outline_closed(const Segment* first, const Segment* last) {
  sides(first, last, true);
  Outline& o = k.staged_;
  o.move_to(pen = k.right_.front().p[0]);
  emit(k.right_, false);
  o.close();
  o.move_to(pen = k.left_.back().end());
  emit(k.left_, true);
  o.close();
}

void Stroker::Run::emit_dot(Vec2 p, Vec2 t) {
  k.cap_.clear();
  append_dot(p, t, h, cap, k.cap_);
  if (k.cap_.empty()) return;
  k.staged_.move_to(pen = k.cap_.front().p[0]);
  emit(k.cap_, false);
  k.staged_.close();
}

// The part of segment i between arc lengths `from` and `to` (from its
// start) appended to the dash being built.
void Stroker::Run::add_part(std::size_t i, double from, double to) {
  const Segment& s = k.path_[i];
  const double len = k.lengths_[i];
  if (!(to - from > 0.0)) return;
  if (s.kind == Segment::Kind::Line) {
    k.piece_.push_back(Segment::line(lerp(s.p[0], s.p[1], from / len), lerp(s.p[0], s.p[1], std::min(1.0, to / len))));
    return;
  }
  // Split where the arc length reaches `from`, then measure again on the
  // tail (a split conic is reparametrised).
  Segment tail = s;
  if (from > 0.0) tail = split(s, parameter_at_length(s, from, len, 0.5 * len_tol)).second;
  if (to < len) tail = split(tail, parameter_at_length(tail, to - from, len - from, 0.5 * len_tol)).first;
  if (!zero_length(tail, eps)) k.piece_.push_back(tail);
}

// Ends the dash being built: outlined, or kept as a closed subpath's first
// dash, to be joined to its last.
void Stroker::Run::finish_dash(bool into_first) {
  if (into_first) {
    k.first_dash_.swap(k.piece_);
  } else if (!k.piece_.empty()) {
    outline_open(k.piece_.data(), k.piece_.data() + k.piece_.size());
  }
  k.piece_.clear();
}

void Stroker::Run::dash(std::size_t first, std::size_t last, bool closed) {
  const std::vector<double>& pattern = dashes.lengths;
  std::size_t j = 0;
  double pos = dashes.phase;
  // A dash that ends exactly at the phase is passed; one of length 0 there
  // is a dot.
  while (pos > pattern[j] || (pos == pattern[j] && pattern[j] > 0.0)) {
    pos -= pattern[j];
    j = (j + 1) % pattern.size();
  }
  double remaining = pattern[j] - pos;
  bool on = j % 2 == 0, capture = closed && on;
  k.piece_.clear();
  k.first_dash_.clear();
  for (std::size_t i = first; i < last; ++i) {
    const double len = k.lengths_[i];
    double s0 = 0.0;
    while (remaining <= len - s0) {
      const double s1 = s0 + remaining;
      if (on) {
        add_part(i, s0, s1);
        if (k.piece_.empty() && !capture) {
          const Segment& s = k.path_[i];
          const double t = parameter_at_length(s, s1, len, len_tol);
          emit_dot(evaluate(s, t), unit(derivative(s, t)) == Vec2{} ? start_tangent(s) : unit(derivative(s, t)));
        }
        finish_dash(capture);
        capture = false;
      }
      budget.spend(1);
      s0 = s1;
      j = (j + 1) % pattern.size();
      remaining = pattern[j];
      on = !on;
    }
    if (on) add_part(i, s0, len);
    remaining -= len - s0;
  }
  if (on && capture) {  // one dash all round a closed subpath: no ends
    if (!k.piece_.empty()) outline_closed(k.piece_.data(), k.piece_.data() + k.piece_.size());
    return;
  }
  if (on && closed)
    k.piece_.insert(k.piece_.end(), k.first_dash_.begin(), k.first_dash_.end());
  else if (!k.first_dash_.empty())
    outline_open(k.first_dash_.data(), k.first_dash_.data() + k.first_dash_.size());
  finish_dash(false);
}

void Stroker::stroke(const std::vector<ShapeContour>& contours, const StrokeStyle& style, double tolerance,
                     double px_per_unit, Outline& out) {
  if (!(tolerance > 0.0) || !std::isfinite(tolerance))
    throw Error(ErrorCode::InvalidArgument,
                "stroke tolerance must be positive and finite, got " + detail::format_number_exact(tolerance));
  check_finite(style.miter_limit, "the miter limit");
  Run run(*this);
  run.h = 0.5 * stroke_width_in_units(style, px_per_unit);
  if (!(run.h > 0.0)) return;
  run.tol = 0.5 * tolerance;
  run.len_tol = tolerance * tolerance::kStrokeDashLengthOfTolerance;
  run.cap = style.cap;
  run.join = JoinStyle{style.join, run.h, style.miter_limit, run.tol};
  double reach = 0.0;
  for (const ShapeContour& c : contours)
    for (const RationalBezier& b : c.pieces)
      for (Vec2 p : b.points) reach = std::max({reach, std::abs(p.x), std::abs(p.y)});
  run.eps = tolerance::kStrokeZeroLengthRelative * reach;
  run.snap = std::max(run.eps, tolerance * tolerance::kStrokeSnapOfTolerance);
  path_.clear();
  subpaths_.clear();
  closed_.clear();
  staged_.clear();
  for (const ShapeContour& c : contours) run.flatten(c);
  subpaths_.push_back(path_.size());
  run.dashed = false;
  if (!style.dashes.empty()) {
    lengths_.resize(path_.size());
    double total = 0.0;
    for (std::size_t i = 0; i < path_.size(); ++i) total += lengths_[i] = arc_length(path_[i], 1.0, 0.25 * run.len_tol);
    run.dashed = dash_pattern(style, total, run.dashes);
    if (run.dashed) {
      double period = 0.0;
      for (double v : run.dashes.lengths) period += v;
      if (total / period * static_cast<double>(run.dashes.lengths.size()) > double(tolerance::kMaxStrokeSegments))
        throw Error(ErrorCode::Geometry, "the dash pattern would cut the path into more than " +
                                             std::to_string(tolerance::kMaxStrokeSegments) + " pieces");
    }
  }
  for (std::size_t i = 0; i + 1 < subpaths_.size(); ++i) {
    const Segment* first = path_.data() + subpaths_[i];
    const Segment* last = path_.data() + subpaths_[i + 1];
    if (run.dashed)
      run.dash(subpaths_[i], subpaths_[i + 1], closed_[i] != 0);
    else if (closed_[i])
      run.outline_closed(first, last);
    else
      run.outline_open(first, last);
  }
  staged_.close();
  out.close();
  for (Contour& c : staged_.contours()) out.contours().push_back(c);
}

Outline stroke_outline(const std::vector<ShapeContour>& contours, const StrokeStyle& style, double tolerance,
                       double px_per_unit) {
  Stroker stroker;
  Outline out;
  stroker.stroke(contours, style, tolerance, px_per_unit, out);
  return out;
}

}  // namespace curvetext
