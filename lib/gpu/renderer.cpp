// The curve shader program, an offscreen RGBA framebuffer, and drawing of
// batches with premultiplied source-over blending.
#include <GLES3/gl3.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <vector>
#include <cstdlib>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <initializer_list>
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
  if (text == "vbaa") return AntiAliasing::Vbaa;
  if (text == "msaa") return AntiAliasing::Msaa;
  if (text == "auto") return AntiAliasing::Auto;
  throw Error(ErrorCode::InvalidArgument,
              "unknown antialiasing mode '" + std::string(text) + "' (use none, curves, full, vbaa, msaa or auto)");
}

Blending parse_blending(std::string_view text) {
  if (text == "srgb") return Blending::Srgb;
  if (text == "linear") return Blending::Linear;
  throw Error(ErrorCode::InvalidArgument, "unknown blending '" + std::string(text) + "' (use srgb or linear)");
}

float parse_vbaa_filter(std::string_view text) {
  if (text == "box") return 0.0f;
  if (text == "paper") return tolerance::kVbaaPaperRing;
  double v = 0.0;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || ptr != text.data() + text.size() || !std::isfinite(v) || v < 0.0 || v > 1.0)
    throw Error(ErrorCode::InvalidArgument,
                "unknown vbaa filter '" + std::string(text) + "' (use box, paper, or a ring weight from 0 to 1)");
  return static_cast<float>(v);
}

void check_coverage_gamma(double gamma, std::string_view what) {
  if (!std::isfinite(gamma) || gamma < tolerance::kMinCoverageGamma || gamma > tolerance::kMaxCoverageGamma) {
    char buf[160];
    std::snprintf(buf, sizeof buf, " must be a number from %g to %g, got %g", tolerance::kMinCoverageGamma,
                  tolerance::kMaxCoverageGamma, gamma);
    throw Error(ErrorCode::InvalidArgument, std::string(what) + buf);
  }
}

CurveMode parse_curve_mode(std::string_view text) {
  if (text == "exact") return CurveMode::Exact;
  if (text == "paper") return CurveMode::Paper;
  throw Error(ErrorCode::InvalidArgument, "unknown curve mode '" + std::string(text) + "' (use exact or paper)");
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
  // Tolerances the shaders share with the library (tolerances.hpp), named
  // there only; preprocessor lines may precede #extension.
  char defines[160];
  std::snprintf(defines, sizeof defines,
                "#define CURVETEXT_PIXEL_REACH_PX %.7f\n#define CURVETEXT_THIN_TRIANGLE_PX %.9f\n",
                static_cast<double>(tolerance::kFringeWidthPx), static_cast<double>(tolerance::kThinTrianglePx));
  text += defines;
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
    throw Error(ErrorCode::Gl,
                std::string(type == GL_VERTEX_SHADER ? "vertex" : "fragment") + " shader failed to compile: " + log);
  }
}

// Links a program from two compiled shaders, the attributes bound to fixed
// locations 0, 1, ... in the order given (so the attribute setup does not
// depend on the linker). Error(Gl) with the info log, naming `what`, on failure.
GLuint link_program(const Shader& vs, const Shader& fs, std::initializer_list<const char*> attributes,
                    const char* what) {
  const GLuint program = glCreateProgram();
  glAttachShader(program, vs.id);
  glAttachShader(program, fs.id);
  GLuint location = 0;
  for (const char* name : attributes) glBindAttribLocation(program, location++, name);
  glLinkProgram(program);
  GLint ok = GL_FALSE;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    GLint len = 0;
    glGetProgramiv(program, GL_INFO_LOG_LENGTH, &len);
    std::string log(static_cast<std::size_t>(std::max(len, 1)), '\0');
    glGetProgramInfoLog(program, len, nullptr, log.data());
    log.resize(std::strlen(log.c_str()));
    std::replace(log.begin(), log.end(), '\n', ' ');
    glDeleteProgram(program);
    throw Error(ErrorCode::Gl, std::string(what) + " failed to link: " + log);
  }
  return program;
}

// sRGB transfer functions (IEC 61966-2-1), on values in [0, 1].
float srgb_to_linear(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }
float linear_to_srgb(float c) { return c <= 0.0031308f ? c * 12.92f : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f; }

