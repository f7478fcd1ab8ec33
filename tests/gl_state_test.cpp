// The library is a guest in the application's GL context (docs/design.md section
// 5): in every context kind and every antialiasing mode, a draw leaves the
// application's GL state as it found it, draws into the application's
// framebuffer within its viewport and scissor, and does not take an error the
// application left pending for its own.
#include <GLES3/gl3.h>
#include <gtest/gtest.h>

#include <array>
#include <cctype>
#include <cstdint>
#include <utility>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "curvetext/error.hpp"
#include "curvetext/font.hpp"
#include "curvetext/headless.hpp"
#include "curvetext/renderer.hpp"
#include "curvetext/shape_drawing.hpp"
#include "curvetext/shapes.hpp"
#include "curvetext/shaping.hpp"
#include "curvetext/draw_batch.hpp"
#include "curvetext/font_collection.hpp"
#include "curvetext/layout.hpp"
#include "curvetext/text_block.hpp"
#include "support/fonts.hpp"
#include "support/gpu.hpp"

namespace curvetext {
namespace {

bool desktop() {
  const char* v = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  return std::string(v).rfind("OpenGL ES", 0) != 0;
}
bool gl3() {
  GLint major = 0;
  glGetIntegerv(GL_MAJOR_VERSION, &major);
  glGetError();  // GLES 2 has no GL_MAJOR_VERSION
  return major >= 3;
}

// Everything the state contract covers, as glGet reports it, by name.
struct State {
  std::vector<std::pair<std::string, double>> values;

  void add(const std::string& name, GLint v) { values.emplace_back(name, v); }
  void addf(const std::string& name, GLfloat v) { values.emplace_back(name, v); }

