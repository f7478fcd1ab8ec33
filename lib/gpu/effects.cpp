// Text effects: effect outlines for the glyph cache and the shadow passes
// (docs/strokes.md, "Text effects").
#include "gpu/effects.hpp"

#include <GLES3/gl3.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <string>

#include "curvetext/error.hpp"
#include "curvetext/mesh.hpp"
#include "curvetext/tolerances.hpp"
#include "core/tolerances.hpp"
#include "gpu/batch_impl.hpp"
#include "gpu/gl_state.hpp"
#include "gpu/gl_util.hpp"
#include "gpu/shader_sources.hpp"

namespace curvetext::gpu {

namespace {
// The blur kernel's reach: 3 sigma of the largest blur radius (sigma = blur / 2).
constexpr int kMaxBlurRadius = static_cast<int>(1.5 * tolerance::kMaxShadowBlurPx);
constexpr std::uint32_t kKindShift = 24;
constexpr std::uint32_t kWidthMask = (std::uint32_t{1} << kKindShift) - 1;
static_assert(tolerance::kMaxTextEffectWidthEm * tolerance::kTextEffectWidthStepsPerEm < kWidthMask);
}  // namespace

std::uint32_t effect_code(EffectKind kind, double width_px, double pixels_per_em) {
  const double steps = std::round(width_px / pixels_per_em * tolerance::kTextEffectWidthStepsPerEm);
  if (!(steps >= 1.0)) return 0;
  const double capped = std::min(steps, static_cast<double>(kWidthMask));
  return (static_cast<std::uint32_t>(kind) << kKindShift) | static_cast<std::uint32_t>(capped);
}

namespace {

void to_contours(const Outline& outline, std::vector<ShapeContour>& out) {
  out.clear();
  for (const Contour& c : outline.contours()) {
    ShapeContour& sc = out.emplace_back();
    sc.closed = true;
    for (const Segment& s : c.segments) {
      if (s.kind == Segment::Kind::Line)
        sc.pieces.push_back(RationalBezier::line(s.p[0], s.p[1]));
      else if (s.kind == Segment::Kind::Conic)
        sc.pieces.push_back(RationalBezier::conic(s.p[0], s.p[1], s.p[2], s.weight));
      else
        sc.pieces.push_back(RationalBezier::cubic(s.p[0], s.p[1], s.p[2], s.p[3]));
    }
  }
}

// Appends `from`'s contours to `to`, each reversed when `reverse` is set.
void append_contours(const Outline& from, bool reverse, Outline& to) {
  for (const Contour& c : from.contours()) {
    Contour& r = to.contours().emplace_back();
    r.segments = c.segments;
    if (!reverse) continue;
    std::reverse(r.segments.begin(), r.segments.end());
    for (Segment& s : r.segments) {
      const int last = s.kind == Segment::Kind::Line ? 1 : s.kind == Segment::Kind::Conic ? 2 : 3;
      std::reverse(s.p, s.p + last + 1);
    }
  }
}

}  // namespace

namespace {

// `s` as lines within `flatness` of it: conics halved exactly until their
// control point is that close to their chord.
void flatten_into(const Segment& s, double flatness, std::vector<Segment>& out, int depth = 0) {
  const Vec2 mid{0.5 * (s.p[0].x + s.p[2].x), 0.5 * (s.p[0].y + s.p[2].y)};
  if (s.kind == Segment::Kind::Line || depth >= 24 || std::hypot(s.p[1].x - mid.x, s.p[1].y - mid.y) <= flatness) {
    out.push_back(Segment::line(s.p[0], s.kind == Segment::Kind::Line ? s.p[1] : s.p[2]));
    return;
  }
  const auto [a, b] = split(RationalBezier::conic(s.p[0], s.p[1], s.p[2], s.weight), 0.5);
  for (const RationalBezier* h : {&a, &b}) {
    const double w = h->weights[1] / std::sqrt(h->weights[0] * h->weights[2]);
    flatten_into(Segment::conic(h->points[0], h->points[1], h->points[2], w), flatness, out, depth + 1);
  }
}

void append_flattened(const Outline& from, double flatness, Outline& to) {
  for (const Contour& c : from.contours()) {
    Contour& f = to.contours().emplace_back();
    for (const Segment& s : c.segments) flatten_into(s, flatness, f.segments);
  }
}

}  // namespace

void effect_outline(std::uint32_t code, double units_per_em, double tolerance, Outline& glyph, EffectScratch& scratch) {
  const auto kind = static_cast<EffectKind>(code >> kKindShift);
  const double width = static_cast<double>(code & kWidthMask) / tolerance::kTextEffectWidthStepsPerEm * units_per_em;
  if (glyph.empty()) return;
  // The glyph's region as non-crossing contours, outer ones counter-clockwise.
  scratch.boundary = fill_boundary(glyph, FillRule::NonZero, tolerance);
  to_contours(scratch.boundary, scratch.contours);
  StrokeStyle style;
  style.join = LineJoin::Round;
  style.width = kind == EffectKind::Outline ? 2.0 * width : width;
  Outline stroke;
  scratch.stroker.stroke(scratch.contours, style, tolerance * tolerance::kEffectOffsetOfTolerance, 1.0, stroke);
  const bool negative = stroke.signed_area() < 0.0;
  // The dilated glyph (Outline) or the stroke (Stroke), resolved to winding 1.
  Outline both;
  if (kind == EffectKind::Outline) append_contours(scratch.boundary, false, both);
  append_contours(stroke, negative, both);
  try {
    scratch.dilated = fill_boundary(both, FillRule::NonZero, tolerance);
  } catch (const Error& e) {
    if (e.code() != ErrorCode::Geometry) throw;
    Outline flat;
    append_flattened(both, tolerance * tolerance::kEffectFlatnessOfTolerance, flat);
    scratch.dilated = fill_boundary(flat, FillRule::NonZero, tolerance);
  }
  glyph.clear();
  append_contours(scratch.dilated, false, glyph);
  // The glyph's boundary reversed takes the winding back to 0 inside it.
  if (kind == EffectKind::Outline) append_contours(scratch.boundary, true, glyph);
}

// --- Shadow passes ---------------------------------------------------------------

struct EffectPasses {
  GLuint program = 0;
  GLint u_viewport = -1, u_depth = -1, u_texture = -1, u_step = -1, u_sigma = -1, u_radius = -1, u_color = -1;
  GLuint vbo = 0, vao = 0;
  GLuint fbo[2] = {0, 0}, texture[2] = {0, 0};
  int w = 0, h = 0;  // allocated texels of both textures

