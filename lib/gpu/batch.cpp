// Glyph cache (packed meshes per glyph and level of detail, LRU within a byte
// budget) and draw batches (one vertex buffer, one draw call).
#include <cmath>
#include <cstdio>
#include <string>

#include "curvetext/error.hpp"
#include "curvetext/lod.hpp"
#include "gpu/batch_impl.hpp"

namespace curvetext {

namespace {
std::size_t bytes_of(const std::vector<gpu::Vertex>& v) { return v.size() * sizeof(gpu::Vertex); }
}  // namespace

GlyphCache::Impl::Vertices GlyphCache::Impl::get(const Font& font, std::uint32_t glyph_id,
                                                 double pixels_per_em) {
  const int upem = font.metrics().units_per_em;
  if (!(pixels_per_em > 0) || !std::isfinite(pixels_per_em) || upem <= 0) {
    throw Error(ErrorCode::InvalidArgument, "glyph size must be a positive number of pixels per em");
  }
  // Looking the outline up on every hit would cost a FreeType load, so the
  // cache is probed twice instead: outlines without cubics are exact at every
  // scale and stored under lod 0; outlines with cubics under their band
  // (lod_for_scale never returns 0: the lowest band is tolerance::kMinLodLog2).
  const int cubic_lod = lod_for_scale(pixels_per_em / upem, upem);
  for (int probe : {0, cubic_lod}) {
    auto it = index.find(Key{font.cache_key(), glyph_id, probe});
    if (it != index.end()) {
      lru.splice(lru.begin(), lru, it->second);
      ++stats.hits;
      return it->second->vertices;
    }
  }
  ++stats.misses;
  thread_local Outline outline;  // scratch: its storage serves every miss on this thread
  font.glyph_outline(glyph_id, outline);
  int lod = 0;
  MeshOptions options;
  if (outline.has_cubics()) {
    lod = cubic_lod;
    options.cubic_tolerance = cubic_tolerance_for_lod(lod, upem);
  }
  auto vertices = std::make_shared<std::vector<gpu::Vertex>>();
  if (!outline.empty()) {
    thread_local Mesh mesh;  // scratch: its storage serves every miss on this thread
    build_mesh(outline, options, mesh);
    gpu::pack_mesh(mesh, *vertices);
  }
  Vertices result = vertices;

  const std::size_t size = bytes_of(*result);
  lru.push_front(Entry{Key{font.cache_key(), glyph_id, lod}, result});
  index[lru.front().key] = lru.begin();
  stats.bytes += size;
  stats.glyphs += 1;
  // Evict least recently used glyphs, but never the one just built.
  while (stats.bytes > budget_bytes && lru.size() > 1) {
    const Entry& victim = lru.back();
    stats.bytes -= bytes_of(*victim.vertices);
    stats.glyphs -= 1;
    index.erase(victim.key);
    lru.pop_back();
  }
  return result;
}

GlyphCache::GlyphCache(std::size_t budget_bytes) : impl_(std::make_unique<Impl>(budget_bytes)) {}
GlyphCache::~GlyphCache() = default;
GlyphCache::Stats GlyphCache::stats() const { return impl_->stats; }

namespace {

std::unique_ptr<DrawBatch::Impl> upload(const std::vector<gpu::Vertex>& vertices) {
  auto impl = std::make_unique<DrawBatch::Impl>();
  impl->vertex_count = vertices.size();
  static std::uint64_t next_serial = 0;
  impl->serial = ++next_serial;
  for (const gpu::Vertex& v : vertices) impl->bounds.add({v.pos[0], v.pos[1]});
  if (vertices.empty()) return impl;
  glGenBuffers(1, &impl->vbo);
  if (impl->vbo == 0) throw Error(ErrorCode::Gl, "glGenBuffers failed (is a GL context current?)");
  glBindBuffer(GL_ARRAY_BUFFER, impl->vbo);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(bytes_of(vertices)), vertices.data(), GL_STATIC_DRAW);
  glBindBuffer(GL_ARRAY_BUFFER, 0);
  if (GLenum err = glGetError(); err != GL_NO_ERROR) {
    throw Error(ErrorCode::Gl, "vertex buffer upload failed (GL error 0x" + [err] {
      char buf[16];
      std::snprintf(buf, sizeof buf, "%04x", static_cast<unsigned>(err));
      return std::string(buf);
    }() + ")");
  }
  return impl;
}

}  // namespace

DrawBatch DrawBatch::from_text(GlyphCache& cache, const Font& font, const ShapedLine& line,
                               double pixels_per_em) {
  std::vector<gpu::Vertex> vertices;
  double pen_x = 0.0, pen_y = 0.0;
  for (const ShapedGlyph& g : line.glyphs) {
    auto glyph = cache.impl().get(font, g.glyph_id, pixels_per_em);
    gpu::append_translated(*glyph, Vec2{pen_x + g.x_offset, pen_y + g.y_offset}, vertices);
    pen_x += g.x_advance;
    pen_y += g.y_advance;
  }
  return DrawBatch(upload(vertices));
}

DrawBatch DrawBatch::from_mesh(const Mesh& mesh) { return DrawBatch(upload(gpu::pack_mesh(mesh))); }

DrawBatch::DrawBatch(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
DrawBatch::DrawBatch(DrawBatch&&) noexcept = default;
DrawBatch& DrawBatch::operator=(DrawBatch&&) noexcept = default;
DrawBatch::~DrawBatch() = default;

std::size_t DrawBatch::vertex_count() const { return impl_ ? impl_->vertex_count : 0; }
std::size_t DrawBatch::gpu_bytes() const { return vertex_count() * sizeof(gpu::Vertex); }

}  // namespace curvetext
