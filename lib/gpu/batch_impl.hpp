// Private definitions shared by the glyph cache, draw batches and renderer.
#pragma once

#include <GLES2/gl2.h>

#include <cstdint>
#include <list>
#include <memory>
#include <unordered_map>
#include <vector>

#include "curvetext/renderer.hpp"
#include "gpu/vertex_format.hpp"

namespace curvetext {

struct DrawBatch::Impl {
  GLuint vbo = 0;  // 0 when there is nothing to draw
  std::size_t vertex_count = 0;
  Box bounds;  // of the vertices' base positions (outline units; growth offsets not included)
  std::uint64_t serial = 0;  // unique per upload: the vbaa pass is reused while it and the transform match

  Impl() = default;
  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;
  // Needs the context that created the buffer to be current.
  ~Impl() {
    if (vbo != 0) glDeleteBuffers(1, &vbo);
  }
};

struct GlyphCache::Impl {
  struct Key {
    std::uint64_t font = 0;
    std::uint32_t glyph = 0;
    int lod = 0;
    bool operator==(const Key&) const = default;
  };
  struct KeyHash {
    std::size_t operator()(const Key& k) const noexcept {
      std::uint64_t h = k.font * 0x9E3779B97F4A7C15ull;
      h ^= (static_cast<std::uint64_t>(k.glyph) << 8) + static_cast<std::uint64_t>(k.lod) + (h << 6) + (h >> 2);
      return static_cast<std::size_t>(h);
    }
  };
  using Vertices = std::shared_ptr<const std::vector<gpu::Vertex>>;
  struct Entry {
    Key key;
    Vertices vertices;
  };

  explicit Impl(std::size_t budget) : budget_bytes(budget) {}

  // Packed vertices of a glyph for drawing at `pixels_per_em`; builds them on
  // a miss. The returned pointer stays valid even if the entry is evicted.
  Vertices get(const Font& font, std::uint32_t glyph_id, double pixels_per_em);

  std::size_t budget_bytes;
  std::list<Entry> lru;  // most recently used first
  std::unordered_map<Key, std::list<Entry>::iterator, KeyHash> index;
  Stats stats;
};

}  // namespace curvetext