  EffectPasses() = default;
  EffectPasses(const EffectPasses&) = delete;
  EffectPasses& operator=(const EffectPasses&) = delete;
  ~EffectPasses() {
    if (program != 0) glDeleteProgram(program);
    if (vbo != 0) glDeleteBuffers(1, &vbo);
    if (vao != 0) glDeleteVertexArrays(1, &vao);
    for (int i = 0; i < 2; ++i) {
      if (fbo[i] != 0) glDeleteFramebuffers(1, &fbo[i]);
      if (texture[i] != 0) glDeleteTextures(1, &texture[i]);
    }
  }
  void make_program(const ContextInfo& info);
  void ensure_targets(int need_w, int need_h);
};

void EffectPasses::make_program(const ContextInfo& info) {
  if (program != 0) return;
  const GLuint p =
      glsl1_program(shader_source::shadow_vert_glsl, shader_source::shadow_frag_glsl, info.gles, {"a_pixel", "a_uv"},
                    "the shadow program", "#define CURVETEXT_MAX_BLUR_RADIUS " + std::to_string(kMaxBlurRadius) + "\n");
  program = p;
  u_viewport = glGetUniformLocation(p, "u_viewport");
  u_depth = glGetUniformLocation(p, "u_depth");
  u_texture = glGetUniformLocation(p, "u_texture");
  u_step = glGetUniformLocation(p, "u_step");
  u_sigma = glGetUniformLocation(p, "u_sigma");
  u_radius = glGetUniformLocation(p, "u_radius");
  u_color = glGetUniformLocation(p, "u_color");
  glGenBuffers(1, &vbo);
  if (info.gl3()) glGenVertexArrays(1, &vao);
}

// Two RGBA8 textures with their framebuffers, grown (never per draw) to
// hold need_w x need_h texels.
void EffectPasses::ensure_targets(int need_w, int need_h) {
  if (fbo[0] != 0 && w >= need_w && h >= need_h) return;
  const int nw = std::max(w, (need_w + 63) / 64 * 64), nh = std::max(h, (need_h + 63) / 64 * 64);
  for (int i = 0; i < 2; ++i) {
    if (fbo[i] != 0) glDeleteFramebuffers(1, &fbo[i]);
    if (texture[i] != 0) glDeleteTextures(1, &texture[i]);
    texture[i] = new_texture(GL_RGBA, GL_RGBA, nw, nh);
    glGenFramebuffers(1, &fbo[i]);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo[i]);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture[i], 0);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
      throw Error(ErrorCode::Gl, "shadow framebuffer incomplete");
  }
  w = nw;
  h = nh;
}

