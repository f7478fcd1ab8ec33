// The curve shader program, an offscreen RGBA framebuffer, and drawing of
// batches with premultiplied source-over blending.
#include <GLES2/gl2.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

#include "curvetext/error.hpp"
#include "curvetext/tolerances.hpp"
#include "gpu/batch_impl.hpp"
#include "gpu/shader_sources.hpp"

namespace curvetext {

AntiAliasing parse_antialiasing(std::string_view text) {
  if (text == "none") return AntiAliasing::None;
  if (text == "curves") return AntiAliasing::Curves;
  if (text == "full") return AntiAliasing::Full;
  throw Error(ErrorCode::InvalidArgument,
              "unknown antialiasing mode '" + std::string(text) + "' (use none, curves or full)");
}

CurveMode parse_curve_mode(std::string_view text) {
  if (text == "exact") return CurveMode::Exact;
  if (text == "paper") return CurveMode::Paper;
  throw Error(ErrorCode::InvalidArgument,
              "unknown curve mode '" + std::string(text) + "' (use exact or paper)");
}

namespace {

std::string hex(GLenum e) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "0x%04x", static_cast<unsigned>(e));
  return buf;
}

// Owns one GL shader object.
struct Shader {
  GLuint id = 0;
  explicit Shader(GLenum type) : id(glCreateShader(type)) {}
  Shader(const Shader&) = delete;
  Shader& operator=(const Shader&) = delete;
  ~Shader() {
    if (id != 0) glDeleteShader(id);
  }
};

bool is_gles() {
  const char* v = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  return v != nullptr && std::strncmp(v, "OpenGL ES", 9) == 0;
}

// The shader files are GLSL ES 1.00 without a #version line; desktop core
// profiles (GUI toolkits) get 3.30 with the renamed built-ins mapped back.
std::string preamble(GLenum type, bool gles) {
  if (gles) return "#version 100\n";
  std::string p = "#version 330 core\n#define texture2D texture\n";
  if (type == GL_VERTEX_SHADER) {
    p += "#define attribute in\n#define varying out\n";
  } else {
    p += "#define varying in\nout vec4 curvetext_frag_color;\n#define gl_FragColor curvetext_frag_color\n";
  }
  return p;
}

void compile(const Shader& shader, GLenum type, const char* source, bool gles) {
  std::string text = preamble(type, gles);
  // #extension must precede other statements but follow #version; on desktop
  // core the derivatives are built in and the directive only warns.
  text += source;
  const char* src = text.c_str();
  glShaderSource(shader.id, 1, &src, nullptr);
  glCompileShader(shader.id);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader.id, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    GLint len = 0;
    glGetShaderiv(shader.id, GL_INFO_LOG_LENGTH, &len);
    std::string log(static_cast<std::size_t>(std::max(len, 1)), '\0');
    glGetShaderInfoLog(shader.id, len, nullptr, log.data());
    log.resize(std::strlen(log.c_str()));
    std::replace(log.begin(), log.end(), '\n', ' ');
    throw Error(ErrorCode::Gl, std::string(type == GL_VERTEX_SHADER ? "vertex" : "fragment") +
                                   " shader failed to compile: " + log);
  }
}

}  // namespace

struct Renderer::Impl {
  GLuint program = 0;
  GLint a_pos = -1, a_coef = -1, a_info = -1, a_fade = -1;
  GLint u_transform = -1, u_viewport = -1, u_fringe_px = -1, u_color = -1,
        u_aa = -1, u_curve_mode = -1;
  GLuint framebuffer = 0;
  GLuint texture = 0;
  int width = 0, height = 0;

  Impl() = default;
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;
  ~Impl() {
    release_target();
    if (program != 0) glDeleteProgram(program);
  }
  void release_target() {
    if (framebuffer != 0) glDeleteFramebuffers(1, &framebuffer);
    if (texture != 0) glDeleteTextures(1, &texture);
    framebuffer = 0;
    texture = 0;
    width = height = 0;
  }
};

