// Even-odd fill through the nonzero mesher (build_mesh fills nonzero only).
//
// The even-odd region R is where the winding number is odd. Its boundary,
// oriented with R on the left, is a closed chain whose winding number is 1 in
// R and 0 elsewhere, so its NONZERO fill is R. We build that chain:
//  1. split every segment wherever it meets another segment (or itself), so
//     that pieces meet only at their ends (an arrangement);
//  2. for each piece, the winding numbers on its two sides differ by exactly
//     1; find the parity of the one on its left at the piece's midpoint by
//     counting the pieces a ray from there crosses (along x, or along y where
//     the piece runs closer to x) and reverse the piece when it is even;
//  3. chain the oriented pieces into closed loops (every vertex has as many
//     pieces in as out, since the chain is a boundary).
// Nesting contours that never cross reduce to flipping whole contours by the
// parity of their depth; crossing ones (a pentagram) are handled the same way.
#include <algorithm>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

#include "curvetext/curves.hpp"
#include "curvetext/error.hpp"
#include "curvetext/shapes.hpp"
#include "core/tolerances.hpp"

namespace curvetext {

namespace {

struct Hp {
  double x = 0, y = 0, w = 0;
};

// Homogeneous Bernstein coefficients of a line or conic.
std::vector<Hp> homogeneous(const Segment& s) {
  if (s.kind == Segment::Kind::Line) return {{s.p[0].x, s.p[0].y, 1}, {s.p[1].x, s.p[1].y, 1}};
  const double w = s.weight;
  return {{s.p[0].x, s.p[0].y, 1}, {s.p[1].x * w, s.p[1].y * w, w}, {s.p[2].x, s.p[2].y, 1}};
}

using Bernstein = std::vector<double>;  // coefficients of a polynomial on [0,1]

double binomial(int n, int k) {
  double r = 1;
  for (int i = 1; i <= k; ++i) r = r * (n - k + i) / i;
  return r;
}

Bernstein multiply(const Bernstein& a, const Bernstein& b) {
  const int m = static_cast<int>(a.size()) - 1, n = static_cast<int>(b.size()) - 1;
  Bernstein c(static_cast<std::size_t>(m + n + 1), 0.0);
  for (int i = 0; i <= m; ++i)
    for (int j = 0; j <= n; ++j)
      c[static_cast<std::size_t>(i + j)] += binomial(m, i) * binomial(n, j) / binomial(m + n, i + j) *
                                            a[static_cast<std::size_t>(i)] * b[static_cast<std::size_t>(j)];
  return c;
}

// Roots in [lo, hi] by subdivision: a Bernstein polynomial whose coefficients
// all have one sign has no root (convex hull property). Depth 44 gives the
// parameter to ~6e-14; `budget` bounds the work for near-coincident curves.
void roots(const Bernstein& c, double lo, double hi, int depth, int& budget, std::vector<double>& out) {
  if (--budget < 0) return;
  bool any_pos = false, any_neg = false;
  for (double v : c) {
    any_pos = any_pos || v >= 0.0;
    any_neg = any_neg || v <= 0.0;
  }
  if (!(any_pos && any_neg)) return;
  if (depth >= 44) {
    out.push_back(0.5 * (lo + hi));
    return;
  }
  Bernstein left(c.size()), right(c.size()), t = c;
  const std::size_t n = c.size();
  left[0] = t[0];
  right[n - 1] = t[n - 1];
  for (std::size_t level = 1; level < n; ++level) {
    for (std::size_t i = 0; i + level < n; ++i) t[i] = 0.5 * (t[i] + t[i + 1]);
    left[level] = t[0];
    right[n - 1 - level] = t[n - 1 - level];
  }
  const double mid = 0.5 * (lo + hi);
  roots(left, lo, mid, depth + 1, budget, out);
  roots(right, mid, hi, depth + 1, budget, out);
}

// Barycentric coordinates of q in a conic's control triangle, as affine
// functions: tau_i(q) = g_i . q + h_i.
struct Bary {
  Vec2 g[3]{};
  double h[3]{};
  bool ok = false;
  explicit Bary(const Segment& s) {
    const Vec2 p0 = s.p[0], c = s.p[1], p2 = s.p[2];
    const double area = cross(c - p0, p2 - p0);
    if (!(area != 0.0) || !std::isfinite(area)) return;
    const Vec2 e = p2 - p0, f = c - p0;
    g[1] = Vec2{e.y, -e.x} / area;  // tau1 = cross(q - p0, e) / area
    h[1] = -dot(g[1], p0);
    g[2] = Vec2{-f.y, f.x} / area;  // tau2 = cross(f, q - p0) / area
    h[2] = -dot(g[2], p0);
    g[0] = (g[1] + g[2]) * -1.0;
    h[0] = 1.0 - h[1] - h[2];
    ok = true;
  }
  double tau(int i, Vec2 q) const { return dot(g[i], q) + h[i]; }
  double tau_h(int i, Hp p) const { return g[i].x * p.x + g[i].y * p.y + h[i] * p.w; }
};

constexpr double kParamEps = 1e-9;

struct Hit {
  double t;
  Vec2 point;
};

// Points where segment `b` meets segment `a`: roots on b of a's implicit
// equation, kept where they lie on a's arc. Appends to both hit lists.
void intersect(const Segment& a, const Segment& b, std::vector<Hit>& hits_a, std::vector<Hit>& hits_b) {
  const std::vector<Hp> hb = homogeneous(b);
  Bernstein poly;
  double magnitude = 0.0;
  Bary bary(a);
  if (a.kind == Segment::Kind::Line) {
    const Vec2 d = a.p[1] - a.p[0];
    for (const Hp& h : hb) {
      const Vec2 r{h.x - a.p[0].x * h.w, h.y - a.p[0].y * h.w};
      poly.push_back(cross(d, r));
      magnitude = std::max(magnitude, length(d) * length(r));
    }
  } else {
    if (!bary.ok) return;
    Bernstein t0, t1, t2;
    double m = 0.0;
    for (const Hp& h : hb) {
      t0.push_back(bary.tau_h(0, h));
      t1.push_back(bary.tau_h(1, h));
      t2.push_back(bary.tau_h(2, h));
      m = std::max(m, std::abs(t0.back()) + std::abs(t1.back()) + std::abs(t2.back()));
    }
    const double w2 = a.weight * a.weight;
    const Bernstein sq = multiply(t1, t1), pr = multiply(t0, t2);
    for (std::size_t i = 0; i < sq.size(); ++i) poly.push_back(sq[i] - 4.0 * w2 * pr[i]);
    magnitude = m * m * (1.0 + 4.0 * w2);
  }
  double largest = 0.0;
  for (double v : poly) largest = std::max(largest, std::abs(v));
  // Identically zero: b lies on a's line or conic (overlapping segments);
  // not resolved (see shapes.hpp).
  if (largest <= 1e-13 * magnitude) return;
  std::vector<double> ts;
  int budget = 4000;
  roots(poly, 0.0, 1.0, 0, budget, ts);
  std::sort(ts.begin(), ts.end());
  double last = -1.0;
  for (double tb : ts) {
    if (tb - last <= kParamEps) continue;
    last = tb;
    Vec2 x = evaluate(b, tb);
    double ta;
    if (a.kind == Segment::Kind::Line) {
      const Vec2 d = a.p[1] - a.p[0];
      ta = dot(x - a.p[0], d) / dot(d, d);
      if (ta < -kParamEps || ta > 1.0 + kParamEps) continue;
    } else {
      const double u0 = bary.tau(0, x), u1 = bary.tau(1, x), u2 = bary.tau(2, x);
      const double eps = 1e-9;
      if (u0 < -eps || u1 < -eps || u2 < -eps) continue;  // on the conic, off the arc
      const double s0 = std::sqrt(std::max(u0, 0.0)), s2 = std::sqrt(std::max(u2, 0.0));
      if (!(s0 + s2 > 0.0)) continue;
      ta = s2 / (s0 + s2);  // tau2 / tau0 = (t / (1 - t))^2 for end weights 1
    }
    ta = std::clamp(ta, 0.0, 1.0);
    // A hit at an end of one segment is that end exactly, so every segment
    // through the point ends or splits at the same coordinates.
    if (ta <= kParamEps)
      x = a.start();
    else if (ta >= 1.0 - kParamEps)
      x = a.end();
    else if (tb <= kParamEps)
      x = b.start();
    else if (tb >= 1.0 - kParamEps)
      x = b.end();
    hits_a.push_back({ta, x});
    hits_b.push_back({tb, x});
  }
}

// The part of `s` over [t0, t1] with the given end points: for a conic, the
// blossoms H(t0,t0), H(t0,t1), H(t1,t1) are its exact homogeneous control
// points; normalised to end weights 1.
Segment piece(const Segment& s, double t0, double t1, Vec2 a, Vec2 b) {
  if (s.kind == Segment::Kind::Line) return Segment::line(a, b);
  const std::vector<Hp> h = homogeneous(s);
  auto blossom = [&](double u, double v) {
    const double b0 = (1 - u) * (1 - v), b1 = (1 - u) * v + u * (1 - v), b2 = u * v;
    return Hp{b0 * h[0].x + b1 * h[1].x + b2 * h[2].x, b0 * h[0].y + b1 * h[1].y + b2 * h[2].y,
              b0 * h[0].w + b1 * h[1].w + b2 * h[2].w};
  };
  const Hp s0 = blossom(t0, t0), m = blossom(t0, t1), s1 = blossom(t1, t1);
  return Segment::conic(a, {m.x / m.w, m.y / m.w}, b, m.w / std::sqrt(s0.w * s1.w));
}

struct Piece {
  Segment seg;
  int from = 0, to = 0;
};

Segment reversed(const Segment& s) {
  if (s.kind == Segment::Kind::Line) return Segment::line(s.p[1], s.p[0]);
  return Segment::conic(s.p[2], s.p[1], s.p[0], s.weight);
}

// Ends closer than this are one vertex: crossings computed from different
// pairs of segments agree only to rounding.
double merge_distance(double diag) { return std::max(1e-10 * diag, 1e-300); }

Vec2 swapped(Vec2 p) { return {p.y, p.x}; }

// 0. Lines and proper conics only; conics as flat as the mesher treats as
// straight become lines, segments without length are dropped.
std::vector<Segment> usable_segments(const Outline& outline) {
  std::vector<Segment> segs;
  for (const Contour& c : outline.contours()) {
    for (const Segment& s : c.segments) {
      if (s.kind == Segment::Kind::Cubic)
        throw Error(ErrorCode::InvalidArgument, "even-odd fill: cubics must be replaced by conics first");
      if (s.start() == s.end()) continue;  // a zero-length line, or a conic out and back: no area
      const double chord = distance(s.start(), s.end());
      if (s.kind == Segment::Kind::Conic &&
          std::abs(cross(s.p[1] - s.p[0], s.p[2] - s.p[0])) <= tolerance::kConicFlatnessRelative * chord * chord) {
        segs.push_back(Segment::line(s.p[0], s.p[2]));
        continue;
      }
      segs.push_back(s);
    }
  }
  return segs;
}

Box control_box(const Segment& s) {
  Box b;
  b.add(s.p[0]);
  b.add(s.p[1]);
  if (s.kind == Segment::Kind::Conic) b.add(s.p[2]);
  return b;
}

// Calls f(i, j), i < j, for every pair of boxes that meet (within pad): a
// sweep along the longer side of all the boxes together, so that a tall thin
// outline's pieces are not all compared with each other.
template <class F>
void for_each_box_pair(const std::vector<Box>& boxes, double pad, F&& f) {
  Box all;
  for (const Box& b : boxes) {
    all.add(b.min);
    all.add(b.max);
  }
  const bool along_y = all.max.y - all.min.y > all.max.x - all.min.x;
  auto lo = [&](std::size_t i) { return along_y ? boxes[i].min.y : boxes[i].min.x; };
  auto hi = [&](std::size_t i) { return along_y ? boxes[i].max.y : boxes[i].max.x; };
  auto across_apart = [&](std::size_t i, std::size_t j) {
    return along_y ? boxes[i].min.x > boxes[j].max.x + pad || boxes[j].min.x > boxes[i].max.x + pad
                   : boxes[i].min.y > boxes[j].max.y + pad || boxes[j].min.y > boxes[i].max.y + pad;
  };
  std::vector<std::size_t> order(boxes.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return lo(a) < lo(b); });
  for (std::size_t k = 0; k < order.size(); ++k) {
    const std::size_t i = order[k];
    for (std::size_t m = k + 1; m < order.size() && lo(order[m]) <= hi(i) + pad; ++m) {
      const std::size_t j = order[m];
      if (!across_apart(i, j)) f(std::min(i, j), std::max(i, j));
    }
  }
}

// 1a. Every segment cut wherever it meets another (bounding boxes first).
std::vector<Segment> split_at_crossings(const std::vector<Segment>& segs, double diag) {
  const std::size_t n = segs.size();
  std::vector<Box> boxes(n);
  for (std::size_t i = 0; i < n; ++i) boxes[i] = control_box(segs[i]);
  const double pad = 1e-9 * diag;
  std::vector<std::vector<Hit>> hits(n);
  for_each_box_pair(boxes, pad, [&](std::size_t i, std::size_t j) { intersect(segs[i], segs[j], hits[i], hits[j]); });
  std::vector<Segment> pieces;
  for (std::size_t i = 0; i < n; ++i) {
    std::vector<Hit>& h = hits[i];
    std::sort(h.begin(), h.end(), [](const Hit& a, const Hit& b) { return a.t < b.t; });
    double t_prev = 0.0;
    Vec2 p_prev = segs[i].start();
    for (const Hit& hit : h) {
      if (hit.t <= t_prev + kParamEps || hit.t >= 1.0 - kParamEps) continue;
      pieces.push_back(piece(segs[i], t_prev, hit.t, p_prev, hit.point));
      t_prev = hit.t;
      p_prev = hit.point;
    }
    pieces.push_back(piece(segs[i], t_prev, 1.0, p_prev, segs[i].end()));
  }
  return pieces;
}

// 1b. Vertices: ends within the merge distance are one vertex, and the
// pieces take its exact coordinates.
std::vector<Piece> merge_vertices(const std::vector<Segment>& pieces, double diag, std::size_t& vertex_count) {
  std::vector<Vec2> ends;
  for (const Segment& s : pieces) {
    ends.push_back(s.start());
    ends.push_back(s.end());
  }
  // Swept along the longer side, so a tall thin outline's window stays short.
  Box all;
  for (const Vec2 p : ends) all.add(p);
  const bool swap = all.max.y - all.min.y > all.max.x - all.min.x;
  if (swap)
    for (Vec2& p : ends) p = swapped(p);
  std::vector<std::size_t> order(ends.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return ends[a].x < ends[b].x; });
  const double merge = merge_distance(diag);
  std::vector<int> vertex_of(ends.size(), -1);
  std::vector<Vec2> vertices;
  for (std::size_t k = 0; k < order.size(); ++k) {
    const std::size_t i = order[k];
    if (vertex_of[i] >= 0) continue;
    vertex_of[i] = static_cast<int>(vertices.size());
    vertices.push_back(swap ? swapped(ends[i]) : ends[i]);
    for (std::size_t m = k + 1; m < order.size() && ends[order[m]].x - ends[i].x <= merge; ++m)
      if (vertex_of[order[m]] < 0 && distance(ends[order[m]], ends[i]) <= merge) vertex_of[order[m]] = vertex_of[i];
  }
  std::vector<Piece> arr;
  for (std::size_t i = 0; i < pieces.size(); ++i) {
    Piece p{pieces[i], vertex_of[2 * i], vertex_of[2 * i + 1]};
    if (p.from == p.to) continue;
    p.seg.p[0] = vertices[static_cast<std::size_t>(p.from)];
    if (p.seg.kind == Segment::Kind::Line)
      p.seg.p[1] = vertices[static_cast<std::size_t>(p.to)];
    else
      p.seg.p[2] = vertices[static_cast<std::size_t>(p.to)];
    arr.push_back(p);
  }
  vertex_count = vertices.size();
  return arr;
}

