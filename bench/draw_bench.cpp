// Drawing speed and size, side by side with the incumbents in one run and one
// GL context (docs/design.md section 7). The scene is one text block of 40 lines of
// at most 50 characters (word wrapped English, DejaVu Sans) in a 1920x1080
// framebuffer, drawn by curvetext in every antialiasing mode and by two atlas
// renderers written the way apps write them:
//   - bitmap atlas: FreeType AA bitmaps at the drawn size, shelf-packed into one
//     GL_ALPHA texture, one quad per glyph, one buffer and one draw call;
//   - SDF atlas: FreeType's SDF renderer at 64 px, quads scaled to the drawn
//     size, smoothstep around 0.5 with a width from the derivatives.
// All three draw the same glyphs at the same HarfBuzz positions into the same
// kind of framebuffer (Renderer::begin). Every figure is also given as a ratio
// to the bitmap atlas measured in the same rounds.
//
// Timing: a frame is the drawing calls plus glFinish(); the clear (begin)
// runs and finishes before the timed span. Implementations take turns frame by
// frame (the order reversed every other round) so machine noise hits all of
// them alike; the first round is a warm-up and is not counted. Each curvetext
// implementation has a Renderer of its own so that one mode's offscreen pass
// never evicts another's.
//
// Sections: steady scene (static and moving placement), cold first frame,
// zoom animation, static block plus a changing label, 200 small labels each
// drawn on its own, every glyph changing, block build time against glyph
// count, bytes per glyph (and vertices per placed glyph) of each path.
//
// Run: build/bench/draw_bench [--frames N] [--sizes 12,16,32,64,128]
//        [--modes none,curves,full,vbaa,msaa] [--zoom-modes full,...]
//        [--zoom-frames 60] [--sections steady,rotated,cold,zoom,label,labels,churn,build,bytes]
//        [--quick] [--csv]
#include <GLES2/gl2.h>

#include <ft2build.h>
#include FT_FREETYPE_H

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <sstream>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "curvetext/error.hpp"
#include "curvetext/font.hpp"
#include "curvetext/headless.hpp"
#include "curvetext/renderer.hpp"
#include "curvetext/shaping.hpp"
#include "curvetext/transform.hpp"
#include "gpu/batch_impl.hpp"  // the GLES2 path forced, for its rows
#include "option_values.hpp"

namespace {

using curvetext::AntiAliasing;
using curvetext::Color;
using curvetext::DrawBatch;
using curvetext::DrawOptions;
using curvetext::Font;
using curvetext::GlyphCache;
using curvetext::PlacedGlyph;
using curvetext::Placement;
using curvetext::Renderer;
using curvetext::Transform;
using Clock = std::chrono::steady_clock;

constexpr int kWidth = 1920, kHeight = 1080;
constexpr const char* kFontPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
constexpr int kLines = 40, kLineChars = 50;
constexpr int kSdfPx = 64;
constexpr double kMarginPx = 10.0;
constexpr double kMovePerFramePx = 0.37;
constexpr double kInkTolerance = 0.10;  // bitmap atlas vs curvetext full
const Color kWhite{1, 1, 1, 1};
const Color kBlack{0, 0, 0, 1};

const char* const kParagraph =
    "The old lighthouse keeper climbed the spiral stairs every evening, counting the steps as his "
    "father had taught him, and lit the great lamp just as the sun slipped below the grey horizon. "
    "Ships that passed in the night never knew his name, yet each one trusted the steady beam that "
    "swept across the water, warning of rocks hidden beneath the waves. In winter the storms came "
    "quickly, throwing spray against the windows and shaking the iron railings, but the light never "
    "failed. He kept a journal of every vessel he saw: fishing boats returning with their catch, "
    "heavy freighters bound for distant ports, and once a tall sailing ship with white canvas "
    "glowing in the moonlight. Years later, when the lamp was replaced by an automatic beacon, "
    "visitors found his journals stacked neatly on a shelf, thousands of pages written in a careful "
    "hand, quiet proof that someone had been watching over the sea.";

[[noreturn]] void fail(const std::string& message) {
  std::fprintf(stderr, "draw_bench: %s\n", message.c_str());
  std::exit(1);
}

void check_gl(const char* where) {
  if (GLenum err = glGetError(); err != GL_NO_ERROR) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "0x%04x", static_cast<unsigned>(err));
    fail(std::string("GL error ") + buf + " " + where);
  }
}

double ms_since(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

struct Summary {
  double median = 0.0, min = 0.0, total = 0.0;
};
Summary summarize(std::vector<double> v) {
  Summary s;
  if (v.empty()) return s;
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  s.median = n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
  s.min = v.front();
  for (double x : v) s.total += x;
  return s;
}

std::string fmt(const char* format, double value) {
  std::string out(static_cast<std::size_t>(std::snprintf(nullptr, 0, format, value)), '\0');
  std::snprintf(out.data(), out.size() + 1, format, value);
  return out;
}
std::string ms_text(double ms) { return fmt(ms < 10 ? "%.2f" : ms < 100 ? "%.1f" : "%.0f", ms); }
std::string ratio_text(double r) { return fmt(r < 10 ? "%.2f" : r < 100 ? "%.1f" : "%.0f", r); }

// ---------------------------------------------------------------------------
// Output: markdown tables (docs/performance.md) or CSV.

bool g_csv = false;

struct Table {
  std::string title;
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
  std::vector<std::string> notes;

  Table(std::string title_, std::vector<std::string> header_) : title(std::move(title_)), header(std::move(header_)) {}

  void print() const {
    if (g_csv) {
      std::printf("\n# %s\n", title.c_str());
      auto line = [](const std::vector<std::string>& cells) {
        for (std::size_t i = 0; i < cells.size(); ++i) {
          const bool quote = cells[i].find(',') != std::string::npos;
          std::printf("%s%s%s%s", i ? "," : "", quote ? "\"" : "", cells[i].c_str(), quote ? "\"" : "");
        }
        std::printf("\n");
      };
      line(header);
      for (const auto& r : rows) line(r);
      for (const auto& n : notes) std::printf("# %s\n", n.c_str());
    } else {
      std::printf("\n### %s\n\n", title.c_str());
      auto line = [](const std::vector<std::string>& cells) {
        std::printf("|");
        for (const auto& c : cells) std::printf(" %s |", c.c_str());
        std::printf("\n");
      };
      line(header);
      std::printf("|");
      for (std::size_t i = 0; i < header.size(); ++i) std::printf("%s", i == 0 ? "---|" : "--:|");
      std::printf("\n");
      for (const auto& r : rows) line(r);
      if (!notes.empty()) std::printf("\n");
      for (const auto& n : notes) std::printf("%s\n", n.c_str());
    }
    std::fflush(stdout);
  }
};

// ---------------------------------------------------------------------------
// Text and layout.

// Word-wraps the paragraph, repeated as often as needed, into `lines` lines of
// at most `width` characters; `start_word` rotates where the text begins.
std::vector<std::string> wrap_lines(int lines, int width, std::size_t start_word = 0) {
  std::vector<std::string> words;
  std::istringstream in(kParagraph);
  for (std::string w; in >> w;) words.push_back(w);
  std::vector<std::string> out;
  std::string line;
  for (std::size_t i = start_word; static_cast<int>(out.size()) < lines; ++i) {
    const std::string& w = words[i % words.size()];
    if (!line.empty() && line.size() + 1 + w.size() > static_cast<std::size_t>(width)) {
      out.push_back(line);
      line.clear();
    }
    if (!line.empty()) line += ' ';
    line += w;
  }
  return out;
}

// Each line's characters rotated left by `k`: every glyph of the block changes
// while the line lengths (and so the glyph count) stay the same.
std::vector<std::string> rotated(const std::vector<std::string>& lines, std::size_t k) {
  std::vector<std::string> out;
  out.reserve(lines.size());
  for (const auto& l : lines) {
    const std::size_t r = l.empty() ? 0 : k % l.size();
    out.push_back(l.substr(r) + l.substr(0, r));
  }
  return out;
}

double line_height_units(const Font& font) {
  const auto m = font.metrics();
  return m.ascender - m.descender + m.line_gap;
}

// Shapes each line with HarfBuzz and places line n at y = -n * line height
// (font units, y up, relative to the first line's pen start).
std::vector<PlacedGlyph> layout_block(const Font& font, const std::vector<std::string>& lines) {
  const double lh = line_height_units(font);
  std::vector<PlacedGlyph> placed;
  for (std::size_t n = 0; n < lines.size(); ++n) {
    const curvetext::ShapedLine shaped = curvetext::shape_line(font, lines[n]);
    double pen_x = 0.0, pen_y = -static_cast<double>(n) * lh;
    for (const auto& g : shaped.glyphs) {
      placed.push_back(PlacedGlyph{g.glyph_id, pen_x + g.x_offset, pen_y + g.y_offset});
      pen_x += g.x_advance;
      pen_y += g.y_advance;
    }
  }
  return placed;
}

// Pen start of the block's first line in pixels (y down).
struct Origin {
  double x = 0.0, y = 0.0;
};
Origin block_origin(const Font& font, double px, double shift_x = 0.0) {
  const double scale = px / font.metrics().units_per_em;
  return Origin{kMarginPx + shift_x, kMarginPx + std::ceil(font.metrics().ascender * scale)};
}
// The moving variant: a fractional shift that changes every frame.
double moving_shift(int frame) { return std::fmod(frame * kMovePerFramePx, 8.0); }

std::string label_text(int frame) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "FPS %.2f frame %d", 59.0 + std::fmod(frame * 0.37, 1.0), frame);
  return buf;
}

