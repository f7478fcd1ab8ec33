// The curve shader programs, offscreen coverage passes, and drawing of
// batches with premultiplied source-over blending.
#include <GLES3/gl3.h>

#include <algorithm>
#include <array>
#include <vector>
#include <cstdlib>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <initializer_list>
#include <string>
#include <utility>

#include "curvetext/renderer.hpp"

#include "curvetext/error.hpp"
#include "core/tolerances.hpp"
#include "gpu/bands.hpp"
#include "gpu/bands_es2.hpp"
#include "gpu/batch_impl.hpp"
#include "gpu/effects.hpp"
#include "gpu/gl_state.hpp"
#include "gpu/gl_util.hpp"
#include "gpu/paint.hpp"
#include "gpu/shader_sources.hpp"

namespace curvetext {

using gpu::glsl1_preamble;
using gpu::hex;
using gpu::new_texture;
using gpu::premultiplied;

namespace {

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

void compile_text(const Shader& shader, GLenum type, const std::string& text);

void compile(const Shader& shader, GLenum type, const char* source, bool gles, const char* defines_ = "") {
  std::string text = glsl1_preamble(type, gles);  // (the files have no #version line)
  text += defines_;
  // Tolerances the shaders share with the library (tolerances.hpp), named
  // there only; preprocessor lines may precede #extension.
  char defines[160];
  std::snprintf(defines, sizeof defines,
                "#define CURVETEXT_PIXEL_REACH_PX %.7f\n#define CURVETEXT_THIN_TRIANGLE_PX %.9f\n",
                static_cast<double>(tolerance::kFringeWidthPx), static_cast<double>(tolerance::kThinTrianglePx));
  text += defines;
  // #extension must precede other statements but follow #version. Desktop
  // GLSL 3.30 has the derivatives built in, and its preamble has declared
  // the fragment output already, so the directive goes.
  if (gles) {
    text += source;
  } else {
    for (const char* line = source; *line != '\0';) {
      const char* end = std::strchr(line, '\n');
      const std::size_t n = end != nullptr ? static_cast<std::size_t>(end - line + 1) : std::strlen(line);
      if (std::strncmp(line, "#extension", 10) != 0) text.append(line, n);
      line += n;
    }
  }
  compile_text(shader, type, text);
}

// The band shaders (bands.vert/frag.glsl) are GLSL ES 3.00 / desktop 3.30
// (texelFetch, integer operations, flat varyings); the preamble is only the
// #version line and these: the band texture's width, the cell grids' sizes,
// and whether the GLES 2 program's part of bands.frag.glsl is wanted.
std::string band_defines(bool es2) {
  char width[256];
  std::snprintf(width, sizeof width,
                "#define CURVETEXT_BAND_WIDTH %d\n#define CURVETEXT_BAND_WIDTH_LOG2 %d\n"
                "#define CURVETEXT_GRID_MIN_LOG2 %d\n#define CURVETEXT_GRID_MAX_LOG2 %d\n"
                "#define CURVETEXT_ES2 %d\n#define CURVETEXT_ES2_ENTRY_CAP %d\n",
                gpu::kBandTextureWidth, gpu::kBandTextureWidthLog2, gpu::kGridMinLog2, gpu::kGridMaxLog2, es2 ? 1 : 0,
                tolerance::kEs2BandEntryCap);
  return width;
}

void compile_glsl3(const Shader& shader, GLenum type, const char* source, bool gles, const std::string& defines) {
  compile_text(
      shader, type,
      std::string(gles ? "#version 300 es\n" : "#version 330 core\n") + band_defines(false) + defines + source);
}

// The GLES 2 band program (lib/gpu/bands_es2.hpp) is GLSL ES 1.00: its
// fragment stage is bands.frag.glsl's area functions (CURVETEXT_ES2 1)
// followed by bands_es2.frag.glsl.
void compile_es2_bands(const Shader& vs, const Shader& fs, const std::string& defines) {
  const std::string preamble = "#version 100\n" + band_defines(true);
  compile_text(vs, GL_VERTEX_SHADER, preamble + shader_source::bands_es2_vert_glsl);
  compile_text(fs, GL_FRAGMENT_SHADER,
               preamble + defines + shader_source::bands_frag_glsl + shader_source::bands_es2_frag_glsl);
}

void compile_text(const Shader& shader, GLenum type, const std::string& text) {
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

}  // namespace

namespace {
// The uniforms both curve programs (curve.vert.glsl with curve.frag.glsl or
// area.frag.glsl) have.
struct ProgramUniforms {
  GLint transform = -1, viewport = -1, depth = -1, fringe_px = -1, color = -1, coverage_exponent = -1, curve_mode = -1;
  static ProgramUniforms of(GLuint program) {
    ProgramUniforms u;
    u.depth = glGetUniformLocation(program, "u_depth");
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
  // Full AA: the same vertex stage, the exact area of each triangle per
  // pixel; one program for interior triangles, one for curved ones.
  // Each also with gamma (CURVETEXT_GAMMA 1, [1][...]), compiled when first
  // needed: a software rasteriser runs every path of a shader, so the pow of
  // gamma would cost every fragment even where gamma is 1.
  GLuint area_program[2][2] = {{0, 0}, {0, 0}};
  ProgramUniforms area_u[2][2];
  // The depth plane of the pass being drawn (set_view): the placement's for
  // the pass into the application's framebuffer, 0 offscreen.
  std::array<float, 3> pass_depth{0.0f, 0.0f, 0.0f};
  DepthTest pass_depth_test = DepthTest::Application;
  Blending target_blending = Blending::Srgb;  // of the framebuffer the current draw targets
  bool gles = true;
  gpu::ContextInfo info;  // of the context current at construction
  GLuint vao = 0;         // curvetext's own vertex array object (GLES 3, desktop GL 3)
  // Coverage textures with one 8-bit channel (GL_R8) where the context renders
  // into them (GLES 3, desktop GL 3), else RGBA8: a quarter of the memory and
  // of the bytes the passes write and the composite reads.
  bool single_channel = false;
  std::size_t texel_bytes() const { return single_channel ? 1u : 4u; }

  // The second pass of full / vbaa / msaa: a quad over the block's box that
  // reads its coverage texture, one fetch per pixel (composite.frag.glsl) or
  // through vbaa's filter (resolve.frag.glsl).
  struct QuadProgram {
    GLuint id = 0;
    GLint texture = -1, texture_size = -1, rect_origin = -1, rows = -1, r = -1, ring = -1, color = -1,
          coverage_exponent = -1, depth = -1;
  };
  // composite[box][gamma]: one fetch per pixel, or vbaa's box filter
  // (CURVETEXT_BOX); with gamma or not. Each made when first needed.
  QuadProgram resolve, composite[2][2];
  // The same with a gradient's colour per pixel (CURVETEXT_PAINT).
  QuadProgram paint_composite[2][2];
  gpu::PaintUniforms paint_u[2][2];
  // One pass exact area from curve bands (bands.vert/frag.glsl), without
  // and with gamma; a quad's corners for its instances.
  struct BandProgram {
    GLuint id = 0;
    ProgramUniforms view;
    GLint half = -1, bands = -1, rows = -1, inverse = -1, projective = -1;
  };
  // GLSL ES 3.00 / 3.30, or ES 1.00 in a GLES 2 context (bands_es2.hpp,
  // boxes only).
  BandProgram band_program[2][2][2];  // [gamma][conics][footprint: a map that turns the axes]
  GLuint corner_vbo = 0;
  GLuint quad_indices = 0;  // GLES 2: each glyph's quad as 4 vertices, 6 indices
  std::size_t band_draws = 0;
  // Colour bitmaps: textured quads (bitmap.vert/frag.glsl).
  GLuint bitmap_program = 0;
  GLint bitmap_transform = -1, bitmap_viewport = -1, bitmap_depth = -1, bitmap_texture = -1, bitmap_opacity = -1,
        bitmap_linear = -1;
  GLuint quad_vbo = 0;
  int max_samples = 0;    // 0: no multisampled renderbuffers
  int max_offscreen = 0;  // largest offscreen side

  // What a coverage texture holds: the batch, its transform, the tile of the
  // framebuffer (with its apron) and how it was drawn.
  struct OffscreenKey {
    std::uint64_t serial = 0;
    std::array<double, 9> matrix{};
    int x0 = 0, y0 = 0, w = 0, h = 0, factor = 0;
    bool msaa = false, paper = false;
    bool operator==(const OffscreenKey&) const = default;
  };
  // A coverage texture, allocated once and grown (never per draw), up to a
  // tile of tolerance::kCoverageTileTexels per side; the pass it holds is
  // reused while its key matches. A new one is made while there are fewer
  // than kCoverageSlots and they fit kCoverageBudgetBytes; else the least
  // recently used one takes the new pass.
  struct Slot {
    GLuint fbo = 0, texture = 0;
    int w = 0, h = 0;  // allocated texels
    OffscreenKey key;
    bool valid = false;
    std::uint64_t used = 0;
  };
  std::vector<Slot> slots;
  std::uint64_t clock = 0;
  // msaa: one multisampled renderbuffer, grown up to kMsaaTileTexels per side.
  GLuint ms_fbo = 0, ms_rb = 0;
  int ms_w = 0, ms_h = 0;
  std::size_t offscreen_passes = 0;
  std::shared_ptr<gpu::EffectPasses> effect_passes;  // text shadows (gpu/effects.cpp)

  // The slot holding `key`'s pass (hit), else the least recently used one,
  // grown to w x h texels and marked empty.
  Slot& slot_for(const OffscreenKey& key, int w, int h, bool& hit) {
    ++clock;
    for (Slot& s : slots)
      if (s.valid && s.key == key) {
        s.used = clock;
        hit = true;
        return s;
      }
    hit = false;
    std::size_t bytes = 0;
    for (const Slot& s : slots) bytes += texel_bytes() * static_cast<std::size_t>(s.w) * static_cast<std::size_t>(s.h);
    const std::size_t needed =
        texel_bytes() * static_cast<std::size_t>(round_up(w)) * static_cast<std::size_t>(round_up(h));
    if (slots.empty() ||
        (slots.size() < tolerance::kCoverageSlots && bytes + needed <= tolerance::kCoverageBudgetBytes))
      slots.emplace_back();
    Slot& s =
        *std::min_element(slots.begin(), slots.end(), [](const Slot& a, const Slot& b) { return a.used < b.used; });
    s.used = clock;
    s.valid = false;
    if (s.fbo == 0 || s.w < w || s.h < h) allocate(s, std::max(s.w, round_up(w)), std::max(s.h, round_up(h)));
    return s;
  }
  static int round_up(int n) { return (n + 63) / 64 * 64; }
  void allocate(Slot& s, int w, int h) {
    if (s.fbo != 0) glDeleteFramebuffers(1, &s.fbo);
    if (s.texture != 0) glDeleteTextures(1, &s.texture);
    s.texture = single_channel ? new_texture(GL_R8, GL_RED, w, h) : new_texture(GL_RGBA, GL_RGBA, w, h);
    glGenFramebuffers(1, &s.fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, s.fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, s.texture, 0);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
      throw Error(ErrorCode::Gl, "offscreen antialiasing framebuffer incomplete");
    s.w = w;
    s.h = h;
  }
  void ensure_multisample(int w, int h) {
    if (ms_fbo != 0 && ms_w >= w && ms_h >= h) return;
    w = std::max(ms_w, round_up(w));
    h = std::max(ms_h, round_up(h));
    if (ms_fbo != 0) glDeleteFramebuffers(1, &ms_fbo);
    if (ms_rb != 0) glDeleteRenderbuffers(1, &ms_rb);
    glGenRenderbuffers(1, &ms_rb);
    glBindRenderbuffer(GL_RENDERBUFFER, ms_rb);
    // The format of the coverage textures it is resolved into (a resolve
    // blit cannot convert).
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, max_samples, single_channel ? GL_R8 : GL_RGBA8, w, h);
    glGenFramebuffers(1, &ms_fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, ms_fbo);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, ms_rb);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
      throw Error(ErrorCode::Gl, "multisampled framebuffer incomplete");
    ms_w = w;
    ms_h = h;
  }
  void resolve_multisample(const Slot& s, int w, int h) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, ms_fbo);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, s.fbo);
    glBlitFramebuffer(0, 0, w, h, 0, 0, w, h, GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
  }

