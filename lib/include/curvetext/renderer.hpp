// Drawing meshes and text with the GLES2 curve shader (paper section 4, with
// the exact conic test of docs/design.md section 3) into the caller's current GL
// context. The library does not own windows; see headless.hpp for a context
// without one.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <memory>

#include "curvetext/color.hpp"
#include "curvetext/draw_batch.hpp"
#include "curvetext/export.hpp"
#include "curvetext/glyph_cache.hpp"
#include "curvetext/image_target.hpp"
#include "curvetext/transform.hpp"

namespace curvetext {

struct Gradient;  // paint.hpp

enum class AntiAliasing {
  None,    // in/out test only
  Curves,  // the paper's single pass: curved edges antialiased, straight edges aliased
  Full,    // the exact area of each pixel inside the shape (default): text blocks in one
           // pass, a quad per glyph over its curve bands (shaders/bands.frag.glsl), on
           // GLES 3 / GL 3.3 under any affine map or a perspective in front of the eye, and
           // on GLES 2 with highp fragment floats and OES_texture_float under maps that keep
           // the axes; otherwise every triangle's exact area summed into a coverage buffer,
           // then blended over the target (area.frag.glsl)
  Vbaa,    // the paper's view based AA: `full` drawn r times larger into a texture over the
           // block's projected bounding box, filtered down (falls back to full when the
           // texture would exceed the GL maximum)
  Msaa,    // in/out test into a multisampled renderbuffer, resolved (GLES3 / desktop GL;
           // falls back to full where the context has none)
  Auto,    // full where a text block draws from its curve bands (Renderer::draws_from_bands),
           // else per size, what bench/quality_bench measures best (image_style.hpp)
};
enum class CurveMode {
  Exact,  // F = tau1^2 - 4 w^2 tau0 tau2 (docs/design.md section 3), exact for every weight
  Paper,  // the paper's equation 2: exact only for weight 1
};

// How the pass that writes the application's framebuffer meets the
// application's depth test (Placement::depth_test).
enum class DepthTest {
  Application,  // its depth test, function and mask as they are (on or off)
  Off,          // not depth-tested, no depth written: drawn over what is there
                // (a HUD drawn while a 3D scene's depth test is on)
};

// Maps outline units (y up) to framebuffer pixels (y down, pixel (i,j) covers
// [i,i+1]x[j,j+1]):  x_px = scale * x + origin_x,  y_px = origin_y - scale * y.
// Then `transform` (rotation, scale, skew, perspective; identity by
// default) maps those pixels to the framebuffer's.
struct Placement {
  double scale = 1.0;  // pixels per outline unit, not 0
  double origin_x = 0.0;
  double origin_y = 0.0;
  Transform transform;
  // Depth for the application's depth test: the text's normalized device z
  // at the viewport's pixel (X, Y) is depth[0] X + depth[1] Y + depth[2]
  // ({0, 0, d}: a constant d in [-1, 1], the GL default depth range mapping
  // it to a window depth of (d + 1) / 2). The pass that writes the
  // application's framebuffer is depth-tested with its depth test, function
  // and mask as they are (unless depth_test is Off); text outside [-1, 1] is
  // clipped, as the app's own geometry would be. A HUD's default depth 0 is
  // window depth 0.5: with the application's depth test on, geometry nearer
  // than that hides it; DepthTest::Off draws it over everything.
  std::array<double, 3> depth{0.0, 0.0, 0.0};
  // Pulls the text towards the viewer before the depth test, as
  // glPolygonOffset pulls a decal: subtracted from the normalized device z
  // above (GL's depth grows away from the viewer). 0 by default; on_plane
  // sets it so that text on a plane drawn after the plane is not hidden by
  // the plane's own depth (z-fighting).
  double depth_offset = 0.0;
  DepthTest depth_test = DepthTest::Application;

  // on_plane's constant part of depth_offset, in normalized device z: about
  // 3 steps of a 16-bit depth buffer (800 of a 24-bit one), far above the
  // rounding between the plane's rasterized depth and the text's. Geometry
  // that close in front of the plane does not hide its text.
  static constexpr double kOnPlaneDepthOffset = 1e-4;

  Placement() = default;
  Placement(double scale_, double origin_x_, double origin_y_, const Transform& transform_ = {})
      : scale(scale_), origin_x(origin_x_), origin_y(origin_y_), transform(transform_) {}