  static State read() {
    State s;
    auto i = [&](const char* name, GLenum e) {
      GLint v = 0;
      glGetIntegerv(e, &v);
      s.add(name, v);
    };
    auto on = [&](const char* name, GLenum e) { s.add(name, glIsEnabled(e)); };
    i("program", GL_CURRENT_PROGRAM);
    i("array buffer", GL_ARRAY_BUFFER_BINDING);
    i("element buffer", GL_ELEMENT_ARRAY_BUFFER_BINDING);
    i("renderbuffer", GL_RENDERBUFFER_BINDING);
    i("active texture", GL_ACTIVE_TEXTURE);
    i("texture 2d (active unit)", GL_TEXTURE_BINDING_2D);
    i("blend src rgb", GL_BLEND_SRC_RGB);
    i("blend dst rgb", GL_BLEND_DST_RGB);
    i("blend src alpha", GL_BLEND_SRC_ALPHA);
    i("blend dst alpha", GL_BLEND_DST_ALPHA);
    i("blend equation rgb", GL_BLEND_EQUATION_RGB);
    i("blend equation alpha", GL_BLEND_EQUATION_ALPHA);
    on("blend", GL_BLEND);
    on("depth test", GL_DEPTH_TEST);
    GLboolean depth_mask = GL_TRUE;
    glGetBooleanv(GL_DEPTH_WRITEMASK, &depth_mask);
    s.add("depth writemask", depth_mask);
    i("depth func", GL_DEPTH_FUNC);
    on("stencil test", GL_STENCIL_TEST);
    on("cull face", GL_CULL_FACE);
    on("scissor test", GL_SCISSOR_TEST);
    i("pack alignment", GL_PACK_ALIGNMENT);
    i("unpack alignment", GL_UNPACK_ALIGNMENT);
    GLint box[4];
    glGetIntegerv(GL_VIEWPORT, box);
    for (int k = 0; k < 4; ++k) s.add("viewport " + std::to_string(k), box[k]);
    glGetIntegerv(GL_SCISSOR_BOX, box);
    for (int k = 0; k < 4; ++k) s.add("scissor box " + std::to_string(k), box[k]);
    GLboolean mask[4];
    glGetBooleanv(GL_COLOR_WRITEMASK, mask);
    for (int k = 0; k < 4; ++k) s.add("colour mask " + std::to_string(k), mask[k]);
    GLfloat clear[4];
    glGetFloatv(GL_COLOR_CLEAR_VALUE, clear);
    for (int k = 0; k < 4; ++k) s.addf("clear colour " + std::to_string(k), clear[k]);
    GLint unit = 0;
    glGetIntegerv(GL_ACTIVE_TEXTURE, &unit);
    glActiveTexture(GL_TEXTURE0);
    i("texture 2d (unit 0)", GL_TEXTURE_BINDING_2D);
    glActiveTexture(static_cast<GLenum>(unit));
    for (GLuint a = 0; a < 3; ++a) {
      const std::string n = "attribute " + std::to_string(a) + " ";
      GLint v = 0;
      glGetVertexAttribiv(a, GL_VERTEX_ATTRIB_ARRAY_ENABLED, &v);
      s.add(n + "enabled", v);
      glGetVertexAttribiv(a, GL_VERTEX_ATTRIB_ARRAY_SIZE, &v);
      s.add(n + "size", v);
      glGetVertexAttribiv(a, GL_VERTEX_ATTRIB_ARRAY_STRIDE, &v);
      s.add(n + "stride", v);
      glGetVertexAttribiv(a, GL_VERTEX_ATTRIB_ARRAY_BUFFER_BINDING, &v);
      s.add(n + "buffer", v);
      void* p = nullptr;
      glGetVertexAttribPointerv(a, GL_VERTEX_ATTRIB_ARRAY_POINTER, &p);
      s.add(n + "pointer", static_cast<GLint>(reinterpret_cast<std::uintptr_t>(p)));
      if (a != 0) {  // attribute 0's current value cannot be queried in a compatibility profile
        GLfloat cur[4];
        glGetVertexAttribfv(a, GL_CURRENT_VERTEX_ATTRIB, cur);
        for (int k = 0; k < 4; ++k) s.addf(n + "current " + std::to_string(k), cur[k]);
      }
    }
    if (gl3()) {
      i("vertex array", GL_VERTEX_ARRAY_BINDING);
      i("draw framebuffer", GL_DRAW_FRAMEBUFFER_BINDING);
      i("read framebuffer", GL_READ_FRAMEBUFFER_BINDING);
      i("pixel pack buffer", GL_PIXEL_PACK_BUFFER_BINDING);
      i("pixel unpack buffer", GL_PIXEL_UNPACK_BUFFER_BINDING);
      i("pack row length", GL_PACK_ROW_LENGTH);
      i("unpack row length", GL_UNPACK_ROW_LENGTH);
      glGetIntegerv(GL_ACTIVE_TEXTURE, &unit);
      glActiveTexture(GL_TEXTURE0);
      i("sampler (unit 0)", GL_SAMPLER_BINDING);
      glActiveTexture(static_cast<GLenum>(unit));
      on("rasterizer discard", GL_RASTERIZER_DISCARD);
      for (GLuint a = 0; a < 3; ++a) {
        GLint v = 0;
        glGetVertexAttribiv(a, GL_VERTEX_ATTRIB_ARRAY_DIVISOR, &v);
        s.add("attribute " + std::to_string(a) + " divisor", v);
      }
    } else {
      i("framebuffer", GL_FRAMEBUFFER_BINDING);
    }
    return s;
  }
};

GLuint compile_app_program() {
  const bool d = desktop();
  const std::string vs = d ? "#version 330 core\nlayout(location = 0) in vec4 p;\nvoid main() { gl_Position = p; }\n"
                           : "#version 100\nattribute vec4 p;\nvoid main() { gl_Position = p; }\n";
  const std::string fs = d ? "#version 330 core\nout vec4 c;\nvoid main() { c = vec4(1.0); }\n"
                           : "#version 100\nvoid main() { gl_FragColor = vec4(1.0); }\n";
  auto shader = [](GLenum type, const std::string& src) {
    const GLuint s = glCreateShader(type);
    const char* p = src.c_str();
    glShaderSource(s, 1, &p, nullptr);
    glCompileShader(s);
    return s;
  };
  const GLuint program = glCreateProgram();
  glAttachShader(program, shader(GL_VERTEX_SHADER, vs));
  glAttachShader(program, shader(GL_FRAGMENT_SHADER, fs));
  glBindAttribLocation(program, 0, "p");
  glLinkProgram(program);
  return program;
}

// An application's frame in progress: its own framebuffer, program, VAO,
// buffers, textures and every piece of state set away from the defaults.
struct AppState {
  static constexpr int kSize = 256;
  GLuint fbo = 0, color = 0, texture0 = 0, texture3 = 0, vao = 0, vbo = 0, ibo = 0, rbo = 0, program = 0, unpack = 0;