  // curvetext's own state for its draws (the caller restores the
  // application's): its VAO, additive blend equation, no depth, stencil,
  // culling, rasterizer discard or primitive restart.
  void bind_own_state() {
    if (info.gl3()) {
      if (vao == 0) glGenVertexArrays(1, &vao);
      glBindVertexArray(vao);
      glDisable(GL_RASTERIZER_DISCARD);
      if (info.gles) glDisable(GL_PRIMITIVE_RESTART_FIXED_INDEX);
    }
    glBlendEquation(GL_FUNC_ADD);
    glDisable(GL_STENCIL_TEST);
    glDisable(GL_CULL_FACE);  // triangles come in either orientation
    // The depth test stays the application's for the pass into its
    // framebuffer (unless the placement turns it off); the offscreen passes
    // turn it off.
    if (pass_depth_test == DepthTest::Off) glDisable(GL_DEPTH_TEST);
  }
  // The application's target for the pass into it, with the placement's
  // depth test.
  void apply_target(const gpu::GlStateBackup& target) const {
    target.apply_target();
    if (pass_depth_test == DepthTest::Off) glDisable(GL_DEPTH_TEST);
  }

  // Each program compiled and linked on first use (Error(Gl) if it fails).
  void make_curve_program();
  void make_area_programs(bool gamma);  // area_program[gamma]
  const BandProgram& make_band_program(bool gamma, bool conics, bool footprint);
  const QuadProgram& composite_program(bool box, bool gamma);
  const QuadProgram& resolve_program();
  const QuadProgram& paint_program(bool box, bool gamma);