// `c` premultiplied, in the space the framebuffer blends in.
std::array<float, 4> premultiplied(const Color& c, Blending blending) {
  const float a = std::clamp(c.a, 0.0f, 1.0f);
  std::array<float, 4> out{std::clamp(c.r, 0.0f, 1.0f), std::clamp(c.g, 0.0f, 1.0f), std::clamp(c.b, 0.0f, 1.0f), a};
  for (int i = 0; i < 3; ++i) {
    if (blending == Blending::Linear) out[i] = srgb_to_linear(out[i]);
    out[i] *= a;
  }
  return out;
}

}  // namespace

namespace {
// The uniforms both curve programs (curve.vert.glsl with curve.frag.glsl or
// area.frag.glsl) have.
struct ProgramUniforms {
  GLint transform = -1, viewport = -1, fringe_px = -1, color = -1, coverage_exponent = -1, curve_mode = -1;
  static ProgramUniforms of(GLuint program) {
    ProgramUniforms u;
    u.transform = glGetUniformLocation(program, "u_transform");
    u.viewport = glGetUniformLocation(program, "u_viewport");
    u.fringe_px = glGetUniformLocation(program, "u_fringe_px");
    u.color = glGetUniformLocation(program, "u_color");
    u.coverage_exponent = glGetUniformLocation(program, "u_coverage_exponent");
    u.curve_mode = glGetUniformLocation(program, "u_curve_mode");
    return u;
  }
};
}  // namespace

struct Renderer::Impl {
  GLuint program = 0;
  ProgramUniforms curve_u;  // of `program`
  GLint u_aa = -1, u_debug = -1;
  // Full AA: the same vertex stage, the exact area of each triangle per pixel.
  GLuint area_program = 0;
  ProgramUniforms area_u;
  Blending blending = Blending::Srgb;  // of the target begin() made
  bool gles = true;
  GLuint framebuffer = 0;
  GLuint texture = 0;
  int width = 0, height = 0;

  // vbaa / msaa: the second pass's program and offscreen targets.
  GLuint resolve_program = 0;
  GLint u_r_texture = -1, u_r_texture_size = -1, u_r_rect_origin = -1, u_r_r = -1, u_r_ring = -1, u_r_color = -1,
        u_r_coverage_exponent = -1;
  GLuint quad_vbo = 0;
  GLuint off_fbo = 0, off_tex = 0;
  int off_w = 0, off_h = 0;
  GLuint ms_fbo = 0, ms_rb = 0;
  int ms_w = 0, ms_h = 0;
  int max_samples = 0;    // 0: no multisampled renderbuffers
  int max_offscreen = 0;  // largest offscreen side
  struct OffscreenKey {
    std::uint64_t serial = 0;
    std::array<double, 9> matrix{};
    int x0 = 0, y0 = 0, w = 0, h = 0, factor = 0;
    bool msaa = false, paper = false;
    bool operator==(const OffscreenKey&) const = default;
  };
  OffscreenKey offscreen_key;
  bool offscreen_valid = false;
  std::size_t offscreen_passes = 0;