// Two pieces between the same vertices along the same curve bound no area
// between them and change the winding by 2 (or 0) across them, never by 1:
// they cancel in pairs before orientation, which assumes a step of 1.
void cancel_coincident(std::vector<Piece>& arr, double merge) {
  auto key = [](const Piece& p) { return std::minmax(p.from, p.to); };
  std::vector<std::size_t> order(arr.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return key(arr[a]) < key(arr[b]); });
  auto same_curve = [&](const Piece& a, const Piece& b) {
    if (a.seg.kind != b.seg.kind) return false;
    if (a.seg.kind == Segment::Kind::Line) return true;
    return distance(a.seg.p[1], b.seg.p[1]) <= merge && std::abs(a.seg.weight - b.seg.weight) <= 1e-9 * a.seg.weight;
  };
  std::vector<char> gone(arr.size(), 0);
  for (std::size_t g = 0; g < order.size();) {
    std::size_t h = g;
    while (h < order.size() && key(arr[order[h]]) == key(arr[order[g]])) ++h;
    for (std::size_t i = g; i < h; ++i)
      for (std::size_t j = i + 1; j < h && !gone[order[i]]; ++j)
        if (!gone[order[j]] && same_curve(arr[order[i]], arr[order[j]])) gone[order[i]] = gone[order[j]] = 1;
    g = h;
  }
  std::size_t kept = 0;
  for (std::size_t i = 0; i < arr.size(); ++i)
    if (!gone[i]) arr[kept++] = arr[i];
  arr.resize(kept);
}

