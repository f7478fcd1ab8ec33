// Text in a 3D scene is depth-tested against the application's geometry
// (Placement::depth): in every context kind and antialiasing mode, text
// behind the application's quad is hidden, text in front of it is drawn,
// a sloped depth plane hides it exactly where the plane passes behind, and
// where nothing hides it the coverage is the exact coverage of its outline.
// Text on a plane (Placement::on_plane) drawn after the plane shows (its
// depth offset), HUD text can be drawn over near geometry (DepthTest::Off),
// and a TextBlock takes the same Placement.
#include <GLES3/gl3.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <string>
#include <tuple>
#include <vector>

#include "curvetext/font.hpp"
#include "curvetext/font_collection.hpp"
#include "curvetext/headless.hpp"
#include "curvetext/layout.hpp"
#include "curvetext/renderer.hpp"
#include "curvetext/shaping.hpp"
#include "curvetext/text_block.hpp"
#include "support/camera.hpp"
#include "support/coverage.hpp"
#include "support/fonts.hpp"
#include "support/gpu.hpp"
#include "support/union_coverage.hpp"

namespace curvetext {
namespace {

constexpr int kW = 240, kH = 80;
constexpr double kPx = 40.0;

bool desktop() {
  const char* v = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  return std::string(v).rfind("OpenGL ES", 0) != 0;
}

// The application: a framebuffer with a depth buffer, and a program drawing
// a flat quad at a given normalized device z.
struct Scene {
  GLuint fbo = 0, color = 0, depth = 0, program = 0, plane_program = 0, vao = 0, vbo = 0;
  GLint u_z = -1, u_mvp = -1;

  Scene() {
    glGenTextures(1, &color);
    glBindTexture(GL_TEXTURE_2D, color);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, kW, kH, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    glGenRenderbuffers(1, &depth);
    glBindRenderbuffer(GL_RENDERBUFFER, depth);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT16, kW, kH);
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color, 0);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
    EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), static_cast<GLenum>(GL_FRAMEBUFFER_COMPLETE));
    glViewport(0, 0, kW, kH);
    const bool d = desktop();
    const std::string vs = d ? "#version 330 core\nlayout(location = 0) in vec2 p;\nuniform float z;\n"
                               "void main() { gl_Position = vec4(p, z, 1.0); }\n"
                             : "#version 100\nattribute vec2 p;\nuniform float z;\n"
                               "void main() { gl_Position = vec4(p, z, 1.0); }\n";
    const std::string fs = d ? "#version 330 core\nout vec4 c;\nvoid main() { c = vec4(0.5, 0.5, 0.5, 1.0); }\n"
                             : "#version 100\nvoid main() { gl_FragColor = vec4(0.5, 0.5, 0.5, 1.0); }\n";
    program = link(vs, fs);
    u_z = glGetUniformLocation(program, "z");
    // The plane z = 0 through a model-view-projection, as a 3D app draws it.
    const std::string plane_vs = d ? "#version 330 core\nlayout(location = 0) in vec2 p;\nuniform mat4 mvp;\n"
                                     "void main() { gl_Position = mvp * vec4(p, 0.0, 1.0); }\n"
                                   : "#version 100\nattribute vec2 p;\nuniform mat4 mvp;\n"
                                     "void main() { gl_Position = mvp * vec4(p, 0.0, 1.0); }\n";
    plane_program = link(plane_vs, fs);
    u_mvp = glGetUniformLocation(plane_program, "mvp");
    if (d) {
      glGenVertexArrays(1, &vao);
      glBindVertexArray(vao);
    }
    glGenBuffers(1, &vbo);
  }

  static GLuint link(const std::string& vs, const std::string& fs) {
    const GLuint program = glCreateProgram();
    for (const auto& [type, src] : {std::pair{GL_VERTEX_SHADER, vs}, std::pair{GL_FRAGMENT_SHADER, fs}}) {
      const GLuint s = glCreateShader(type);
      const char* p = src.c_str();
      glShaderSource(s, 1, &p, nullptr);
      glCompileShader(s);
      glAttachShader(program, s);
    }
    glBindAttribLocation(program, 0, "p");
    glLinkProgram(program);
    return program;
  }

  // White, depth 1 everywhere; the depth test on (GL_LESS, writes on).
  void clear() const {
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glViewport(0, 0, kW, kH);
    glClearColor(1, 1, 1, 1);
    glClearDepthf(1.0f);
    glDepthMask(GL_TRUE);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
  }

  // A grey quad over the framebuffer's columns [0, x1) at device z.
  void quad(int x1, float z) const {
    const float cx = 2.0f * static_cast<float>(x1) / kW - 1.0f;
    const float v[12] = {-1, -1, cx, -1, cx, 1, -1, -1, cx, 1, -1, 1};
    glUseProgram(program);
    glUniform1f(u_z, z);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glBufferData(GL_ARRAY_BUFFER, sizeof v, v, GL_STREAM_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, nullptr);
    glDrawArrays(GL_TRIANGLES, 0, 6);
    glDisableVertexAttribArray(0);
  }

  // The grey square [-h, h]^2 of the plane z = 0 seen through `mvp`.
  void plane(const std::array<float, 16>& mvp, float h) const {
    const float v[12] = {-h, -h, h, -h, h, h, -h, -h, h, h, -h, h};
    glUseProgram(plane_program);
    glUniformMatrix4fv(u_mvp, 1, GL_FALSE, mvp.data());
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glBufferData(GL_ARRAY_BUFFER, sizeof v, v, GL_STREAM_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, nullptr);
    glDrawArrays(GL_TRIANGLES, 0, 6);
    glDisableVertexAttribArray(0);
  }

  // The framebuffer, row 0 at the top.
  std::vector<std::uint8_t> pixels() const {
    std::vector<std::uint8_t> gl_rows(static_cast<std::size_t>(kW) * kH * 4), out(gl_rows.size());
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glReadPixels(0, 0, kW, kH, GL_RGBA, GL_UNSIGNED_BYTE, gl_rows.data());
    const std::size_t row = static_cast<std::size_t>(kW) * 4;
    for (int y = 0; y < kH; ++y)
      std::copy_n(&gl_rows[static_cast<std::size_t>(kH - 1 - y) * row], row, &out[static_cast<std::size_t>(y) * row]);
    return out;
  }
};

