// Glyph cache (packed meshes per glyph and level of detail, LRU within a byte
// budget) and draw batches (one vertex and one index buffer, one draw call).
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

#include "curvetext/error.hpp"
#include "curvetext/lod.hpp"
#include "gpu/batch_impl.hpp"

namespace curvetext {

GlyphCache::Impl::Packed GlyphCache::Impl::get(const Font& font, std::uint32_t glyph_id, double pixels_per_em) {
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
      return it->second->packed;
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
  auto packed = std::make_shared<gpu::PackedMesh>();
  if (!outline.empty()) {
    thread_local Mesh mesh;  // scratch: its storage serves every miss on this thread
    build_mesh(outline, options, mesh);
    gpu::pack_mesh(mesh, *packed);
  }
  Packed result = packed;

  const std::size_t size = result->memory_bytes();
  lru.push_front(Entry{Key{font.cache_key(), glyph_id, lod}, result});
  index[lru.front().key] = lru.begin();
  stats.bytes += size;
  stats.glyphs += 1;
  // Evict least recently used glyphs, but never the one just built.
  while (stats.bytes > budget_bytes && lru.size() > 1) {
    const Entry& victim = lru.back();
    stats.bytes -= victim.packed->memory_bytes();
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
  glBindBuffer(target, buffer);
  glBufferData(target, static_cast<GLsizeiptr>(data.size() * sizeof(T)), data.data(), GL_STATIC_DRAW);
  glBindBuffer(target, 0);
}

}  // namespace

namespace gpu {

std::unique_ptr<DrawBatch::Impl> upload(PackedMesh packed, IndexUpload how) {
  auto impl = std::make_unique<DrawBatch::Impl>();
  static std::uint64_t next_serial = 0;
  impl->serial = ++next_serial;
  for (const Vertex& v : packed.vertices) impl->bounds.add({v.pos[0], v.pos[1]});
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

}  // namespace gpu

DrawBatch DrawBatch::from_text(GlyphCache& cache, const Font& font, const ShapedLine& line, double pixels_per_em) {
  gpu::PackedMesh packed;
  double pen_x = 0.0, pen_y = 0.0;
  for (const ShapedGlyph& g : line.glyphs) {
    auto glyph = cache.impl().get(font, g.glyph_id, pixels_per_em);
    gpu::append_translated(*glyph, Vec2{pen_x + g.x_offset, pen_y + g.y_offset}, packed);
    pen_x += g.x_advance;
    pen_y += g.y_advance;
  }
  return DrawBatch(gpu::upload(std::move(packed)));
}

DrawBatch DrawBatch::from_mesh(const Mesh& mesh) { return DrawBatch(gpu::upload(gpu::pack_mesh(mesh))); }

DrawBatch::DrawBatch(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
DrawBatch::DrawBatch(DrawBatch&&) noexcept = default;
DrawBatch& DrawBatch::operator=(DrawBatch&&) noexcept = default;
DrawBatch::~DrawBatch() = default;

std::size_t DrawBatch::vertex_count() const { return impl_ ? impl_->vertex_count : 0; }
std::size_t DrawBatch::gpu_bytes() const {
  if (!impl_) return 0;
  const std::size_t index_bytes = impl_->index_type == GL_UNSIGNED_SHORT ? 2
                                  : impl_->index_type == GL_UNSIGNED_INT ? 4
                                                                         : 0;
  return impl_->vertex_count * sizeof(gpu::Vertex) + impl_->index_count * index_bytes;
}

}  // namespace curvetext
