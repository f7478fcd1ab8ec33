// Private definitions shared by the glyph cache, draw batches and renderer.
#pragma once

#include <GLES2/gl2.h>

#include <array>
#include <atomic>
#include <cstdint>
#include <list>
#include <memory>
#include <span>
#include <unordered_map>
#include <vector>

#include "curvetext/draw_batch.hpp"
#include "curvetext/glyph_cache.hpp"
#include "gpu/bands.hpp"
#include "gpu/effects.hpp"
#include "gpu/vertex_format.hpp"

namespace curvetext {

namespace gpu {

// One glyph's packed mesh in GPU buffers of its own, drawn once per placement
// by instancing. Shared by the cache entry and every block that places the
// glyph; deleted with the last of them (the context that made it current).
struct GlyphBuffers {
  GLuint vbo = 0;
  GLuint ibo = 0;
  GLsizei index_count = 0;
  GLsizei interior_index_count = 0;  // the interior triangles' indices come first
  GLenum index_type = 0;             // GL_UNSIGNED_SHORT or GL_UNSIGNED_INT
  std::size_t vertex_count = 0;
  std::size_t bytes = 0;

  GlyphBuffers() = default;
  GlyphBuffers(const GlyphBuffers&) = delete;
  GlyphBuffers& operator=(const GlyphBuffers&) = delete;
  ~GlyphBuffers() {
    if (vbo != 0) glDeleteBuffers(1, &vbo);
    if (ibo != 0) glDeleteBuffers(1, &ibo);
  }
};

// A texture of glyphs' curve bands (bands.hpp): RGBA32F, kBandTextureWidth
// texels a row, rows added as glyphs are (the texels kept here too, to fill
// a grown texture). Shared by the cache and every block that draws from it;
// deleted with the last of them (the context that made it current).
struct BandPage {
  GLuint texture = 0;
  int rows = 0;                              // allocated
  std::size_t used = 0;                      // texels
  std::vector<std::array<float, 4>> texels;  // rows * kBandTextureWidth

  BandPage() = default;
  BandPage(const BandPage&) = delete;
  BandPage& operator=(const BandPage&) = delete;
  ~BandPage() {
    if (texture != 0) glDeleteTextures(1, &texture);
  }
};

// A glyph's place in a band page: its first texel, its bands' levels and
// the box of its pieces (outline units, the floats the shader reads).
struct GlyphBandRef {
  std::shared_ptr<BandPage> page;  // null: no bands (not built, or too large for a page)
  int first = 0, levels = 0;
  bool conics = false;  // GlyphBands::conics
  Box box;
  std::size_t bytes = 0;  // its texels
  bool tried = false;     // built (or found too large) already
  int most_entries = 0;   // in any one band (the GLES 2 program's bound, bands_es2.hpp)
};

// A glyph cache entry: the packed mesh, the box of its base positions
// (outline units), its GPU buffers once an instanced block needed them, and
// its curve bands then (where the context has float textures).
struct CachedGlyph {
  PackedMesh packed;
  Box bounds;
  std::shared_ptr<const GlyphBuffers> buffers;
  GlyphBandRef bands;
};

// A page of the colour bitmap atlas (lib/gpu/color_bitmaps.cpp): one RGBA8
// texture of premultiplied bitmaps packed in shelves, sampled linearly. Shared
// by the cache and every block that draws from it; deleted with the last of
// them (the context that made it current).
struct AtlasPage {
  GLuint texture = 0;
  int side = 0;                         // texels
  int shelf_y = 0, shelf_h = 0, x = 0;  // the shelf being filled: its top, height, next free column
  std::size_t bytes = 0;

  AtlasPage() = default;
  AtlasPage(const AtlasPage&) = delete;
  AtlasPage& operator=(const AtlasPage&) = delete;
  ~AtlasPage() {
    if (texture != 0) glDeleteTextures(1, &texture);
  }
};

// A colour glyph's bitmap in the atlas, at one level (the strike's bitmap
// halved `level` times), and the box it covers from the glyph origin in
// font units (y up): the texels [x, x + w) x [y, y + h), their border of a
// transparent texel outside.
struct CachedBitmap {
  std::shared_ptr<const AtlasPage> page;  // null: the glyph has no bitmap
  int x = 0, y = 0, w = 0, h = 0;
  double left = 0.0, top = 0.0, width = 0.0, height = 0.0;  // font units
};

}  // namespace gpu

struct DrawBatch::Impl {
  // Expanded: every placement's vertices in one buffer (GLES2, meshes).
  GLuint vbo = 0;  // 0 when there is nothing to draw or the batch is instanced
  GLuint ibo = 0;  // 0 when drawn as plain arrays (index_type 0)
  std::size_t vertex_count = 0;
  std::size_t index_count = 0;           // with index_type 0: vertex_count (3 per triangle)
  std::size_t interior_index_count = 0;  // the interior triangles' indices (or vertices) come first
  GLenum index_type = 0;                 // GL_UNSIGNED_SHORT, GL_UNSIGNED_INT, or 0: no index buffer