// ---------------------------------------------------------------------------
// The incumbents: glyph atlases.

std::string ft_error(FT_Error e) {
  const char* s = FT_Error_String(e);
  return s ? s : "FreeType error " + std::to_string(e);
}

// Shelf packing: rows of the tallest glyph so far, left to right.
class ShelfPacker {
 public:
  ShelfPacker(int width, int height) : width_(width), height_(height) {}
  // Top-left corner of a w x h cell, or false when the texture is full.
  bool place(int w, int h, int& x, int& y) {
    if (w > width_) return false;
    for (Shelf& s : shelves_) {
      if (h <= s.height && s.x + w <= width_) {
        x = s.x;
        y = s.y;
        s.x += w;
        return true;
      }
    }
    if (used_ + h > height_) return false;
    shelves_.push_back(Shelf{used_, h, w});
    x = 0;
    y = used_;
    used_ += h;
    return true;
  }
  void clear() {
    shelves_.clear();
    used_ = 0;
  }

 private:
  struct Shelf {
    int y, height, x;
  };
  int width_, height_, used_ = 0;
  std::vector<Shelf> shelves_;
};

struct QuadVertex {
  float x, y, u, v;
};

// One texture of glyph images, each rasterised on first use at the atlas's
// current size; a size change clears it (bitmap). The SDF atlas has one size.
class GlyphAtlas {
 public:
  enum class Kind { Bitmap, Sdf };
  static constexpr int kSide = 1024;
  static constexpr int kPad = 1;  // zero texels around each cell: filtering never reads a neighbour

  GlyphAtlas(FT_Library library, Kind kind) : kind_(kind), packer_(kSide, kSide), pixels_(kSide * kSide, 0) {
    if (FT_Error e = FT_New_Face(library, kFontPath, 0, &face_)) fail(std::string("FT_New_Face: ") + ft_error(e));
    glGenTextures(1, &texture_);
    glBindTexture(GL_TEXTURE_2D, texture_);
    const GLint filter = kind == Kind::Sdf ? GL_LINEAR : GL_NEAREST;  // bitmaps are drawn pixel aligned
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_ALPHA, kSide, kSide, 0, GL_ALPHA, GL_UNSIGNED_BYTE, nullptr);
    glBindTexture(GL_TEXTURE_2D, 0);
    check_gl("creating an atlas texture");
    if (kind == Kind::Sdf) set_size(kSdfPx);
  }
  ~GlyphAtlas() {
    glDeleteTextures(1, &texture_);
    FT_Done_Face(face_);
  }
  GlyphAtlas(const GlyphAtlas&) = delete;
  GlyphAtlas& operator=(const GlyphAtlas&) = delete;

  Kind kind() const { return kind_; }
  double size_px() const { return size_px_; }
  GLuint texture() const { return texture_; }

  // The bitmap atlas rasterises at the drawn size (1/64 px steps, as
  // FT_Set_Char_Size takes them) and starts over when it changes.
  void set_size(double px) {
    if (px == size_px_) return;
    if (FT_Error e = FT_Set_Char_Size(face_, 0, static_cast<FT_F26Dot6>(std::lround(px * 64)), 72, 72))
      fail(std::string("FT_Set_Char_Size: ") + ft_error(e));
    size_px_ = px;
    glyphs_.clear();
    packer_.clear();
    cell_bytes_ = padded_cell_bytes_ = 0;
  }

  // Quad corners relative to the pen (pixels at the atlas size, y down) and
  // texture coordinates; empty for glyphs without ink.
  struct Entry {
    float x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    float u0 = 0, v0 = 0, u1 = 0, v1 = 0;
    bool empty = true;
  };

  const Entry& glyph(std::uint32_t id) {
    if (auto it = glyphs_.find(id); it != glyphs_.end()) return it->second;
    return glyphs_[id] = rasterise(id);
  }

  // Sends the rows written since the last upload to the texture.
  void upload() {
    if (dirty_y1_ <= dirty_y0_) return;
    glBindTexture(GL_TEXTURE_2D, texture_);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, dirty_y0_, kSide, dirty_y1_ - dirty_y0_, GL_ALPHA, GL_UNSIGNED_BYTE,
                    &pixels_[static_cast<std::size_t>(dirty_y0_) * kSide]);
    glBindTexture(GL_TEXTURE_2D, 0);
    dirty_y0_ = kSide;
    dirty_y1_ = 0;
  }

  std::size_t distinct_inked() const {
    std::size_t n = 0;
    for (const auto& [id, e] : glyphs_) n += e.empty ? 0 : 1;
    return n;
  }
  std::size_t cell_bytes() const { return cell_bytes_; }  // glyph images, 1 byte per texel
  std::size_t padded_cell_bytes() const { return padded_cell_bytes_; }

 private:
  Entry rasterise(std::uint32_t id) {
    FT_Error e = FT_Load_Glyph(face_, id, FT_LOAD_DEFAULT);
    if (!e) e = FT_Render_Glyph(face_->glyph, kind_ == Kind::Sdf ? FT_RENDER_MODE_SDF : FT_RENDER_MODE_NORMAL);
    if (e) fail("rasterising glyph " + std::to_string(id) + ": " + ft_error(e));
    const FT_GlyphSlot slot = face_->glyph;
    const FT_Bitmap& bm = slot->bitmap;
    Entry entry;
    const int w = static_cast<int>(bm.width), h = static_cast<int>(bm.rows);
    if (w == 0 || h == 0) return entry;
    int x = 0, y = 0;
    if (!packer_.place(w + 2 * kPad, h + 2 * kPad, x, y)) fail("the glyph atlas texture is full");
    // Cell with its zero border: stale texels from an earlier size never bleed in.
    for (int row = 0; row < h + 2 * kPad; ++row)
      std::memset(&pixels_[static_cast<std::size_t>(y + row) * kSide + x], 0, static_cast<std::size_t>(w + 2 * kPad));
    for (int row = 0; row < h; ++row)
      std::memcpy(&pixels_[static_cast<std::size_t>(y + kPad + row) * kSide + x + kPad],
                  bm.buffer + static_cast<std::ptrdiff_t>(row) * bm.pitch, static_cast<std::size_t>(w));
    dirty_y0_ = std::min(dirty_y0_, y);
    dirty_y1_ = std::max(dirty_y1_, y + h + 2 * kPad);
    cell_bytes_ += static_cast<std::size_t>(w) * h;
    padded_cell_bytes_ += static_cast<std::size_t>(w + 2 * kPad) * (h + 2 * kPad);
    entry.x0 = static_cast<float>(slot->bitmap_left);
    entry.y0 = static_cast<float>(-slot->bitmap_top);
    entry.x1 = entry.x0 + static_cast<float>(w);
    entry.y1 = entry.y0 + static_cast<float>(h);
    entry.u0 = static_cast<float>(x + kPad) / kSide;
    entry.v0 = static_cast<float>(y + kPad) / kSide;
    entry.u1 = static_cast<float>(x + kPad + w) / kSide;
    entry.v1 = static_cast<float>(y + kPad + h) / kSide;
    entry.empty = false;
    return entry;
  }

  Kind kind_;
  FT_Face face_ = nullptr;
  GLuint texture_ = 0;
  double size_px_ = 0.0;
  ShelfPacker packer_;
  std::vector<std::uint8_t> pixels_;  // CPU copy of the texture
  int dirty_y0_ = kSide, dirty_y1_ = 0;
  std::unordered_map<std::uint32_t, Entry> glyphs_;
  std::size_t cell_bytes_ = 0, padded_cell_bytes_ = 0;
};

// A block's quads: 4 vertices and 6 16-bit indices per inked glyph, in pixels
// at the atlas size relative to the block origin. The bitmap atlas rounds pen
// positions to whole pixels (its images are rasterised pixel aligned); the
// SDF atlas keeps them exact.
struct Quads {
  std::vector<QuadVertex> vertices;
  std::vector<std::uint16_t> indices;
  std::size_t bytes() const { return vertices.size() * sizeof(QuadVertex) + indices.size() * sizeof(std::uint16_t); }
};

void build_quads(GlyphAtlas& atlas, double units_per_em, std::span<const PlacedGlyph> glyphs, Quads& out) {
  out.vertices.clear();
  out.indices.clear();
  const double scale = atlas.size_px() / units_per_em;
  const bool snap = atlas.kind() == GlyphAtlas::Kind::Bitmap;
  for (const PlacedGlyph& g : glyphs) {
    const GlyphAtlas::Entry& e = atlas.glyph(g.glyph_id);
    if (e.empty) continue;
    double px = g.x * scale, py = -g.y * scale;
    if (snap) {
      px = std::round(px);
      py = std::round(py);
    }
    const float x = static_cast<float>(px), y = static_cast<float>(py);
    if (out.vertices.size() + 4 > 65536) fail("a block of more than 16,384 glyphs needs 32-bit indices");
    const auto base = static_cast<std::uint16_t>(out.vertices.size());
    out.vertices.push_back({x + e.x0, y + e.y0, e.u0, e.v0});
    out.vertices.push_back({x + e.x1, y + e.y0, e.u1, e.v0});
    out.vertices.push_back({x + e.x1, y + e.y1, e.u1, e.v1});
    out.vertices.push_back({x + e.x0, y + e.y1, e.u0, e.v1});
    for (int i : {0, 1, 2, 0, 2, 3}) out.indices.push_back(static_cast<std::uint16_t>(base + i));
  }
  atlas.upload();
}