  // Text lying on a 3D scene's plane z = 0, seen through a column-major
  // model-view-projection matrix (glm::value_ptr(mvp)) in a viewport of
  // width x height pixels: outline units (y up) at `units_per_outline_unit`
  // plane units each, the outline's origin at the plane's (x, y), upright
  // along the plane's +y. Throws as Transform::plane_to_viewport.
  // Its depth is the plane's (Transform::plane_depth), so a 3D scene's own
  // geometry in front of the text hides it, and its depth_offset the plane's
  // depth change over one pixel (glPolygonOffset's factor 1) plus
  // kOnPlaneDepthOffset: drawn after the plane with GL_LESS, the text shows.
  // (On a decal the application pulls further forward with glPolygonOffset,
  // add as much, in normalized device z, to depth_offset.)
  static Placement on_plane(const float mvp[16], double viewport_width, double viewport_height,
                            double units_per_outline_unit, double x, double y) {
    Placement p(units_per_outline_unit, x, -y, Transform::plane_to_viewport(mvp, viewport_width, viewport_height));
    p.depth = Transform::plane_depth(mvp, viewport_width, viewport_height);
    p.depth_offset = std::max(std::abs(p.depth[0]), std::abs(p.depth[1])) + kOnPlaneDepthOffset;
    return p;
  }
};

// How Renderer::draw draws one batch.
struct DrawOptions {
  Color color{0, 0, 0, 1};  // straight alpha, sRGB
  AntiAliasing antialiasing = AntiAliasing::Full;
  CurveMode curve_mode = CurveMode::Exact;
  // vbaa: texels per pixel of the offscreen pass (1..8) and the weight of the
  // ring of texels around each pixel's block (0: a box filter).
  int vbaa_factor = 4;
  float vbaa_ring = 0.0f;
  // Coverage is raised to 1/gamma before blending: above 1 edge pixels get
  // more ink (dark text on light looks heavier, small text more contrast),
  // below 1 less. 1 (default) leaves exact area coverage. Clamped to
  // [tolerance::kMinCoverageGamma, kMaxCoverageGamma].
  float gamma = 1.0f;
  // Shows the method at work (paper Figure 1): pixels a curved triangle
  // discards (outside its curve) in orange, and every triangle's edges in
  // blue. vbaa / msaa draw as full while debugging.
  bool debug = false;
  // Paints with this gradient (paint.hpp) instead of `color`, in full, vbaa
  // (without a ring) and msaa; not owned, read during draw() only.
  const Gradient* gradient = nullptr;

  DrawOptions() = default;
  DrawOptions(Color color_, AntiAliasing aa = AntiAliasing::Full, CurveMode mode = CurveMode::Exact)
      : color(color_), antialiasing(aa), curve_mode(mode) {}
};

// Compiled shaders and offscreen coverage textures for full / vbaa / msaa.
// Owns those GL objects: they belong to the context current at
// construction, which must be current whenever the renderer is used or
// destroyed. Not thread-safe: one thread (and its context) at a time;
// distinct renderers may be used on distinct threads with distinct contexts.
//
// A guest in the application's context (GLES 2, GLES 3, desktop GL 3.3+
// core or compatibility): draw() reads the state it changes and puts it back
// before returning, also when it throws: the program, vertex array object
// (curvetext draws with its own where the context has them; on GLES 2,
// vertex attributes 0 to 2: arrays, pointers, buffers), array and element
// buffer bindings, attribute 2's current value, the draw and read
// framebuffers, renderbuffer, active texture and texture unit 0's 2D
// binding (and sampler object, GLES 3 / GL 3), viewport, scissor test and box, blend enable, equations and
// functions, depth test and depth writes, stencil and cull-face tests,
// rasterizer discard, primitive restart, colour mask, clear colour, and the
// pixel pack state. Buffers a DrawBatch uploads leave the bindings as they
// were. A GL error the application left pending when a call begins is not
// taken for curvetext's: the call throws Error(Gl) saying so, before
// changing anything, and the error flag is then clear.
//
// Colours blend in the space of the framebuffer drawn into: linear light
// where it is sRGB-encoded and the context converts (GLES 3; desktop GL with
// GL_FRAMEBUFFER_SRGB enabled), else on the stored values.
class CURVETEXT_API Renderer {
 public:
  // Needs a current GLES2 (or later, or desktop GL 3.3) context. Throws
  // Error(Gl) when there is none. Each mode's shaders are compiled on the
  // first draw that needs them: that draw throws Error(Gl) if one fails to
  // compile or link.
  Renderer();
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // Draws `batch` with premultiplied source-over blending of `options.color`
  // times coverage into the framebuffer bound now (the application's, or an
  // ImageTarget's), within its viewport, whose top-left pixel is (0, 0) of
  // the placement, and its scissor box and colour mask. A batch of colour
  // bitmaps (DrawBatch::from_color_bitmaps) is drawn in its own colours times
  // `options.color`'s alpha, sampled linearly; antialiasing, curve mode,
  // gamma and debug do not apply to it. `batch` must have been built
  // with this context (or one sharing with it). Throws
  // Error(InvalidArgument) for a non-finite or zero scale, a non-finite
  // origin or depth offset, or a transform Transform::validate refuses, Error(Gl) when a GL
  // call fails.
  void draw(const DrawBatch& batch, const Placement& placement, const DrawOptions& options);
  // Whether `full` draws `batch` under `placement` in one pass from its
  // glyphs' curve bands here (docs/design.md section 9: text blocks whose
  // glyphs all have bands, on the contexts and under the maps the band
  // shader serves), with no offscreen pass. `auto` then means full at every
  // size (image_style.hpp). Throws as draw() does for a bad placement.
  bool draws_from_bands(const DrawBatch& batch, const Placement& placement) const;
  // Samples per pixel msaa uses here: GL_MAX_SAMPLES capped at 16 (llvmpipe
  // offers 4); 0 where the context has no multisampled renderbuffers.
  int msaa_samples() const;
  // How many times full / vbaa / msaa drew their offscreen pass (a draw of
  // the same batch with the same transform into the same box reuses the
  // last one).
  std::size_t offscreen_passes() const;

 private:
  friend struct RendererAccess;  // lib/gpu/renderer.cpp
  struct CURVETEXT_HIDDEN Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace curvetext
