// HeadlessContext makes every context kind: GLES 2, GLES 3, desktop GL 3.3
// core and compatibility. Each is checked through GL itself (GL_VERSION, the
// profile mask) and by clearing a framebuffer and reading the colour back,
// with GL calls through the library's one GL link (libGLESv2 of libglvnd).
// Independent of the Renderer, so a shader problem in one kind shows there,
// not here.
#include <gtest/gtest.h>

#include <GLES2/gl2.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "curvetext/error.hpp"
#include "curvetext/headless.hpp"

namespace curvetext {
namespace {

struct Version {
  bool gles = false;
  int major = 0, minor = 0;
};

Version current_version() {
  const char* v = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  Version out;
  if (v == nullptr) return out;
  out.gles = std::strncmp(v, "OpenGL ES ", 10) == 0;
  std::sscanf(out.gles ? v + 10 : v, "%d.%d", &out.major, &out.minor);
  return out;
}

bool at_least(const Version& v, int major, int minor) {
  return v.major > major || (v.major == major && v.minor >= minor);
}

// Clears an RGBA texture framebuffer (colour-renderable in every kind,
// GLES 2 included) and reads one pixel back.
std::array<unsigned, 4> clear_and_read(float r, float g, float b, float a) {
  GLuint texture = 0, framebuffer = 0;
  glGenTextures(1, &texture);
  glBindTexture(GL_TEXTURE_2D, texture);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, 4, 4, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glGenFramebuffers(1, &framebuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, texture, 0);
  EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), static_cast<GLenum>(GL_FRAMEBUFFER_COMPLETE));
  glViewport(0, 0, 4, 4);
  glClearColor(r, g, b, a);
  glClear(GL_COLOR_BUFFER_BIT);
  std::array<unsigned char, 4> px{};
  glReadPixels(2, 1, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, px.data());
  EXPECT_EQ(glGetError(), static_cast<GLenum>(GL_NO_ERROR));
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glDeleteFramebuffers(1, &framebuffer);
  glDeleteTextures(1, &texture);
  return {px[0], px[1], px[2], px[3]};
}

void expect_clear_works() {
  const std::array<unsigned, 4> want{51, 102, 153, 255};
  EXPECT_EQ(clear_and_read(0.2f, 0.4f, 0.6f, 1.0f), want);
}

constexpr GLenum kContextProfileMask = 0x9126;  // desktop GL 3.2
constexpr GLint kCoreProfileBit = 0x1, kCompatibilityProfileBit = 0x2;

GLint profile_mask() {
  GLint mask = 0;
  glGetIntegerv(kContextProfileMask, &mask);
  return mask;
}

TEST(HeadlessContext, DefaultIsGles2) {
  HeadlessContext ctx = HeadlessContext::create();
  EXPECT_EQ(ctx.kind(), ContextKind::Gles2);
  const Version v = current_version();
  EXPECT_TRUE(v.gles) << ctx.version();
  EXPECT_GE(v.major, 2) << ctx.version();
}

TEST(HeadlessContext, Gles2) {
  HeadlessContext ctx = HeadlessContext::create(ContextKind::Gles2);
  std::printf("GLES 2 asked, got: %s (%s)\n", ctx.version().c_str(), ctx.renderer().c_str());
  EXPECT_EQ(ctx.kind(), ContextKind::Gles2);
  const Version v = current_version();
  EXPECT_TRUE(v.gles) << ctx.version();
  EXPECT_TRUE(at_least(v, 2, 0)) << ctx.version();
  expect_clear_works();
}

TEST(HeadlessContext, Gles3) {
  HeadlessContext ctx = HeadlessContext::create(ContextKind::Gles3);
  std::printf("GLES 3 asked, got: %s\n", ctx.version().c_str());
  EXPECT_EQ(ctx.kind(), ContextKind::Gles3);
  const Version v = current_version();
  EXPECT_TRUE(v.gles) << ctx.version();
  EXPECT_TRUE(at_least(v, 3, 0)) << ctx.version();
  expect_clear_works();
}

TEST(HeadlessContext, GlCore) {
  HeadlessContext ctx = HeadlessContext::create(ContextKind::GlCore);
  std::printf("GL core asked, got: %s\n", ctx.version().c_str());
  EXPECT_EQ(ctx.kind(), ContextKind::GlCore);
  const Version v = current_version();
  EXPECT_FALSE(v.gles) << ctx.version();
  EXPECT_TRUE(at_least(v, 3, 3)) << ctx.version();
  EXPECT_TRUE(profile_mask() & kCoreProfileBit) << ctx.version();
  expect_clear_works();
}