  void ensure_offscreen(int w, int h, bool msaa) {
    offscreen_valid = false;
    if (off_fbo == 0 || off_w < w || off_h < h || off_w != w || off_h != h) {
      if (off_fbo != 0) glDeleteFramebuffers(1, &off_fbo);
      if (off_tex != 0) glDeleteTextures(1, &off_tex);
      glGenTextures(1, &off_tex);
      glBindTexture(GL_TEXTURE_2D, off_tex);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
      glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, w, h, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
      glBindTexture(GL_TEXTURE_2D, 0);
      glGenFramebuffers(1, &off_fbo);
      glBindFramebuffer(GL_FRAMEBUFFER, off_fbo);
      glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, off_tex, 0);
      if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw Error(ErrorCode::Gl, "offscreen antialiasing framebuffer incomplete");
      off_w = w;
      off_h = h;
    }
    if (msaa && (ms_fbo == 0 || ms_w != w || ms_h != h)) {
      if (ms_fbo != 0) glDeleteFramebuffers(1, &ms_fbo);
      if (ms_rb != 0) glDeleteRenderbuffers(1, &ms_rb);
      glGenRenderbuffers(1, &ms_rb);
      glBindRenderbuffer(GL_RENDERBUFFER, ms_rb);
      glRenderbufferStorageMultisample(GL_RENDERBUFFER, max_samples, GL_RGBA8, w, h);
      glGenFramebuffers(1, &ms_fbo);
      glBindFramebuffer(GL_FRAMEBUFFER, ms_fbo);
      glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, ms_rb);
      if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw Error(ErrorCode::Gl, "multisampled framebuffer incomplete");
      ms_w = w;
      ms_h = h;
    }
  }
  void resolve_multisample(int w, int h) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, ms_fbo);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, off_fbo);
    glBlitFramebuffer(0, 0, w, h, 0, 0, w, h, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
  }

  Impl() = default;
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;
  ~Impl() {
    release_target();
    if (program != 0) glDeleteProgram(program);
    if (area_program != 0) glDeleteProgram(area_program);
    if (resolve_program != 0) glDeleteProgram(resolve_program);
    if (quad_vbo != 0) glDeleteBuffers(1, &quad_vbo);
    if (off_fbo != 0) glDeleteFramebuffers(1, &off_fbo);
    if (off_tex != 0) glDeleteTextures(1, &off_tex);
    if (ms_fbo != 0) glDeleteFramebuffers(1, &ms_fbo);
    if (ms_rb != 0) glDeleteRenderbuffers(1, &ms_rb);
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
  r.program = link_program(vs, fs, {"a_pos", "a_info"}, "curve shader program");
  r.curve_u = ProgramUniforms::of(r.program);
  r.u_aa = glGetUniformLocation(r.program, "u_aa");
  r.u_debug = glGetUniformLocation(r.program, "u_debug");
  r.gles = gles;

  {
    Shader avs(GL_VERTEX_SHADER), afs(GL_FRAGMENT_SHADER);
    compile(avs, GL_VERTEX_SHADER, shader_source::curve_vert_glsl, gles);
    compile(afs, GL_FRAGMENT_SHADER, shader_source::area_frag_glsl, gles);
    r.area_program = link_program(avs, afs, {"a_pos", "a_info"}, "full antialiasing program");
    r.area_u = ProgramUniforms::of(r.area_program);
  }

  // The vbaa / msaa filter pass.
  {
    Shader rvs(GL_VERTEX_SHADER), rfs(GL_FRAGMENT_SHADER);
    compile(rvs, GL_VERTEX_SHADER, shader_source::resolve_vert_glsl, gles);
    compile(rfs, GL_FRAGMENT_SHADER, shader_source::resolve_frag_glsl, gles);
    r.resolve_program = link_program(rvs, rfs, {"a_clip", "a_pixel"}, "vbaa/msaa filter program");
    r.u_r_texture = glGetUniformLocation(r.resolve_program, "u_texture");
    r.u_r_texture_size = glGetUniformLocation(r.resolve_program, "u_texture_size");
    r.u_r_rect_origin = glGetUniformLocation(r.resolve_program, "u_rect_origin");
    r.u_r_r = glGetUniformLocation(r.resolve_program, "u_r");
    r.u_r_ring = glGetUniformLocation(r.resolve_program, "u_ring");
    r.u_r_color = glGetUniformLocation(r.resolve_program, "u_color");
    r.u_r_coverage_exponent = glGetUniformLocation(r.resolve_program, "u_coverage_exponent");
    glGenBuffers(1, &r.quad_vbo);
  }
  GLint max_texture = 0, max_renderbuffer = 0, max_viewport[2] = {0, 0};
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_texture);
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_renderbuffer);
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, max_viewport);
  r.max_offscreen = std::min({max_texture, max_renderbuffer, max_viewport[0], max_viewport[1]});
  // Multisampled renderbuffers: GLES 3.0+ or desktop GL 3.0+.
  const char* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  int major = 0;
  if (version != nullptr) {
    const char* digits = gles ? version + 10 : version;  // "OpenGL ES 3.2 ..." or "4.6 ..."
    if (std::strlen(version) > 10 || !gles) major = std::atoi(digits);
  }
  if (major >= 3) {
    GLint samples = 0;
    glGetIntegerv(GL_MAX_SAMPLES, &samples);
    r.max_samples = std::min(samples, 16);  // the most offered, capped at 16 (llvmpipe: 4)
  }
  glGetError();  // a GLES2-only context may reject GL_MAX_SAMPLES
}