// A vertex and an index buffer of quads.
class QuadBuffer {
 public:
  QuadBuffer() {
    glGenBuffers(1, &vbo_);
    glGenBuffers(1, &ibo_);
  }
  ~QuadBuffer() {
    glDeleteBuffers(1, &vbo_);
    glDeleteBuffers(1, &ibo_);
  }
  QuadBuffer(const QuadBuffer&) = delete;
  QuadBuffer& operator=(const QuadBuffer&) = delete;

  void upload(const Quads& q, GLenum usage) {
    glBindBuffer(GL_ARRAY_BUFFER, vbo_);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(q.vertices.size() * sizeof(QuadVertex)), q.vertices.data(),
                 usage);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ibo_);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(q.indices.size() * sizeof(std::uint16_t)),
                 q.indices.data(), usage);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
    index_count_ = static_cast<GLsizei>(q.indices.size());
  }
  GLuint vbo() const { return vbo_; }
  GLuint ibo() const { return ibo_; }
  GLsizei index_count() const { return index_count_; }

 private:
  GLuint vbo_ = 0, ibo_ = 0;
  GLsizei index_count_ = 0;
};

// GLSL ES 1.00: runs on GLES2 and on the ES 3.x contexts Mesa gives.
const char* const kQuadVertexShader = R"(#version 100
attribute vec2 a_pos;
attribute vec2 a_uv;
uniform float u_scale;
uniform vec2 u_origin;
uniform vec2 u_viewport;
varying highp vec2 v_uv;
void main() {
  vec2 p = a_pos * u_scale + u_origin;
  // Pixel row 0 at the top, as curvetext's shaders place it.
  gl_Position = vec4(p.x / u_viewport.x * 2.0 - 1.0, 1.0 - p.y / u_viewport.y * 2.0, 0.0, 1.0);
  v_uv = a_uv;
}
)";

const char* const kBitmapFragmentShader = R"(#version 100
precision mediump float;
uniform sampler2D u_texture;
uniform vec4 u_color;  // premultiplied
varying highp vec2 v_uv;
void main() { gl_FragColor = u_color * texture2D(u_texture, v_uv).a; }
)";

// Distance 0.5 is the outline; the ramp spans about one pixel, from the
// derivatives where the context has them, else from the drawing scale.
const char* const kSdfFragmentShader = R"(#version 100
#ifdef USE_DERIVATIVES
#extension GL_OES_standard_derivatives : enable
#endif
precision mediump float;
uniform sampler2D u_texture;
uniform vec4 u_color;  // premultiplied
uniform float u_width;  // half ramp in distance units without derivatives
varying highp vec2 v_uv;
void main() {
  float d = texture2D(u_texture, v_uv).a;
#ifdef USE_DERIVATIVES
  float w = 0.7 * length(vec2(dFdx(d), dFdy(d)));
#else
  float w = u_width;
#endif
  gl_FragColor = u_color * smoothstep(0.5 - w, 0.5 + w, d);
}
)";

GLuint compile_shader(GLenum type, const std::string& source) {
  const GLuint s = glCreateShader(type);
  const char* src = source.c_str();
  glShaderSource(s, 1, &src, nullptr);
  glCompileShader(s);
  GLint ok = GL_FALSE;
  glGetShaderiv(s, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    char log[2048] = {};
    glGetShaderInfoLog(s, sizeof log, nullptr, log);
    fail(std::string("atlas shader failed to compile: ") + log);
  }
  return s;
}

bool has_extension(const char* name) {
  const char* ext = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
  if (ext == nullptr) return false;
  const std::size_t len = std::strlen(name);
  for (const char* p = std::strstr(ext, name); p != nullptr; p = std::strstr(p + len, name))
    if ((p == ext || p[-1] == ' ') && (p[len] == '\0' || p[len] == ' ')) return true;
  return false;
}

struct QuadProgram {
  GLuint program = 0;
  GLint u_scale = -1, u_origin = -1, u_viewport = -1, u_texture = -1, u_color = -1, u_width = -1;

  QuadProgram(const char* fragment, const std::string& defines) {
    const GLuint vs = compile_shader(GL_VERTEX_SHADER, kQuadVertexShader);
    std::string fs_source = fragment;
    // Defines go after the #version line.
    fs_source.insert(fs_source.find('\n') + 1, defines);
    const GLuint fs = compile_shader(GL_FRAGMENT_SHADER, fs_source);
    program = glCreateProgram();
    glAttachShader(program, vs);
    glAttachShader(program, fs);
    glBindAttribLocation(program, 0, "a_pos");
    glBindAttribLocation(program, 1, "a_uv");
    glLinkProgram(program);
    glDeleteShader(vs);
    glDeleteShader(fs);
    GLint ok = GL_FALSE;
    glGetProgramiv(program, GL_LINK_STATUS, &ok);
    if (ok != GL_TRUE) fail("atlas shader program failed to link");
    u_scale = glGetUniformLocation(program, "u_scale");
    u_origin = glGetUniformLocation(program, "u_origin");
    u_viewport = glGetUniformLocation(program, "u_viewport");
    u_texture = glGetUniformLocation(program, "u_texture");
    u_color = glGetUniformLocation(program, "u_color");
    u_width = glGetUniformLocation(program, "u_width");
  }
  ~QuadProgram() { glDeleteProgram(program); }
  QuadProgram(const QuadProgram&) = delete;
  QuadProgram& operator=(const QuadProgram&) = delete;
};

// Draws quads into the bound framebuffer: positions times `scale` plus the
// origin, premultiplied source-over of black (curvetext's blending). GL state
// is set in full every time: curvetext's renderer shares the context.
void draw_quads(const QuadProgram& prog, const GlyphAtlas& atlas, const QuadBuffer& buffer, double scale,
                Origin origin) {
  if (buffer.index_count() == 0) return;
  glUseProgram(prog.program);
  glUniform1f(prog.u_scale, static_cast<float>(scale));
  glUniform2f(prog.u_origin, static_cast<float>(origin.x), static_cast<float>(origin.y));
  glUniform2f(prog.u_viewport, static_cast<float>(kWidth), static_cast<float>(kHeight));
  glUniform4f(prog.u_color, 0, 0, 0, 1);
  glUniform1i(prog.u_texture, 0);
  if (prog.u_width >= 0) {
    // FreeType's SDF maps +-spread (8 px at 64 px) to 0..1; half a drawn pixel in those units.
    const double spread_px = 8.0 * scale;
    glUniform1f(prog.u_width, static_cast<float>(0.5 / (2.0 * spread_px)));
  }
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, atlas.texture());
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_STENCIL_TEST);
  glDisable(GL_CULL_FACE);
  glDisable(GL_SCISSOR_TEST);
  glEnable(GL_BLEND);
  glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  glBindBuffer(GL_ARRAY_BUFFER, buffer.vbo());
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, buffer.ibo());
  glEnableVertexAttribArray(0);
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, sizeof(QuadVertex), nullptr);
  glVertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, sizeof(QuadVertex), reinterpret_cast<const void*>(2 * sizeof(float)));
  glDrawElements(GL_TRIANGLES, buffer.index_count(), GL_UNSIGNED_SHORT, nullptr);
  glDisableVertexAttribArray(0);
  glDisableVertexAttribArray(1);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, 0);
  glBindTexture(GL_TEXTURE_2D, 0);
}

// ---------------------------------------------------------------------------
// The benchmark's shared state.

struct Options {
  int frames = 5;
  int zoom_frames = 60;
  std::vector<int> sizes{12, 16, 32, 64, 128};
  std::vector<AntiAliasing> modes{AntiAliasing::None, AntiAliasing::Curves, AntiAliasing::Full, AntiAliasing::Vbaa,
                                  AntiAliasing::Msaa};
  std::vector<AntiAliasing> zoom_modes{AntiAliasing::Curves, AntiAliasing::Full};
  std::vector<std::string> sections{"steady", "rotated", "cold", "zoom", "label", "labels", "churn", "build", "bytes"};
  std::vector<int> label_sizes{16, 64};
  int build_reps = 9;
  int warmup = 1;  // uncounted rounds before the counted ones (the steady scene always has one)
  bool quick = false;
  bool wants(std::string_view s) const { return std::find(sections.begin(), sections.end(), s) != sections.end(); }
};

const char* mode_name(AntiAliasing aa) {
  switch (aa) {
    case AntiAliasing::None:
      return "none";
    case AntiAliasing::Curves:
      return "curves";
    case AntiAliasing::Full:
      return "full";
    case AntiAliasing::Vbaa:
      return "vbaa";
    case AntiAliasing::Msaa:
      return "msaa";
    case AntiAliasing::Auto:
      return "auto";
  }
  return "?";
}

struct Bench {
  Options opt;
  FT_Library ft = nullptr;
  Font font;
  int upem = 0;
  std::vector<std::string> lines;  // the scene's text
  std::vector<PlacedGlyph> block;  // the scene, laid out
  GlyphCache cache;                // warm for everything but the cold frames
  std::map<std::string, std::unique_ptr<Renderer>> renderers;
  curvetext::ImageTarget target;  // the framebuffer every frame is drawn into
  std::unique_ptr<QuadProgram> bitmap_program, sdf_program;
  bool sdf_derivatives = false;