// A part of a piece that is monotone in the ray frame's y, in that frame's
// coordinates (x and y swapped for rays along y).
struct Part {
  Segment seg;
  double t0 = 0, t1 = 1;  // its parameters on the piece
  std::size_t piece = 0;
  double ylo = 0, yhi = 0, xlo = 0, xhi = 0;
};

// Parameters in (0, 1) where a conic's y turns: roots of the numerator of
// its derivative, w (y1 - y0) (1-t)^2 + (y2 - y0) t (1-t) + w (y2 - y1) t^2.
std::vector<double> y_turns(const Segment& s) {
  if (s.kind == Segment::Kind::Line) return {};
  const double w = s.weight;
  const double a = w * (s.p[1].y - s.p[0].y), b = s.p[2].y - s.p[0].y, c = w * (s.p[2].y - s.p[1].y);
  const double qa = a - b + c, qb = b - 2.0 * a, qc = a;
  std::vector<double> ts;
  if (std::abs(qa) <= 1e-14 * (std::abs(a) + std::abs(b) + std::abs(c))) {
    if (qb != 0.0) ts.push_back(-qc / qb);
  } else {
    const double disc = qb * qb - 4.0 * qa * qc;
    if (disc >= 0.0) {
      const double r = std::sqrt(disc), q = -0.5 * (qb + std::copysign(r, qb));
      if (q != 0.0) ts.push_back(qc / q);
      ts.push_back(q / qa);
    }
  }
  std::vector<double> inside;
  for (double t : ts)
    if (t > 1e-12 && t < 1.0 - 1e-12) inside.push_back(t);
  std::sort(inside.begin(), inside.end());
  return inside;
}