  // The passes of Renderer::draw (below).
  void draw_curves(const gpu::BatchImpl& b, const Transform& full, float vw, float vh, const DrawOptions& options);
  void render_coverage(const gpu::BatchImpl& b, const Transform& full, const OffscreenKey& key, Slot& slot,
                       const DrawOptions& options);
  bool draw_offscreen(const gpu::BatchImpl& b, const Transform& full, float vw, float vh,
                      const gpu::GlStateBackup& target, const DrawOptions& options);
  void draw_area(const gpu::BatchImpl& b, const Transform& full, float vw, float vh, const std::array<float, 4>& color,
                 float gamma, CurveMode curve_mode, bool accumulate);
  void draw_debug_edges(const gpu::BatchImpl& b, const Transform& full, float vw, float vh);
  // Whether the band program draws `b` under `full` (outline units ->
  // pixels): draw_bands' precondition.
  bool bands_serve(const gpu::BatchImpl& b, const Transform& full) const;
  void draw_bands(const gpu::BatchImpl& b, const Transform& full, float vw, float vh, const DrawOptions& options);
  void draw_bitmaps(const gpu::BatchImpl& b, const Transform& full, float vw, float vh, const DrawOptions& options);

  Impl() = default;
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;
  ~Impl() {
    for (GLuint p :
         {program, area_program[0][0], area_program[0][1], area_program[1][0], area_program[1][1], resolve.id,
          composite[0][0].id, composite[0][1].id, composite[1][0].id, composite[1][1].id, bitmap_program,
          paint_composite[0][0].id, paint_composite[0][1].id, paint_composite[1][0].id, paint_composite[1][1].id})
      if (p != 0) glDeleteProgram(p);
    for (const auto& by_gamma : band_program)
      for (const auto& by_conics : by_gamma)
        for (const BandProgram& p : by_conics)
          if (p.id != 0) glDeleteProgram(p.id);
    if (quad_vbo != 0) glDeleteBuffers(1, &quad_vbo);
    if (corner_vbo != 0) glDeleteBuffers(1, &corner_vbo);
    if (quad_indices != 0) glDeleteBuffers(1, &quad_indices);
    if (vao != 0) glDeleteVertexArrays(1, &vao);
    for (Slot& s : slots) {
      if (s.fbo != 0) glDeleteFramebuffers(1, &s.fbo);
      if (s.texture != 0) glDeleteTextures(1, &s.texture);
    }
    if (ms_fbo != 0) glDeleteFramebuffers(1, &ms_fbo);
    if (ms_rb != 0) glDeleteRenderbuffers(1, &ms_rb);
  }
};

// Names Renderer::Impl for the helpers below (a friend of Renderer).
struct RendererAccess {
  using Impl = Renderer::Impl;
  static Impl& impl(Renderer& r) { return *r.impl_; }
};

std::shared_ptr<gpu::EffectPasses>& gpu::effect_passes(Renderer& renderer) {
  return RendererAccess::impl(renderer).effect_passes;
}

namespace {
using RendererImpl = RendererAccess::Impl;

// Compiles and links one of the second pass's programs.
RendererImpl::QuadProgram quad_program(const char* fragment_source, bool gles, const char* defines, const char* what) {
  Shader vs(GL_VERTEX_SHADER), fs(GL_FRAGMENT_SHADER);
  compile(vs, GL_VERTEX_SHADER, shader_source::resolve_vert_glsl, gles);
  compile(fs, GL_FRAGMENT_SHADER, fragment_source, gles, defines);
  RendererImpl::QuadProgram q;
  q.id = link_program(vs, fs, {"a_clip", "a_pixel"}, what);
  q.texture = glGetUniformLocation(q.id, "u_texture");
  q.texture_size = glGetUniformLocation(q.id, "u_texture_size");
  q.rect_origin = glGetUniformLocation(q.id, "u_rect_origin");
  q.depth = glGetUniformLocation(q.id, "u_depth");
  q.rows = glGetUniformLocation(q.id, "u_rows");
  q.r = glGetUniformLocation(q.id, "u_r");
  q.ring = glGetUniformLocation(q.id, "u_ring");
  q.color = glGetUniformLocation(q.id, "u_color");
  q.coverage_exponent = glGetUniformLocation(q.id, "u_coverage_exponent");
  return q;
}
}  // namespace

void Renderer::Impl::make_curve_program() {
  if (program != 0) return;
  Shader vs(GL_VERTEX_SHADER), fs(GL_FRAGMENT_SHADER);
  if (vs.id == 0 || fs.id == 0) throw Error(ErrorCode::Gl, "glCreateShader failed");
  compile(vs, GL_VERTEX_SHADER, shader_source::curve_vert_glsl, gles);
  compile(fs, GL_FRAGMENT_SHADER, shader_source::curve_frag_glsl, gles);
  program = link_program(vs, fs, {"a_pos", "a_info", "a_offset"}, "curve shader program");
  curve_u = ProgramUniforms::of(program);
  u_aa = glGetUniformLocation(program, "u_aa");
  u_debug = glGetUniformLocation(program, "u_debug");
}

const Renderer::Impl::QuadProgram& Renderer::Impl::resolve_program() {
  if (resolve.id == 0) resolve = quad_program(shader_source::resolve_frag_glsl, gles, "", "vbaa filter program");
  return resolve;
}

void Renderer::Impl::make_area_programs(bool gamma) {
  const int g = gamma ? 1 : 0;
  if (area_program[g][0] != 0) return;
  for (int curved = 0; curved < 2; ++curved) {
    Shader vs(GL_VERTEX_SHADER), fs(GL_FRAGMENT_SHADER);
    compile(vs, GL_VERTEX_SHADER, shader_source::curve_vert_glsl, gles);
    const std::string defines = std::string("#define CURVETEXT_AREA_CURVED ") + (curved ? "1" : "0") +
                                "\n#define CURVETEXT_GAMMA " + (gamma ? "1" : "0") + "\n";
    compile(fs, GL_FRAGMENT_SHADER, shader_source::area_frag_glsl, gles, defines.c_str());
    area_program[g][curved] = link_program(vs, fs, {"a_pos", "a_info", "a_offset"}, "full antialiasing program");
    area_u[g][curved] = ProgramUniforms::of(area_program[g][curved]);
  }
}