  explicit Bench(Options o) : opt(std::move(o)), font(Font::open(kFontPath)) {
    upem = font.metrics().units_per_em;
    if (FT_Error e = FT_Init_FreeType(&ft)) fail("FT_Init_FreeType: " + ft_error(e));
    lines = wrap_lines(kLines, kLineChars);
    block = layout_block(font, lines);
    bitmap_program = std::make_unique<QuadProgram>(kBitmapFragmentShader, "");
    sdf_derivatives = has_extension("GL_OES_standard_derivatives");
    sdf_program =
        std::make_unique<QuadProgram>(kSdfFragmentShader, sdf_derivatives ? "#define USE_DERIVATIVES 1\n" : "");
    check_gl("compiling the atlas shaders");
  }
  ~Bench() {
    renderers.clear();
    FT_Done_FreeType(ft);
  }

  double scale(double px) const { return px / upem; }

  // Each implementation draws through a Renderer of its own.
  Renderer& renderer(const std::string& key) {
    auto& r = renderers[key];
    if (!r) r = std::make_unique<Renderer>();
    return *r;
  }

  const QuadProgram& program(const GlyphAtlas& a) const {
    return a.kind() == GlyphAtlas::Kind::Sdf ? *sdf_program : *bitmap_program;
  }
  // Drawing scale of atlas quads at `px`.
  static double quad_scale(const GlyphAtlas& a, double px) {
    return a.kind() == GlyphAtlas::Kind::Sdf ? px / kSdfPx : 1.0;
  }
  // The bitmap atlas draws at whole-pixel origins.
  static Origin atlas_origin(const GlyphAtlas& a, Origin o) {
    if (a.kind() == GlyphAtlas::Kind::Bitmap) return Origin{std::round(o.x), std::round(o.y)};
    return o;
  }
};

// One implementation in a measurement: its Renderer (whose offscreen passes
// are counted), and its frame's work (after the clear, before glFinish).
struct Contender {
  std::string name;
  Renderer* target = nullptr;
  std::function<void(int frame)> draw;
  bool curvetext = true;
  std::vector<double> ms;
  std::size_t offscreen_passes = 0;

  Contender(std::string name_, Renderer* target_, std::function<void(int)> draw_, bool curvetext_ = true)
      : name(std::move(name_)), target(target_), draw(std::move(draw_)), curvetext(curvetext_) {}
};

double timed_frame(curvetext::ImageTarget& image, Contender& c, int frame) {
  image.begin(kWidth, kHeight, kWhite);
  glFinish();
  const std::size_t passes = c.target->offscreen_passes();
  const auto t0 = Clock::now();
  c.draw(frame);
  glFinish();
  const double ms = ms_since(t0);
  c.offscreen_passes += c.target->offscreen_passes() - passes;
  check_gl(("drawing " + c.name).c_str());
  return ms;
}

// Rounds of one frame per contender, the order reversed every other round;
// `warmup` rounds first, not counted.
void run_interleaved(curvetext::ImageTarget& image, std::vector<Contender>& cs, int frames, int warmup = 1) {
  for (int round = 0; round < warmup + frames; ++round) {
    const bool counted = round >= warmup;
    if (counted && round == warmup)
      for (auto& c : cs) c.offscreen_passes = 0;
    for (std::size_t k = 0; k < cs.size(); ++k) {
      Contender& c = cs[round % 2 ? cs.size() - 1 - k : k];
      const double ms = timed_frame(image, c, round);
      if (counted) c.ms.push_back(ms);
    }
  }
}

std::string passes_text(const Contender& c, int frames) {
  if (!c.curvetext) return "-";
  const double per_frame = static_cast<double>(c.offscreen_passes) / std::max(frames, 1);
  return fmt(per_frame == std::round(per_frame) ? "%.0f" : "%.1f", per_frame);
}

// ---------------------------------------------------------------------------
// Sanity: the implementations must draw comparable ink.

double ink(const curvetext::ImageTarget& target) {
  const curvetext::Image img = target.read_pixels();
  double sum = 0.0;
  for (std::size_t i = 0; i < img.rgba.size(); i += 4) sum += 255.0 - img.rgba[i];
  return sum / 255.0;
}

void check_ink(Bench& b) {
  const double px = 16.0;
  const Origin o = block_origin(b.font, px);
  Table t{"Ink check: one frame at 16 px, sum of darkness (pixels of full ink)", {"implementation", "ink", "vs full"}};
  std::vector<std::pair<std::string, double>> inks;
  double full_ink = 0.0;
  DrawBatch batch = DrawBatch::from_glyphs(b.cache, b.font, b.block, px);
  for (AntiAliasing aa :
       {AntiAliasing::Full, AntiAliasing::None, AntiAliasing::Curves, AntiAliasing::Vbaa, AntiAliasing::Msaa}) {
    Renderer& r = b.renderer("ink");
    b.target.begin(kWidth, kHeight, kWhite);
    r.draw(batch, Placement(b.scale(px), o.x, o.y), DrawOptions(kBlack, aa));
    check_gl("drawing the ink check");
    const double v = ink(b.target);
    if (aa == AntiAliasing::Full) full_ink = v;
    inks.emplace_back(std::string("curvetext ") + mode_name(aa), v);
  }
  double bitmap_ink = 0.0;
  for (auto kind : {GlyphAtlas::Kind::Bitmap, GlyphAtlas::Kind::Sdf}) {
    GlyphAtlas atlas(b.ft, kind);
    atlas.set_size(kind == GlyphAtlas::Kind::Bitmap ? px : kSdfPx);
    Quads q;
    build_quads(atlas, b.upem, b.block, q);
    QuadBuffer buf;
    buf.upload(q, GL_STATIC_DRAW);
    b.target.begin(kWidth, kHeight, kWhite);
    draw_quads(b.program(atlas), atlas, buf, Bench::quad_scale(atlas, px), Bench::atlas_origin(atlas, o));
    check_gl("drawing the ink check");
    const double v = ink(b.target);
    if (kind == GlyphAtlas::Kind::Bitmap) bitmap_ink = v;
    inks.emplace_back(kind == GlyphAtlas::Kind::Bitmap ? "bitmap atlas" : "SDF atlas", v);
  }
  bool ok = full_ink > 0.0;
  for (const auto& [name, v] : inks) {
    const double rel = full_ink > 0 ? v / full_ink : 0.0;
    t.rows.push_back({name, fmt("%.0f", v), ratio_text(rel)});
    if (rel < 0.5 || rel > 1.5) ok = false;  // a blank or garbled frame
  }
  const double rel = full_ink > 0 ? bitmap_ink / full_ink : 0.0;
  t.notes.push_back(fmt("Bitmap atlas vs curvetext full: %.3f", rel) +
                    fmt(" (must be within %.0f%%; every implementation within 50%%).", kInkTolerance * 100));
  t.print();
  if (std::abs(rel - 1.0) > kInkTolerance) ok = false;
  if (!ok) fail("the implementations do not draw the same ink: the comparison would be worthless");
}

// ---------------------------------------------------------------------------
// The rotated scene: the steady block turned 30 degrees about the frame's centre, moving:
// the map turns the axes, so full's one pass integrates each pixel's
// parallelogram footprint (docs/design.md section 9).

void rotated(Bench& b) {
  Table t{"Rotated scene: the 40-line block turned 30 degrees, moving, ms per frame (draw + glFinish)",
          {"px", "implementation", "median ms", "min ms", "median / first", "offscreen passes / frame"}};
  const Transform turn = Transform::translation(kWidth / 2.0, kHeight / 2.0) * Transform::rotation(30.0) *
                         Transform::translation(-kWidth / 2.0, -kHeight / 2.0);
  for (int px : b.opt.sizes) {
    DrawBatch batch = DrawBatch::from_glyphs(b.cache, b.font, b.block, px);
    std::vector<Contender> cs;
    for (AntiAliasing aa : b.opt.modes) {
      const std::string name = std::string("curvetext ") + mode_name(aa) + " moving, turned";
      Renderer* r = &b.renderer(name);
      cs.push_back({name, r, [&, r, aa](int f) {
                      const Origin o = block_origin(b.font, px, moving_shift(f));
                      r->draw(batch, Placement(b.scale(px), o.x, o.y, turn), DrawOptions(kBlack, aa));
                    }});
    }
    // full through the mesh and its offscreen pass (the block as a GLES2
    // context draws it), the path such a map took before the bands handled it.
    std::optional<DrawBatch> expanded;
    if (batch.instanced() &&
        std::find(b.opt.modes.begin(), b.opt.modes.end(), AntiAliasing::Full) != b.opt.modes.end()) {
      expanded.emplace(curvetext::DrawBatchAccess::make(curvetext::gpu::text_block(
          curvetext::GlyphCacheAccess::impl(b.cache), b.font, b.block, px, curvetext::gpu::BlockPath::Expanded)));
      Renderer* r = &b.renderer("curvetext full moving, turned, mesh path");
      cs.push_back({"curvetext full moving, turned, mesh path", r, [&, r](int f) {
                      const Origin o = block_origin(b.font, px, moving_shift(f));
                      r->draw(*expanded, Placement(b.scale(px), o.x, o.y, turn),
                              DrawOptions(kBlack, AntiAliasing::Full));
                    }});
    }
    if (cs.empty()) continue;
    run_interleaved(b.target, cs, b.opt.frames);
    const Summary first = summarize(cs[0].ms);
    for (const auto& c : cs) {
      const Summary s = summarize(c.ms);
      t.rows.push_back({std::to_string(px), c.name, ms_text(s.median), ms_text(s.min),
                        ratio_text(s.median / first.median), passes_text(c, b.opt.frames)});
    }
    for (AntiAliasing aa : b.opt.modes)
      b.renderers.erase(std::string("curvetext ") + mode_name(aa) + " moving, turned");
  }
  t.notes.push_back(fmt("%.0f frames per figure, interleaved; the block moves by ", b.opt.frames) +
                    fmt("%.2f", kMovePerFramePx) +
                    " px every frame before the turn. \"mesh path\": full through each placed glyph's mesh and an "
                    "offscreen pass, as on a GLES2 context.");
  t.print();
}