std::uint8_t red(const std::vector<std::uint8_t>& px, int x, int y) {
  return px[(static_cast<std::size_t>(y) * kW + static_cast<std::size_t>(x)) * 4];
}

double edge_limit(AntiAliasing aa) {
  switch (aa) {
    case AntiAliasing::Full:
    case AntiAliasing::Vbaa:
      return 0.005;
    case AntiAliasing::Msaa:
      return 0.06;
    case AntiAliasing::Curves:
      return 0.12;
    default:
      return 0.3;  // none: an in/out test per pixel centre
  }
}

class Depth : public ::testing::TestWithParam<ContextKind> {};

TEST_P(Depth, TextIsHiddenBehindTheScenesGeometryAndExactElsewhere) {
  const bool gles2_run = test::expects_gles2();
  if (gles2_run && GetParam() != ContextKind::Gles2) GTEST_SKIP() << "OpenGL ES 2.0 only in this run";
  HeadlessContext context = HeadlessContext::create(GetParam());
  std::printf("%s: %s\n", context_kind_name(GetParam()), context.version().c_str());
  const Font font = Font::open(test::kDejaVuSans);
  GlyphCache cache;
  Renderer renderer;
  const Scene scene;
  const ShapedLine line = shape_line(font, "Depth test");
  const DrawBatch batch = DrawBatch::from_text(cache, font, line, kPx);
  Placement at(kPx / font.metrics().units_per_em, 8.25, 55.5);
  Placement flat = at;
  flat.transform = Transform{};
  const test::Coverage exact = test::union_coverage(test::place_outline(test::line_outline(font, line), flat), kW, kH);
  constexpr int kHalf = kW / 2;

  for (AntiAliasing aa :
       {AntiAliasing::None, AntiAliasing::Curves, AntiAliasing::Full, AntiAliasing::Vbaa, AntiAliasing::Msaa}) {
    const std::string mode =
        std::string(context_kind_name(GetParam())) + " mode " + std::to_string(static_cast<int>(aa));
    const DrawOptions black(Color{0, 0, 0, 1}, aa);
    // Behind the quad over the left half: hidden there, drawn on the right.
    scene.clear();
    scene.quad(kHalf, 0.0f);
    at.depth = {0.0, 0.0, 0.5};
    renderer.draw(batch, at, black);
    std::vector<std::uint8_t> px = scene.pixels();
    int grey_changed = 0;
    test::Coverage right(kW, kH), right_exact(kW, kH);
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x) {
        if (x < kHalf) {
          grey_changed += red(px, x, y) != 128 && red(px, x, y) != 127 ? 1 : 0;
        } else {
          right.at(x, y) = 1.0f - red(px, x, y) / 255.0f;
          right_exact.at(x, y) = exact.at(x, y);
        }
      }
    EXPECT_EQ(grey_changed, 0) << mode << ": text behind the quad showed through";
    // The uncovered half: exact coverage, within the split-screen test's
    // limits for the mode (render_test.cpp; none is aliased).
    const test::CoverageStats st = test::compare(right, right_exact);
    test::expect_coverage("depth-behind-" + std::to_string(static_cast<int>(aa)) + "-" + context_kind_name(GetParam()),
                          right, right_exact, st, edge_limit(aa),
                          aa == AntiAliasing::Curves || aa == AntiAliasing::None ? 0.1 : 0.03);

    // In front of the quad: drawn over it on the left too.
    scene.clear();
    scene.quad(kHalf, 0.0f);
    at.depth = {0.0, 0.0, -0.5};
    renderer.draw(batch, at, black);
    px = scene.pixels();
    int dark_left = 0;
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kHalf; ++x) dark_left += red(px, x, y) < 40 ? 1 : 0;
    EXPECT_GT(dark_left, 150) << mode << ": text in front of the quad is missing";

    // A sloped plane through z = 0 at the middle column, in front on the
    // left, behind on the right, against a quad over the whole width: ink
    // only left of the middle (a pixel's margin for the fringe).
    scene.clear();
    scene.quad(kW, 0.0f);
    at.depth = {1.0 / kW, 0.0, -0.5};
    renderer.draw(batch, at, black);
    px = scene.pixels();
    int ink_right = 0, ink_left = 0;
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kW; ++x) {
        const bool dark = red(px, x, y) < 120;
        if (x >= kHalf + 1) ink_right += dark ? 1 : 0;
        if (x < kHalf - 1) ink_left += dark ? 1 : 0;
      }
    EXPECT_EQ(ink_right, 0) << mode << ": text behind the sloped plane's crossing showed";
    EXPECT_GT(ink_left, 150) << mode;
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR)) << mode;
  }
}