const Renderer::Impl::BandProgram& Renderer::Impl::make_band_program(bool gamma, bool conics, bool footprint) {
  BandProgram& p = band_program[gamma ? 1 : 0][conics ? 1 : 0][footprint ? 1 : 0];
  if (p.id != 0) return p;
  Shader vs(GL_VERTEX_SHADER), fs(GL_FRAGMENT_SHADER);
  const std::string footprint_define = std::string("#define CURVETEXT_FOOTPRINT ") + (footprint ? "1" : "0") + "\n";
  const std::string defines = std::string("#define CURVETEXT_GAMMA ") + (gamma ? "1" : "0") +
                              "\n#define CURVETEXT_CONICS " + (conics ? "1" : "0") + "\n" + footprint_define;
  if (!info.gl3()) {
    compile_es2_bands(vs, fs, defines);
  } else {
    compile_glsl3(vs, GL_VERTEX_SHADER, shader_source::bands_vert_glsl, gles, footprint_define);
    compile_glsl3(fs, GL_FRAGMENT_SHADER, shader_source::bands_frag_glsl, gles, defines);
  }
  p.id = link_program(vs, fs, {"a_corner", "a_rect", "a_place"}, "band program");
  p.view = ProgramUniforms::of(p.id);
  p.half = glGetUniformLocation(p.id, "u_half");
  p.bands = glGetUniformLocation(p.id, "u_bands");
  p.inverse = glGetUniformLocation(p.id, "u_inverse");
  p.projective = glGetUniformLocation(p.id, "u_projective");
  p.rows = glGetUniformLocation(p.id, "u_rows");
  if (!info.gl3()) {
    if (quad_indices == 0) quad_indices = gpu::make_band_quad_indices();
  } else if (corner_vbo == 0) {
    const GLfloat corners[8] = {0, 0, 1, 0, 0, 1, 1, 1};
    glGenBuffers(1, &corner_vbo);
    const gpu::BufferBindingScope bound(GL_ARRAY_BUFFER, corner_vbo);
    glBufferData(GL_ARRAY_BUFFER, sizeof corners, corners, GL_STATIC_DRAW);
  }
  return p;
}

const Renderer::Impl::QuadProgram& Renderer::Impl::composite_program(bool box, bool gamma) {
  QuadProgram& q = composite[box ? 1 : 0][gamma ? 1 : 0];
  if (q.id == 0) {
    const std::string defines = std::string("#define CURVETEXT_BOX ") + (box ? "1" : "0") +
                                "\n#define CURVETEXT_GAMMA " + (gamma ? "1" : "0") + "\n";
    q = quad_program(shader_source::composite_frag_glsl, gles, (defines + "#define CURVETEXT_PAINT 0\n").c_str(),
                     "coverage composite program");
  }
  return q;
}

const Renderer::Impl::QuadProgram& Renderer::Impl::paint_program(bool box, bool gamma) {
  QuadProgram& q = paint_composite[box ? 1 : 0][gamma ? 1 : 0];
  if (q.id == 0) {
    const std::string defines = std::string("#define CURVETEXT_BOX ") + (box ? "1" : "0") +
                                "\n#define CURVETEXT_GAMMA " + (gamma ? "1" : "0") + "\n";
    q = quad_program(shader_source::composite_frag_glsl, gles, (defines + "#define CURVETEXT_PAINT 1\n").c_str(),
                     "gradient composite program");
    paint_u[box ? 1 : 0][gamma ? 1 : 0] = gpu::PaintUniforms::of(q.id);
  }
  return q;
}

Renderer::Renderer() : impl_(std::make_unique<Impl>()) {
  if (glGetString(GL_VERSION) == nullptr) {
    throw Error(ErrorCode::Gl, "no current GL context (create a HeadlessContext or make one current)");
  }
  Impl& r = *impl_;
  r.gles = is_gles();
  r.info = gpu::ContextInfo::current();
  // The programs are compiled when a mode first needs them (a process that
  // draws once, as the CLI does, compiles only its mode's).
  glGenBuffers(1, &r.quad_vbo);
  GLint max_texture = 0, max_renderbuffer = 0, max_viewport[2] = {0, 0};
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_texture);
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &max_renderbuffer);
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, max_viewport);
  r.max_offscreen = std::min({max_texture, max_renderbuffer, max_viewport[0], max_viewport[1]});
  // Multisampled renderbuffers: GLES 3.0+ or desktop GL 3.0+.
  const char* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  int major = 0;
  if (version != nullptr) {
    const char* digits = r.gles ? version + 10 : version;  // "OpenGL ES 3.2 ..." or "4.6 ..."
    if (std::strlen(version) > 10 || !r.gles) major = std::atoi(digits);
  }
  r.single_channel = major >= 3;
  if (major >= 3) {
    GLint samples = 0;
    glGetIntegerv(GL_MAX_SAMPLES, &samples);
    r.max_samples = std::min(samples, 16);  // the most offered, capped at 16 (llvmpipe: 4)
  }
  glGetError();  // a GLES2-only context may reject GL_MAX_SAMPLES
}

Renderer::~Renderer() = default;

namespace {

void check_placement(const Placement& placement) {
  if (!std::isfinite(placement.scale) || placement.scale == 0.0 || !std::isfinite(placement.origin_x) ||
      !std::isfinite(placement.origin_y) || !std::isfinite(placement.depth_offset)) {
    throw Error(ErrorCode::InvalidArgument,
                "placement needs a finite non-zero scale, a finite origin and a finite depth offset");
  }
  placement.transform.validate();
}

// Outline units -> pixels (x_px = s x + ox, y_px = oy - s y), then the
// placement's projective transform.
Transform outline_to_pixels(const Placement& placement) {
  const double s = placement.scale;
  return placement.transform * Transform{{s, 0.0, placement.origin_x, 0.0, -s, placement.origin_y, 0.0, 0.0, 1.0}};
}

}  // namespace

bool Renderer::draws_from_bands(const DrawBatch& batch, const Placement& placement) const {
  check_placement(placement);
  return impl_->bands_serve(DrawBatchAccess::impl(batch), outline_to_pixels(placement));
}

