// Gradient paint: validation and the composite shader's uniforms.
#include "gpu/paint.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "curvetext/error.hpp"
#include "gpu/gl_util.hpp"

namespace curvetext {

namespace {

[[noreturn]] void fail(const std::string& message) { throw Error(ErrorCode::InvalidArgument, "gradient: " + message); }

bool finite(Vec2 p) { return std::isfinite(p.x) && std::isfinite(p.y); }

}  // namespace

void validate_gradient(const Gradient& g) {
  if (g.stops.empty()) fail("no stops");
  if (g.stops.size() > static_cast<std::size_t>(kMaxGradientStops))
    fail(std::to_string(g.stops.size()) + " stops; at most " + std::to_string(kMaxGradientStops) + " are drawn");
  float previous = 0.0f;
  for (const GradientStop& s : g.stops) {
    if (!(s.offset >= previous && s.offset <= 1.0f)) fail("stop offsets must rise within [0, 1]");
    previous = s.offset;
    for (float c : {s.color.r, s.color.g, s.color.b, s.color.a})
      if (!std::isfinite(c)) fail("a stop colour is not finite");
  }
  if (!finite(g.start) || !finite(g.end) || !finite(g.centre) || !finite(g.focus) || !std::isfinite(g.radius) ||
      !std::isfinite(g.focal_radius) || !std::isfinite(g.start_angle) || !std::isfinite(g.end_angle))
    fail("a coordinate is not finite");
  if (g.kind == Gradient::Kind::Linear && g.start == g.end) fail("a linear gradient needs start != end");
  if (g.kind == Gradient::Kind::Radial) {
    if (!(g.radius > 0.0 || g.focal_radius > 0.0)) fail("a radial gradient needs a circle of positive radius");
    if (g.focus == g.centre && g.radius == g.focal_radius) fail("a radial gradient's two circles are the same");
  }
  if (g.kind == Gradient::Kind::Sweep && !(g.start_angle != g.end_angle))
    fail("a sweep gradient needs start_angle != end_angle");
  // Any invertible projective map: Transform::validate's scale limits are
  // for pixel maps, and a gradient's unit box may be far smaller or larger.
  const auto& m = g.from_outline.m;
  for (double v : m)
    if (!std::isfinite(v)) fail("its transform has a value that is not finite");
  const double det =
      m[0] * (m[4] * m[8] - m[5] * m[7]) - m[1] * (m[3] * m[8] - m[5] * m[6]) + m[2] * (m[3] * m[7] - m[4] * m[6]);
  if (!std::isfinite(det) || det == 0.0) fail("its transform is singular");
}

namespace gpu {

Transform inverse(const Transform& t) {
  const auto& m = t.m;
  const double a = m[4] * m[8] - m[5] * m[7], b = m[5] * m[6] - m[3] * m[8], c = m[3] * m[7] - m[4] * m[6];
  const double det = m[0] * a + m[1] * b + m[2] * c;
  const double k = 1.0 / det;
  return Transform{{a * k, (m[2] * m[7] - m[1] * m[8]) * k, (m[1] * m[5] - m[2] * m[4]) * k, b * k,
                    (m[0] * m[8] - m[2] * m[6]) * k, (m[2] * m[3] - m[0] * m[5]) * k, c * k,
                    (m[1] * m[6] - m[0] * m[7]) * k, (m[0] * m[4] - m[1] * m[3]) * k}};
}

PaintUniforms PaintUniforms::of(GLuint program) {
  PaintUniforms u;
  u.paint = glGetUniformLocation(program, "u_paint");
  u.kind = glGetUniformLocation(program, "u_kind");
  u.spread = glGetUniformLocation(program, "u_spread");
  u.a = glGetUniformLocation(program, "u_a");
  u.b = glGetUniformLocation(program, "u_b");
  u.radius = glGetUniformLocation(program, "u_radius");
  u.focal_radius = glGetUniformLocation(program, "u_focal_radius");
  u.count = glGetUniformLocation(program, "u_count");
  u.stop_color = glGetUniformLocation(program, "u_stop_color");
  u.stop_offset = glGetUniformLocation(program, "u_stop_offset");
  return u;
}

void PaintUniforms::set(const Gradient& g, const Transform& full, Blending blending) const {
  // Pixels -> outline units -> gradient coordinates, as a column-major mat3.
  const Transform to_paint = g.from_outline * inverse(full);
  GLfloat m[9];
  for (int row = 0; row < 3; ++row)
    for (int col = 0; col < 3; ++col) m[col * 3 + row] = static_cast<GLfloat>(to_paint.m[row * 3 + col]);
  glUniformMatrix3fv(paint, 1, GL_FALSE, m);
  glUniform1f(kind, static_cast<float>(static_cast<int>(g.kind)));
  glUniform1f(spread, static_cast<float>(static_cast<int>(g.spread)));
  Vec2 pa = g.start, pb = g.end;
  if (g.kind == Gradient::Kind::Radial) {
    pa = g.focus;
    pb = g.centre;
  } else if (g.kind == Gradient::Kind::Sweep) {
    const double radians = 3.14159265358979323846 / 180.0;
    pa = g.centre;
    pb = Vec2{g.start_angle * radians, g.end_angle * radians};
  }
  glUniform2f(a, static_cast<float>(pa.x), static_cast<float>(pa.y));
  glUniform2f(b, static_cast<float>(pb.x), static_cast<float>(pb.y));
  glUniform1f(radius, static_cast<float>(g.radius));
  glUniform1f(focal_radius, static_cast<float>(g.focal_radius));
  glUniform1f(count, static_cast<float>(g.stops.size()));
  GLfloat colors[4 * kMaxGradientStops] = {}, offsets[kMaxGradientStops] = {};
  for (std::size_t i = 0; i < g.stops.size(); ++i) {
    // Straight alpha, in the space the target blends in; the shader
    // interpolates, then premultiplies (as SVG renderers interpolate stops).
    const Color& k = g.stops[i].color;
    const std::array<float, 4> c = premultiplied(Color{k.r, k.g, k.b, 1.0f}, blending);
    for (int j = 0; j < 3; ++j) colors[4 * i + j] = c[j];
    colors[4 * i + 3] = std::clamp(k.a, 0.0f, 1.0f);
    offsets[i] = g.stops[i].offset;
  }
  glUniform4fv(stop_color, kMaxGradientStops, colors);
  glUniform1fv(stop_offset, kMaxGradientStops, offsets);
}

}  // namespace gpu
}  // namespace curvetext