TEST(HeadlessContext, GlCompat) {
  HeadlessContext ctx = HeadlessContext::create(ContextKind::GlCompat);
  std::printf("GL compatibility asked, got: %s\n", ctx.version().c_str());
  EXPECT_EQ(ctx.kind(), ContextKind::GlCompat);
  const Version v = current_version();
  EXPECT_FALSE(v.gles) << ctx.version();
  EXPECT_TRUE(at_least(v, 3, 3)) << ctx.version();
  EXPECT_TRUE(profile_mask() & kCompatibilityProfileBit) << ctx.version();
  expect_clear_works();
}

TEST(HeadlessContext, ExplicitDesktopVersion) {
  HeadlessContext ctx = HeadlessContext::create(ContextOptions{ContextKind::GlCore, 4, 1});
  EXPECT_TRUE(at_least(current_version(), 4, 1)) << ctx.version();
}

TEST(HeadlessContext, KindsOneAfterAnother) {
  // Each context releases itself, so the next kind (another client API) can
  // become current on the same thread.
  for (ContextKind kind : {ContextKind::GlCore, ContextKind::Gles2, ContextKind::GlCompat, ContextKind::Gles3}) {
    HeadlessContext ctx = HeadlessContext::create(kind);
    EXPECT_EQ(current_version().gles, kind == ContextKind::Gles2 || kind == ContextKind::Gles3) << ctx.version();
    expect_clear_works();
  }
}

TEST(HeadlessContext, MakeCurrentAfterAnotherKind) {
  HeadlessContext es = HeadlessContext::create(ContextKind::Gles3);
  HeadlessContext core = HeadlessContext::create(ContextKind::GlCore);
  es.make_current();
  EXPECT_TRUE(current_version().gles) << es.version();
  expect_clear_works();
  core.make_current();
  EXPECT_FALSE(current_version().gles) << core.version();
  expect_clear_works();
}

TEST(HeadlessContext, VersionTheKindCannotHave) {
  for (const ContextOptions& bad :
       {ContextOptions{ContextKind::Gles2, 3, 0}, ContextOptions{ContextKind::Gles3, 2, 0},
        ContextOptions{ContextKind::GlCore, 3, 1}, ContextOptions{ContextKind::GlCompat, 2, 1}}) {
    try {
      HeadlessContext::create(bad);
      ADD_FAILURE() << context_kind_name(bad.kind) << " " << bad.major << "." << bad.minor << " was accepted";
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), ErrorCode::InvalidArgument) << e.what();
    }
  }
}

TEST(HeadlessContext, VersionPastTheDriverIsNoDevice) {
  try {
    HeadlessContext::create(ContextOptions{ContextKind::GlCore, 9, 9});
    ADD_FAILURE() << "GL 9.9 core was created";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::NoDevice);
    EXPECT_NE(std::string(e.what()).find("no OpenGL 9.9 core context"), std::string::npos) << e.what();
  }
}

// Mesa answers a GLES 2 request with its highest ES version; with
// MESA_GLES_VERSION_OVERRIDE=2.0 it has only ES 2.0, which is how a GLES 2
// floor is tested, and GLES 3 is then unavailable: a NoDevice error naming it.
// Each case runs in a fresh process that sets the variable before EGL starts
// (Mesa reads it once); other drivers pass without checking.
bool is_mesa(const HeadlessContext& ctx) { return ctx.version().find("Mesa") != std::string::npos; }

TEST(HeadlessContext, MesaGles2OnlyGivesEs20) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(
      {
        setenv("MESA_GLES_VERSION_OVERRIDE", "2.0", 1);
        HeadlessContext ctx = HeadlessContext::create(ContextKind::Gles2);
        const Version v = current_version();
        std::exit(!is_mesa(ctx) || (v.gles && v.major == 2 && v.minor == 0) ? 0 : 3);
      },
      testing::ExitedWithCode(0), "");
}

TEST(HeadlessContext, MesaGles2OnlyRefusesGles3) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(
      {
        setenv("MESA_GLES_VERSION_OVERRIDE", "2.0", 1);
        int code = 2;
        try {
          HeadlessContext ctx = HeadlessContext::create(ContextKind::Gles3);
          code = is_mesa(ctx) ? 4 : 0;
        } catch (const Error& e) {
          const bool named = std::string(e.what()).rfind("no OpenGL ES 3.0 context: ", 0) == 0;
          code = e.code() == ErrorCode::NoDevice && named ? 0 : 3;
        }
        std::exit(code);
      },
      testing::ExitedWithCode(0), "");
}

}  // namespace
}  // namespace curvetext
