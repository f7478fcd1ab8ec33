// Drawing meshes and text with the GLES2 curve shader (paper section 4, with
// the exact conic test of DESIGN.md section 3) into the caller's current GL
// context. The library does not own windows; see headless.hpp for a context
// without one.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "curvetext/color.hpp"
#include "curvetext/font.hpp"
#include "curvetext/image.hpp"
#include "curvetext/mesh.hpp"
#include "curvetext/shaping.hpp"
#include "curvetext/transform.hpp"

namespace curvetext {

enum class AntiAliasing {
  None,    // in/out test only
  Curves,  // the paper's single pass: curved edges antialiased, straight edges aliased
  Full,    // every triangle's exact area per pixel summed into a coverage buffer, then
           // blended over the target (default; shaders/area.frag.glsl)
  Vbaa,    // the paper's view based AA: `full` drawn r times larger into a texture over the
           // block's projected bounding box, filtered down (falls back to full when the
           // texture would exceed the GL maximum)
  Msaa,    // in/out test into a multisampled renderbuffer, resolved (GLES3 / desktop GL;
           // falls back to full where the context has none)
  Auto,    // per size, what bench/quality_bench measures best (text_image.hpp)
};
enum class CurveMode {
  Exact,  // F = tau1^2 - 4 w^2 tau0 tau2 (DESIGN.md section 3), exact for every weight
  Paper,  // the paper's equation 2: exact only for weight 1
};

// How the framebuffer blends (Renderer::begin).
enum class Blending {
  Srgb,    // on the stored sRGB-encoded values, as most apps do (default)
  Linear,  // in linear light: an sRGB framebuffer decodes, blends and encodes
           // (GLES 3 / desktop GL 3); colours are sRGB and converted
};

AntiAliasing parse_antialiasing(std::string_view text);
Blending parse_blending(std::string_view text);  // "srgb" | "linear"
// vbaa's filter: "box" (ring 0), "paper" (tolerance::kVbaaPaperRing) or a
// ring weight from 0 to 1. Throws Error(InvalidArgument).
float parse_vbaa_filter(std::string_view text);
// Coverage gamma: finite, within [kMinCoverageGamma, kMaxCoverageGamma].
// Throws Error(InvalidArgument) naming `what`.
void check_coverage_gamma(double gamma,
                          std::string_view what = "gamma");  // "none" | "curves" | "full" | "vbaa" | "msaa" | "auto"
CurveMode parse_curve_mode(std::string_view text);           // "exact" | "paper"

// Maps outline units (y up) to framebuffer pixels (y down, pixel (i,j) covers
// [i,i+1]x[j,j+1]):  x_px = scale * x + origin_x,  y_px = origin_y - scale * y.
// Then `transform` (rotation, scale, skew, perspective; identity by
// default) maps those pixels to the framebuffer's.
struct Placement {
  double scale = 1.0;
  double origin_x = 0.0;
  double origin_y = 0.0;
  Transform transform;

  Placement() = default;
  Placement(double scale_, double origin_x_, double origin_y_, const Transform& transform_ = {})
      : scale(scale_), origin_x(origin_x_), origin_y(origin_y_), transform(transform_) {}
};

struct DrawOptions {
  Color color{0, 0, 0, 1};
  AntiAliasing antialiasing = AntiAliasing::Full;
  CurveMode curve_mode = CurveMode::Exact;
  // vbaa: texels per pixel of the offscreen pass (1..8) and the weight of the
  // ring of texels around each pixel's block (0: a box filter).
  int vbaa_factor = 4;
  float vbaa_ring = 0.0f;
  // Coverage is raised to 1/gamma before blending: above 1 edge pixels get
  // more ink (dark text on light looks heavier, small text more contrast),
  // below 1 less. 1 (default) leaves exact area coverage.
  float gamma = 1.0f;
  // Shows the method at work (paper Figure 1): pixels a curved triangle
  // discards (outside its curve) in orange, and every triangle's edges in
  // blue. vbaa / msaa draw as full while debugging.
  bool debug = false;