void Renderer::draw(const DrawBatch& batch, const Placement& placement, const DrawOptions& options) {
  Impl& r = *impl_;
  check_placement(placement);
  const gpu::BatchImpl& b = DrawBatchAccess::impl(batch);
  if (b.empty()) return;
  gpu::check_no_pending_error("Renderer::draw");

  // The application's state comes back as it was when this returns or throws.
  const gpu::GlStateBackup state(r.info);
  r.pass_depth_test = placement.depth_test;
  r.bind_own_state();
  // Into the framebuffer and viewport bound now; pixel (0, 0) is the
  // viewport's top left.
  const float vw = static_cast<float>(state.viewport()[2]), vh = static_cast<float>(state.viewport()[3]);
  r.target_blending = gpu::bound_framebuffer_blending(r.info.gles, r.info.gl3(), state.draw_framebuffer());

  for (int i = 0; i < 3; ++i) r.pass_depth[i] = static_cast<float>(placement.depth[i]);
  r.pass_depth[2] -= static_cast<float>(placement.depth_offset);
  const Transform full = outline_to_pixels(placement);
  if (b.bitmaps()) {
    r.draw_bitmaps(b, full, vw, vh, options);
    return;
  }
  if (options.debug) {
    // The paper's Figure 1: its single pass, with what curved triangles discard shown.
    DrawOptions shown = options;
    if (shown.antialiasing != AntiAliasing::None) shown.antialiasing = AntiAliasing::Curves;
    r.draw_curves(b, full, vw, vh, shown);
    r.draw_debug_edges(b, full, vw, vh);
    return;
  }
  if (options.gradient) {
    // Evaluated in the composite pass only.
    validate_gradient(*options.gradient);
    if (options.antialiasing == AntiAliasing::None || options.antialiasing == AntiAliasing::Curves || options.debug ||
        (options.antialiasing == AntiAliasing::Vbaa && options.vbaa_ring > 0.0f))
      throw Error(ErrorCode::InvalidArgument,
                  "a gradient is drawn with antialiasing full, vbaa (without a filter ring) or msaa, not debug");
  }
  if (options.antialiasing == AntiAliasing::None || options.antialiasing == AntiAliasing::Curves) {
    r.draw_curves(b, full, vw, vh, options);
    return;
  }
  if ((options.antialiasing == AntiAliasing::Full || options.antialiasing == AntiAliasing::Auto) &&
      options.curve_mode == CurveMode::Exact && options.gradient == nullptr && r.bands_serve(b, full)) {
    r.draw_bands(b, full, vw, vh, options);
    return;
  }
  if (r.draw_offscreen(b, full, vw, vh, state, options)) return;
  if (options.gradient)
    throw Error(ErrorCode::InvalidArgument, "a gradient cannot be drawn where no coverage buffer fits the block");
  // No coverage buffer fits (a block past the GL texture limit, or a
  // perspective that puts part of it behind the eye): the triangles' areas
  // blend straight into the target. Where two triangles split a pixel,
  // source-over blending then loses up to a quarter of it (a + b - ab).
  // The grown triangles overlap: depth writes would hide a triangle's
  // fringe behind its neighbour's (restored with the state).
  glDepthMask(GL_FALSE);
  r.draw_area(b, full, vw, vh, premultiplied(options.color, r.target_blending), options.gamma, options.curve_mode,
              false);
}

namespace {

// The transform (outline units -> pixels) as a column-major mat3 uniform,
// the viewport, and the depth plane (Placement::depth; 0 offscreen).
void set_view(const ProgramUniforms& u, const Transform& full, float vw, float vh, const std::array<float, 3>& depth) {
  GLfloat m[9];
  for (int row = 0; row < 3; ++row)
    for (int col = 0; col < 3; ++col) m[col * 3 + row] = static_cast<GLfloat>(full.m[row * 3 + col]);
  glUniformMatrix3fv(u.transform, 1, GL_FALSE, m);
  glUniform2f(u.viewport, vw, vh);
  glUniform3f(u.depth, depth[0], depth[1], depth[2]);
}

GLfloat coverage_exponent(float gamma) {
  return 1.0f / std::clamp(gamma, static_cast<float>(tolerance::kMinCoverageGamma),
                           static_cast<float>(tolerance::kMaxCoverageGamma));
}

// The curve programs' attributes (link_program binds them in this order):
// a_pos and a_info from a vertex buffer, a_offset per instance or constant.
constexpr GLuint kOffsetAttribute = gpu::kConstantAttribute;
static_assert(kOffsetAttribute == gpu::kVertexAttributes, "a_offset follows a_pos and a_info");

// Points a_pos and a_info at `vbo`'s vertices.
void bind_vertices(GLuint vbo) {
  glBindBuffer(GL_ARRAY_BUFFER, vbo);
  const GLsizei stride = static_cast<GLsizei>(sizeof(gpu::Vertex));
  for (GLuint i = 0; i < gpu::kVertexAttributes; ++i) {
    glEnableVertexAttribArray(i);
    glVertexAttribPointer(i, 4, GL_FLOAT, GL_FALSE, stride,
                          reinterpret_cast<const void*>(static_cast<std::uintptr_t>(i) * 16u));
  }
}

void unbind_vertices() {
  for (GLuint i = 0; i <= kOffsetAttribute; ++i) glDisableVertexAttribArray(i);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
}

// Which of a batch's triangles a draw takes.
enum class Part { All, Interior, Curved };

// The range [first, first + count) of a batch's (or glyph's) indices that
// `part` takes, of `count` in all with the interior ones first.
std::pair<std::size_t, std::size_t> part_range(Part part, std::size_t count, std::size_t interior) {
  if (part == Part::Interior) return {0, interior};
  if (part == Part::Curved) return {interior, count - interior};
  return {0, count};
}

std::size_t index_size(GLenum type) { return type == GL_UNSIGNED_INT ? 4 : type == GL_UNSIGNED_SHORT ? 2 : 0; }

// An instanced block: per distinct glyph, its mesh drawn once per placement,
// a_offset stepping through the run's offsets.
void draw_instanced(const gpu::BatchImpl& b, Part part) {
  glEnableVertexAttribArray(kOffsetAttribute);
  glVertexAttribDivisor(kOffsetAttribute, 1);
  for (const gpu::BatchImpl::Run& run : b.runs) {
    bind_vertices(run.glyph->vbo);
    glBindBuffer(GL_ARRAY_BUFFER, b.offsets_vbo);
    glVertexAttribPointer(kOffsetAttribute, 2, GL_FLOAT, GL_FALSE, 0,
                          reinterpret_cast<const void*>(static_cast<std::uintptr_t>(run.first) * 2 * sizeof(float)));
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, run.glyph->ibo);
    const auto [first, count] = part_range(part, static_cast<std::size_t>(run.glyph->index_count),
                                           static_cast<std::size_t>(run.glyph->interior_index_count));
    if (count == 0) continue;
    glDrawElementsInstanced(GL_TRIANGLES, static_cast<GLsizei>(count), run.glyph->index_type,
                            reinterpret_cast<const void*>(first * index_size(run.glyph->index_type)), run.count);
  }
  glVertexAttribDivisor(kOffsetAttribute, 0);
}

// Draws the batch's triangles (those `part` takes) with the current program
// and blending.
void draw_triangles(const gpu::BatchImpl& b, Part part = Part::All) {
  if (b.instanced()) {
    draw_instanced(b, part);
  } else {
    bind_vertices(b.vbo);
    glDisableVertexAttribArray(kOffsetAttribute);
    glVertexAttrib2f(kOffsetAttribute, 0.0f, 0.0f);
    const auto [first, count] = part_range(part, b.index_count, b.interior_index_count);
    if (count == 0) {
    } else if (b.index_type != 0) {
      glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, b.ibo);
      glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(count), b.index_type,
                     reinterpret_cast<const void*>(first * index_size(b.index_type)));
    } else {
      glDrawArrays(GL_TRIANGLES, static_cast<GLint>(first), static_cast<GLsizei>(count));
    }
  }
  unbind_vertices();
  if (GLenum err = glGetError(); err != GL_NO_ERROR) {
    throw Error(ErrorCode::Gl, "drawing a batch failed (GL error " + hex(err) + ")");
  }
}

}  // namespace