// 1 - (the framebuffer with text) / (the same without): the text's coverage
// over whatever the scene drew there (black text), from the red channel.
test::Coverage coverage_over(const std::vector<std::uint8_t>& with_text, const std::vector<std::uint8_t>& scene) {
  test::Coverage c(kW, kH);
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x)
      c.at(x, y) = red(scene, x, y) == 0 ? 0.0f : 1.0f - static_cast<float>(red(with_text, x, y)) / red(scene, x, y);
  return c;
}

// Text lying on a plane, drawn after the plane with the depth test GL_LESS:
// its depth is the plane's own, so without a depth offset it z-fights (hidden
// wherever its depth rounds to the plane's or behind it). With on_plane's
// depth offset its coverage over the plane is the exact coverage of its
// outline, and without it (the control) ink is missing.
TEST_P(Depth, TextOnAPlaneDrawnAfterThePlaneShows) {
  const bool gles2_run = test::expects_gles2();
  if (gles2_run && GetParam() != ContextKind::Gles2) GTEST_SKIP() << "OpenGL ES 2.0 only in this run";
  HeadlessContext context = HeadlessContext::create(GetParam());
  const Font font = Font::open(test::kDejaVuSans);
  GlyphCache cache;
  Renderer renderer;
  const Scene scene;
  const std::array<float, 16> mvp = test::camera_mvp(static_cast<double>(kW) / kH);
  const ShapedLine line = shape_line(font, "Plane");
  const DrawBatch batch = DrawBatch::from_text(cache, font, line, 48.0);
  const Placement at = Placement::on_plane(mvp.data(), kW, kH, 0.0008, -0.6, 0.1);
  EXPECT_GT(at.depth_offset, Placement::kOnPlaneDepthOffset);  // plus the plane's slope over a pixel
  Placement flat = at;
  flat.transform = Transform{};
  const test::Coverage exact = test::union_coverage(
      test::transform_outline(test::place_outline(test::line_outline(font, line), flat), at.transform), kW, kH);
  scene.clear();
  scene.plane(mvp, 4.0f);
  const std::vector<std::uint8_t> plane_only = scene.pixels();
  for (AntiAliasing aa :
       {AntiAliasing::None, AntiAliasing::Curves, AntiAliasing::Full, AntiAliasing::Vbaa, AntiAliasing::Msaa}) {
    const std::string mode = std::string(context_kind_name(GetParam())) + "-" + std::to_string(static_cast<int>(aa));
    const DrawOptions black(Color{0, 0, 0, 1}, aa);
    scene.clear();
    scene.plane(mvp, 4.0f);
    renderer.draw(batch, at, black);
    const test::Coverage got = coverage_over(scene.pixels(), plane_only);
    const test::CoverageStats st = test::compare(got, exact);
    std::printf("%s: text on the plane: ink %.4f, edge %.4f (%zu edge pixels)\n", mode.c_str(), st.ink_ratio,
                st.edge_mean_abs, st.edge_pixels);
    EXPECT_GT(st.edge_pixels, 100u) << mode;
    // The grey under the text has 128 levels: coverage is known to 1/128.
    const bool aliased = aa == AntiAliasing::Curves || aa == AntiAliasing::None;
    test::expect_coverage("on-plane-" + mode, got, exact, st, std::max(edge_limit(aa), 0.01), aliased ? 0.1 : 0.03);

    // The control: the plane's depth as it is, no offset.
    Placement no_offset = at;
    no_offset.depth_offset = 0.0;
    scene.clear();
    scene.plane(mvp, 4.0f);
    renderer.draw(batch, no_offset, black);
    const test::CoverageStats fighting = test::compare(coverage_over(scene.pixels(), plane_only), exact);
    std::printf("%s: without the depth offset: ink %.4f\n", mode.c_str(), fighting.ink_ratio);
    EXPECT_LT(fighting.ink_ratio, 0.8) << mode << ": the control drew the text without z-fighting";
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR)) << mode;
  }
}