// ---------------------------------------------------------------------------
// 1. The steady scene.

void steady(Bench& b) {
  Table t{"Steady scene: one 40-line block, ms per frame (draw + glFinish)",
          {"px", "implementation", "median ms", "min ms", "median / atlas", "min / atlas", "offscreen passes / frame"}};
  for (int px : b.opt.sizes) {
    DrawBatch batch = DrawBatch::from_glyphs(b.cache, b.font, b.block, px);
    GlyphAtlas bitmap(b.ft, GlyphAtlas::Kind::Bitmap), sdf(b.ft, GlyphAtlas::Kind::Sdf);
    bitmap.set_size(px);
    Quads q;
    QuadBuffer bitmap_buf, sdf_buf;
    build_quads(bitmap, b.upem, b.block, q);
    bitmap_buf.upload(q, GL_STATIC_DRAW);
    build_quads(sdf, b.upem, b.block, q);
    sdf_buf.upload(q, GL_STATIC_DRAW);

    std::vector<Contender> cs;
    Renderer& atlas_target = b.renderer("atlas");
    // The atlases' blocks move with a uniform: moving costs them nothing more.
    cs.push_back({"bitmap atlas", &atlas_target,
                  [&](int f) {
                    draw_quads(b.program(bitmap), bitmap, bitmap_buf, 1.0,
                               Bench::atlas_origin(bitmap, block_origin(b.font, px, moving_shift(f))));
                  },
                  false});
    cs.push_back({"SDF atlas", &atlas_target,
                  [&](int f) {
                    draw_quads(b.program(sdf), sdf, sdf_buf, Bench::quad_scale(sdf, px),
                               block_origin(b.font, px, moving_shift(f)));
                  },
                  false});
    for (AntiAliasing aa : b.opt.modes) {
      for (bool moving : {false, true}) {
        const std::string name = std::string("curvetext ") + mode_name(aa) + (moving ? " moving" : " static");
        Renderer* r = &b.renderer(name);
        cs.push_back({name, r, [&, r, aa, moving](int f) {
                        const Origin o = block_origin(b.font, px, moving ? moving_shift(f) : 0.0);
                        r->draw(batch, Placement(b.scale(px), o.x, o.y), DrawOptions(kBlack, aa));
                      }});
      }
    }
    // The same block on the GLES2 path (each placement's mesh copied into one
    // buffer, one draw call) where the context instances: what instancing
    // costs or saves on this renderer.
    std::optional<DrawBatch> expanded;
    if (batch.instanced()) {
      expanded.emplace(curvetext::DrawBatchAccess::make(curvetext::gpu::text_block(
          curvetext::GlyphCacheAccess::impl(b.cache), b.font, b.block, px, curvetext::gpu::BlockPath::Expanded)));
      for (AntiAliasing aa : b.opt.modes) {
        if (aa == AntiAliasing::Vbaa || aa == AntiAliasing::Msaa) continue;
        const std::string name = std::string("curvetext ") + mode_name(aa) + " moving, GLES2 path";
        Renderer* r = &b.renderer(name);
        cs.push_back({name, r, [&, r, aa](int f) {
                        const Origin o = block_origin(b.font, px, moving_shift(f));
                        r->draw(*expanded, Placement(b.scale(px), o.x, o.y), DrawOptions(kBlack, aa));
                      }});
      }
    }
    run_interleaved(b.target, cs, b.opt.frames);
    const Summary atlas = summarize(cs[0].ms);
    for (const auto& c : cs) {
      const Summary s = summarize(c.ms);
      t.rows.push_back({std::to_string(px), c.name, ms_text(s.median), ms_text(s.min),
                        ratio_text(s.median / atlas.median), ratio_text(s.min / atlas.min),
                        passes_text(c, b.opt.frames)});
    }
    // Renderers of modes not used again keep large offscreen textures: free them.
    for (AntiAliasing aa : b.opt.modes)
      for (const char* v : {" static", " moving", " moving, GLES2 path"})
        b.renderers.erase(std::string("curvetext ") + mode_name(aa) + v);
  }
  t.notes.push_back(
      fmt("%.0f frames per figure, interleaved; ", b.opt.frames) + "\"moving\" shifts the block by " +
      fmt("%.2f", kMovePerFramePx) +
      " px every frame, so any offscreen pass is redone (the honest steady cost); \"static\" reuses it. "
      "The atlases move with a uniform (no rebuild). From 32 px on the block is larger than the frame; "
      "all implementations draw it whole and GL clips it. \"GLES2 path\": the block with each placed glyph's "
      "mesh copied into its buffer, as on a GLES2 context, where this context would instance it.");
  t.print();
}

// ---------------------------------------------------------------------------
// 2. Cold first frame.

void cold(Bench& b) {
  Table t{"Cold first frame: empty glyph cache / new atlas, build the block, draw, glFinish (ms)",
          {"px", "implementation", "median ms", "min ms", "median / atlas", "min / atlas"}};
  const int rounds = std::max(1, std::min(b.opt.frames, 3));
  for (int px : b.opt.sizes) {
    std::vector<Contender> cs;
    Renderer& atlas_target = b.renderer("atlas");
    for (auto kind : {GlyphAtlas::Kind::Bitmap, GlyphAtlas::Kind::Sdf}) {
      cs.push_back({kind == GlyphAtlas::Kind::Bitmap ? "bitmap atlas" : "SDF atlas", &atlas_target,
                    [&, kind](int) {
                      GlyphAtlas atlas(b.ft, kind);
                      atlas.set_size(kind == GlyphAtlas::Kind::Bitmap ? px : kSdfPx);
                      Quads q;
                      build_quads(atlas, b.upem, b.block, q);
                      QuadBuffer buf;
                      buf.upload(q, GL_STATIC_DRAW);
                      draw_quads(b.program(atlas), atlas, buf, Bench::quad_scale(atlas, px),
                                 Bench::atlas_origin(atlas, block_origin(b.font, px)));
                      glFinish();  // before the atlas and buffers are deleted
                    },
                    false});
    }
    for (AntiAliasing aa : b.opt.modes) {
      const std::string name = std::string("curvetext ") + mode_name(aa);
      Renderer* r = &b.renderer(name);
      cs.push_back({name, r, [&, r, aa](int) {
                      GlyphCache fresh;
                      DrawBatch batch = DrawBatch::from_glyphs(fresh, b.font, b.block, px);
                      const Origin o = block_origin(b.font, px);
                      r->draw(batch, Placement(b.scale(px), o.x, o.y), DrawOptions(kBlack, aa));
                      glFinish();  // before the batch and cache are deleted
                    }});
    }
    // Warm-up: shaders, offscreen targets and FreeType's own state exist in a
    // running app before its first text frame.
    run_interleaved(b.target, cs, rounds, b.opt.warmup);
    const Summary atlas = summarize(cs[0].ms);
    for (const auto& c : cs) {
      const Summary s = summarize(c.ms);
      t.rows.push_back({std::to_string(px), c.name, ms_text(s.median), ms_text(s.min),
                        ratio_text(s.median / atlas.median), ratio_text(s.min / atlas.min)});
    }
  }
  for (AntiAliasing aa : b.opt.modes) b.renderers.erase(std::string("curvetext ") + mode_name(aa));
  t.notes.push_back(fmt("Median of %.0f cold frames each. ", rounds) +
                    "Atlas cold = new texture, rasterise + shelf-pack + upload the block's glyphs, quads, draw "
                    "(the SDF atlas rasterises at 64 px whatever the drawn size). curvetext cold = new GlyphCache, "
                    "every glyph's mesh built, block built, draw. Renderers and shaders exist already.");
  t.print();
}

// ---------------------------------------------------------------------------
// 3. Zoom animation.