  AppState() {
    glGenTextures(1, &color);
    glBindTexture(GL_TEXTURE_2D, color);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, kSize, kSize, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, color, 0);
    glViewport(0, 0, kSize, kSize);
    glClearColor(1, 1, 1, 1);
    glClear(GL_COLOR_BUFFER_BIT);
    glGenTextures(1, &texture0);
    glGenTextures(1, &texture3);
    glGenRenderbuffers(1, &rbo);
    glBindRenderbuffer(GL_RENDERBUFFER, rbo);
    program = compile_app_program();
    glUseProgram(program);
    if (gl3()) {
      glGenVertexArrays(1, &vao);
      glBindVertexArray(vao);
      // A texture upload with no data reads from a bound unpack buffer.
      glGenBuffers(1, &unpack);
      glBindBuffer(GL_PIXEL_UNPACK_BUFFER, unpack);
      glBufferData(GL_PIXEL_UNPACK_BUFFER, 16, nullptr, GL_STREAM_DRAW);
    }
    glGenBuffers(1, &vbo);
    glGenBuffers(1, &ibo);
    glBindBuffer(GL_ARRAY_BUFFER, vbo);
    glBufferData(GL_ARRAY_BUFFER, 256, nullptr, GL_STATIC_DRAW);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ibo);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, 64, nullptr, GL_STATIC_DRAW);
    for (GLuint a = 0; a < 3; ++a) {
      glEnableVertexAttribArray(a);
      glVertexAttribPointer(a, 2 + static_cast<GLint>(a), GL_FLOAT, GL_FALSE, 36, reinterpret_cast<void*>(4 * a));
    }
    glVertexAttrib4f(2, 0.5f, 0.25f, 0.125f, 1.0f);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, texture0);
    glActiveTexture(GL_TEXTURE3);
    glBindTexture(GL_TEXTURE_2D, texture3);
    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_DST_COLOR, GL_ONE, GL_ZERO);
    glBlendEquationSeparate(GL_FUNC_SUBTRACT, GL_FUNC_ADD);
    glEnable(GL_DEPTH_TEST);
    glDepthMask(GL_FALSE);
    glDepthFunc(GL_GEQUAL);
    glEnable(GL_STENCIL_TEST);
    glEnable(GL_CULL_FACE);
    glEnable(GL_SCISSOR_TEST);
    glScissor(20, 30, 180, 120);
    glViewport(10, 20, 220, 160);
    glClearColor(0.1f, 0.2f, 0.3f, 0.4f);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);
    glPixelStorei(GL_PACK_ALIGNMENT, 2);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 8);
  }

  // Pixels of the application's framebuffer, read without disturbing the
  // state compared (saved and put back around the read).
  std::vector<std::uint8_t> pixels() const {
    std::vector<std::uint8_t> out(static_cast<std::size_t>(kSize) * kSize * 4);
    GLint pack = 0, read_fbo = 0;
    glGetIntegerv(GL_PACK_ALIGNMENT, &pack);
    glGetIntegerv(gl3() ? GL_READ_FRAMEBUFFER_BINDING : GL_FRAMEBUFFER_BINDING, &read_fbo);
    glBindFramebuffer(gl3() ? GL_READ_FRAMEBUFFER : GL_FRAMEBUFFER, fbo);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, kSize, kSize, GL_RGBA, GL_UNSIGNED_BYTE, out.data());
    glPixelStorei(GL_PACK_ALIGNMENT, pack);
    glBindFramebuffer(gl3() ? GL_READ_FRAMEBUFFER : GL_FRAMEBUFFER, static_cast<GLuint>(read_fbo));
    return out;
  }
};

