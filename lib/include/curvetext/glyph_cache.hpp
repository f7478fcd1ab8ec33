// Glyph meshes packed for the GPU, cached per glyph so that every text block
// (draw_batch.hpp) at every size reuses them.
#pragma once

#include <cstddef>
#include <memory>

#include "curvetext/export.hpp"

namespace curvetext {

// Meshes packed for the GPU, per glyph, keyed by (Font::cache_key, glyph,
// level of detail), with a memory budget (least recently used glyphs are
// dropped). An entry costs its packed mesh in CPU memory, its GPU buffers
// once an instanced block needed them, and its bookkeeping. A block keeps the
// meshes it uses alive after they are dropped from the cache.
//
// Colour bitmaps (CBDT/sbix emoji, color_glyph.hpp) are kept in an atlas of
// RGBA texture pages of tolerance::kColorAtlasPageTexels a side, per glyph
// at the power-of-two reduction of its strike just above the size drawn
// (box-filtered, so scaling down never skips texels), and drawn as textured
// quads.
//
// Entries are filled by DrawBatch::from_text / from_glyphs /
// from_color_bitmaps. GPU buffers in it
// belong to the GL context (or share group) current when they were made: use
// a cache with one context, and destroy it with that context current when it
// holds any (GlyphCache::Stats::gpu_bytes > 0). Not thread-safe: one thread
// at a time; distinct caches may be used on distinct threads with distinct
// contexts.
class CURVETEXT_API GlyphCache {
 public:
  // `budget_bytes`: what the entries may cost together (CPU and GPU bytes);
  // the newest entry is kept even when it alone exceeds it. Does not throw
  // but std::bad_alloc.
  explicit GlyphCache(std::size_t budget_bytes = 64u << 20);
  ~GlyphCache();
  GlyphCache(const GlyphCache&) = delete;
  GlyphCache& operator=(const GlyphCache&) = delete;

  struct Stats {
    std::size_t glyphs = 0;     // entries held
    std::size_t bytes = 0;      // what they cost, against the budget
    std::size_t hits = 0;       // lookups answered from the cache, since construction
    std::size_t misses = 0;     // lookups that built a mesh
    std::size_t gpu_bytes = 0;  // of the glyph meshes uploaded for instanced blocks (part of `bytes`)
    // Colour bitmaps: texture pages of the atlas (not part of `bytes`; a new
    // page drops the oldest ones while pages and meshes would pass the
    // budget) and the bitmaps placed in them.
    std::size_t bitmap_bytes = 0;
    std::size_t bitmaps = 0;
  };
  Stats stats() const;

 private:
  friend struct GlyphCacheAccess;  // lib/gpu/batch_impl.hpp
  struct CURVETEXT_HIDDEN Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace curvetext