// HUD text while the application's depth test is on: at its default depth 0
// (window depth 0.5) geometry nearer than that hides it; with
// DepthTest::Off it is drawn over the geometry, at its exact coverage, and
// the application's depth test is on again afterwards. A TextBlock takes the
// same Placement, depth included.
TEST_P(Depth, HudTextWithTheDepthTestOffIsDrawnOverNearGeometry) {
  const bool gles2_run = test::expects_gles2();
  if (gles2_run && GetParam() != ContextKind::Gles2) GTEST_SKIP() << "OpenGL ES 2.0 only in this run";
  HeadlessContext context = HeadlessContext::create(GetParam());
  const Font font = Font::open(test::kDejaVuSans);
  GlyphCache cache;
  Renderer renderer;
  const Scene scene;
  const ShapedLine line = shape_line(font, "HUD text");
  const DrawBatch batch = DrawBatch::from_text(cache, font, line, kPx);
  Placement hud(kPx / font.metrics().units_per_em, 8.25, 55.5);
  const test::Coverage exact = test::union_coverage(test::place_outline(test::line_outline(font, line), hud), kW, kH);
  constexpr int kHalf = kW / 2;
  scene.clear();
  scene.quad(kHalf, -0.9f);  // near geometry over the left half
  const std::vector<std::uint8_t> scene_only = scene.pixels();
  auto ink_left = [&](const std::vector<std::uint8_t>& px) {
    int n = 0;
    for (int y = 0; y < kH; ++y)
      for (int x = 0; x < kHalf; ++x) n += red(px, x, y) != red(scene_only, x, y);
    return n;
  };
  for (AntiAliasing aa : {AntiAliasing::Curves, AntiAliasing::Full, AntiAliasing::Msaa}) {
    const std::string mode = std::string(context_kind_name(GetParam())) + "-" + std::to_string(static_cast<int>(aa));
    const DrawOptions black(Color{0, 0, 0, 1}, aa);
    hud.depth_test = DepthTest::Application;
    scene.clear();
    scene.quad(kHalf, -0.9f);
    renderer.draw(batch, hud, black);
    EXPECT_EQ(ink_left(scene.pixels()), 0) << mode << ": the app's depth test let HUD text at depth 0 through";

    hud.depth_test = DepthTest::Off;
    scene.clear();
    scene.quad(kHalf, -0.9f);
    renderer.draw(batch, hud, black);
    EXPECT_TRUE(glIsEnabled(GL_DEPTH_TEST)) << mode;
    const test::Coverage got = coverage_over(scene.pixels(), scene_only);
    const test::CoverageStats st = test::compare(got, exact);
    const bool aliased = aa == AntiAliasing::Curves;
    test::expect_coverage("hud-over-" + mode, got, exact, st, std::max(edge_limit(aa), 0.01), aliased ? 0.1 : 0.03);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR)) << mode;
  }

  // A paragraph's TextBlock: behind the quad, in front of it, and over it.
  FontCollection fonts;
  ParagraphStyle style;
  style.default_style.fonts = {test::kDejaVuSans};
  style.default_style.size_px = kPx;
  const Paragraph paragraph = Paragraph::layout(fonts, "Block text", {}, style);
  const TextBlock block = TextBlock::from_paragraph(cache, paragraph);
  Placement at(1.0, 8.25, 10.5);
  const DrawOptions full(Color{0, 0, 0, 1}, AntiAliasing::Full);
  for (const auto& [z, test_mode, drawn_left] :
       {std::tuple{0.5, DepthTest::Application, false}, std::tuple{-0.95, DepthTest::Application, true},
        std::tuple{0.5, DepthTest::Off, true}}) {
    at.depth = {0.0, 0.0, z};
    at.depth_test = test_mode;
    scene.clear();
    scene.quad(kHalf, -0.9f);
    block.draw(renderer, at, full);
    const std::vector<std::uint8_t> px = scene.pixels();
    int ink_right = 0;
    for (int y = 0; y < kH; ++y)
      for (int x = kHalf; x < kW; ++x) ink_right += red(px, x, y) < 128;
    EXPECT_GT(ink_right, 100) << "text block at z " << z;
    if (drawn_left)
      EXPECT_GT(ink_left(px), 150) << "text block at z " << z;
    else
      EXPECT_EQ(ink_left(px), 0) << "text block at z " << z;
  }
}