Segment in_frame(const Segment& s, bool swap) {
  if (!swap) return s;
  Segment r = s;
  for (Vec2& p : r.p) p = swapped(p);
  return r;
}

// The monotone parts of every piece.
std::vector<Part> monotone_parts(const std::vector<Piece>& arr, bool swap) {
  std::vector<Part> parts;
  for (std::size_t i = 0; i < arr.size(); ++i) {
    const Segment s = in_frame(arr[i].seg, swap);
    std::vector<double> cuts = y_turns(s);
    cuts.push_back(1.0);
    double t0 = 0.0;
    Vec2 a = s.start();
    for (double t1 : cuts) {
      const Vec2 b = t1 == 1.0 ? s.end() : evaluate(s, t1);
      Part p{piece(s, t0, t1, a, b), t0, t1, i};
      const Box box = control_box(p.seg);
      p.ylo = std::min(a.y, b.y);
      p.yhi = std::max(a.y, b.y);
      p.xlo = box.min.x;
      p.xhi = box.max.x;
      parts.push_back(p);
      t0 = t1;
      a = b;
    }
  }
  return parts;
}

// The parts a horizontal line meets, found through buckets of equal height
// (as many as parts); parts across more than kTallBuckets buckets are in one
// list that every query reads.
class PartIndex {
 public:
  explicit PartIndex(std::vector<Part> parts) : parts_(std::move(parts)) {
    double y0 = 0, y1 = 0;
    for (std::size_t i = 0; i < parts_.size(); ++i) {
      y0 = i == 0 ? parts_[i].ylo : std::min(y0, parts_[i].ylo);
      y1 = i == 0 ? parts_[i].yhi : std::max(y1, parts_[i].yhi);
    }
    y0_ = y0;
    buckets_.resize(std::max<std::size_t>(parts_.size(), 1));
    cell_ = (y1 - y0) / static_cast<double>(buckets_.size());
    for (std::size_t i = 0; i < parts_.size(); ++i) {
      const std::size_t b0 = bucket(parts_[i].ylo), b1 = bucket(parts_[i].yhi);
      if (b1 - b0 >= kTallBuckets) {
        tall_.push_back(i);
        continue;
      }
      for (std::size_t b = b0; b <= b1; ++b) buckets_[b].push_back(i);
    }
  }
  // f(part) for every part with ylo <= y <= yhi.
  template <class F>
  void at_height(double y, F&& f) const {
    auto visit = [&](std::size_t i) {
      if (parts_[i].ylo <= y && y <= parts_[i].yhi) f(parts_[i]);
    };
    for (const std::size_t i : buckets_[bucket(y)]) visit(i);
    for (const std::size_t i : tall_) visit(i);
  }