void expect_same(const State& before, const State& after, const std::string& where) {
  ASSERT_EQ(before.values.size(), after.values.size());
  for (std::size_t k = 0; k < before.values.size(); ++k)
    EXPECT_EQ(before.values[k].second, after.values[k].second) << where << ": " << before.values[k].first;
}

class GlState : public ::testing::TestWithParam<ContextKind> {};

TEST_P(GlState, EveryModeLeavesTheApplicationsStateAndDrawsInItsViewport) {
  // The run under Mesa's OpenGL ES 2.0 override (tests/CMakeLists.txt) tests
  // a true GLES2 context, without VAOs: the others are not available there.
  const bool gles2_run = test::expects_gles2();
  if (gles2_run && GetParam() != ContextKind::Gles2) GTEST_SKIP() << "OpenGL ES 2.0 only in this run";
  HeadlessContext context = HeadlessContext::create(GetParam());
  std::printf("%s: %s\n", context_kind_name(GetParam()), context.version().c_str());
  if (gles2_run) {
    ASSERT_EQ(context.version().rfind("OpenGL ES 2.0", 0), 0u) << context.version();
  }
  {
    const Font font = Font::open(test::kDejaVuSans);
    GlyphCache cache;
    Renderer renderer;
    AppState app;
    const ShapedLine line = shape_line(font, "Guest");
    const DrawBatch batch = DrawBatch::from_text(cache, font, line, 48.0);
    const State before = State::read();
    for (AntiAliasing aa :
         {AntiAliasing::None, AntiAliasing::Curves, AntiAliasing::Full, AntiAliasing::Vbaa, AntiAliasing::Msaa}) {
      // The viewport is 220 x 160 at (10, 20) (GL rows up): the text at
      // (6, 60) in its pixels lands inside it and inside the scissor box.
      renderer.draw(batch, Placement(48.0 / font.metrics().units_per_em, 16.0, 100.0),
                    DrawOptions(Color{0, 0, 0, 1}, aa));
      EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
      expect_same(
          before, State::read(),
          std::string(context_kind_name(GetParam())) + " after a draw in mode " + std::to_string(static_cast<int>(aa)));
    }
    // Ink only inside the scissor box (x 20..200, GL rows 30..150).
    const std::vector<std::uint8_t> px = app.pixels();
    std::size_t inside = 0, outside = 0;
    for (int y = 0; y < AppState::kSize; ++y)
      for (int x = 0; x < AppState::kSize; ++x) {
        const bool dark = px[(static_cast<std::size_t>(y) * AppState::kSize + x) * 4] < 128;
        const bool in = x >= 20 && x < 200 && y >= 30 && y < 150;
        (in ? inside : outside) += dark ? 1 : 0;
      }
    EXPECT_GT(inside, 200u);
    EXPECT_EQ(outside, 0u);

    // An error the application left pending is reported as its own, and
    // nothing is drawn or changed.
    glBindTexture(GL_TEXTURE_2D, 0xFFFFFF);  // not a texture name: GL_INVALID_OPERATION on core, fine elsewhere
    glEnable(0x1234);                        // GL_INVALID_ENUM everywhere
    glBindTexture(GL_TEXTURE_2D, app.texture3);
    try {
      renderer.draw(batch, Placement(48.0 / font.metrics().units_per_em, 16.0, 100.0), DrawOptions{});
      ADD_FAILURE() << "a pending application error went unreported";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("pending"), std::string::npos) << e.what();
    }
    while (glGetError() != GL_NO_ERROR) {
    }
    expect_same(before, State::read(), "after the pending-error draw");
    // Building a block reports it the same way.
    glEnable(0x1234);
    try {
      (void)DrawBatch::from_text(cache, font, line, 24.0);
      ADD_FAILURE() << "a pending application error went unreported by DrawBatch::from_text";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("pending"), std::string::npos) << e.what();
    }
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    expect_same(before, State::read(), "after the pending-error block");
  }
}