Renderer::~Renderer() = default;

void Renderer::begin(int width, int height, Color background, Blending blending) {
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
    throw Error(ErrorCode::InvalidArgument, "image size " + std::to_string(width) + "x" + std::to_string(height) +
                                                " exceeds the GL maximum of " + std::to_string(limit) +
                                                " pixels per side");
  }
  if (r.framebuffer == 0 || r.width != width || r.height != height || r.blending != blending) {
    r.release_target();
    glGenTextures(1, &r.texture);
    glBindTexture(GL_TEXTURE_2D, r.texture);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    // RGBA/UNSIGNED_BYTE is colour-renderable in every GLES2 implementation.
    // Linear blending: an sRGB texture, which GL decodes before blending and
    // encodes after (always on in GLES 3; desktop GL needs GL_FRAMEBUFFER_SRGB).
    if (blending == Blending::Linear)
      glTexImage2D(GL_TEXTURE_2D, 0, GL_SRGB8_ALPHA8, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
    else
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
    r.blending = blending;
  }
  if (!r.gles) {
    constexpr GLenum kFramebufferSrgb = 0x8DB9;  // GL_FRAMEBUFFER_SRGB (desktop GL only)
    if (blending == Blending::Linear)
      glEnable(kFramebufferSrgb);
    else
      glDisable(kFramebufferSrgb);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, r.framebuffer);
  glViewport(0, 0, width, height);
  glDisable(GL_SCISSOR_TEST);
  const std::array<float, 4> bg = premultiplied(background, blending);
  glClearColor(bg[0], bg[1], bg[2], bg[3]);
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
  const double s = placement.scale;
  // Outline units -> pixels (x_px = s x + ox, y_px = oy - s y), then the
  // projective transform.
  const Transform full =
      placement.transform * Transform{{s, 0.0, placement.origin_x, 0.0, -s, placement.origin_y, 0.0, 0.0, 1.0}};
  if (options.debug) {
    // The paper's Figure 1: its single pass, with what curved triangles discard shown.
    DrawOptions shown = options;
    if (shown.antialiasing != AntiAliasing::None) shown.antialiasing = AntiAliasing::Curves;
    draw_curves(b, full, vw, vh, shown);
    draw_debug_edges(b, full, vw, vh);
    return;
  }
  if (options.antialiasing == AntiAliasing::None || options.antialiasing == AntiAliasing::Curves) {
    draw_curves(b, full, vw, vh, options);
    return;
  }
  GLint target_fbo = 0;
  glGetIntegerv(GL_FRAMEBUFFER_BINDING, &target_fbo);
  if (draw_offscreen(b, full, vw, vh, static_cast<GLuint>(target_fbo), options)) return;
  // No coverage buffer fits (a block past the GL texture limit, or a
  // perspective that puts part of it behind the eye): the triangles' areas
  // blend straight into the target. Where two triangles split a pixel,
  // source-over blending then loses up to a quarter of it (a + b - ab).
  draw_area(b, full, vw, vh, premultiplied(options.color, r.blending), options.gamma, options.curve_mode, false);
}