 private:
  static constexpr std::size_t kTallBuckets = 64;
  std::size_t bucket(double y) const {
    if (!(cell_ > 0.0)) return 0;
    const double b = std::floor((y - y0_) / cell_);
    return static_cast<std::size_t>(std::clamp(b, 0.0, static_cast<double>(buckets_.size() - 1)));
  }
  std::vector<Part> parts_;
  double y0_ = 0, cell_ = 0;
  std::vector<std::vector<std::size_t>> buckets_;
  std::vector<std::size_t> tall_;
};

// Whether the ray from (x, y) along +x crosses the part. Ends on the ray
// count as below it (a half-open rule), so a ray through a vertex counts the
// pieces there consistently.
bool crosses(const Part& p, double x, double y) {
  const Vec2 a = p.seg.start(), b = p.seg.end();
  if ((a.y <= y) == (b.y <= y)) return false;
  if (p.xlo > x) return true;
  if (p.xhi <= x) return false;
  if (p.seg.kind == Segment::Kind::Line) return a.x + (y - a.y) * (b.x - a.x) / (b.y - a.y) > x;
  double lo = 0.0, hi = 1.0;  // y is monotone on the part: bisect
  const bool rising = b.y > a.y;
  for (int k = 0; k < 64 && lo < hi; ++k) {
    const double mid = 0.5 * (lo + hi);
    if ((evaluate(p.seg, mid).y <= y) == rising)
      lo = mid;
    else
      hi = mid;
  }
  return evaluate(p.seg, 0.5 * (lo + hi)).x > x;
}