void zoom(Bench& b) {
  const int n = b.opt.zoom_frames;
  auto size_at = [n](int f) { return n <= 1 ? 12.0 : 12.0 * std::pow(128.0 / 12.0, static_cast<double>(f) / (n - 1)); };
  Table t{fmt("Zoom: 12 -> 128 px over %.0f frames (geometric steps)", n),
          {"implementation", "total ms", "ms / frame", "total / bitmap atlas", "offscreen passes / frame"}};

  GlyphAtlas bitmap(b.ft, GlyphAtlas::Kind::Bitmap), sdf(b.ft, GlyphAtlas::Kind::Sdf);
  QuadBuffer bitmap_buf, sdf_buf;
  Quads q;
  build_quads(sdf, b.upem, b.block, q);
  sdf_buf.upload(q, GL_STATIC_DRAW);
  DrawBatch fixed = DrawBatch::from_glyphs(b.cache, b.font, b.block, 128.0);

  std::vector<Contender> cs;
  Renderer& atlas_target = b.renderer("atlas");
  cs.push_back({"bitmap atlas (re-rasterised every size)", &atlas_target,
                [&](int f) {
                  const double px = size_at(f);
                  bitmap.set_size(px);  // a new size: the atlas starts over
                  Quads quads;
                  build_quads(bitmap, b.upem, b.block, quads);
                  bitmap_buf.upload(quads, GL_STREAM_DRAW);
                  draw_quads(b.program(bitmap), bitmap, bitmap_buf, 1.0,
                             Bench::atlas_origin(bitmap, block_origin(b.font, px)));
                },
                false});
  cs.push_back({"SDF atlas (scaled)", &atlas_target,
                [&](int f) {
                  const double px = size_at(f);
                  draw_quads(b.program(sdf), sdf, sdf_buf, Bench::quad_scale(sdf, px), block_origin(b.font, px));
                },
                false});
  for (AntiAliasing aa : b.opt.zoom_modes) {
    const std::string a_name = std::string("curvetext ") + mode_name(aa) + " (a) Placement::scale";
    const std::string b_name = std::string("curvetext ") + mode_name(aa) + " (b) block rebuilt";
    Renderer* ra = &b.renderer(a_name);
    Renderer* rb = &b.renderer(b_name);
    cs.push_back({a_name, ra, [&, ra, aa](int f) {
                    const double px = size_at(f);
                    const Origin o = block_origin(b.font, px);
                    ra->draw(fixed, Placement(b.scale(px), o.x, o.y), DrawOptions(kBlack, aa));
                  }});
    cs.push_back({b_name, rb, [&, rb, aa](int f) {
                    const double px = size_at(f);
                    DrawBatch batch = DrawBatch::from_glyphs(b.cache, b.font, b.block, px);
                    const Origin o = block_origin(b.font, px);
                    rb->draw(batch, Placement(b.scale(px), o.x, o.y), DrawOptions(kBlack, aa));
                    glFinish();  // inside the span anyway; before the batch is deleted
                  }});
  }
  // The zoom is one pass of n frames, frame f of every contender in turn. The
  // warm-up round draws one step below 12 px, so that frame 0 is a new size
  // for everyone.
  if (b.opt.warmup > 0)
    for (auto& c : cs) timed_frame(b.target, c, -1);
  for (int f = 0; f < n; ++f)
    for (std::size_t k = 0; k < cs.size(); ++k) {
      Contender& c = cs[f % 2 ? cs.size() - 1 - k : k];
      if (f == 0) c.offscreen_passes = 0;
      c.ms.push_back(timed_frame(b.target, c, f));
    }
  const Summary atlas = summarize(cs[0].ms);
  for (const auto& c : cs) {
    const Summary s = summarize(c.ms);
    t.rows.push_back(
        {c.name, ms_text(s.total), ms_text(s.total / n), ratio_text(s.total / atlas.total), passes_text(c, n)});
  }
  for (const auto& c : cs)
    if (c.curvetext) b.renderers.erase(c.name);
  t.notes.push_back(
      "The bitmap atlas rasterises the block's glyphs at each frame's size (1/64 px steps), packs, "
      "uploads and rebuilds its quads; (a) draws one block with a new Placement::scale; (b) builds "
      "the block anew each frame from the warm glyph cache.");
  t.print();
}

// ---------------------------------------------------------------------------
// 4. Static block plus a label that changes every frame.

void label(Bench& b) {
  Table t{"Static block + a label changing every frame (\"FPS 59.94 frame 123\"), ms per frame",
          {"px", "implementation", "median ms", "min ms", "median / atlas", "min / atlas", "offscreen passes / frame"}};
  for (int px : b.opt.label_sizes) {
    const Origin block_o = block_origin(b.font, px);
    const Origin label_o{kMarginPx, kHeight - kMarginPx};
    DrawBatch batch = DrawBatch::from_glyphs(b.cache, b.font, b.block, px);
    GlyphAtlas bitmap(b.ft, GlyphAtlas::Kind::Bitmap), sdf(b.ft, GlyphAtlas::Kind::Sdf);
    bitmap.set_size(px);
    Quads q;
    QuadBuffer bitmap_buf, sdf_buf, bitmap_label, sdf_label;
    build_quads(bitmap, b.upem, b.block, q);
    bitmap_buf.upload(q, GL_STATIC_DRAW);
    build_quads(sdf, b.upem, b.block, q);
    sdf_buf.upload(q, GL_STATIC_DRAW);

    // Both sides shape the label each frame: its glyphs and positions change.
    auto label_glyphs = [&](int f) { return layout_block(b.font, {label_text(f)}); };
    std::vector<Contender> cs;
    Renderer& atlas_target = b.renderer("atlas");
    struct AtlasSide {
      const char* name;
      GlyphAtlas* atlas;
      QuadBuffer *block, *label;
    };
    for (const AtlasSide side : {AtlasSide{"bitmap atlas", &bitmap, &bitmap_buf, &bitmap_label},
                                 AtlasSide{"SDF atlas", &sdf, &sdf_buf, &sdf_label}}) {
      cs.push_back({side.name, &atlas_target,
                    [&, side, px](int f) {
                      const auto glyphs = label_glyphs(f);
                      Quads quads;
                      build_quads(*side.atlas, b.upem, glyphs, quads);
                      side.label->upload(quads, GL_STREAM_DRAW);
                      const double s = Bench::quad_scale(*side.atlas, px);
                      const QuadProgram& prog = b.program(*side.atlas);
                      draw_quads(prog, *side.atlas, *side.block, s, Bench::atlas_origin(*side.atlas, block_o));
                      draw_quads(prog, *side.atlas, *side.label, s, Bench::atlas_origin(*side.atlas, label_o));
                    },
                    false});
    }
    for (AntiAliasing aa : b.opt.modes) {
      const std::string name = std::string("curvetext ") + mode_name(aa);
      Renderer* r = &b.renderer(name);
      cs.push_back({name, r, [&, r, aa, px](int f) {
                      const auto glyphs = label_glyphs(f);
                      DrawBatch label_batch = DrawBatch::from_glyphs(b.cache, b.font, glyphs, px);
                      r->draw(batch, Placement(b.scale(px), block_o.x, block_o.y), DrawOptions(kBlack, aa));
                      r->draw(label_batch, Placement(b.scale(px), label_o.x, label_o.y), DrawOptions(kBlack, aa));
                      glFinish();  // inside the span anyway; before the label batch is deleted
                    }});
    }
    run_interleaved(b.target, cs, b.opt.frames, b.opt.warmup);
    const Summary atlas = summarize(cs[0].ms);
    for (const auto& c : cs) {
      const Summary s = summarize(c.ms);
      t.rows.push_back({std::to_string(px), c.name, ms_text(s.median), ms_text(s.min),
                        ratio_text(s.median / atlas.median), ratio_text(s.min / atlas.min),
                        passes_text(c, b.opt.frames)});
    }
    for (AntiAliasing aa : b.opt.modes) b.renderers.erase(std::string("curvetext ") + mode_name(aa));
  }
  t.notes.push_back(
      "Per frame: shape the label, build its quads (atlas) or a new small block (curvetext), draw "
      "the unchanged block and the label. Offscreen passes count the block's and the label's.");
  t.print();
}

// ---------------------------------------------------------------------------
// 4b. A GUI screen: many small labels, each its own draw call, scrolling.

constexpr int kLabelCount = 200, kLabelChars = 12;
constexpr double kLabelPx = 14.0;

// Label n: 12 characters of the paragraph from character 7 n, in a grid of 5
// columns of 40 rows, laid out on its own (one block each).
std::vector<std::vector<PlacedGlyph>> label_blocks(const Font& font) {
  const std::string text = kParagraph;
  std::vector<std::vector<PlacedGlyph>> out;
  for (int n = 0; n < kLabelCount; ++n) {
    const std::size_t at = (static_cast<std::size_t>(n) * 7) % (text.size() - kLabelChars);
    out.push_back(layout_block(font, {text.substr(at, kLabelChars)}));
  }
  return out;
}

Origin label_origin(int n, int frame) {
  return Origin{kMarginPx + (n % 5) * 380.0, 30.0 + (n / 5) * 26.0 - moving_shift(frame)};
}