namespace {

// The transform (outline units -> pixels) as a column-major mat3 uniform, and the viewport.
void set_view(GLint u_transform, GLint u_viewport, const Transform& full, float vw, float vh) {
  GLfloat m[9];
  for (int row = 0; row < 3; ++row)
    for (int col = 0; col < 3; ++col) m[col * 3 + row] = static_cast<GLfloat>(full.m[row * 3 + col]);
  glUniformMatrix3fv(u_transform, 1, GL_FALSE, m);
  glUniform2f(u_viewport, vw, vh);
}

GLfloat coverage_exponent(float gamma) {
  return 1.0f / std::clamp(gamma, static_cast<float>(tolerance::kMinCoverageGamma),
                           static_cast<float>(tolerance::kMaxCoverageGamma));
}

// Binds the batch's vertex buffer to the attributes at locations 0, 1
// (link_program binds them in order).
void bind_vertices(const DrawBatch::Impl& b) {
  glBindBuffer(GL_ARRAY_BUFFER, b.vbo);
  const GLsizei stride = static_cast<GLsizei>(sizeof(gpu::Vertex));
  for (GLuint i = 0; i < gpu::kVertexAttributes; ++i) {
    glEnableVertexAttribArray(i);
    glVertexAttribPointer(i, 4, GL_FLOAT, GL_FALSE, stride,
                          reinterpret_cast<const void*>(static_cast<std::uintptr_t>(i) * 16u));
  }
}

void unbind_vertices() {
  for (GLuint i = 0; i < gpu::kVertexAttributes; ++i) glDisableVertexAttribArray(i);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
}

// Draws the batch's triangles with the current program and blending.
void draw_triangles(const DrawBatch::Impl& b) {
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_STENCIL_TEST);
  glDisable(GL_CULL_FACE);  // triangles come in either orientation
  bind_vertices(b);
  if (b.index_type != 0) {
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, b.ibo);
    glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(b.index_count), b.index_type, nullptr);
  } else {
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(b.vertex_count));
  }
  unbind_vertices();
  if (GLenum err = glGetError(); err != GL_NO_ERROR) {
    throw Error(ErrorCode::Gl, "drawing a batch failed (GL error " + hex(err) + ")");
  }
}

}  // namespace

// Full AA: every triangle's exact area per pixel (shaders/area.frag.glsl),
// added into the bound framebuffer (`accumulate`) or blended over it.
void Renderer::draw_area(const DrawBatch::Impl& b, const Transform& full, float vw, float vh,
                         const std::array<float, 4>& color, float gamma, CurveMode curve_mode, bool accumulate) {
  Impl& r = *impl_;
  glUseProgram(r.area_program);
  set_view(r.area_u.transform, r.area_u.viewport, full, vw, vh);
  glUniform1f(r.area_u.fringe_px, tolerance::kFringeWidthPx);
  glUniform4f(r.area_u.color, color[0], color[1], color[2], color[3]);
  glUniform1f(r.area_u.coverage_exponent, coverage_exponent(gamma));
  glUniform1i(r.area_u.curve_mode, curve_mode == CurveMode::Paper ? 1 : 0);
  glEnable(GL_BLEND);
  if (accumulate)
    glBlendFunc(GL_ONE, GL_ONE);
  else
    glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  draw_triangles(b);
}

// none and curves (and msaa's in/out pass): the paper's single pass.
void Renderer::draw_curves(const DrawBatch::Impl& b, const Transform& full, float vw, float vh,
                           const DrawOptions& options) {
  Impl& r = *impl_;
  glUseProgram(r.program);
  set_view(r.curve_u.transform, r.curve_u.viewport, full, vw, vh);
  glUniform1f(r.curve_u.fringe_px, 0.0f);  // triangles as they are
  const std::array<float, 4> color = premultiplied(options.color, r.blending);
  glUniform4f(r.curve_u.color, color[0], color[1], color[2], color[3]);
  glUniform1f(r.curve_u.coverage_exponent, coverage_exponent(options.gamma));
  glUniform1i(r.u_debug, options.debug ? 1 : 0);
  glUniform1i(r.u_aa, options.antialiasing == AntiAliasing::Curves ? 1 : 0);
  glUniform1i(r.curve_u.curve_mode, options.curve_mode == CurveMode::Paper ? 1 : 0);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);  // premultiplied source-over
  draw_triangles(b);
}

int Renderer::msaa_samples() const { return impl_->max_samples; }