// 2. Reverse every piece whose left side has an even winding number. The
// parity comes from a ray from the piece's midpoint along x, or along y where
// the piece runs closer to x, so the ray leaves the piece at 45 degrees or
// more; the piece itself counts when the left side lies behind the ray's start.
void orient_by_parity(std::vector<Piece>& arr) {
  const PartIndex frames[2] = {PartIndex(monotone_parts(arr, false)), PartIndex(monotone_parts(arr, true))};
  std::vector<char> flip(arr.size(), 0);
  for (std::size_t i = 0; i < arr.size(); ++i) {
    const Segment& s = arr[i].seg;
    const Vec2 t = s.end() - s.start();  // for end weights 1, parallel to the tangent at t = 1/2
    const bool swap = std::abs(t.y) < std::abs(t.x);
    const Vec2 m = swap ? swapped(evaluate(s, 0.5)) : evaluate(s, 0.5);
    int count = swap ? t.x < 0.0 : t.y > 0.0;
    frames[swap ? 1 : 0].at_height(m.y, [&](const Part& p) {
      if (p.piece == i && p.t0 <= 0.5 && 0.5 <= p.t1) return;  // the crossing at m itself
      count += crosses(p, m.x, m.y);
    });
    flip[i] = count % 2 == 0;
  }
  for (std::size_t i = 0; i < arr.size(); ++i) {
    if (!flip[i]) continue;
    arr[i].seg = reversed(arr[i].seg);
    std::swap(arr[i].from, arr[i].to);
  }
}