void labels(Bench& b) {
  Table t{"Labels: 200 labels of 12 characters at 14 px, each its own block and draw call, scrolling " +
              fmt("%.2f", kMovePerFramePx) + " px a frame, ms per frame",
          {"implementation", "median ms", "min ms", "median / atlas", "min / atlas", "offscreen passes / frame"}};
  const auto blocks = label_blocks(b.font);
  GlyphAtlas bitmap(b.ft, GlyphAtlas::Kind::Bitmap);
  bitmap.set_size(kLabelPx);
  std::vector<QuadBuffer> quads(blocks.size());
  std::vector<DrawBatch> batches;
  for (std::size_t n = 0; n < blocks.size(); ++n) {
    Quads q;
    build_quads(bitmap, b.upem, blocks[n], q);
    quads[n].upload(q, GL_STATIC_DRAW);
    batches.push_back(DrawBatch::from_glyphs(b.cache, b.font, blocks[n], kLabelPx));
  }
  // The same labels as blocks without bands (as on a GLES2 context): full
  // through its mesh and offscreen pass, side by side.
  std::vector<DrawBatch> mesh_batches;
  if (batches.front().instanced())
    for (const auto& blk : blocks)
      mesh_batches.push_back(curvetext::DrawBatchAccess::make(curvetext::gpu::text_block(
          curvetext::GlyphCacheAccess::impl(b.cache), b.font, blk, kLabelPx, curvetext::gpu::BlockPath::Expanded)));
  std::vector<Contender> cs;
  cs.push_back({"bitmap atlas", &b.renderer("atlas"),
                [&](int f) {
                  for (std::size_t n = 0; n < quads.size(); ++n)
                    draw_quads(b.program(bitmap), bitmap, quads[n], 1.0,
                               Bench::atlas_origin(bitmap, label_origin(static_cast<int>(n), f)));
                },
                false});
  for (AntiAliasing aa : b.opt.modes) {
    const std::string name = std::string("curvetext ") + mode_name(aa);
    Renderer* r = &b.renderer(name);
    cs.push_back({name, r, [&, r, aa](int f) {
                    for (std::size_t n = 0; n < batches.size(); ++n) {
                      const Origin o = label_origin(static_cast<int>(n), f);
                      r->draw(batches[n], Placement(b.scale(kLabelPx), o.x, o.y), DrawOptions(kBlack, aa));
                    }
                  }});
  }
  if (!mesh_batches.empty()) {
    Renderer* r = &b.renderer("full mesh path");
    cs.push_back({"curvetext full, GLES2 path", r, [&, r](int f) {
                    for (std::size_t n = 0; n < mesh_batches.size(); ++n) {
                      const Origin o = label_origin(static_cast<int>(n), f);
                      r->draw(mesh_batches[n], Placement(b.scale(kLabelPx), o.x, o.y),
                              DrawOptions(kBlack, AntiAliasing::Full));
                    }
                  }});
  }
  run_interleaved(b.target, cs, b.opt.frames, b.opt.warmup);
  b.renderers.erase("full mesh path");
  const Summary atlas = summarize(cs[0].ms);
  for (const auto& c : cs) {
    const Summary s = summarize(c.ms);
    t.rows.push_back({c.name, ms_text(s.median), ms_text(s.min), ratio_text(s.median / atlas.median),
                      ratio_text(s.min / atlas.min), passes_text(c, b.opt.frames)});
  }
  for (AntiAliasing aa : b.opt.modes) b.renderers.erase(std::string("curvetext ") + mode_name(aa));
  t.notes.push_back(
      "Each label is a block of its own (built once) drawn with a draw call of its own; the bitmap "
      "atlas draws each label's quads with a draw call of their own, at whole pixels.");
  t.print();
}

// ---------------------------------------------------------------------------
// 5. Every glyph changing every frame.

void churn(Bench& b) {
  const double px = 16.0;
  Table t{"Every glyph changing every frame (the 40 lines rotated by one character per frame), 16 px, ms per frame",
          {"implementation", "median ms", "min ms", "median / atlas", "min / atlas"}};
  const Origin o = block_origin(b.font, px);
  GlyphAtlas bitmap(b.ft, GlyphAtlas::Kind::Bitmap), sdf(b.ft, GlyphAtlas::Kind::Sdf);
  bitmap.set_size(px);
  QuadBuffer bitmap_buf, sdf_buf;
  auto text_at = [&](int f) { return layout_block(b.font, rotated(b.lines, static_cast<std::size_t>(f) + 1)); };
  std::vector<Contender> cs;
  Renderer& atlas_target = b.renderer("atlas");
  struct AtlasSide {
    const char* name;
    GlyphAtlas* atlas;
    QuadBuffer* buffer;
  };
  for (const AtlasSide side :
       {AtlasSide{"bitmap atlas", &bitmap, &bitmap_buf}, AtlasSide{"SDF atlas", &sdf, &sdf_buf}}) {
    cs.push_back({side.name, &atlas_target,
                  [&, side](int f) {
                    const auto glyphs = text_at(f);
                    Quads quads;
                    build_quads(*side.atlas, b.upem, glyphs, quads);
                    side.buffer->upload(quads, GL_STREAM_DRAW);
                    draw_quads(b.program(*side.atlas), *side.atlas, *side.buffer, Bench::quad_scale(*side.atlas, px),
                               Bench::atlas_origin(*side.atlas, o));
                  },
                  false});
  }
  for (AntiAliasing aa : b.opt.modes) {
    const std::string name = std::string("curvetext ") + mode_name(aa);
    Renderer* r = &b.renderer(name);
    cs.push_back({name, r, [&, r, aa](int f) {
                    const auto glyphs = text_at(f);
                    DrawBatch batch = DrawBatch::from_glyphs(b.cache, b.font, glyphs, px);
                    r->draw(batch, Placement(b.scale(px), o.x, o.y), DrawOptions(kBlack, aa));
                    glFinish();  // inside the span anyway; before the batch is deleted
                  }});
  }
  run_interleaved(b.target, cs, b.opt.frames, b.opt.warmup);
  const Summary atlas = summarize(cs[0].ms);
  for (const auto& c : cs) {
    const Summary s = summarize(c.ms);
    t.rows.push_back({c.name, ms_text(s.median), ms_text(s.min), ratio_text(s.median / atlas.median),
                      ratio_text(s.min / atlas.min)});
  }
  for (AntiAliasing aa : b.opt.modes) b.renderers.erase(std::string("curvetext ") + mode_name(aa));
  t.notes.push_back(
      fmt("Per frame: shape the 40 lines (%.0f glyphs), build the block (curvetext, warm glyph cache) "
          "or its quads (atlas, warm atlas), upload, draw.",
          static_cast<double>(b.block.size())));
  t.print();
}

// ---------------------------------------------------------------------------
// 6. Block build time against glyph count.

void build(Bench& b) {
  const double px = 16.0;
  Table t{
      "Text block build time (CPU, warm caches, no draw)",
      {"glyphs", "curvetext median ms", "curvetext us / glyph", "bitmap atlas quads median ms", "curvetext / atlas"}};
  // Enough text for the largest count.
  const std::vector<PlacedGlyph> text = layout_block(b.font, wrap_lines(kLines * 3, kLineChars));
  GlyphAtlas bitmap(b.ft, GlyphAtlas::Kind::Bitmap);
  bitmap.set_size(px);
  QuadBuffer buf;
  std::map<int, double> curvetext_ms;
  for (int n : {500, 1000, 2000, 4000}) {
    if (static_cast<std::size_t>(n) > text.size()) fail("build text too short");
    const std::span<const PlacedGlyph> glyphs(text.data(), static_cast<std::size_t>(n));
    {
      DrawBatch warm = DrawBatch::from_glyphs(b.cache, b.font, glyphs, px);  // every glyph cached
    }
    Quads q;
    build_quads(bitmap, b.upem, glyphs, q);
    std::vector<double> ct, at;
    for (int rep = 0; rep < b.opt.build_reps; ++rep) {
      auto t0 = Clock::now();
      {
        DrawBatch batch = DrawBatch::from_glyphs(b.cache, b.font, glyphs, px);
        ct.push_back(ms_since(t0));
      }
      t0 = Clock::now();
      build_quads(bitmap, b.upem, glyphs, q);
      buf.upload(q, GL_STREAM_DRAW);
      at.push_back(ms_since(t0));
    }
    glFinish();
    check_gl("building blocks");
    const double c_ms = summarize(ct).median, a_ms = summarize(at).median;
    curvetext_ms[n] = c_ms;
    t.rows.push_back({std::to_string(n), fmt("%.3f", c_ms), fmt("%.3f", c_ms * 1000.0 / n), fmt("%.3f", a_ms),
                      ratio_text(c_ms / a_ms)});
  }
  t.notes.push_back(fmt("Median of %.0f builds each, interleaved with the atlas's. ", b.opt.build_reps) +
                    "curvetext: DrawBatch::from_glyphs (includes its buffer upload); atlas: quads from the warm "
                    "atlas + glBufferData. " +
                    fmt("4,000 / 2,000 glyphs: %.2f (linear: 2).", curvetext_ms[4000] / curvetext_ms[2000]));
  t.print();
}

// ---------------------------------------------------------------------------
// 7. Bytes per glyph.

void bytes_per_path(Bench& b);
void bytes_notes(Table& t, double placed, bool instanced);

void bytes(Bench& b) {
  Table t{"Bytes per glyph (the 40-line block)",
          {"px", "curvetext block B / placed glyph", "curvetext cache B / cached glyph", "of which GPU",
           "atlas quads B / placed glyph", "bitmap atlas B / distinct glyph", "bitmap atlas, padded cells",
           "SDF atlas (64 px) B / distinct glyph"}};
  GlyphAtlas sdf(b.ft, GlyphAtlas::Kind::Sdf);
  Quads sdf_q;
  build_quads(sdf, b.upem, b.block, sdf_q);
  const double placed = static_cast<double>(b.block.size());
  bool instanced = false;
  for (int px : {16, 32, 64, 128}) {
    GlyphCache fresh;  // only this block's glyphs
    DrawBatch batch = DrawBatch::from_glyphs(fresh, b.font, b.block, px);
    instanced = batch.instanced();
    const auto st = fresh.stats();
    GlyphAtlas bitmap(b.ft, GlyphAtlas::Kind::Bitmap);
    bitmap.set_size(px);
    Quads q;
    build_quads(bitmap, b.upem, b.block, q);
    auto d = [](std::size_t v) { return static_cast<double>(v); };
    const double inked = d(bitmap.distinct_inked()), cached = d(std::max<std::size_t>(st.glyphs, 1));
    t.rows.push_back({std::to_string(px), fmt("%.1f", d(batch.gpu_bytes()) / placed), fmt("%.0f", d(st.bytes) / cached),
                      fmt("%.0f", d(st.gpu_bytes) / cached), fmt("%.1f", d(q.bytes()) / placed),
                      fmt("%.0f", d(bitmap.cell_bytes()) / inked), fmt("%.0f", d(bitmap.padded_cell_bytes()) / inked),
                      fmt("%.0f", d(sdf.cell_bytes()) / d(sdf.distinct_inked()))});
  }
  bytes_notes(t, placed, instanced);
  t.print();
  bytes_per_path(b);
}