// full, vbaa and msaa: the block's projected bounding box (plus a border) is
// drawn into an offscreen texture: for full, the sum of its triangles' exact
// areas per pixel; for vbaa (paper section 5) the same r times larger; for
// msaa, an in/out pass into a multisampled renderbuffer resolved into it.
// Then a quad over the box filters it into the target. The offscreen pass is
// kept and reused while the batch, its transform, the box and the mode stay
// the same. False when it cannot be done here (the caller blends the areas
// directly).
bool Renderer::draw_offscreen(const DrawBatch::Impl& b, const Transform& full, float vw, float vh, GLuint target_fbo,
                              const DrawOptions& options) {
  Impl& r = *impl_;
  const bool msaa = options.antialiasing == AntiAliasing::Msaa && r.max_samples >= 2;
  const bool vbaa = options.antialiasing == AntiAliasing::Vbaa;
  if (b.bounds.empty()) return true;
  // Projected box of the batch (a projective map with w > 0 keeps convex
  // sets convex, so the corners' box holds the block), plus a border for
  // the triangles' growth and the filter's ring.
  Box box;
  const Vec2 corners[4] = {
      b.bounds.min, {b.bounds.max.x, b.bounds.min.y}, {b.bounds.min.x, b.bounds.max.y}, b.bounds.max};
  for (Vec2 c : corners) {
    if (!(full.w(c) > 0.0)) return false;
    box.add(full.apply(c));
  }
  const double border = tolerance::kOffscreenBorderPx;
  const int x0 = std::max(0, static_cast<int>(std::floor(box.min.x - border)));
  const int y0 = std::max(0, static_cast<int>(std::floor(box.min.y - border)));
  const int x1 = std::min(static_cast<int>(vw), static_cast<int>(std::ceil(box.max.x + border)));
  const int y1 = std::min(static_cast<int>(vh), static_cast<int>(std::ceil(box.max.y + border)));
  if (x1 <= x0 || y1 <= y0) return true;  // off screen
  const int w = x1 - x0, h = y1 - y0;
  int factor = vbaa ? std::clamp(options.vbaa_factor, 1, 8) : 1;
  // Degrade gracefully: a smaller factor where the texture would pass the GL
  // maximum (factor 1 is full).
  while (factor > 1 && (w * factor > r.max_offscreen || h * factor > r.max_offscreen)) --factor;
  if (w * factor > r.max_offscreen || h * factor > r.max_offscreen) return false;
  const int tw = w * factor, th = h * factor;

  Impl::OffscreenKey key{b.serial, full.m, x0, y0, w, h, factor, msaa, options.curve_mode == CurveMode::Paper};
  if (!(r.offscreen_valid && key == r.offscreen_key)) {
    r.ensure_offscreen(tw, th, msaa);
    // Draw the block's coverage (white, so alpha holds it) into the texture,
    // or the multisampled renderbuffer, with the box's origin at (0, 0).
    glBindFramebuffer(GL_FRAMEBUFFER, msaa ? r.ms_fbo : r.off_fbo);
    glViewport(0, 0, tw, th);
    glDisable(GL_SCISSOR_TEST);
    glClearColor(0, 0, 0, 0);
    glClear(GL_COLOR_BUFFER_BIT);
    const Transform to_texture = Transform::scale(factor, factor) * Transform::translation(-x0, -y0) * full;
    if (msaa) {
      DrawOptions pass = options;
      pass.color = Color{1, 1, 1, 1};
      pass.antialiasing = AntiAliasing::None;
      pass.gamma = 1.0f;  // applied after the filter
      const Blending target_blending = r.blending;
      r.blending = Blending::Srgb;  // the coverage texture is plain RGBA
      draw_curves(b, to_texture, static_cast<float>(tw), static_cast<float>(th), pass);
      r.blending = target_blending;
      r.resolve_multisample(tw, th);
    } else {
      draw_area(b, to_texture, static_cast<float>(tw), static_cast<float>(th), {1.0f, 1.0f, 1.0f, 1.0f}, 1.0f,
                options.curve_mode, true);
    }
    r.offscreen_key = key;
    r.offscreen_valid = true;
    ++r.offscreen_passes;
  }

  // The filter pass into the target, over the box only.
  glBindFramebuffer(GL_FRAMEBUFFER, target_fbo);
  glViewport(0, 0, static_cast<GLsizei>(vw), static_cast<GLsizei>(vh));
  glUseProgram(r.resolve_program);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, r.off_tex);
  glUniform1i(r.u_r_texture, 0);
  glUniform2f(r.u_r_texture_size, static_cast<float>(tw), static_cast<float>(th));
  glUniform2f(r.u_r_rect_origin, static_cast<float>(x0), static_cast<float>(y0));
  glUniform1f(r.u_r_r, static_cast<float>(factor));
  glUniform1f(r.u_r_ring, vbaa && factor > 1 ? std::clamp(options.vbaa_ring, 0.0f, 1.0f) : 0.0f);
  const std::array<float, 4> color = premultiplied(options.color, r.blending);
  glUniform4f(r.u_r_color, color[0], color[1], color[2], color[3]);
  glUniform1f(r.u_r_coverage_exponent, coverage_exponent(options.gamma));
  const float cx0 = 2.0f * static_cast<float>(x0) / vw - 1.0f, cx1 = 2.0f * static_cast<float>(x1) / vw - 1.0f;
  const float cy0 = 1.0f - 2.0f * static_cast<float>(y0) / vh, cy1 = 1.0f - 2.0f * static_cast<float>(y1) / vh;
  // Each corner as (clip x, clip y, pixel x, pixel y down); the pixel
  // position reaches the fragment stage as a highp varying (resolve.vert.glsl).
  const GLfloat px0 = static_cast<GLfloat>(x0), px1 = static_cast<GLfloat>(x1);
  const GLfloat py0 = static_cast<GLfloat>(y0), py1 = static_cast<GLfloat>(y1);
  const GLfloat quad[24] = {cx0, cy0, px0, py0, cx1, cy0, px1, py0, cx1, cy1, px1, py1,
                            cx0, cy0, px0, py0, cx1, cy1, px1, py1, cx0, cy1, px0, py1};
  glBindBuffer(GL_ARRAY_BUFFER, r.quad_vbo);
  glBufferData(GL_ARRAY_BUFFER, sizeof quad, quad, GL_STREAM_DRAW);
  glEnableVertexAttribArray(0);
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 4 * sizeof(GLfloat), nullptr);
  glVertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, 4 * sizeof(GLfloat),
                        reinterpret_cast<const void*>(2 * sizeof(GLfloat)));
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  glDrawArrays(GL_TRIANGLES, 0, 6);
  glDisableVertexAttribArray(0);
  glDisableVertexAttribArray(1);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glBindTexture(GL_TEXTURE_2D, 0);
  if (GLenum err = glGetError(); err != GL_NO_ERROR) {
    throw Error(ErrorCode::Gl, std::string(msaa   ? "msaa"
                                           : vbaa ? "vbaa"
                                                  : "full antialiasing") +
                                   " pass failed (GL error " + hex(err) + ")");
  }
  return true;
}