void emit_loop(const std::vector<Piece>& arr, const std::vector<std::size_t>& loop, Outline& result) {
  result.move_to(arr[loop.front()].seg.start());
  for (std::size_t e : loop) {
    const Segment& s = arr[e].seg;
    if (s.kind == Segment::Kind::Line)
      result.line_to(s.p[1]);
    else
      result.conic_to(s.p[1], s.p[2], s.weight);
  }
  result.close();
}

// 3. Closed loops. A walk that comes back to a vertex it already passed
// closes a loop there, so each loop visits each vertex once.
Outline chain_loops(const std::vector<Piece>& arr, std::size_t vertex_count) {
  std::vector<std::vector<std::size_t>> out_of(vertex_count);
  for (std::size_t i = arr.size(); i-- > 0;) out_of[static_cast<std::size_t>(arr[i].from)].push_back(i);
  Outline result;
  for (std::size_t v0 = 0; v0 < vertex_count; ++v0) {
    while (!out_of[v0].empty()) {
      std::vector<std::size_t> path;
      std::map<int, std::size_t> seen;  // vertex -> position in path where it starts
      int v = static_cast<int>(v0);
      seen[v] = 0;
      while (!out_of[static_cast<std::size_t>(v)].empty()) {
        const std::size_t e = out_of[static_cast<std::size_t>(v)].back();
        out_of[static_cast<std::size_t>(v)].pop_back();
        path.push_back(e);
        v = arr[e].to;
        const auto it = seen.find(v);
        if (it != seen.end()) {
          const std::size_t at = it->second;  // `it` dies with the erase below
          std::vector<std::size_t> loop(path.begin() + static_cast<std::ptrdiff_t>(at), path.end());
          for (std::size_t k = at; k < path.size(); ++k) seen.erase(arr[path[k]].to);
          path.resize(at);
          seen[v] = path.size();
          emit_loop(arr, loop, result);
        } else {
          seen[v] = path.size();
        }
      }
      // Only unbalanced (numerically inconsistent) input leaves a path here;
      // Outline::close() joins it with a line.
      if (!path.empty()) emit_loop(arr, path, result);
    }
  }
  return result;
}

}  // namespace

Outline even_odd_to_nonzero(const Outline& outline) {
  if (!outline.is_finite()) throw Error(ErrorCode::Geometry, "even-odd fill: the outline has non-finite values");
  const std::vector<Segment> segs = usable_segments(outline);
  if (segs.empty()) return Outline{};
  const Box box = outline.control_box();
  const double diag = box.empty() ? 0.0 : distance(box.min, box.max);
  std::size_t vertex_count = 0;
  std::vector<Piece> arr = merge_vertices(split_at_crossings(segs, diag), diag, vertex_count);
  cancel_coincident(arr, merge_distance(diag));
  orient_by_parity(arr);
  return chain_loops(arr, vertex_count);
}

}  // namespace curvetext