// An application may delete its program while it is current (GL keeps it
// until another program is made current). curvetext's draw makes its own
// current, so the application's is gone afterwards: binding its name again
// would be GL_INVALID_VALUE (or bind another program that reused the name).
// The draw leaves no program current and no error; a live program is put back.
TEST_P(GlState, AProgramDeletedWhileCurrentIsNotBoundAgain) {
  const bool gles2_run = test::expects_gles2();
  if (gles2_run && GetParam() != ContextKind::Gles2) GTEST_SKIP() << "OpenGL ES 2.0 only in this run";
  HeadlessContext context = HeadlessContext::create(GetParam());
  {
    const Font font = Font::open(test::kDejaVuSans);
    GlyphCache cache;
    Renderer renderer;
    AppState app;
    const ShapedLine line = shape_line(font, "Gone");
    const DrawBatch batch = DrawBatch::from_text(cache, font, line, 48.0);
    const Placement at(48.0 / font.metrics().units_per_em, 16.0, 100.0);
    const std::string kind = context_kind_name(GetParam());
    for (AntiAliasing aa : {AntiAliasing::Curves, AntiAliasing::Full}) {
      const GLuint program = compile_app_program();
      glUseProgram(program);
      glDeleteProgram(program);  // flagged for deletion, still current
      ASSERT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
      renderer.draw(batch, at, DrawOptions(Color{0, 0, 0, 1}, aa));
      EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR)) << kind << " mode " << static_cast<int>(aa);
      GLint current = -1;
      glGetIntegerv(GL_CURRENT_PROGRAM, &current);
      EXPECT_EQ(current, 0) << kind << " mode " << static_cast<int>(aa);
      EXPECT_FALSE(glIsProgram(program)) << kind;
    }
    // A program that still exists is current again after the draw.
    glUseProgram(app.program);
    renderer.draw(batch, at, DrawOptions{});
    GLint current = 0;
    glGetIntegerv(GL_CURRENT_PROGRAM, &current);
    EXPECT_EQ(current, static_cast<GLint>(app.program)) << kind;
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR)) << kind;
  }
}