namespace {

struct Region {
  int x0 = 0, y0 = 0, w = 0, h = 0;  // viewport pixels, y down
};

// The box of the batches' ink at `full` (font units -> viewport pixels),
// grown by the blur's reach and clipped to the viewport grown as much;
// the whole grown viewport where a corner is behind the eye.
Region shadow_region(std::span<const DrawBatch* const> batches, const Transform& full, int reach, float vw, float vh) {
  Box box;
  for (const DrawBatch* b : batches) {
    const Box& bb = DrawBatchAccess::impl(*b).bounds;
    if (bb.min.x <= bb.max.x) {
      box.add(bb.min);
      box.add(bb.max);
    }
  }
  const double rc = reach;
  if (!(box.min.x <= box.max.x)) return Region{};  // nothing inked (spaces)
  double x0 = -rc, y0 = -rc, x1 = double{vw} + rc, y1 = double{vh} + rc;
  {
    double bx0 = 1e300, by0 = 1e300, bx1 = -1e300, by1 = -1e300;
    bool behind = false;
    for (const Vec2 c : {box.min, box.max, Vec2{box.min.x, box.max.y}, Vec2{box.max.x, box.min.y}}) {
      if (!(full.w(c) > 0.0)) behind = true;
      const Vec2 p = full.apply(c);
      bx0 = std::min(bx0, p.x), by0 = std::min(by0, p.y), bx1 = std::max(bx1, p.x), by1 = std::max(by1, p.y);
    }
    if (!behind) {
      const double grow = reach + 2.0;  // the antialiasing fringe
      x0 = std::max(x0, std::floor(bx0 - grow)), y0 = std::max(y0, std::floor(by0 - grow));
      x1 = std::min(x1, std::ceil(bx1 + grow)), y1 = std::min(y1, std::ceil(by1 + grow));
    }
  }
  Region r;
  if (!(x1 > x0 && y1 > y0)) return r;
  r.x0 = static_cast<int>(x0), r.y0 = static_cast<int>(y0);
  r.w = static_cast<int>(x1 - x0), r.h = static_cast<int>(y1 - y0);
  return r;
}

// A quad from pixel (px0, py0) to (px1, py1) (y down) showing the region's
// texels of a w x h texture (row 0 its bottom).
void draw_quad(const EffectPasses& p, float px0, float py0, float px1, float py1, const Region& r) {
  const float u1 = static_cast<float>(r.w) / static_cast<float>(p.w),
              v1 = static_cast<float>(r.h) / static_cast<float>(p.h);
  const float quad[16] = {px0, py0, 0.0f, v1, px1, py0, u1, v1, px0, py1, 0.0f, 0.0f, px1, py1, u1, 0.0f};
  glBindBuffer(GL_ARRAY_BUFFER, p.vbo);
  glBufferData(GL_ARRAY_BUFFER, sizeof quad, quad, GL_STREAM_DRAW);
  glEnableVertexAttribArray(0);
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 4 * sizeof(float), nullptr);
  glVertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, 4 * sizeof(float), reinterpret_cast<void*>(2 * sizeof(float)));
  glDrawArrays(GL_TRIANGLE_STRIP, 0, 4);
}

// curvetext's state for the blur passes (the backup puts the application's back).
void bind_blur_state(const ContextInfo& info, const EffectPasses& p) {
  if (info.gl3()) {
    glBindVertexArray(p.vao);
    glDisable(GL_RASTERIZER_DISCARD);
    glBindSampler(0, 0);
  } else {
    glDisableVertexAttribArray(2);
  }
  glUseProgram(p.program);
  glActiveTexture(GL_TEXTURE0);
  glUniform1i(p.u_texture, 0);
  glBlendEquation(GL_FUNC_ADD);
  glDisable(GL_STENCIL_TEST);
  glDisable(GL_CULL_FACE);
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

}  // namespace