  // Instanced: per placement, its offset (2 floats, outline units), grouped
  // by glyph; one run of placements per distinct glyph.
  struct Run {
    std::shared_ptr<const gpu::GlyphBuffers> glyph;
    GLsizei first = 0;  // placement index of the run's first offset
    GLsizei count = 0;
  };
  GLuint offsets_vbo = 0;
  std::vector<Run> runs;
  std::size_t placements = 0;

  // One pass exact area (bands.hpp): per placement 8 floats, the glyph's
  // box (a_rect) and (offset, first texel, levels) (a_place), one run of
  // placements per band page. `banded`: every inked placement has bands.
  struct BandRun {
    std::shared_ptr<const gpu::BandPage> page;
    GLint first = 0;
    GLsizei count = 0;
  };
  GLuint bands_vbo = 0;
  std::vector<BandRun> band_runs;
  bool banded = false;
  bool band_quads = false;   // GLES 2: 4 vertices per placement, not one instance (bands_es2.hpp)
  bool band_conics = false;  // a placed glyph's bands have conics (GlyphBands::conics)

  // Colour bitmaps: textured quads (6 vertices of x, y, u, v each, outline
  // units and texture coordinates), one run per atlas page.
  struct BitmapRun {
    std::shared_ptr<const gpu::AtlasPage> page;
    GLint first = 0;  // vertex
    GLsizei count = 0;
  };
  GLuint bitmap_vbo = 0;
  std::vector<BitmapRun> bitmap_runs;

  Box bounds;                // of the vertices' base positions (outline units; growth offsets not included)
  std::uint64_t serial = 0;  // unique per upload: an offscreen pass is reused while it and the transform match

  Impl() = default;
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;
  // Needs the context that created the buffers to be current.
  ~Impl() {
    if (vbo != 0) glDeleteBuffers(1, &vbo);
    if (ibo != 0) glDeleteBuffers(1, &ibo);
    if (offsets_vbo != 0) glDeleteBuffers(1, &offsets_vbo);
    if (bands_vbo != 0) glDeleteBuffers(1, &bands_vbo);
    if (bitmap_vbo != 0) glDeleteBuffers(1, &bitmap_vbo);
  }
  bool instanced() const { return offsets_vbo != 0; }
  bool bitmaps() const { return bitmap_vbo != 0; }
  bool empty() const {
    if (bitmaps()) return bitmap_runs.empty();
    return instanced() ? runs.empty() : vbo == 0 || vertex_count == 0;
  }
};

struct GlyphCache::Impl {
  struct Key {
    std::uint64_t font = 0;
    std::uint32_t glyph = 0;
    int lod = 0;
    std::uint32_t effect = 0;  // 0: the glyph's fill; else an effect's mesh (gpu/effects.hpp)
    bool operator==(const Key&) const = default;
  };
  struct KeyHash {
    std::size_t operator()(const Key& k) const noexcept {
      std::uint64_t h = k.font * 0x9E3779B97F4A7C15ull;
      h ^= (static_cast<std::uint64_t>(k.glyph) << 8) + static_cast<std::uint64_t>(k.lod) + (h << 6) + (h >> 2);
      h ^= static_cast<std::uint64_t>(k.effect) * 0xC2B2AE3D27D4EB4Full;
      return static_cast<std::size_t>(h);
    }
  };
  using Packed = std::shared_ptr<gpu::CachedGlyph>;
  struct Entry {
    Key key;
    Packed glyph;
    std::size_t cost = 0;  // bytes counted in the budget
  };

  explicit Impl(std::size_t budget) : budget_bytes(budget) {}

  // The packed mesh of a glyph for drawing at `pixels_per_em`; builds it on
  // a miss, and uploads its GPU buffers when `upload` is set and it has none.
  // The returned pointer stays valid even if the entry is evicted. `effect`:
  // the mesh of that effect of the glyph instead (gpu/effects.hpp).
  // `es2_bands`: builds its bands without uploading buffers (a GLES 2 block
  // of the band path, bands_es2.hpp).
  Packed get(const Font& font, std::uint32_t glyph_id, double pixels_per_em, bool upload = false,
             std::uint32_t effect = 0, bool es2_bands = false);