Renderer::Renderer() : impl_(std::make_unique<Impl>()) {
  if (glGetString(GL_VERSION) == nullptr) {
    throw Error(ErrorCode::Gl, "no current GL context (create a HeadlessContext or make one current)");
  }
  const bool gles = is_gles();
  Shader vs(GL_VERTEX_SHADER), fs(GL_FRAGMENT_SHADER);
  if (vs.id == 0 || fs.id == 0) throw Error(ErrorCode::Gl, "glCreateShader failed");
  compile(vs, GL_VERTEX_SHADER, shader_source::curve_vert_glsl, gles);
  compile(fs, GL_FRAGMENT_SHADER, shader_source::curve_frag_glsl, gles);
  Impl& r = *impl_;
  r.program = glCreateProgram();
  glAttachShader(r.program, vs.id);
  glAttachShader(r.program, fs.id);
  // Fixed locations so the attribute setup does not depend on the linker.
  glBindAttribLocation(r.program, 0, "a_pos");
  glBindAttribLocation(r.program, 1, "a_coef");
  glBindAttribLocation(r.program, 2, "a_info");
  glBindAttribLocation(r.program, 3, "a_fade");
  glLinkProgram(r.program);
  GLint ok = GL_FALSE;
  glGetProgramiv(r.program, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    GLint len = 0;
    glGetProgramiv(r.program, GL_INFO_LOG_LENGTH, &len);
    std::string log(static_cast<std::size_t>(std::max(len, 1)), '\0');
    glGetProgramInfoLog(r.program, len, nullptr, log.data());
    log.resize(std::strlen(log.c_str()));
    std::replace(log.begin(), log.end(), '\n', ' ');
    throw Error(ErrorCode::Gl, "curve shader program failed to link: " + log);
  }
  r.a_pos = 0;
  r.a_coef = 1;
  r.a_info = 2;
  r.a_fade = 3;
  r.u_transform = glGetUniformLocation(r.program, "u_transform");
  r.u_viewport = glGetUniformLocation(r.program, "u_viewport");
  r.u_fringe_px = glGetUniformLocation(r.program, "u_fringe_px");
  r.u_color = glGetUniformLocation(r.program, "u_color");
  r.u_aa = glGetUniformLocation(r.program, "u_aa");
  r.u_curve_mode = glGetUniformLocation(r.program, "u_curve_mode");
}

Renderer::~Renderer() = default;

void Renderer::begin(int width, int height, Color background) {
  Impl& r = *impl_;
  if (width <= 0 || height <= 0) {
    throw Error(ErrorCode::InvalidArgument,
                "image size " + std::to_string(width) + "x" + std::to_string(height) + " must be positive");
  }
  GLint max_texture = 0, max_renderbuffer = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_texture);
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_renderbuffer);
  GLint max_viewport[2] = {0, 0};
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, max_viewport);
  int limit = std::min({max_texture, max_renderbuffer, max_viewport[0], max_viewport[1]});
  limit = std::min(limit, static_cast<int>(tolerance::kMaxImageSidePx));
  if (width > limit || height > limit) {
    throw Error(ErrorCode::InvalidArgument, "image size " + std::to_string(width) + "x" +
                                                std::to_string(height) + " exceeds the GL maximum of " +
                                                std::to_string(limit) + " pixels per side");
  }
  if (r.framebuffer == 0 || r.width != width || r.height != height) {
    r.release_target();
    glGenTextures(1, &r.texture);
    glBindTexture(GL_TEXTURE_2D, r.texture);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    // RGBA/UNSIGNED_BYTE is colour-renderable in every GLES2 implementation.
    glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    glBindTexture(GL_TEXTURE_2D, 0);
    if (GLenum err = glGetError(); err != GL_NO_ERROR) {
      r.release_target();
      throw Error(ErrorCode::Gl, "cannot allocate a " + std::to_string(width) + "x" + std::to_string(height) +
                                     " framebuffer texture (GL error " + hex(err) + ")");
    }
    glGenFramebuffers(1, &r.framebuffer);
    glBindFramebuffer(GL_FRAMEBUFFER, r.framebuffer);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, r.texture, 0);
    const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
    if (status != GL_FRAMEBUFFER_COMPLETE) {
      r.release_target();
      throw Error(ErrorCode::Gl, "offscreen framebuffer incomplete (status " + hex(status) + ")");
    }
    r.width = width;
    r.height = height;
  }
  glBindFramebuffer(GL_FRAMEBUFFER, r.framebuffer);
  glViewport(0, 0, width, height);
  glDisable(GL_SCISSOR_TEST);
  const float a = std::clamp(background.a, 0.0f, 1.0f);
  glClearColor(std::clamp(background.r, 0.0f, 1.0f) * a, std::clamp(background.g, 0.0f, 1.0f) * a,
               std::clamp(background.b, 0.0f, 1.0f) * a, a);
  glClear(GL_COLOR_BUFFER_BIT);
}

