#include "curvetext/transform.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "curvetext/error.hpp"
#include "curvetext/tolerances.hpp"

namespace curvetext {

namespace {
double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }
}  // namespace

Transform Transform::translation(double dx, double dy) { return Transform{{1, 0, dx, 0, 1, dy, 0, 0, 1}}; }

Transform Transform::rotation(double degrees) {
  const double c = std::cos(radians(degrees)), s = std::sin(radians(degrees));
  return Transform{{c, -s, 0, s, c, 0, 0, 0, 1}};
}

Transform Transform::scale(double sx, double sy) { return Transform{{sx, 0, 0, 0, sy, 0, 0, 0, 1}}; }

Transform Transform::skew(double x_degrees, double y_degrees) {
  return Transform{{1, std::tan(radians(x_degrees)), 0, std::tan(radians(y_degrees)), 1, 0, 0, 0, 1}};
}

Transform Transform::perspective(double degrees, double distance) {
  // A point (x, y) of the plane goes to (x, y cos a, y sin a) in 3D, seen
  // from z = -distance: (x, y cos a) * distance / (distance + y sin a).
  const double c = std::cos(radians(degrees)), s = std::sin(radians(degrees));
  return Transform{{1, 0, 0, 0, c, 0, 0, s / distance, 1}};
}

Transform Transform::plane_to_viewport(const float mvp[16], double width, double height) {
  if (!(width > 0.0) || !(height > 0.0) || !std::isfinite(width) || !std::isfinite(height))
    throw Error(ErrorCode::InvalidArgument, "the viewport's sides must be positive and finite");
  for (int i = 0; i < 16; ++i)
    if (!std::isfinite(mvp[i])) throw Error(ErrorCode::InvalidArgument, "the matrix has a NaN or infinite entry");
  // (x, y, 0, 1) goes to clip = x col0 + y col1 + col3 (z's column drops out);
  // the viewport takes X = w/2 (cx + cw), Y = h/2 (cw - cy), over W = cw. The
  // input's second coordinate is -y, so column 1 enters negated.
  const double hw = width / 2.0, hh = height / 2.0;
  auto entry = [&](int column, int row) { return static_cast<double>(mvp[4 * column + row]); };
  Transform t;
  const int columns[3] = {0, 1, 3};
  const double sign[3] = {1.0, -1.0, 1.0};
  for (int k = 0; k < 3; ++k) {
    const int c = columns[k];
    t.m[0 + k] = sign[k] * hw * (entry(c, 0) + entry(c, 3));
    t.m[3 + k] = sign[k] * hh * (entry(c, 3) - entry(c, 1));
    t.m[6 + k] = sign[k] * entry(c, 3);
  }
  return t;
}

std::array<double, 3> Transform::plane_depth(const float mvp[16], double width, double height) {
  plane_to_viewport(mvp, width, height);  // the same checks
  // The plane's points are clip = x col0 + y col1 + col3; L with L . clip = 0
  // for all of them is the generalized cross product of those three columns.
  // Dividing by w: L0 x_ndc + L1 y_ndc + L2 z_ndc + L3 = 0.
  double c[3][4];
  const int columns[3] = {0, 1, 3};
  for (int k = 0; k < 3; ++k)
    for (int row = 0; row < 4; ++row) c[k][row] = static_cast<double>(mvp[4 * columns[k] + row]);
  auto minor = [&](int skip) {
    int col[3], n = 0;
    for (int i = 0; i < 4; ++i)
      if (i != skip) col[n++] = i;
    return c[0][col[0]] * (c[1][col[1]] * c[2][col[2]] - c[1][col[2]] * c[2][col[1]]) -
           c[0][col[1]] * (c[1][col[0]] * c[2][col[2]] - c[1][col[2]] * c[2][col[0]]) +
           c[0][col[2]] * (c[1][col[0]] * c[2][col[1]] - c[1][col[1]] * c[2][col[0]]);
  };
  const double l[4] = {minor(0), -minor(1), minor(2), -minor(3)};
  const double scale = std::max({std::abs(l[0]), std::abs(l[1]), std::abs(l[3])});
  if (!(std::abs(l[2]) > 1e-12 * scale)) return {0.0, 0.0, 0.0};  // edge-on
  // z_ndc = -(L0 x_ndc + L1 y_ndc + L3) / L2 with x_ndc = X / hw - 1, y_ndc = 1 - Y / hh.
  const double hw = width / 2.0, hh = height / 2.0;
  const double a = -l[0] / l[2], b = -l[1] / l[2], g = -l[3] / l[2];
  return {a / hw, -b / hh, g - a + b};
}

Transform Transform::about(Vec2 c) const { return translation(c.x, c.y) * *this * translation(-c.x, -c.y); }

bool Transform::is_identity() const { return m == Transform{}.m; }
bool Transform::is_affine() const { return m[6] == 0.0 && m[7] == 0.0 && m[8] == 1.0; }

Vec2 Transform::apply(Vec2 p) const {
  const double w_ = w(p);
  return {(m[0] * p.x + m[1] * p.y + m[2]) / w_, (m[3] * p.x + m[4] * p.y + m[5]) / w_};
}

namespace {
// Singular values of the Jacobian of the projective map at p.
void stretches(const Transform& t, Vec2 p, double& lo, double& hi) {
  const auto& m = t.m;
  const double w = t.w(p);
  const Vec2 q = t.apply(p);
  const double a = (m[0] - q.x * m[6]) / w, b = (m[1] - q.x * m[7]) / w;
  const double c = (m[3] - q.y * m[6]) / w, d = (m[4] - q.y * m[7]) / w;
  const double s = a * a + b * b + c * c + d * d, det = std::abs(a * d - b * c);
  hi = std::sqrt(0.5 * (s + std::sqrt(std::max(s * s - 4.0 * det * det, 0.0))));
  lo = hi > 0.0 ? det / hi : 0.0;
}
}  // namespace

double Transform::largest_stretch(Vec2 p) const {
  double lo, hi;
  stretches(*this, p, lo, hi);
  return hi;
}
double Transform::smallest_stretch(Vec2 p) const {
  double lo, hi;
  stretches(*this, p, lo, hi);
  return lo;
}

void Transform::validate() const {
  double largest = 0.0;
  for (double v : m) {
    if (!std::isfinite(v)) throw Error(ErrorCode::InvalidArgument, "the transform has a NaN or infinite entry");
    largest = std::max(largest, std::abs(v));
  }
  if (largest > tolerance::kMaxTransformEntry) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "a transform entry is %g, above the limit of %g", largest,
                  tolerance::kMaxTransformEntry);
    throw Error(ErrorCode::InvalidArgument, buf);
  }
  const double det =
      m[0] * (m[4] * m[8] - m[5] * m[7]) - m[1] * (m[3] * m[8] - m[5] * m[6]) + m[2] * (m[3] * m[7] - m[4] * m[6]);
  if (std::abs(det) <= tolerance::kMinTransformDeterminant * largest * largest * largest)
    throw Error(ErrorCode::InvalidArgument, "the transform is singular (it flattens the text to a line or a point)");
}

Transform operator*(const Transform& a, const Transform& b) {
  Transform r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      double s = 0.0;
      for (int k = 0; k < 3; ++k) s += a.m[i * 3 + k] * b.m[k * 3 + j];
      r.m[i * 3 + j] = s;
    }
  return r;
}

}  // namespace curvetext