// --debug: every triangle's edges in a flat colour (the curve program with
// u_debug = 2 draws the triangles themselves and keeps only the pixels within
// a pixel of an edge), over what draw_curves drew.
void Renderer::draw_debug_edges(const DrawBatch::Impl& b, const Transform& full, float vw, float vh) {
  Impl& r = *impl_;
  glUseProgram(r.program);
  set_view(r.curve_u.transform, r.curve_u.viewport, full, vw, vh);
  glUniform1f(r.curve_u.fringe_px, 0.0f);  // the triangles themselves, not grown
  glUniform1i(r.u_debug, 2);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  draw_triangles(b);
  glUniform1i(r.u_debug, 0);
  if (GLenum err = glGetError(); err != GL_NO_ERROR)
    throw Error(ErrorCode::Gl, "drawing debug edges failed (GL error " + hex(err) + ")");
}

std::size_t Renderer::offscreen_passes() const { return impl_->offscreen_passes; }

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
      if (r.blending == Blending::Linear && a > 0 && a < 255) {
        // Stored: sRGB encoding of premultiplied linear colour. Straight
        // alpha: decode, divide by alpha, encode.
        for (std::size_t k = 0; k < 3; ++k) {
          const float lin = srgb_to_linear(src[i + k] / 255.0f) * 255.0f / static_cast<float>(a);
          dst[i + k] = static_cast<std::uint8_t>(
              std::lround(std::clamp(linear_to_srgb(std::min(lin, 1.0f)), 0.0f, 1.0f) * 255.0f));
        }
        dst[i + 3] = static_cast<std::uint8_t>(a);
        continue;
      }
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
