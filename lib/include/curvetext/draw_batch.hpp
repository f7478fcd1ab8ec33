// Text blocks and meshes uploaded for drawing with a Renderer (renderer.hpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>

#include "curvetext/export.hpp"
#include "curvetext/font.hpp"
#include "curvetext/glyph_cache.hpp"
#include "curvetext/mesh.hpp"
#include "curvetext/shaping.hpp"

namespace curvetext {

// Bytes `mesh` takes in GPU vertex and index buffers once packed (interior and
// curved triangles, each grown for antialiasing; 32-byte vertices, 16-bit
// indices up to 65,536 vertices, else 32-bit), as DrawBatch uploads it. No GL;
// thread-safe.
CURVETEXT_API std::size_t gpu_bytes(const Mesh& mesh);

// A glyph placed in a text block: its id and the position of its origin in
// font units (y up), relative to the block's origin (the Placement's origin).
// Positions relative to the block keep float precision on the GPU however far
// the block itself lies from the framebuffer's origin.
struct PlacedGlyph {
  std::uint32_t glyph_id = 0;
  double x = 0.0;
  double y = 0.0;
};

// A text block or mesh ready to draw: moving, scaling or transforming it
// changes only uniforms.
//
// Text blocks refer to the glyph meshes of a GlyphCache. Where the context
// instances (GLES 3, desktop GL 3.3), each distinct glyph's mesh is uploaded
// once, into buffers of the cache's entry, and the block uploads 8 bytes per
// placed glyph (its offset); it is drawn with one instanced call per distinct
// glyph. On GLES2 the block's buffer holds a copy of each placed glyph's mesh
// (one draw call), and where the context's fragment shaders have highp
// floats and float textures, each glyph's band quad (4 vertices, 160 bytes)
// that full draws. Building is linear in the number of glyphs either way.
//
// Lifetime and threads: owns its GL buffers, and shares the glyph meshes it
// uses with the cache (they outlive their eviction while the block lives);
// it does not refer to the Font or the cache after it is built. Needs the GL
// context (or one sharing with it) that draws it to be current when built and
// destroyed. Not thread-safe: one thread (and its context) at a time; distinct
// batches may be used on distinct threads with distinct contexts. A moved-from
// batch may only be assigned to or destroyed.
class CURVETEXT_API DrawBatch {
 public:
  // Glyph meshes from `cache` (built on a miss at the level of detail for
  // `pixels_per_em`), placed at the shaped pen positions from pen (0,0).
  // Same errors as from_glyphs.
  static DrawBatch from_text(GlyphCache& cache, const Font& font, const ShapedLine& line, double pixels_per_em);
  // Glyph meshes from `cache` at the given positions (a paragraph's lines, or
  // any placement the caller computes). Throws Error(InvalidArgument) for a
  // non-finite position or a size that is not positive and finite,
  // Error(FontInvalid) for a glyph id the font does not have,
  // Error(Geometry) for an outline the tessellator refuses, Error(Gl) when
  // the upload fails (no current context).
  static DrawBatch from_glyphs(GlyphCache& cache, const Font& font, std::span<const PlacedGlyph> glyphs,
                               double pixels_per_em);
  // A bitmap colour font's glyphs (Font::color_format() == Bitmap) from the
  // cache's atlas, as textured quads: each bitmap scaled from its strike to
  // `pixels_per_em` and placed at its glyph's origin (font units, y up, as
  // from_glyphs). Glyphs without a bitmap (a space) draw nothing. Renderer::draw
  // draws them in their own colours, times DrawOptions::color's alpha, with
  // linear filtering (antialiasing modes do not apply). Throws as
  // from_glyphs, Error(InvalidArgument) for a font that is not a bitmap
  // colour font, and Font::color_bitmap's errors.
  static DrawBatch from_color_bitmaps(GlyphCache& cache, const Font& font, std::span<const PlacedGlyph> glyphs,
                                      double pixels_per_em);
  // One mesh (outline units, drawn at offset (0,0)); the mesh is copied.
  // Throws Error(Gl) when the upload fails.
  static DrawBatch from_mesh(const Mesh& mesh);

  DrawBatch(DrawBatch&&) noexcept;
  DrawBatch& operator=(DrawBatch&&) noexcept;
  ~DrawBatch();

  std::size_t vertex_count() const;  // vertices drawn (each placement's mesh counted)
  // Bytes this block uploaded into buffers of its own: its vertices and
  // indices, or (instanced) its per-glyph offsets. The shared glyph meshes
  // are counted in GlyphCache::Stats::gpu_bytes.
  std::size_t gpu_bytes() const;
  bool instanced() const;  // drawn with one instanced call per distinct glyph

 private:
  friend struct DrawBatchAccess;  // lib/gpu/batch_impl.hpp
  struct CURVETEXT_HIDDEN Impl;
  explicit DrawBatch(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace curvetext