// A block with an outline, a centred stroke and a blurred shadow is
// depth-tested like its text: behind the quad over the left half none of it
// shows there (the shadow's composite included), in front of it all of it.
TEST_P(Depth, TextEffectsAreDepthTestedLikeTheText) {
  const bool gles2_run = test::expects_gles2();
  if (gles2_run && GetParam() != ContextKind::Gles2) GTEST_SKIP() << "OpenGL ES 2.0 only in this run";
  HeadlessContext context = HeadlessContext::create(GetParam());
  GlyphCache cache;
  Renderer renderer;
  const Scene scene;
  FontCollection fonts;
  ParagraphStyle style;
  style.default_style.fonts = {test::kDejaVuSans};
  style.default_style.size_px = kPx;
  style.default_style.effects.outline_width = 3.0;
  style.default_style.effects.outline_color = Color{1, 0, 0, 1};
  style.default_style.effects.stroke_width = 1.0;
  style.default_style.effects.shadow = TextShadow{2.0, 2.0, 6.0, Color{0, 0, 1, 1}};
  const TextBlock block = TextBlock::from_paragraph(cache, Paragraph::layout(fonts, "Effects here", {}, style));
  constexpr int kHalf = kW / 2;
  for (AntiAliasing aa : {AntiAliasing::Curves, AntiAliasing::Full, AntiAliasing::Msaa}) {
    const std::string mode = std::string(context_kind_name(GetParam())) + "-" + std::to_string(static_cast<int>(aa));
    for (const double z : {0.5, -0.5}) {
      Placement at(1.0, 8.25, 10.5);
      at.depth = {0.0, 0.0, z};
      scene.clear();
      scene.quad(kHalf, 0.0f);
      block.draw(renderer, at, DrawOptions(Color{0, 0, 0, 1}, aa));
      const std::vector<std::uint8_t> px = scene.pixels();
      int changed_left = 0, ink_right = 0, shadow_left = 0;
      for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
          const std::uint8_t* p = &px[(static_cast<std::size_t>(y) * kW + x) * 4];
          if (x < kHalf) {
            changed_left += (p[0] < 126 || p[0] > 129 || p[2] < 126 || p[2] > 129) ? 1 : 0;
            shadow_left += p[2] > p[0] + 20 ? 1 : 0;  // the blue shadow over the grey quad
          } else
            ink_right += p[0] < 250 || p[2] < 250 ? 1 : 0;
        }
      EXPECT_GT(ink_right, 500) << mode << " z " << z;
      if (z > 0) {
        EXPECT_EQ(changed_left, 0) << mode << ": effects behind the quad showed through";
      } else {
        EXPECT_GT(changed_left, 500) << mode << ": effects in front of the quad are missing";
        EXPECT_GT(shadow_left, 100) << mode << ": the shadow in front of the quad is missing";
      }
      EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR)) << mode;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Kinds, Depth,
                         ::testing::Values(ContextKind::Gles2, ContextKind::Gles3, ContextKind::GlCore,
                                           ContextKind::GlCompat),
                         [](const ::testing::TestParamInfo<ContextKind>& p) {
                           std::string n = context_kind_name(p.param);
                           for (char& c : n)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return n;
                         });

}  // namespace
}  // namespace curvetext