// Full AA: every triangle's exact area per pixel (shaders/area.frag.glsl),
// added into the bound framebuffer (`accumulate`) or blended over it.
void Renderer::Impl::draw_area(const gpu::BatchImpl& b, const Transform& full, float vw, float vh,
                               const std::array<float, 4>& color, float gamma, CurveMode curve_mode, bool accumulate) {
  Impl& r = *this;
  glEnable(GL_BLEND);
  if (accumulate)
    glBlendFunc(GL_ONE, GL_ONE);
  else
    glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  const bool with_gamma = coverage_exponent(gamma) != 1.0f;
  r.make_area_programs(with_gamma);
  for (int curved = 0; curved < 2; ++curved) {
    const ProgramUniforms& u = r.area_u[with_gamma][curved];
    glUseProgram(r.area_program[with_gamma][curved]);
    set_view(u, full, vw, vh, r.pass_depth);
    glUniform1f(u.fringe_px, tolerance::kFringeWidthPx);
    glUniform4f(u.color, color[0], color[1], color[2], color[3]);
    glUniform1f(u.coverage_exponent, coverage_exponent(gamma));
    glUniform1i(u.curve_mode, curve_mode == CurveMode::Paper ? 1 : 0);
    draw_triangles(b, curved ? Part::Curved : Part::Interior);
  }
}

// none and curves (and msaa's in/out pass): the paper's single pass.
void Renderer::Impl::draw_curves(const gpu::BatchImpl& b, const Transform& full, float vw, float vh,
                                 const DrawOptions& options) {
  Impl& r = *this;
  r.make_curve_program();
  glUseProgram(r.program);
  set_view(r.curve_u, full, vw, vh, r.pass_depth);
  glUniform1f(r.curve_u.fringe_px, 0.0f);  // triangles as they are
  const std::array<float, 4> color = premultiplied(options.color, r.target_blending);
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

namespace {

// Draws a tile's coverage texture into the target as a quad over the tile's
// pixels: one fetch per pixel (full, msaa), or vbaa's filter over the r x r
// texels of each pixel and their ring.
void composite_tile(RendererImpl& r, const RendererImpl::Slot& slot, int tx, int ty, int w, int h, float vw, float vh,
                    const DrawOptions& options, bool filter, const Transform& full) {
  const int factor = slot.key.factor;
  const float ring = std::clamp(options.vbaa_ring, 0.0f, 1.0f);
  // vbaa's box filter without the ring's loop (composite.frag.glsl with
  // CURVETEXT_BOX); with a ring, resolve.frag.glsl.
  const bool box = filter && ring == 0.0f;
  const bool gamma = coverage_exponent(options.gamma) != 1.0f;
  const RendererImpl::QuadProgram& q = options.gradient ? r.paint_program(box, gamma)
                                       : filter && !box ? r.resolve_program()
                                                        : r.composite_program(box, gamma);
  glUseProgram(q.id);
  if (options.gradient) r.paint_u[box ? 1 : 0][gamma ? 1 : 0].set(*options.gradient, full, r.target_blending);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, slot.texture);
  glUniform1i(q.texture, 0);
  glUniform2f(q.texture_size, static_cast<float>(slot.w), static_cast<float>(slot.h));
  glUniform2f(q.rect_origin, static_cast<float>(slot.key.x0), static_cast<float>(slot.key.y0));
  glUniform1f(q.rows, static_cast<float>(slot.key.h));
  if (filter) {
    glUniform1f(q.r, static_cast<float>(factor));
    glUniform1f(q.ring, ring);
  }
  const std::array<float, 4> color = premultiplied(options.color, r.target_blending);
  glUniform4f(q.color, color[0], color[1], color[2], color[3]);
  glUniform1f(q.coverage_exponent, coverage_exponent(options.gamma));
  glUniform3f(q.depth, r.pass_depth[0], r.pass_depth[1], r.pass_depth[2]);
  const float x0 = static_cast<float>(tx), x1 = static_cast<float>(tx + w);
  const float y0 = static_cast<float>(ty), y1 = static_cast<float>(ty + h);
  const float cx0 = 2.0f * x0 / vw - 1.0f, cx1 = 2.0f * x1 / vw - 1.0f;
  const float cy0 = 1.0f - 2.0f * y0 / vh, cy1 = 1.0f - 2.0f * y1 / vh;
  // Each corner as (clip x, clip y, pixel x, pixel y down); the pixel
  // position reaches the fragment stage as a highp varying (resolve.vert.glsl).
  const GLfloat quad[24] = {cx0, cy0, x0, y0, cx1, cy0, x1, y0, cx1, cy1, x1, y1,
                            cx0, cy0, x0, y0, cx1, cy1, x1, y1, cx0, cy1, x0, y1};
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
}

}  // namespace

// Renders the coverage of `b` under `full` into `slot` for the tile `key`
// (its texels, the apron included, key.factor per pixel): the areas summed
// (full, vbaa) or an in/out pass resolved (msaa).
void Renderer::Impl::render_coverage(const gpu::BatchImpl& b, const Transform& full, const OffscreenKey& key,
                                     Slot& slot, const DrawOptions& options) {
  if (key.msaa) ensure_multisample(key.w, key.h);
  glBindFramebuffer(GL_FRAMEBUFFER, key.msaa ? ms_fbo : slot.fbo);
  glViewport(0, 0, key.w, key.h);
  glDisable(GL_SCISSOR_TEST);  // the application's scissor and depth test are for its target
  glDisable(GL_DEPTH_TEST);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  const std::array<float, 3> target_depth = pass_depth;
  pass_depth = {0.0f, 0.0f, 0.0f};
  // A slot grown for a larger tile is cleared within this one only. (A
  // scissored clear is a drawn quad on some drivers: Mesa compiles a
  // shader for its first one, so a slot made for this tile is cleared whole.)
  const bool larger = slot.w > Impl::round_up(key.w) || slot.h > Impl::round_up(key.h);
  if (larger) {
    glEnable(GL_SCISSOR_TEST);
    glScissor(0, 0, key.w, key.h);
  }
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT);
  if (larger) glDisable(GL_SCISSOR_TEST);
  const Transform to_texture =
      Transform::scale(key.factor, key.factor) * Transform::translation(-key.x0, -key.y0) * full;
  const float kw = static_cast<float>(key.w), kh = static_cast<float>(key.h);
  if (key.msaa) {
    DrawOptions pass = options;
    pass.color = Color{1, 1, 1, 1};
    pass.antialiasing = AntiAliasing::None;
    pass.gamma = 1.0f;  // applied by the composite
    const Blending drawn_blending = target_blending;
    target_blending = Blending::Srgb;  // the coverage texture is plain RGBA
    draw_curves(b, to_texture, kw, kh, pass);
    target_blending = drawn_blending;
    resolve_multisample(slot, key.w, key.h);
  } else {
    draw_area(b, to_texture, kw, kh, {1.0f, 1.0f, 1.0f, 1.0f}, 1.0f, options.curve_mode, true);
  }
  pass_depth = target_depth;
  slot.key = key;
  slot.valid = true;
  ++offscreen_passes;
}