// GPU bytes per distinct glyph and vertices per placed glyph of each path:
// the mesh (none, curves, msaa, vbaa, and full where bands are not used)
// and the curve bands (full for text blocks).
void bytes_per_path(Bench& b) {
  Table t{"GPU bytes per distinct glyph and vertices per placed glyph, by path (the 40-line block)",
          {"path", "GPU B / distinct glyph", "vertices / placed glyph", "block B / placed glyph"}};
  GlyphCache fresh;
  DrawBatch batch = DrawBatch::from_glyphs(fresh, b.font, b.block, 16.0);
  const auto& impl = curvetext::DrawBatchAccess::impl(batch);
  std::size_t glyphs = 0, mesh_bytes = 0, band_bytes = 0;
  for (const auto& entry : curvetext::GlyphCacheAccess::impl(fresh).lru) {
    if (entry.glyph->packed.empty()) continue;
    ++glyphs;
    mesh_bytes += entry.glyph->buffers ? entry.glyph->buffers->bytes : 0;
    band_bytes += entry.glyph->bands.bytes;
  }
  std::size_t placements = 0;
  for (const auto& run : impl.band_runs) placements += static_cast<std::size_t>(run.count);
  auto d = [](std::size_t v) { return static_cast<double>(v); };
  const double g = d(std::max<std::size_t>(glyphs, 1)), p = d(std::max<std::size_t>(impl.placements, 1));
  t.rows.push_back(
      {"mesh (instanced)", fmt("%.0f", d(mesh_bytes) / g), fmt("%.1f", d(batch.vertex_count()) / p), fmt("%.1f", 8.0)});
  if (impl.banded) t.rows.push_back({"curve bands (full)", fmt("%.0f", d(band_bytes) / g), "4", fmt("%.1f", 32.0)});
  t.notes.push_back(fmt("%.0f distinct inked glyphs, ", g) + fmt("%.0f inked placements. ", p) +
                    "Mesh: the glyph's vertex and index buffers; bands: its RGBA32F texels (headers, entries, "
                    "pieces; bands.hpp). A block holds both per placement (40 bytes): the mesh's offset and the "
                    "band quad's box, offset, first texel and levels.");
  t.print();
}

void bytes_notes(Table& t, double placed, bool instanced) {
  t.notes.push_back(fmt("%.0f placed glyphs (spaces included) in the block; ", placed) +
                    (instanced ? "the block is instanced here (its buffer holds one offset per placed glyph; the "
                                 "glyph meshes are uploaded once, into the cache's entries). "
                               : "the block is expanded here (its buffer holds a copy of each placed glyph's mesh). ") +
                    "Cache bytes per cached glyph: GlyphCache::stats().bytes / glyphs: CPU-side packed mesh plus "
                    "bookkeeping plus the GPU buffers counted in \"of which GPU\"; one mesh serves every size. "
                    "Atlas quads: 4 x 16-byte vertices + 6 x 16-bit indices per inked glyph. Atlas bytes per distinct "
                    "glyph: the bitmaps' w x h at 1 byte per texel, and with the 1-texel border each cell has in "
                    "the texture (shelf waste not counted); the SDF bitmaps include FreeType's 8 px spread. Peak "
                    "offscreen memory of full/vbaa/msaa is not visible through the "
                    "API and not measured.");
}

// ---------------------------------------------------------------------------

std::vector<std::string> split(std::string_view s) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (start <= s.size()) {
    const std::size_t end = std::min(s.find(',', start), s.size());
    if (end > start) out.emplace_back(s.substr(start, end - start));
    start = end + 1;
  }
  return out;
}

std::vector<AntiAliasing> parse_modes(std::string_view s) {
  std::vector<AntiAliasing> out;
  for (const auto& m : split(s)) {
    const AntiAliasing aa = curvetext::cli::parse_antialiasing(m);
    if (aa == AntiAliasing::Auto) fail("--modes: auto is not a drawing mode of its own");
    out.push_back(aa);
  }
  if (out.empty()) fail("--modes: no mode given");
  return out;
}

int parse_int(std::string_view s, const char* what, int lo, int hi) {
  char* end = nullptr;
  const std::string str(s);
  const long v = std::strtol(str.c_str(), &end, 10);
  if (str.empty() || *end != '\0' || v < lo || v > hi)
    fail(std::string(what) + ": expected an integer from " + std::to_string(lo) + " to " + std::to_string(hi) +
         ", got '" + str + "'");
  return static_cast<int>(v);
}

Options parse_args(int argc, char** argv) {
  Options o;
  std::optional<int> frames;
  std::optional<std::vector<int>> sizes;
  for (int i = 1; i < argc; ++i) {
    std::string_view a = argv[i];
    std::string_view value;
    auto take = [&](std::string_view flag) {
      if (a == flag) {
        if (i + 1 >= argc) fail(std::string(flag) + " needs a value");
        value = argv[++i];
        return true;
      }
      if (a.size() > flag.size() && a.substr(0, flag.size()) == flag && a[flag.size()] == '=') {
        value = a.substr(flag.size() + 1);
        return true;
      }
      return false;
    };
    if (a == "--quick") {
      o.quick = true;
    } else if (a == "--csv") {
      g_csv = true;
    } else if (a == "--markdown") {
      g_csv = false;
    } else if (take("--frames")) {
      frames = parse_int(value, "--frames", 1, 100000);
    } else if (take("--zoom-frames")) {
      o.zoom_frames = parse_int(value, "--zoom-frames", 2, 100000);
    } else if (take("--sizes")) {
      std::vector<int> v;
      for (const auto& s : split(value)) v.push_back(parse_int(s, "--sizes", 1, 512));
      if (v.empty()) fail("--sizes: no size given");
      sizes = v;
    } else if (take("--modes")) {
      o.modes = parse_modes(value);
    } else if (take("--zoom-modes")) {
      o.zoom_modes = parse_modes(value);
    } else if (take("--sections")) {
      o.sections = split(value);
    } else if (a == "--help" || a == "-h") {
      std::printf(
          "draw_bench: drawing speed and size vs a FreeType bitmap atlas and an SDF atlas, in one GL context\n"
          "  --frames N          counted frames per figure (default 5; --quick: 1)\n"
          "  --sizes 12,16,...   pixel sizes of the steady and cold scenes (default 12,16,32,64,128)\n"
          "  --modes none,...    curvetext modes (default none,curves,full,vbaa,msaa)\n"
          "  --zoom-modes ...    curvetext modes of the zoom (default curves,full)\n"
          "  --zoom-frames N     frames of the zoom (default 60)\n"
          "  --sections ...      steady,rotated,cold,zoom,label,labels,churn,build,bytes (default all)\n"
          "  --quick             a smoke run: 1 frame, 16 px, a 3-frame zoom, no warm-up outside the steady scene, "
          "every section\n"
          "  --csv               CSV instead of markdown tables\n");
      std::exit(0);
    } else {
      fail("unknown option '" + std::string(a) + "' (see --help)");
    }
  }
  if (o.quick) {
    o.frames = 1;
    o.sizes = {16};
    o.label_sizes = {16};
    o.zoom_frames = 3;
    o.build_reps = 3;
    o.warmup = 0;
  }
  if (frames) o.frames = *frames;
  if (sizes) o.sizes = *sizes;
  for (const auto& s : o.sections)
    if (s != "steady" && s != "rotated" && s != "cold" && s != "zoom" && s != "label" && s != "labels" &&
        s != "churn" && s != "build" && s != "bytes")
      fail("--sections: unknown section '" + s + "'");
  return o;
}

}  // namespace

int main(int argc, char** argv) {
  const Options options = parse_args(argc, argv);
  const auto t0 = Clock::now();
  try {
    curvetext::HeadlessContext context = curvetext::HeadlessContext::create();
    const char* lead = g_csv ? "# " : "";  // CSV: the preamble as comments
    std::printf("%sGL_RENDERER: %s\n%sGL_VERSION: %s\n", lead, context.renderer().c_str(), lead,
                context.version().c_str());
    Bench b(options);
    std::printf("%sScene: %zu lines of at most %d characters, %zu glyphs, %s, %dx%d framebuffer, one block\n", lead,
                b.lines.size(), kLineChars, b.block.size(), kFontPath, kWidth, kHeight);
    std::printf("%sSDF atlas edge width: %s; msaa samples: %d\n", lead,
                b.sdf_derivatives ? "derivatives (GL_OES_standard_derivatives)" : "from the scale",
                b.renderer("ink").msaa_samples());
    std::fflush(stdout);
    check_ink(b);
    if (b.opt.wants("steady")) steady(b);
    if (b.opt.wants("rotated")) rotated(b);
    if (b.opt.wants("cold")) cold(b);
    if (b.opt.wants("zoom")) zoom(b);
    if (b.opt.wants("label")) label(b);
    if (b.opt.wants("labels")) labels(b);
    if (b.opt.wants("churn")) churn(b);
    if (b.opt.wants("build")) build(b);
    if (b.opt.wants("bytes")) bytes(b);
    check_gl("at the end");
  } catch (const std::exception& e) {
    fail(e.what());
  }
  std::printf("\n%sRun time: %.1f s\n", g_csv ? "# " : "", ms_since(t0) / 1000.0);
  return 0;
}