void Renderer::draw(const DrawBatch& batch, const Placement& placement, const DrawOptions& options) {
  Impl& r = *impl_;
  if (!std::isfinite(placement.scale) || placement.scale == 0.0 || !std::isfinite(placement.origin_x) ||
      !std::isfinite(placement.origin_y)) {
    throw Error(ErrorCode::InvalidArgument, "placement needs a finite non-zero scale and a finite origin");
  }
  const DrawBatch::Impl& b = batch.impl();
  if (b.vbo == 0 || b.vertex_count == 0) return;

  // Without begin(), draw into whatever framebuffer and viewport the caller has bound.
  float vw = static_cast<float>(r.width), vh = static_cast<float>(r.height);
  if (r.framebuffer != 0) {
    glBindFramebuffer(GL_FRAMEBUFFER, r.framebuffer);
    glViewport(0, 0, r.width, r.height);
  } else {
    GLint vp[4] = {0, 0, 0, 0};
    glGetIntegerv(GL_VIEWPORT, vp);
    vw = static_cast<float>(vp[2]);
    vh = static_cast<float>(vp[3]);
  }

  placement.transform.validate();
  glUseProgram(r.program);
  const double s = placement.scale;
  // Outline units -> pixels (x_px = s x + ox, y_px = oy - s y), then the
  // projective transform; uploaded column-major.
  const Transform full =
      placement.transform * Transform{{s, 0.0, placement.origin_x, 0.0, -s, placement.origin_y, 0.0, 0.0, 1.0}};
  GLfloat m[9];
  for (int row = 0; row < 3; ++row)
    for (int col = 0; col < 3; ++col) m[col * 3 + row] = static_cast<GLfloat>(full.m[row * 3 + col]);
  glUniformMatrix3fv(r.u_transform, 1, GL_FALSE, m);
  glUniform2f(r.u_viewport, vw, vh);
  glUniform1f(r.u_fringe_px, options.antialiasing == AntiAliasing::Full ? tolerance::kFringeWidthPx : 0.0f);
  const Color& c = options.color;
  const float a = std::clamp(c.a, 0.0f, 1.0f);
  glUniform4f(r.u_color, std::clamp(c.r, 0.0f, 1.0f) * a, std::clamp(c.g, 0.0f, 1.0f) * a,
              std::clamp(c.b, 0.0f, 1.0f) * a, a);
  glUniform1i(r.u_aa, options.antialiasing == AntiAliasing::None     ? 0
                      : options.antialiasing == AntiAliasing::Curves ? 1
                                                                     : 2);
  glUniform1i(r.u_curve_mode, options.curve_mode == CurveMode::Paper ? 1 : 0);

  glDisable(GL_DEPTH_TEST);
  glDisable(GL_STENCIL_TEST);
  glDisable(GL_CULL_FACE);  // fringe quads come in either orientation
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);  // premultiplied source-over

  glBindBuffer(GL_ARRAY_BUFFER, b.vbo);
  const GLsizei stride = static_cast<GLsizei>(sizeof(gpu::Vertex));
  const GLuint locs[4] = {static_cast<GLuint>(r.a_pos), static_cast<GLuint>(r.a_coef),
                          static_cast<GLuint>(r.a_info), static_cast<GLuint>(r.a_fade)};
  for (GLuint i = 0; i < 4; ++i) {
    glEnableVertexAttribArray(locs[i]);
    glVertexAttribPointer(locs[i], 4, GL_FLOAT, GL_FALSE, stride,
                          reinterpret_cast<const void*>(static_cast<std::uintptr_t>(i) * 16u));
  }
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(b.vertex_count));
  for (GLuint loc : locs) glDisableVertexAttribArray(loc);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  if (GLenum err = glGetError(); err != GL_NO_ERROR) {
    throw Error(ErrorCode::Gl, "drawing a batch failed (GL error " + hex(err) + ")");
  }
}

Image Renderer::read_pixels() {
  Impl& r = *impl_;
  if (r.framebuffer == 0) throw Error(ErrorCode::InvalidArgument, "read_pixels needs begin() first");
  glBindFramebuffer(GL_FRAMEBUFFER, r.framebuffer);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  Image gl_rows(r.width, r.height);
  glReadPixels(0, 0, r.width, r.height, GL_RGBA, GL_UNSIGNED_BYTE, gl_rows.rgba.data());
  if (GLenum err = glGetError(); err != GL_NO_ERROR) {
    throw Error(ErrorCode::Gl, "glReadPixels failed (GL error " + hex(err) + ")");
  }
  Image out(r.width, r.height);
  const std::size_t row = static_cast<std::size_t>(r.width) * 4;
  for (int y = 0; y < r.height; ++y) {
    // GL's row 0 is the bottom; the shader put pixel row 0 at the top (clip y = +1).
    const std::uint8_t* src = &gl_rows.rgba[static_cast<std::size_t>(r.height - 1 - y) * row];
    std::uint8_t* dst = &out.rgba[static_cast<std::size_t>(y) * row];
    for (std::size_t i = 0; i < row; i += 4) {
      const unsigned a = src[i + 3];
      for (std::size_t k = 0; k < 3; ++k) {
        unsigned v = src[i + k];
        if (a == 0) {
          v = 0;
        } else if (a < 255) {
          v = std::min(255u, (v * 255u + a / 2u) / a);
        }
        dst[i + k] = static_cast<std::uint8_t>(v);
      }
      dst[i + 3] = static_cast<std::uint8_t>(a);
    }
  }
  return out;
}

}  // namespace curvetext