// full, vbaa and msaa: the block's projected bounding box (plus a border) is
// drawn into offscreen coverage textures: for full, the sum of its
// triangles' exact areas per pixel; for vbaa (paper section 5) the same r
// times larger; for msaa, an in/out pass into a multisampled renderbuffer
// resolved into one. A box larger than a texture tile
// (tolerance::kCoverageTileTexels, kMsaaTileTexels) is done tile by tile, so
// the memory these passes hold is bounded whatever the block's size or r.
// Each tile has an apron of a pixel all round (vbaa's ring reads it). Then a
// quad per tile puts the coverage into the target. A tile's pass is kept and
// reused while the batch, its transform, the tile and the mode stay the same
// (up to tolerance::kCoverageSlots passes, so a static block stays cached
// beside a changing label). False when it cannot be done here (the caller
// blends the areas directly).
bool Renderer::Impl::draw_offscreen(const gpu::BatchImpl& b, const Transform& full, float vw, float vh,
                                    const gpu::GlStateBackup& target, const DrawOptions& options) {
  Impl& r = *this;
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
  const int factor = vbaa ? std::clamp(options.vbaa_factor, 1, 8) : 1;
  // Tiles hold at most `area` texels (a long line of text is one wide tile),
  // with sides within the GL maximum; the apron is a pixel on each side.
  const long long side = tolerance::kCoverageTileTexels;
  const long long area =
      msaa ? static_cast<long long>(tolerance::kMsaaTileTexels) * tolerance::kMsaaTileTexels : side * side;
  const long long f = factor;
  const int tile_w = static_cast<int>(std::min<long long>({x1 - x0, r.max_offscreen / f - 2, area / (3 * f * f) - 2}));
  const int tile_h =
      static_cast<int>(std::min<long long>({y1 - y0, r.max_offscreen / f - 2, area / ((tile_w + 2) * f) / f - 2}));
  if (tile_w < 1 || tile_h < 1) return false;
  const bool paper = options.curve_mode == CurveMode::Paper;
  for (int ty = y0; ty < y1; ty += tile_h) {
    for (int tx = x0; tx < x1; tx += tile_w) {
      const int w = std::min(tile_w, x1 - tx), h = std::min(tile_h, y1 - ty);
      // The tile's texels: its pixels and the apron, r per pixel.
      const Impl::OffscreenKey key{b.serial,         full.m, tx - 1, ty - 1, (w + 2) * factor,
                                   (h + 2) * factor, factor, msaa,   paper};
      bool hit = false;
      Impl::Slot& slot = r.slot_for(key, key.w, key.h, hit);
      if (!hit) render_coverage(b, full, key, slot, options);
      r.apply_target(target);
      composite_tile(r, slot, tx, ty, w, h, vw, vh, options, vbaa && factor > 1, full);
    }
  }
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
void Renderer::Impl::draw_debug_edges(const gpu::BatchImpl& b, const Transform& full, float vw, float vh) {
  Impl& r = *this;
  r.make_curve_program();
  glUseProgram(r.program);
  set_view(r.curve_u, full, vw, vh, r.pass_depth);
  glUniform1f(r.curve_u.fringe_px, 0.0f);  // the triangles themselves, not grown
  glUniform1i(r.u_debug, 2);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  draw_triangles(b);
  glUniform1i(r.u_debug, 0);
  if (GLenum err = glGetError(); err != GL_NO_ERROR)
    throw Error(ErrorCode::Gl, "drawing debug edges failed (GL error " + hex(err) + ")");
}

namespace {

// Unbinds a sampler object the application bound to texture unit 0 (GL 3
// and GLES 3: it would override the atlas's filtering) and binds it back.
class SamplerScope {
 public:
  explicit SamplerScope(bool gl3) : gl3_(gl3) {
    if (!gl3_) return;
    glGetIntegerv(GL_SAMPLER_BINDING, &sampler_);
    glBindSampler(0, 0);
  }
  ~SamplerScope() {
    if (gl3_) glBindSampler(0, static_cast<GLuint>(sampler_));
  }
  SamplerScope(const SamplerScope&) = delete;
  SamplerScope& operator=(const SamplerScope&) = delete;

 private:
  bool gl3_;
  GLint sampler_ = 0;
};

}  // namespace

namespace {

// How the band program sees a pixel's footprint in outline units under
// `full`: a box (a map that keeps the axes: scale, flips, translation), a
// parallelogram (affine), or one per pixel (perspective, where w stays
// positive over the block's box); none where the map is degenerate or part
// of the block lies behind the eye (the mesh path then). `half`: the half
// size of the box, or of the parallelogram's bounding box.
struct BandFootprint {
  enum Kind { None, Box, Affine, Projective } kind = None;
  Vec2 half{0.0, 0.0};
};

BandFootprint band_footprint(const Transform& full, const Box& bounds) {
  const auto& m = full.m;
  const auto finite_positive = [](Vec2 h) {
    return h.x > 0.0 && h.y > 0.0 && std::isfinite(h.x) && std::isfinite(h.y);
  };
  if (m[6] == 0.0 && m[7] == 0.0) {
    if (!(m[8] > 0.0)) return {};
    if (m[1] == 0.0 && m[3] == 0.0) {
      const Vec2 half{0.5 * std::abs(m[8] / m[0]), 0.5 * std::abs(m[8] / m[4])};
      return finite_positive(half) ? BandFootprint{BandFootprint::Box, half} : BandFootprint{};
    }
    // The inverse's columns, m[8] A^-1 (A the linear part).
    const double det = m[0] * m[4] - m[1] * m[3];
    const Vec2 u{m[8] * m[4] / det, -m[8] * m[3] / det}, v{-m[8] * m[1] / det, m[8] * m[0] / det};
    const Vec2 half{0.5 * (std::abs(u.x) + std::abs(v.x)), 0.5 * (std::abs(u.y) + std::abs(v.y))};
    return finite_positive(half) ? BandFootprint{BandFootprint::Affine, half} : BandFootprint{};
  }
  if (bounds.empty()) return {};
  for (Vec2 c : {bounds.min, Vec2{bounds.max.x, bounds.min.y}, Vec2{bounds.min.x, bounds.max.y}, bounds.max})
    if (!(full.w(c) > 0.0)) return {};
  for (double v : gpu::inverse(full).m)
    if (!std::isfinite(v)) return {};
  return {BandFootprint::Projective, {0.0, 0.0}};
}

}  // namespace

// full for text blocks (docs/design.md section 9): one instanced quad per
// placed glyph (on GLES 2, 4 vertices per glyph: bands_es2.hpp), each pixel's exact area from the glyph's curve bands
// blended straight into the target (premultiplied source-over, its depth
// test): no offscreen pass. Under a map that keeps the axes a pixel's
// footprint in outline units is a box of half-size u_half; under one that
// turns them the program built with CURVETEXT_FOOTPRINT integrates over its
// parallelogram (exact for affine maps; per pixel, first order, under
// perspective; GLES 3 / GL 3.3 only). Only where bands_serve (else the
// caller takes the mesh path). Where the application writes depth, the
// glyphs' quads overlap at one depth: the colour pass leaves depth alone (a glyph would hide its
// neighbour's fringe), and a second pass writes it where there is ink.
bool Renderer::Impl::bands_serve(const gpu::BatchImpl& b, const Transform& full) const {
  if (!b.banded) return false;
  const BandFootprint::Kind kind = band_footprint(full, b.bounds).kind;
  return kind == BandFootprint::Box || (kind != BandFootprint::None && info.gl3());
}

void Renderer::Impl::draw_bands(const gpu::BatchImpl& b, const Transform& full, float vw, float vh,
                                const DrawOptions& options) {
  const BandFootprint footprint = band_footprint(full, b.bounds);
  const bool gamma = coverage_exponent(options.gamma) != 1.0f;
  const BandProgram& p = make_band_program(gamma, b.band_conics, footprint.kind != BandFootprint::Box);
  glUseProgram(p.id);
  set_view(p.view, full, vw, vh, pass_depth);
  glUniform2f(p.half, static_cast<float>(footprint.half.x), static_cast<float>(footprint.half.y));
  if (footprint.kind != BandFootprint::Box) {
    const Transform inv = gpu::inverse(full);
    GLfloat m[9];
    for (int row = 0; row < 3; ++row)
      for (int col = 0; col < 3; ++col) m[col * 3 + row] = static_cast<GLfloat>(inv.m[row * 3 + col]);
    glUniformMatrix3fv(p.inverse, 1, GL_FALSE, m);
    glUniform1i(p.projective, footprint.kind == BandFootprint::Projective ? 1 : 0);
  }
  const std::array<float, 4> color = premultiplied(options.color, target_blending);
  glUniform4f(p.view.color, color[0], color[1], color[2], color[3]);
  glUniform1f(p.view.coverage_exponent, coverage_exponent(options.gamma));
  glUniform1i(p.bands, 0);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  glActiveTexture(GL_TEXTURE0);
  const SamplerScope sampler(info.gl3());
  const bool quads = b.band_quads;  // GLES 2: 4 vertices per glyph (bands_es2.hpp)
  if (quads) {
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, quad_indices);  // restored with the application's state
    for (GLuint a = 0; a <= 2; ++a) glEnableVertexAttribArray(a);
  } else {
    glBindBuffer(GL_ARRAY_BUFFER, corner_vbo);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, nullptr);
    for (GLuint a = 1; a <= 2; ++a) {
      glEnableVertexAttribArray(a);
      glVertexAttribDivisor(a, 1);
    }
  }
  glBindBuffer(GL_ARRAY_BUFFER, b.bands_vbo);
  GLboolean depth_writes = GL_FALSE;
  glGetBooleanv(GL_DEPTH_WRITEMASK, &depth_writes);
  const bool depth_pass = depth_writes == GL_TRUE && glIsEnabled(GL_DEPTH_TEST) == GL_TRUE;
  if (depth_pass) glDepthMask(GL_FALSE);
  for (int pass = 0; pass < (depth_pass ? 2 : 1); ++pass) {
    if (pass == 1) {
      glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);  // restored with the application's state
      glDepthMask(GL_TRUE);
    }
    for (const gpu::BatchImpl::BandRun& run : b.band_runs) {
      glBindTexture(GL_TEXTURE_2D, run.page->texture);
      if (quads) {
        glUniform1f(p.rows, static_cast<GLfloat>(run.page->rows));
        gpu::draw_band_quads(run.first, run.count);
        continue;
      }
      const auto at = [&](std::size_t offset) {
        return reinterpret_cast<const void*>(static_cast<std::uintptr_t>(run.first) * 32u + offset);
      };
      glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, 32, at(0));
      glVertexAttribPointer(2, 4, GL_FLOAT, GL_FALSE, 32, at(16));
      glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, run.count);
    }
  }
  for (GLuint a = 0; a <= 2; ++a) {
    if (!quads) glVertexAttribDivisor(a, 0);
    glDisableVertexAttribArray(a);
  }
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glBindTexture(GL_TEXTURE_2D, 0);
  ++band_draws;
  if (GLenum err = glGetError(); err != GL_NO_ERROR)
    throw Error(ErrorCode::Gl, "drawing curve bands failed (GL error " + hex(err) + ")");
}