  std::size_t budget_bytes;
  // A miss's outline, mesh and packing room: their storage serves every miss.
  struct Scratch {
    Outline outline;
    Mesh mesh;
    gpu::PackScratch pack;
    gpu::BandScratch band;
    gpu::GlyphBands bands;
    gpu::EffectScratch effect;
  } scratch;
  // The band page being filled (older ones live while glyphs on them do).
  std::shared_ptr<gpu::BandPage> band_page;
  std::list<Entry> lru;  // most recently used first
  std::unordered_map<Key, std::list<Entry>::iterator, KeyHash> index;
  Stats stats;

  // Colour bitmaps (lib/gpu/color_bitmaps.cpp), keyed by lod = strike * 64 +
  // level; pages oldest first, the last one being filled. Pages count in the
  // budget; past it the oldest pages go with their entries (blocks keep the
  // pages they draw from).
  gpu::CachedBitmap bitmap(const Font& font, std::uint32_t glyph_id, double pixels_per_em);
  std::unordered_map<Key, gpu::CachedBitmap, KeyHash> bitmaps;
  std::vector<std::shared_ptr<gpu::AtlasPage>> pages;

 private:
  void evict();
  // Builds the glyph's bands from scratch.mesh (the entry's mesh) and adds
  // them to the band page; leaves them null where they do not fit a page.
  void add_bands(gpu::CachedGlyph& glyph);
};

// Reach the private state of DrawBatch and GlyphCache (friends of each):
// the library's gpu/ code and the tests.
struct DrawBatchAccess {
  using Impl = DrawBatch::Impl;
  // Makes a batch from an upload.
  static DrawBatch make(std::unique_ptr<Impl> impl) { return DrawBatch(std::move(impl)); }
  static const Impl& impl(const DrawBatch& batch) { return *batch.impl_; }
};
struct GlyphCacheAccess {
  using Impl = GlyphCache::Impl;
  static Impl& impl(GlyphCache& cache) { return *cache.impl_; }
};

namespace gpu {
using BatchImpl = DrawBatchAccess::Impl;
using CacheImpl = GlyphCacheAccess::Impl;

// How a batch's indices reach the GPU (see vertex_format.hpp).
enum class IndexUpload { Auto, Bits16, Bits32, Arrays };
// Uploads `packed` into a new batch's buffers. Auto picks 16-bit indices up to
// 65,536 vertices, else 32-bit where the context has them, else Arrays (the
// triangles expanded into plain vertex arrays); the others force a way, for
// tests (Bits16 throws InvalidArgument past 65,536 vertices).
std::unique_ptr<BatchImpl> upload(gpu::PackedMesh packed, IndexUpload how = IndexUpload::Auto);

// How a text block reaches the GPU: Auto instances where the context can
// (GLES 3, desktop GL 3.3), else copies each placement's mesh (Expanded, the
// GLES2 path); tests force either.
enum class BlockPath { Auto, Expanded, Instanced };
std::unique_ptr<BatchImpl> text_block(CacheImpl& cache, const Font& font, std::span<const PlacedGlyph> glyphs,
                                      double pixels_per_em, BlockPath path = BlockPath::Auto, std::uint32_t effect = 0);
// A glyph's own GPU buffers for instanced drawing (16-bit indices up to
// 65,536 vertices, else 32-bit: instancing contexts have them).
std::shared_ptr<const GlyphBuffers> upload_glyph(const PackedMesh& packed);
// Whether the current context draws instanced (GLES 3+, desktop GL 3.3+).
bool context_instances();
// Rows a band page has at most (16 MiB of RGBA32F texels).
inline constexpr int kMaxBandPageRows = 1024;
// Appends a glyph's bands to the page in `page_slot` (a new page there when
// it is full) and uploads them; false, and nothing added, when they are
// empty or larger than a page. Error(Gl) if the upload fails.
bool append_bands(const GlyphBands& bands, std::shared_ptr<BandPage>& page_slot, GlyphBandRef& out);
// Gives a batch (its meshes uploaded already) the bands of `meshes`, each
// placed at its offset (outline units), in pages of its own: full then draws
// it in one pass (the shapes' and tests' way to the band path). Leaves it
// without bands if one is too large for a page.
void add_mesh_bands(BatchImpl& impl, std::span<const Mesh* const> meshes, std::span<const Vec2> offsets);
// A shaped line's glyphs at their pen positions (font units, from the origin).
std::vector<PlacedGlyph> placed_glyphs(const ShapedLine& line);
}  // namespace gpu

}  // namespace curvetext