void draw_shadow(Renderer& renderer, std::span<const DrawBatch* const> batches, const Placement& at,
                 const DrawOptions& options, const TextShadow& shadow) {
  if (batches.empty() || !(shadow.color.a > 0.0f)) return;
  check_no_pending_error("the shadow pass");
  const ContextInfo info = ContextInfo::current();
  const GlStateBackup state(info);
  const float vw = static_cast<float>(state.viewport()[2]), vh = static_cast<float>(state.viewport()[3]);
  const double sigma = shadow.blur / 2.0;
  const int radius = static_cast<int>(std::min<double>(std::ceil(3.0 * sigma), kMaxBlurRadius));
  Placement moved = at;
  moved.origin_x += shadow.dx;
  moved.origin_y += shadow.dy;
  const double s = at.scale;
  const Transform full = at.transform * Transform{{s, 0.0, moved.origin_x, 0.0, -s, moved.origin_y, 0.0, 0.0, 1.0}};
  const Region r = shadow_region(batches, full, radius, vw, vh);
  GLint max_side = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_side);
  if (r.w <= 0 || r.h <= 0) return;
  if (r.w > max_side || r.h > max_side)
    throw Error(ErrorCode::Gl, "a shadow's region of " + std::to_string(r.w) + "x" + std::to_string(r.h) +
                                   " px exceeds the GL texture limit");
  std::shared_ptr<EffectPasses>& slot = effect_passes(renderer);
  if (!slot) slot = std::make_shared<EffectPasses>();
  EffectPasses& p = *slot;
  p.make_program(info);
  p.ensure_targets(r.w, r.h);

  // 1. The ink's coverage, moved, into texture 0 (the region's top-left at its top-left).
  glBindFramebuffer(GL_FRAMEBUFFER, p.fbo[0]);
  glViewport(0, 0, r.w, r.h);
  glDisable(GL_SCISSOR_TEST);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  moved.transform = Transform::translation(-r.x0, -r.y0) * at.transform;
  moved.depth = {0.0, 0.0, 0.0};
  moved.depth_offset = 0.0;
  moved.depth_test = DepthTest::Off;
  DrawOptions white = options;
  white.color = Color{1, 1, 1, 1};
  white.gradient = nullptr;
  white.debug = false;
  for (const DrawBatch* b : batches) renderer.draw(*b, moved, white);

  // 2. Blurred along x into texture 1.
  bind_blur_state(info, p);
  glBindFramebuffer(GL_FRAMEBUFFER, p.fbo[1]);
  glViewport(0, 0, r.w, r.h);
  // Cleared whole: the vertical pass reads up to the radius past the region.
  glClear(GL_COLOR_BUFFER_BIT);
  glUniform2f(p.u_viewport, static_cast<float>(r.w), static_cast<float>(r.h));
  glUniform3f(p.u_depth, 0.0f, 0.0f, 0.0f);
  glUniform1f(p.u_sigma, static_cast<float>(sigma));
  glUniform1f(p.u_radius, static_cast<float>(radius));
  glUniform2f(p.u_step, 1.0f / static_cast<float>(p.w), 0.0f);
  glUniform4f(p.u_color, 1.0f, 1.0f, 1.0f, 1.0f);
  glBindTexture(GL_TEXTURE_2D, p.texture[0]);
  draw_quad(p, 0.0f, 0.0f, static_cast<float>(r.w), static_cast<float>(r.h), r);

  // 3. Blurred along y, in the shadow's colour, into the application's
  // framebuffer at the placement's depth.
  state.apply_target();
  if (at.depth_test == DepthTest::Off) glDisable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  glUniform2f(p.u_viewport, vw, vh);
  glUniform3f(p.u_depth, static_cast<float>(at.depth[0]), static_cast<float>(at.depth[1]),
              static_cast<float>(at.depth[2] - at.depth_offset));
  glUniform2f(p.u_step, 0.0f, 1.0f / static_cast<float>(p.h));
  const std::array<float, 4> c =
      premultiplied(shadow.color, bound_framebuffer_blending(info.gles, info.gl3(), state.draw_framebuffer()));
  glUniform4f(p.u_color, c[0], c[1], c[2], c[3]);
  glBindTexture(GL_TEXTURE_2D, p.texture[1]);
  draw_quad(p, static_cast<float>(r.x0), static_cast<float>(r.y0), static_cast<float>(r.x0 + r.w),
            static_cast<float>(r.y0 + r.h), r);
  if (GLenum err = glGetError(); err != GL_NO_ERROR)
    throw Error(ErrorCode::Gl, "drawing a text shadow failed (GL error " + hex(err) + ")");
}

}  // namespace curvetext::gpu