// Colour bitmaps: one draw per atlas page, premultiplied source-over into
// the application's framebuffer (its depth test as it is).
void Renderer::Impl::draw_bitmaps(const gpu::BatchImpl& b, const Transform& full, float vw, float vh,
                                  const DrawOptions& options) {
  if (bitmap_program == 0) {
    Shader vs(GL_VERTEX_SHADER), fs(GL_FRAGMENT_SHADER);
    compile(vs, GL_VERTEX_SHADER, shader_source::bitmap_vert_glsl, gles);
    compile(fs, GL_FRAGMENT_SHADER, shader_source::bitmap_frag_glsl, gles);
    bitmap_program = link_program(vs, fs, {"a_vertex"}, "colour bitmap program");
    bitmap_transform = glGetUniformLocation(bitmap_program, "u_transform");
    bitmap_viewport = glGetUniformLocation(bitmap_program, "u_viewport");
    bitmap_depth = glGetUniformLocation(bitmap_program, "u_depth");
    bitmap_texture = glGetUniformLocation(bitmap_program, "u_texture");
    bitmap_opacity = glGetUniformLocation(bitmap_program, "u_opacity");
    bitmap_linear = glGetUniformLocation(bitmap_program, "u_linear");
  }
  glUseProgram(bitmap_program);
  ProgramUniforms u;
  u.transform = bitmap_transform;
  u.viewport = bitmap_viewport;
  u.depth = bitmap_depth;
  set_view(u, full, vw, vh, pass_depth);
  glUniform1i(bitmap_texture, 0);
  glUniform1f(bitmap_opacity, std::clamp(options.color.a, 0.0f, 1.0f));
  glUniform1f(bitmap_linear, target_blending == Blending::Linear ? 1.0f : 0.0f);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  glActiveTexture(GL_TEXTURE0);
  const SamplerScope sampler(info.gl3());
  glBindBuffer(GL_ARRAY_BUFFER, b.bitmap_vbo);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 4, GL_FLOAT, GL_FALSE, 4 * sizeof(GLfloat), nullptr);
  for (const gpu::BatchImpl::BitmapRun& run : b.bitmap_runs) {
    glBindTexture(GL_TEXTURE_2D, run.page->texture);
    glDrawArrays(GL_TRIANGLES, run.first, run.count);
  }
  glDisableVertexAttribArray(0);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glBindTexture(GL_TEXTURE_2D, 0);
  if (GLenum err = glGetError(); err != GL_NO_ERROR)
    throw Error(ErrorCode::Gl, "drawing colour bitmaps failed (GL error " + hex(err) + ")");
}

std::size_t Renderer::offscreen_passes() const { return impl_->offscreen_passes; }

}  // namespace curvetext
