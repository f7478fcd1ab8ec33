// Glyph cache (packed meshes per glyph and level of detail, LRU within a byte
// budget, with GPU buffers per glyph for instanced blocks) and draw batches.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

#include "curvetext/error.hpp"
#include "core/tolerances.hpp"
#include "curvetext/lod.hpp"
#include "gpu/bands_es2.hpp"
#include "gpu/batch_impl.hpp"
#include "gpu/effects.hpp"
#include "gpu/gl_state.hpp"

namespace curvetext {

namespace {

// What an entry costs beyond its meshes: the list node, the index's node, the
// shared glyph and its control block. An empty glyph (a space) costs this
// much, so no number of them fits a budget for free.
constexpr std::size_t kEntryBookkeepingBytes =
    sizeof(gpu::CacheImpl::Entry) + sizeof(gpu::CachedGlyph) + 4 * sizeof(void*) + 32;

Box bounds_of(const gpu::PackedMesh& packed) {
  Box box;
  for (const gpu::Vertex& v : packed.vertices) box.add({v.pos[0], v.pos[1]});
  return box;
}

}  // namespace

GlyphCache::Impl::Packed GlyphCache::Impl::get(const Font& font, std::uint32_t glyph_id, double pixels_per_em,
                                               bool upload, std::uint32_t effect, bool es2_bands) {
  const int upem = font.metrics().units_per_em;
  if (!(pixels_per_em > 0) || !std::isfinite(pixels_per_em) || upem <= 0) {
    throw Error(ErrorCode::InvalidArgument, "glyph size must be a positive number of pixels per em");
  }
  // Looking the outline up on every hit would cost a FreeType load, so the
  // cache is probed twice instead: outlines without cubics are exact at every
  // scale and stored under lod 0; outlines with cubics under their band
  // (lod_for_scale never returns 0: the lowest band is tolerance::kMinLodLog2).
  // Effect meshes are fitted within a tolerance of the band: always under it.
  const int cubic_lod = lod_for_scale(pixels_per_em / upem, upem);
  std::list<Entry>::iterator entry = lru.end();
  for (int probe : {effect != 0 ? cubic_lod : 0, cubic_lod}) {
    auto it = index.find(Key{font.cache_key(), glyph_id, probe, effect});
    if (it != index.end()) {
      lru.splice(lru.begin(), lru, it->second);
      ++stats.hits;
      entry = it->second;
      break;
    }
  }
  bool mesh_fresh = false;  // scratch.mesh holds this glyph's mesh
  if (entry == lru.end()) {
    ++stats.misses;
    mesh_fresh = true;
    Outline& outline = scratch.outline;
    font.glyph_outline(glyph_id, outline);
    int lod = 0;
    MeshOptions options;
    if (outline.has_cubics() || effect != 0) {
      lod = cubic_lod;
      options.cubic_tolerance = cubic_tolerance_for_lod(lod, upem);
    }
    if (effect != 0) gpu::effect_outline(effect, upem, options.cubic_tolerance, outline, scratch.effect);
    auto glyph = std::make_shared<gpu::CachedGlyph>();
    if (!outline.empty()) {
      build_mesh(outline, options, scratch.mesh);
      gpu::pack_mesh(scratch.mesh, glyph->packed, scratch.pack);
      glyph->bounds = bounds_of(glyph->packed);
    }
    const std::size_t cost = glyph->packed.memory_bytes() + kEntryBookkeepingBytes;
    lru.push_front(Entry{Key{font.cache_key(), glyph_id, lod, effect}, std::move(glyph), cost});
    index[lru.front().key] = lru.begin();
    stats.bytes += cost;
    stats.glyphs += 1;
    entry = lru.begin();
  }
  gpu::CachedGlyph& glyph = *entry->glyph;
  if (upload && !glyph.buffers && !glyph.packed.empty()) {
    glyph.buffers = gpu::upload_glyph(glyph.packed);
    entry->cost += glyph.buffers->bytes;
    stats.bytes += glyph.buffers->bytes;
    stats.gpu_bytes += glyph.buffers->bytes;
  }
  // Bands need float textures and texelFetch (GLES 3, GL 3.3), or GLES 2 with highp (bands_es2.hpp).
  if ((es2_bands || (upload && gpu::ContextInfo::current().gl3())) && !glyph.bands.tried && !glyph.packed.empty()) {
    if (!mesh_fresh) {
      // Packed without bands before (a GLES2 block): the mesh again.
      font.glyph_outline(glyph_id, scratch.outline);
      MeshOptions options;
      if (entry->key.lod != 0) options.cubic_tolerance = cubic_tolerance_for_lod(entry->key.lod, upem);
      if (effect != 0) gpu::effect_outline(effect, upem, options.cubic_tolerance, scratch.outline, scratch.effect);
      build_mesh(scratch.outline, options, scratch.mesh);
    }
    add_bands(glyph);
    entry->cost += 2 * glyph.bands.bytes;  // the page's texels on the CPU and on the GPU
    stats.bytes += 2 * glyph.bands.bytes;
    stats.gpu_bytes += glyph.bands.bytes;
  }
  Packed result = entry->glyph;
  evict();
  return result;
}

// Drops least recently used glyphs past the budget, but never the newest.
void GlyphCache::Impl::evict() {
  while (stats.bytes > budget_bytes && lru.size() > 1) {
    const Entry& victim = lru.back();
    stats.bytes -= victim.cost;
    if (victim.glyph->buffers) stats.gpu_bytes -= victim.glyph->buffers->bytes;
    stats.gpu_bytes -= victim.glyph->bands.bytes;
    stats.glyphs -= 1;
    index.erase(victim.key);
    lru.pop_back();
  }
}

void GlyphCache::Impl::add_bands(gpu::CachedGlyph& glyph) {
  glyph.bands.tried = true;
  gpu::build_bands(scratch.mesh, scratch.bands, scratch.band);
  gpu::append_bands(scratch.bands, band_page, glyph.bands);  // false: drawn through its mesh
}

GlyphCache::GlyphCache(std::size_t budget_bytes) : impl_(std::make_unique<Impl>(budget_bytes)) {}
GlyphCache::~GlyphCache() = default;
GlyphCache::Stats GlyphCache::stats() const { return impl_->stats; }

namespace {

std::string gl_error_text(GLenum err) {
  char buf[16];
  std::snprintf(buf, sizeof buf, "%04x", static_cast<unsigned>(err));
  return buf;
}

// Whether glDrawElements takes GL_UNSIGNED_INT in the current context: core
// in desktop GL and GLES3, an extension in GLES2.
bool has_32bit_indices() {
  const char* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  if (version == nullptr) return false;
  if (std::strncmp(version, "OpenGL ES ", 10) != 0) return true;
  if (version[10] >= '3' && version[10] <= '9') return true;
  const char* extensions = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
  if (extensions == nullptr) return false;
  const char* name = "GL_OES_element_index_uint";
  const std::size_t len = std::strlen(name);
  for (const char* p = std::strstr(extensions, name); p != nullptr; p = std::strstr(p + len, name))
    if ((p == extensions || p[-1] == ' ') && (p[len] == '\0' || p[len] == ' ')) return true;
  return false;
}

template <typename T>
void upload_buffer(GLenum target, GLuint& buffer, const std::vector<T>& data) {
  glGenBuffers(1, &buffer);
  if (buffer == 0) throw Error(ErrorCode::Gl, "glGenBuffers failed (is a GL context current?)");
  const gpu::BufferBindingScope bound(target, buffer);  // the application's binding comes back
  glBufferData(target, static_cast<GLsizeiptr>(data.size() * sizeof(T)), data.data(), GL_STATIC_DRAW);
}

}  // namespace

namespace gpu {

namespace {
std::uint64_t next_serial() {
  static std::atomic<std::uint64_t> serial{0};
  return serial.fetch_add(1, std::memory_order_relaxed) + 1;
}
}  // namespace

std::unique_ptr<BatchImpl> upload(PackedMesh packed, IndexUpload how) {
  auto impl = std::make_unique<BatchImpl>();
  impl->serial = next_serial();
  impl->bounds = bounds_of(packed);
  if (packed.indices.empty()) return impl;
  if (how == IndexUpload::Bits16 && packed.vertices.size() > kMaxShortIndexedVertices)
    throw Error(ErrorCode::InvalidArgument, "16-bit indices cannot reach past 65,536 vertices");
  if (how == IndexUpload::Auto)
    how = packed.vertices.size() <= kMaxShortIndexedVertices ? IndexUpload::Bits16
          : has_32bit_indices()                              ? IndexUpload::Bits32
                                                             : IndexUpload::Arrays;
  if (how == IndexUpload::Arrays) {
    std::vector<Vertex> expanded;
    expanded.reserve(packed.indices.size());
    for (std::uint32_t i : packed.indices) expanded.push_back(packed.vertices[i]);
    packed.vertices = std::move(expanded);
  }
  impl->vertex_count = packed.vertices.size();
  impl->index_count = packed.indices.size();
  impl->interior_index_count = packed.interior_indices;
  upload_buffer(GL_ARRAY_BUFFER, impl->vbo, packed.vertices);
  if (how == IndexUpload::Bits16) {
    const std::vector<std::uint16_t> shorts(packed.indices.begin(), packed.indices.end());
    upload_buffer(GL_ELEMENT_ARRAY_BUFFER, impl->ibo, shorts);
    impl->index_type = GL_UNSIGNED_SHORT;
  } else if (how == IndexUpload::Bits32) {
    upload_buffer(GL_ELEMENT_ARRAY_BUFFER, impl->ibo, packed.indices);
    impl->index_type = GL_UNSIGNED_INT;
  }
  if (GLenum err = glGetError(); err != GL_NO_ERROR)
    throw Error(ErrorCode::Gl, "vertex buffer upload failed (GL error 0x" + gl_error_text(err) + ")");
  return impl;
}

std::shared_ptr<const GlyphBuffers> upload_glyph(const PackedMesh& packed) {
  auto buffers = std::make_shared<GlyphBuffers>();
  buffers->vertex_count = packed.vertices.size();
  buffers->index_count = static_cast<GLsizei>(packed.indices.size());
  buffers->interior_index_count = static_cast<GLsizei>(packed.interior_indices);
  upload_buffer(GL_ARRAY_BUFFER, buffers->vbo, packed.vertices);
  if (packed.vertices.size() <= kMaxShortIndexedVertices) {
    const std::vector<std::uint16_t> shorts(packed.indices.begin(), packed.indices.end());
    upload_buffer(GL_ELEMENT_ARRAY_BUFFER, buffers->ibo, shorts);
    buffers->index_type = GL_UNSIGNED_SHORT;
  } else {
    upload_buffer(GL_ELEMENT_ARRAY_BUFFER, buffers->ibo, packed.indices);
    buffers->index_type = GL_UNSIGNED_INT;
  }
  buffers->bytes = packed.gpu_bytes();
  if (GLenum err = glGetError(); err != GL_NO_ERROR)
    throw Error(ErrorCode::Gl, "glyph buffer upload failed (GL error 0x" + gl_error_text(err) + ")");
  return buffers;
}

bool context_instances() {
  const char* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  if (version == nullptr) return false;
  const bool gles = std::strncmp(version, "OpenGL ES ", 10) == 0;
  int major = 0, minor = 0;
  if (std::sscanf(gles ? version + 10 : version, "%d.%d", &major, &minor) != 2) return false;
  return gles ? major >= 3 : (major > 3 || (major == 3 && minor >= 3));
}

namespace {

// The GLES2 path: each placement's mesh copied into one buffer.
std::unique_ptr<BatchImpl> expanded_block(std::span<const CacheImpl::Packed> glyphs,
                                          std::span<const PlacedGlyph> placed) {
  std::size_t vertices = 0, indices = 0;
  for (const auto& g : glyphs) {
    vertices += g->packed.vertices.size();
    indices += g->packed.indices.size();
  }
  PackedMesh packed;
  packed.vertices.reserve(vertices);
  packed.indices.reserve(indices);
  // Two passes keep every interior triangle ahead of every curved one.
  std::vector<std::uint32_t> bases(placed.size());
  for (std::size_t i = 0; i < placed.size(); ++i) {
    const PackedMesh& glyph = glyphs[i]->packed;
    bases[i] = static_cast<std::uint32_t>(packed.vertices.size());
    append_vertices_translated(glyph, Vec2{placed[i].x, placed[i].y}, packed);
    for (std::size_t k = 0; k < glyph.interior_indices; ++k) packed.indices.push_back(bases[i] + glyph.indices[k]);
  }
  packed.interior_indices = packed.indices.size();
  for (std::size_t i = 0; i < placed.size(); ++i) {
    const PackedMesh& glyph = glyphs[i]->packed;
    for (std::size_t k = glyph.interior_indices; k < glyph.indices.size(); ++k)
      packed.indices.push_back(bases[i] + glyph.indices[k]);
  }
  return upload(std::move(packed));
}

// The band instances (8 floats each) as the context draws them: as they
// are where it instances, else each expanded into its quad's 4 vertices
// (GLES 2, bands_es2.hpp).
void upload_band_instances(BatchImpl& impl, const std::vector<float>& instances, bool quads) {
  if (instances.empty()) return;
  impl.band_quads = quads;
  upload_buffer(GL_ARRAY_BUFFER, impl.bands_vbo, quads ? expand_band_quads(instances) : instances);
}

// Whether a glyph's bands can be drawn: built, and on GLES 2 (`quads`)
// within the program's loop bound.
bool drawable(const GlyphBandRef& bands, bool quads) {
  return bands.page && (!quads || bands.most_entries <= tolerance::kEs2BandEntryCap);
}

// One pass exact area: per inked placement its glyph's box and (offset,
// first texel, levels), grouped by band page (shaders/bands.vert.glsl). Left
// out (the block drawn through its meshes) when a glyph has no bands, or on
// GLES 2 (`quads`) one whose bands exceed the program's loop bound.
void band_instances(std::span<const CacheImpl::Packed> glyphs, std::span<const PlacedGlyph> placed, BatchImpl& impl,
                    bool quads) {
  std::vector<std::pair<std::shared_ptr<const BandPage>, std::vector<float>>> pages;
  for (std::size_t i = 0; i < placed.size(); ++i) {
    const CachedGlyph& g = *glyphs[i];
    if (g.packed.empty()) continue;
    if (!drawable(g.bands, quads)) return;
    auto it = std::find_if(pages.begin(), pages.end(), [&](const auto& p) { return p.first == g.bands.page; });
    if (it == pages.end()) it = pages.insert(pages.end(), {g.bands.page, {}});
    const Box& box = g.bands.box;
    impl.band_conics = impl.band_conics || g.bands.conics;
    it->second.insert(it->second.end(),
                      {static_cast<float>(box.min.x), static_cast<float>(box.min.y), static_cast<float>(box.max.x),
                       static_cast<float>(box.max.y), static_cast<float>(placed[i].x), static_cast<float>(placed[i].y),
                       static_cast<float>(g.bands.first), static_cast<float>(g.bands.levels)});
  }
  impl.banded = true;
  std::vector<float> all;
  for (auto& [page, floats] : pages) {
    const auto first = static_cast<GLint>(all.size() / 8);
    impl.band_runs.push_back({page, first, static_cast<GLsizei>(floats.size() / 8)});
    all.insert(all.end(), floats.begin(), floats.end());
  }
  upload_band_instances(impl, all, quads);
}

// Instancing: one offset per placement, grouped by glyph (a counting sort:
// linear in the placements).
std::unique_ptr<BatchImpl> instanced_block(std::span<const CacheImpl::Packed> glyphs,
                                           std::span<const PlacedGlyph> placed) {
  auto impl = std::make_unique<BatchImpl>();
  impl->serial = next_serial();
  std::unordered_map<const CachedGlyph*, std::size_t> run_of;
  std::vector<std::size_t> run_index(placed.size(), SIZE_MAX);
  for (std::size_t i = 0; i < placed.size(); ++i) {
    const CachedGlyph& g = *glyphs[i];
    if (g.packed.empty()) continue;
    const auto [it, fresh] = run_of.try_emplace(&g, impl->runs.size());
    if (fresh) impl->runs.push_back(BatchImpl::Run{g.buffers, 0, 0});
    run_index[i] = it->second;
    ++impl->runs[it->second].count;
    const Vec2 offset{placed[i].x, placed[i].y};
    impl->bounds.add(g.bounds.min + offset);
    impl->bounds.add(g.bounds.max + offset);
  }
  GLsizei next = 0;
  for (auto& run : impl->runs) {
    run.first = next;
    next += run.count;
  }
  impl->placements = static_cast<std::size_t>(next);
  if (impl->runs.empty()) return impl;
  std::vector<GLsizei> fill(impl->runs.size());
  for (std::size_t r = 0; r < impl->runs.size(); ++r) fill[r] = impl->runs[r].first;
  std::vector<float> offsets(2 * impl->placements);
  for (std::size_t i = 0; i < placed.size(); ++i) {
    if (run_index[i] == SIZE_MAX) continue;
    const auto slot = static_cast<std::size_t>(fill[run_index[i]]++);
    offsets[2 * slot] = static_cast<float>(placed[i].x);
    offsets[2 * slot + 1] = static_cast<float>(placed[i].y);
  }
  upload_buffer(GL_ARRAY_BUFFER, impl->offsets_vbo, offsets);
  band_instances(glyphs, placed, *impl, false);
  if (GLenum err = glGetError(); err != GL_NO_ERROR)
    throw Error(ErrorCode::Gl, "text block upload failed (GL error 0x" + gl_error_text(err) + ")");
  return impl;
}

}  // namespace

bool append_bands(const GlyphBands& bands, std::shared_ptr<BandPage>& page_slot, GlyphBandRef& out) {
  constexpr std::size_t kWidth = kBandTextureWidth;
  constexpr std::size_t kPageTexels = kMaxBandPageRows * kWidth;
  if (bands.empty() || bands.texels.size() > kPageTexels) return false;
  if (!page_slot || page_slot->used + bands.texels.size() > kPageTexels) page_slot = std::make_shared<BandPage>();
  BandPage& page = *page_slot;
  const std::size_t first = page.used, end = first + bands.texels.size();
  const int rows = static_cast<int>((end + kWidth - 1) / kWidth);
  const bool grow = rows > page.rows;
  if (grow) {
    page.rows = std::max(rows, std::min(std::max(2 * page.rows, 8), kMaxBandPageRows));
    page.texels.resize(static_cast<std::size_t>(page.rows) * kWidth);
  }
  std::copy(bands.texels.begin(), bands.texels.end(), page.texels.begin() + static_cast<std::ptrdiff_t>(first));
  page.used = end;
  if (page.texture == 0) glGenTextures(1, &page.texture);
  if (page.texture == 0) throw Error(ErrorCode::Gl, "glGenTextures failed (is a GL context current?)");
  {
    const TextureUploadScope bound(page.texture);
    if (grow) {
      // Re-specified whole: blocks drawing from the page keep its texture name.
      // GLES 2 (OES_texture_float) takes the unsized format.
      const GLint format = ContextInfo::current().gl3() ? GL_RGBA32F : GL_RGBA;
      glTexImage2D(GL_TEXTURE_2D, 0, format, static_cast<GLsizei>(kWidth), page.rows, 0, GL_RGBA, GL_FLOAT,
                   page.texels.data());
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    } else {
      const int row0 = static_cast<int>(first / kWidth);
      glTexSubImage2D(GL_TEXTURE_2D, 0, 0, row0, static_cast<GLsizei>(kWidth), rows - row0, GL_RGBA, GL_FLOAT,
                      page.texels.data() + static_cast<std::size_t>(row0) * kWidth);
    }
  }
  if (GLenum err = glGetError(); err != GL_NO_ERROR)
    throw Error(ErrorCode::Gl, "band texture upload failed (GL error 0x" + gl_error_text(err) + ")");
  out.page = page_slot;
  out.first = static_cast<int>(first);
  out.levels = bands.levels;
  out.conics = bands.conics;
  out.box = bands.box;
  out.bytes = bands.bytes();
  out.most_entries = most_band_entries(bands);
  return true;
}

void add_mesh_bands(BatchImpl& impl, std::span<const Mesh* const> meshes, std::span<const Vec2> offsets) {
  const bool quads = !context_instances();
  if (quads && !es2_band_context()) return;
  std::shared_ptr<BandPage> page;
  BandScratch scratch;
  GlyphBands bands;
  std::vector<float> instances;
  std::vector<BatchImpl::BandRun> runs;
  for (std::size_t i = 0; i < meshes.size(); ++i) {
    build_bands(*meshes[i], bands, scratch);
    if (bands.empty()) continue;
    GlyphBandRef ref;
    const BandPage* before = page.get();
    // Too large for a page (or, on GLES 2, for the program's loop): the mesh path only.
    if (!append_bands(bands, page, ref) || !drawable(ref, quads)) return;
    if (runs.empty() || page.get() != before) runs.push_back({page, static_cast<GLint>(instances.size() / 8), 0});
    ++runs.back().count;
    impl.band_conics = impl.band_conics || ref.conics;
    const Box& box = ref.box;
    instances.insert(instances.end(),
                     {static_cast<float>(box.min.x), static_cast<float>(box.min.y), static_cast<float>(box.max.x),
                      static_cast<float>(box.max.y), static_cast<float>(offsets[i].x), static_cast<float>(offsets[i].y),
                      static_cast<float>(ref.first), static_cast<float>(ref.levels)});
  }
  upload_band_instances(impl, instances, quads);
  impl.band_runs = std::move(runs);
  impl.banded = true;
}

std::unique_ptr<BatchImpl> text_block(CacheImpl& cache, const Font& font, std::span<const PlacedGlyph> glyphs,
                                      double pixels_per_em, BlockPath path, std::uint32_t effect) {
  for (const PlacedGlyph& g : glyphs)
    if (!std::isfinite(g.x) || !std::isfinite(g.y))
      throw Error(ErrorCode::InvalidArgument, "glyph positions must be finite");
  check_no_pending_error("DrawBatch::from_glyphs");
  if (path == BlockPath::Auto) path = context_instances() ? BlockPath::Instanced : BlockPath::Expanded;
  const bool instanced = path == BlockPath::Instanced;
  // The GLES 2 band path (bands_es2.hpp): the expanded meshes and the bands' quads.
  const bool es2_bands = !instanced && !context_instances() && es2_band_context();
  // Held here: the cache may drop a glyph of this block while fetching a later one.
  std::vector<CacheImpl::Packed> meshes;
  meshes.reserve(glyphs.size());
  for (const PlacedGlyph& g : glyphs)
    meshes.push_back(cache.get(font, g.glyph_id, pixels_per_em, instanced, effect, es2_bands));
  if (instanced) return instanced_block(meshes, glyphs);
  auto block = expanded_block(meshes, glyphs);
  if (es2_bands) band_instances(meshes, glyphs, *block, true);
  return block;
}

}  // namespace gpu

std::vector<PlacedGlyph> gpu::placed_glyphs(const ShapedLine& line) {
  std::vector<PlacedGlyph> placed;
  placed.reserve(line.glyphs.size());
  double pen_x = 0.0, pen_y = 0.0;
  for (const ShapedGlyph& g : line.glyphs) {
    placed.push_back(PlacedGlyph{g.glyph_id, pen_x + g.x_offset, pen_y + g.y_offset});
    pen_x += g.x_advance;
    pen_y += g.y_advance;
  }
  return placed;
}

DrawBatch DrawBatch::from_text(GlyphCache& cache, const Font& font, const ShapedLine& line, double pixels_per_em) {
  return from_glyphs(cache, font, gpu::placed_glyphs(line), pixels_per_em);
}

DrawBatch DrawBatch::from_glyphs(GlyphCache& cache, const Font& font, std::span<const PlacedGlyph> glyphs,
                                 double pixels_per_em) {
  return DrawBatch(gpu::text_block(GlyphCacheAccess::impl(cache), font, glyphs, pixels_per_em));
}

DrawBatch DrawBatch::from_mesh(const Mesh& mesh) {
  gpu::check_no_pending_error("DrawBatch::from_mesh");
  return DrawBatch(gpu::upload(gpu::pack_mesh(mesh)));
}

DrawBatch::DrawBatch(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
DrawBatch::DrawBatch(DrawBatch&&) noexcept = default;
DrawBatch& DrawBatch::operator=(DrawBatch&&) noexcept = default;
DrawBatch::~DrawBatch() = default;

std::size_t DrawBatch::vertex_count() const {
  if (!impl_) return 0;
  if (!impl_->instanced()) return impl_->vertex_count;
  std::size_t n = 0;
  for (const Impl::Run& run : impl_->runs) n += run.glyph->vertex_count * static_cast<std::size_t>(run.count);
  return n;
}
std::size_t DrawBatch::gpu_bytes() const {
  if (!impl_) return 0;
  std::size_t banded = 0;
  for (const Impl::BandRun& run : impl_->band_runs) banded += static_cast<std::size_t>(run.count);
  if (impl_->instanced()) return impl_->placements * 2 * sizeof(float) + banded * 8 * sizeof(float);
  if (impl_->bitmaps()) return impl_->vertex_count * 4 * sizeof(float);
  const std::size_t index_bytes = impl_->index_type == GL_UNSIGNED_SHORT ? 2
                                  : impl_->index_type == GL_UNSIGNED_INT ? 4
                                                                         : 0;
  // GLES 2's band quads: 4 vertices a glyph (their indices are the renderer's).
  const std::size_t quads = impl_->band_quads ? banded * 4 * gpu::kBandQuadVertexFloats * sizeof(float) : 0;
  return impl_->vertex_count * sizeof(gpu::Vertex) + impl_->index_count * index_bytes + quads;
}
bool DrawBatch::instanced() const { return impl_ && impl_->instanced(); }

}  // namespace curvetext