  DrawOptions() = default;
  DrawOptions(Color color_, AntiAliasing aa = AntiAliasing::Full, CurveMode mode = CurveMode::Exact)
      : color(color_), antialiasing(aa), curve_mode(mode) {}
};

// Bytes `mesh` takes in GPU vertex and index buffers once packed (interior and
// curved triangles, each grown for antialiasing; 32-byte vertices, 16-bit
// indices up to 65,536 vertices, else 32-bit), as DrawBatch uploads it.
std::size_t gpu_bytes(const Mesh& mesh);

// Meshes packed for the GPU, per glyph, keyed by (font cache key, glyph, level
// of detail), with a memory budget (least recently used glyphs are dropped).
class GlyphCache {
 public:
  explicit GlyphCache(std::size_t budget_bytes = 64u << 20);
  ~GlyphCache();
  GlyphCache(const GlyphCache&) = delete;
  GlyphCache& operator=(const GlyphCache&) = delete;

  struct Stats {
    std::size_t glyphs = 0;
    std::size_t bytes = 0;
    std::size_t hits = 0;
    std::size_t misses = 0;
  };
  Stats stats() const;

  struct Impl;
  Impl& impl() { return *impl_; }

 private:
  std::unique_ptr<Impl> impl_;
};

// One vertex buffer and one index buffer drawn with one draw call. Built from shaped text (one
// font) or from arbitrary meshes; moving or scaling it changes only uniforms.
class DrawBatch {
 public:
  // Glyph meshes from `cache` (built on a miss at the level of detail for
  // `pixels_per_em`), placed at the shaped pen positions from pen (0,0).
  static DrawBatch from_text(GlyphCache& cache, const Font& font, const ShapedLine& line, double pixels_per_em);
  // One mesh at offset (0,0).
  static DrawBatch from_mesh(const Mesh& mesh);

  DrawBatch(DrawBatch&&) noexcept;
  DrawBatch& operator=(DrawBatch&&) noexcept;
  ~DrawBatch();

  std::size_t vertex_count() const;  // in the vertex buffer
  std::size_t gpu_bytes() const;     // vertex and index buffers

  struct Impl;
  Impl& impl() const { return *impl_; }

 private:
  friend struct DrawBatchAccess;  // lib/gpu/batch_impl.hpp
  explicit DrawBatch(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

// Compiled shaders and an offscreen RGBA8 framebuffer. Needs a current GLES2
// (or desktop GL) context; throws Error(Gl) when shaders fail to compile.
class Renderer {
 public:
  Renderer();
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // Binds an offscreen framebuffer of this size (throws Error(InvalidArgument)
  // above the GL maximum) and clears it to `background`.
  void begin(int width, int height, Color background, Blending blending = Blending::Srgb);
  // Premultiplied source-over blending of `color` * coverage.
  void draw(const DrawBatch& batch, const Placement& placement, const DrawOptions& options);
  // Samples per pixel msaa uses here: GL_MAX_SAMPLES capped at 16 (llvmpipe
  // offers 4); 0 where the context has no multisampled renderbuffers.
  int msaa_samples() const;
  // The framebuffer as straight-alpha RGBA (sRGB encoded), row 0 at the top.
  Image read_pixels();
  // How many times full / vbaa / msaa drew their offscreen pass (a draw of
  // the same batch with the same transform into the same box reuses the
  // last one).
  std::size_t offscreen_passes() const;

  struct Impl;

 private:
  void draw_curves(const DrawBatch::Impl& batch, const Transform& full, float width, float height,
                   const DrawOptions& options);
  bool draw_offscreen(const DrawBatch::Impl& batch, const Transform& full, float width, float height,
                      unsigned target_framebuffer, const DrawOptions& options);
  void draw_area(const DrawBatch::Impl& batch, const Transform& full, float width, float height,
                 const std::array<float, 4>& color, float gamma, CurveMode curve_mode, bool accumulate);
  void draw_debug_edges(const DrawBatch::Impl& batch, const Transform& full, float width, float height);
  std::unique_ptr<Impl> impl_;
};

}  // namespace curvetext