// Colour bitmaps (emoji from Noto Color Emoji): uploading them into the
// atlas while the application's unpack state (alignment 8, a bound unpack
// buffer, a row length) and texture bindings are set, and drawing them with
// a sampler object of the application's on unit 0, leave all of it as it was.
TEST_P(GlState, ColourBitmapsLeaveTheApplicationsState) {
  const char* kEmoji = "/usr/share/fonts/truetype/noto/NotoColorEmoji.ttf";
  if (FILE* f = std::fopen(kEmoji, "rb")) {
    std::fclose(f);
  } else {
    GTEST_SKIP() << "fonts-noto-color-emoji is not installed";
  }
  const bool gles2_run = test::expects_gles2();
  if (gles2_run && GetParam() != ContextKind::Gles2) GTEST_SKIP() << "OpenGL ES 2.0 only in this run";
  HeadlessContext context = HeadlessContext::create(GetParam());
  {
    const Font font = Font::open(kEmoji);
    GlyphCache cache;
    Renderer renderer;
    AppState app;
    GLuint sampler = 0;
    if (gl3()) {
      glPixelStorei(GL_UNPACK_ROW_LENGTH, 3);
      glGenSamplers(1, &sampler);
      glSamplerParameteri(sampler, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
      glBindSampler(0, sampler);
    }
    const State before = State::read();
    const ShapedLine line = shape_line(font, "\U0001F680\U0001F600");
    std::vector<PlacedGlyph> placed;
    double pen = 0.0;
    for (const ShapedGlyph& g : line.glyphs) {
      placed.push_back({g.glyph_id, pen, 0.0});
      pen += g.x_advance;
    }
    const DrawBatch batch = DrawBatch::from_color_bitmaps(cache, font, placed, 40.0);
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    expect_same(before, State::read(), std::string(context_kind_name(GetParam())) + " after building bitmaps");
    renderer.draw(batch, Placement(40.0 / font.metrics().units_per_em, 30.0, 100.0), DrawOptions{});
    EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
    expect_same(before, State::read(), std::string(context_kind_name(GetParam())) + " after drawing bitmaps");
    // Coloured ink, only inside the scissor box (x 20..200, GL rows 30..150).
    const std::vector<std::uint8_t> px = app.pixels();
    std::size_t inside = 0, outside = 0;
    for (int y = 0; y < AppState::kSize; ++y)
      for (int x = 0; x < AppState::kSize; ++x) {
        const std::uint8_t* p = &px[(static_cast<std::size_t>(y) * AppState::kSize + x) * 4];
        const bool ink = std::abs(p[0] - p[2]) > 40;  // white background: colour, not grey
        const bool in = x >= 20 && x < 200 && y >= 30 && y < 150;
        (in ? inside : outside) += ink ? 1 : 0;
      }
    EXPECT_GT(inside, 300u);
    EXPECT_EQ(outside, 0u);
    if (sampler != 0) {
      glBindSampler(0, 0);
      glDeleteSamplers(1, &sampler);
    }
  }
}

// An SVG icon drawn through ShapeDrawing (fills, a stroke, a gradient
// evaluated in the composite pass, a translucent group composited from an
// offscreen layer) in every offscreen mode, and a solid one
// in the single-pass modes: the application's state is left as it was and
// the ink lands inside its scissor box.
TEST_P(GlState, ShapeDrawingLeavesTheApplicationsState) {
  const bool gles2_run = test::expects_gles2();
  if (gles2_run && GetParam() != ContextKind::Gles2) GTEST_SKIP() << "OpenGL ES 2.0 only in this run";
  HeadlessContext context = HeadlessContext::create(GetParam());
  {
    Renderer renderer;
    AppState app;
    const ShapeDocument icon = parse_svg(
        "<svg viewBox='0 0 16 16'><linearGradient id='g'><stop stop-color='#f00'/><stop offset='1' "
        "stop-color='#00f'/></linearGradient><g opacity='0.9'><rect x='1' y='1' width='14' height='14' rx='3' "
        "fill='url(#g)'/><circle cx='8' cy='8' r='4' fill='none' stroke='#000' stroke-width='1.5'/></g></svg>");
    ASSERT_EQ(icon.groups.size(), 1u);  // drawn through an offscreen layer
    const ShapeDocument solid = parse_svg("<svg viewBox='0 0 16 16'><circle cx='8' cy='8' r='6'/></svg>");
    const Placement at(6.0, 40.0, 16.0);  // 96 px, its top-left at (40, 16): y up, top edge y = 0
    const ShapeDrawing drawing = ShapeDrawing::from_document(icon, 6.0);
    const ShapeDrawing plain = ShapeDrawing::from_document(solid, 6.0);
    const State before = State::read();
    for (AntiAliasing aa : {AntiAliasing::None, AntiAliasing::Curves, AntiAliasing::Full, AntiAliasing::Vbaa,
                            AntiAliasing::Msaa, AntiAliasing::Auto}) {
      const bool offscreen = aa != AntiAliasing::None && aa != AntiAliasing::Curves;
      (offscreen ? drawing : plain).draw(renderer, at, DrawOptions(Color{0, 0, 0, 1}, aa));
      EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
      expect_same(before, State::read(),
                  std::string(context_kind_name(GetParam())) + " after a shape drawing in mode " +
                      std::to_string(static_cast<int>(aa)));
    }
    // A gradient in a single-pass mode is refused, with the state left as it was.
    EXPECT_THROW(drawing.draw(renderer, at, DrawOptions(Color{0, 0, 0, 1}, AntiAliasing::Curves)), Error);
    expect_same(before, State::read(), "after a refused gradient draw");
    const std::vector<std::uint8_t> px = app.pixels();
    std::size_t inside = 0, outside = 0;
    for (int y = 0; y < AppState::kSize; ++y)
      for (int x = 0; x < AppState::kSize; ++x) {
        const std::uint8_t* p = &px[(static_cast<std::size_t>(y) * AppState::kSize + x) * 4];
        const bool ink = p[0] < 200 || p[2] < 200;
        const bool in = x >= 20 && x < 200 && y >= 30 && y < 150;
        (in ? inside : outside) += ink ? 1 : 0;
      }
    EXPECT_GT(inside, 4000u);
    EXPECT_EQ(outside, 0u);
  }
}

// A text block with an outline, a centred stroke and a blurred shadow (the
// shadow's offscreen passes, its blur program and buffers) in every mode:
// the application's state comes back, and ink lands only inside its scissor
// box, the shadow's blur included.
TEST_P(GlState, TextEffectsLeaveTheApplicationsState) {
  const bool gles2_run = test::expects_gles2();
  if (gles2_run && GetParam() != ContextKind::Gles2) GTEST_SKIP() << "OpenGL ES 2.0 only in this run";
  HeadlessContext context = HeadlessContext::create(GetParam());
  {
    FontCollection fonts;
    GlyphCache cache;
    Renderer renderer;
    AppState app;
    ParagraphStyle style;
    style.default_style.fonts = {test::kDejaVuSans};
    style.default_style.size_px = 40.0;
    style.default_style.color = Color{0, 0, 0, 0.5f};
    style.default_style.effects.outline_width = 2.0;
    style.default_style.effects.outline_color = Color{1, 0, 0, 1};
    style.default_style.effects.stroke_width = 1.0;
    style.default_style.effects.stroke_color = Color{0, 0, 1, 1};
    style.default_style.effects.shadow = TextShadow{3.0, 3.0, 8.0, Color{0, 0, 0, 1}};
    const Paragraph paragraph = Paragraph::layout(fonts, "Glow", {}, style);
    const TextBlock block = TextBlock::from_paragraph(cache, paragraph);
    const State before = State::read();
    for (AntiAliasing aa : {AntiAliasing::None, AntiAliasing::Curves, AntiAliasing::Full, AntiAliasing::Vbaa,
                            AntiAliasing::Msaa, AntiAliasing::Auto}) {
      // Near the scissor box's left edge (x 20 of the framebuffer, 10 of the
      // viewport): the shadow's blur reaches past it.
      block.draw(renderer, 12.0, 40.0, DrawOptions(Color{0, 0, 0, 1}, aa));
      EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
      expect_same(before, State::read(),
                  std::string(context_kind_name(GetParam())) + " after a block with effects in mode " +
                      std::to_string(static_cast<int>(aa)));
    }
    const std::vector<std::uint8_t> px = app.pixels();
    std::size_t inside = 0, outside = 0, red = 0;
    for (int y = 0; y < AppState::kSize; ++y)
      for (int x = 0; x < AppState::kSize; ++x) {
        const std::uint8_t* p = &px[(static_cast<std::size_t>(y) * AppState::kSize + x) * 4];
        const bool ink = p[0] < 250 || p[1] < 250 || p[2] < 250;
        const bool in = x >= 20 && x < 200 && y >= 30 && y < 150;
        (in ? inside : outside) += ink ? 1 : 0;
        red += p[0] > 100 && p[1] < 60 && p[2] < 60 ? 1 : 0;
      }
    EXPECT_GT(inside, 2000u);
    EXPECT_GT(red, 50u);  // the outline
    EXPECT_EQ(outside, 0u);
  }
}

INSTANTIATE_TEST_SUITE_P(Kinds, GlState,
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
