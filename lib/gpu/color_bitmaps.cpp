// Colour bitmaps (CBDT/sbix emoji): the glyph cache's atlas of RGBA pages
// and draw batches of textured quads from it. The one place curvetext keeps
// glyphs as pixels: a bitmap font has nothing else to draw from.
#include <GLES3/gl3.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <unordered_map>

#include "curvetext/error.hpp"
#include "curvetext/tolerances.hpp"
#include "gpu/batch_impl.hpp"
#include "gpu/gl_state.hpp"
#include "gpu/gl_util.hpp"

namespace curvetext {

namespace {

void check_gl(const char* what) {
  if (GLenum err = glGetError(); err != GL_NO_ERROR)
    throw Error(ErrorCode::Gl, std::string(what) + " failed (GL error " + gpu::hex(err) + ")");
}

// A bitmap reduced 2^level times by averaging blocks of 2^level x 2^level
// premultiplied texels (the exact area mean; texels past the bitmap's edge
// count as transparent), with a border of one transparent texel.
struct Level {
  int w = 0, h = 0;                // without the border
  std::vector<std::uint8_t> rgba;  // (w + 2) x (h + 2)
};

Level reduce(const ColorBitmap& b, int level) {
  const int f = 1 << level;
  Level out;
  out.w = (b.width + f - 1) / f;
  out.h = (b.height + f - 1) / f;
  const int stride = out.w + 2;
  out.rgba.assign(static_cast<std::size_t>(stride) * (out.h + 2) * 4, 0);
  std::vector<std::uint32_t> sum(static_cast<std::size_t>(out.w) * out.h * 4, 0);
  for (int y = 0; y < b.height; ++y)
    for (int x = 0; x < b.width; ++x)
      for (int c = 0; c < 4; ++c)
        sum[(static_cast<std::size_t>(y / f) * out.w + x / f) * 4 + c] +=
            b.rgba[(static_cast<std::size_t>(y) * b.width + x) * 4 + c];
  const std::uint32_t n = static_cast<std::uint32_t>(f * f);
  for (int y = 0; y < out.h; ++y)
    for (int x = 0; x < out.w; ++x)
      for (int c = 0; c < 4; ++c)
        out.rgba[(static_cast<std::size_t>(y + 1) * stride + x + 1) * 4 + c] =
            static_cast<std::uint8_t>((sum[(static_cast<std::size_t>(y) * out.w + x) * 4 + c] + n / 2) / n);
  return out;
}

int round_up_pow2(int n) {
  int p = 1;
  while (p < n) p *= 2;
  return p;
}

std::shared_ptr<gpu::AtlasPage> new_page(int needed) {
  GLint max_texture = 0;
  glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_texture);
  const int side = std::max(tolerance::kColorAtlasPageTexels, round_up_pow2(needed));
  if (side > max_texture)
    throw Error(ErrorCode::Gl, "a colour bitmap needs a " + std::to_string(side) +
                                   " texel atlas page; the GL context allows " + std::to_string(max_texture));
  auto page = std::make_shared<gpu::AtlasPage>();
  glGenTextures(1, &page->texture);
  if (page->texture == 0) throw Error(ErrorCode::Gl, "glGenTextures failed (is a GL context current?)");
  const gpu::TextureUploadScope bound(page->texture);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA, side, side, 0, GL_RGBA, GL_UNSIGNED_BYTE, nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  check_gl("creating a colour bitmap atlas page");
  page->side = side;
  page->bytes = static_cast<std::size_t>(side) * side * 4;
  return page;
}

// A shelf position for a w x h block in `page`, or false when it is full.
bool place(gpu::AtlasPage& page, int w, int h, int& x, int& y) {
  if (page.x + w > page.side) {
    page.shelf_y += page.shelf_h;
    page.shelf_h = 0;
    page.x = 0;
  }
  if (page.shelf_y + h > page.side || w > page.side) return false;
  x = page.x;
  y = page.shelf_y;
  page.x += w;
  page.shelf_h = std::max(page.shelf_h, h);
  return true;
}

// The level for drawing a strike of `strike_ppem` at `ppem`: the smallest
// reduction still at least as large, so the quad samples at most 2:1.
int level_for(double strike_ppem, double ppem) {
  int level = 0;
  while (level < 10 && strike_ppem / (1 << (level + 1)) >= ppem) ++level;
  return level;
}

}  // namespace

gpu::CachedBitmap gpu::CacheImpl::bitmap(const Font& font, std::uint32_t glyph_id, double pixels_per_em) {
  const std::vector<double> strikes = font.color_bitmap_strikes();
  int strike = -1, largest = 0;  // as Font::color_bitmap chooses
  for (int i = 0; i < static_cast<int>(strikes.size()); ++i) {
    if (strikes[i] > strikes[largest]) largest = i;
    if (strikes[i] >= pixels_per_em && (strike < 0 || strikes[i] < strikes[strike])) strike = i;
  }
  if (strike < 0) strike = largest;
  if (strikes.empty()) return {};
  const int level = level_for(strikes[strike], pixels_per_em);
  const Key key{font.cache_key(), glyph_id, strike * 64 + level};
  if (auto it = bitmaps.find(key); it != bitmaps.end()) {
    ++stats.hits;
    return it->second;
  }
  ++stats.misses;
  const ColorBitmap b = font.color_bitmap(glyph_id, strikes[strike]);
  gpu::CachedBitmap entry;
  if (b.width > 0 && b.height > 0) {
    const Level l = reduce(b, level);
    int x = 0, y = 0;
    if (pages.empty() || !place(*pages.back(), l.w + 2, l.h + 2, x, y)) {
      auto page = new_page(l.w + 2);
      // Oldest pages go while the new one would pass the budget.
      while (!pages.empty() && stats.bytes + stats.bitmap_bytes + page->bytes > budget_bytes) {
        const gpu::AtlasPage* old = pages.front().get();
        std::erase_if(bitmaps, [&](const auto& kv) { return kv.second.page.get() == old; });
        stats.bitmap_bytes -= pages.front()->bytes;
        pages.erase(pages.begin());
      }
      pages.push_back(std::move(page));
      stats.bitmap_bytes += pages.back()->bytes;
      place(*pages.back(), l.w + 2, l.h + 2, x, y);
    }
    {
      const gpu::TextureUploadScope bound(pages.back()->texture);
      glTexSubImage2D(GL_TEXTURE_2D, 0, x, y, l.w + 2, l.h + 2, GL_RGBA, GL_UNSIGNED_BYTE, l.rgba.data());
    }
    check_gl("uploading a colour bitmap");
    const double units = font.metrics().units_per_em / b.strike_ppem;  // font units per strike pixel
    const double texel = units * (1 << level);
    entry.page = pages.back();
    entry.x = x + 1;
    entry.y = y + 1;
    entry.w = l.w;
    entry.h = l.h;
    entry.left = b.left * units;
    entry.top = b.top * units;
    entry.width = l.w * texel;
    entry.height = l.h * texel;
  }
  bitmaps.emplace(key, entry);
  stats.bitmaps = bitmaps.size();
  return entry;
}

namespace {

// Six vertices (x, y, u, v) of a bitmap's quad at `origin`, reaching over
// its transparent border so that linear filtering fades its edge.
void append_quad(const gpu::CachedBitmap& b, Vec2 origin, std::vector<float>& out, Box& bounds) {
  const double tx = b.width / b.w, ty = b.height / b.h;  // font units per texel
  const double x0 = origin.x + b.left - tx, x1 = origin.x + b.left + b.width + tx;
  const double y0 = origin.y + b.top + ty, y1 = origin.y + b.top - b.height - ty;  // top, bottom (y up)
  const double side = b.page->side;
  const double u0 = (b.x - 1) / side, u1 = (b.x + b.w + 1) / side;
  const double v0 = (b.y - 1) / side, v1 = (b.y + b.h + 1) / side;
  const double corners[6][4] = {{x0, y0, u0, v0}, {x1, y0, u1, v0}, {x1, y1, u1, v1},
                                {x0, y0, u0, v0}, {x1, y1, u1, v1}, {x0, y1, u0, v1}};
  for (const auto& c : corners)
    for (double v : c) out.push_back(static_cast<float>(v));
  bounds.add({x0, y0});
  bounds.add({x1, y1});
}

}  // namespace

DrawBatch DrawBatch::from_color_bitmaps(GlyphCache& cache, const Font& font, std::span<const PlacedGlyph> glyphs,
                                        double pixels_per_em) {
  if (!(pixels_per_em > 0.0) || !std::isfinite(pixels_per_em))
    throw Error(ErrorCode::InvalidArgument, "glyph size must be a positive number of pixels per em");
  if (font.color_format() != ColorFormat::Bitmap)
    throw Error(ErrorCode::InvalidArgument, "not a bitmap colour font (CBDT/sbix): " + font.path());
  for (const PlacedGlyph& g : glyphs)
    if (!std::isfinite(g.x) || !std::isfinite(g.y))
      throw Error(ErrorCode::InvalidArgument, "glyph positions must be finite");
  gpu::check_no_pending_error("DrawBatch::from_color_bitmaps");
  gpu::CacheImpl& c = GlyphCacheAccess::impl(cache);
  std::vector<gpu::CachedBitmap> found;
  found.reserve(glyphs.size());
  for (const PlacedGlyph& g : glyphs) found.push_back(c.bitmap(font, g.glyph_id, pixels_per_em));
  // Quads grouped by page, in first-use order.
  auto impl = std::make_unique<Impl>();
  std::unordered_map<const gpu::AtlasPage*, std::vector<float>> by_page;
  std::vector<std::shared_ptr<const gpu::AtlasPage>> order;
  for (std::size_t i = 0; i < glyphs.size(); ++i) {
    if (!found[i].page) continue;
    auto [it, fresh] = by_page.try_emplace(found[i].page.get());
    if (fresh) order.push_back(found[i].page);
    append_quad(found[i], {glyphs[i].x, glyphs[i].y}, it->second, impl->bounds);
  }
  std::vector<float> vertices;
  for (const auto& page : order) {
    const std::vector<float>& v = by_page[page.get()];
    impl->bitmap_runs.push_back({page, static_cast<GLint>(vertices.size() / 4), static_cast<GLsizei>(v.size() / 4)});
    vertices.insert(vertices.end(), v.begin(), v.end());
  }
  glGenBuffers(1, &impl->bitmap_vbo);
  if (impl->bitmap_vbo == 0) throw Error(ErrorCode::Gl, "glGenBuffers failed (is a GL context current?)");
  if (!vertices.empty()) {
    const gpu::BufferBindingScope bound(GL_ARRAY_BUFFER, impl->bitmap_vbo);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(float)), vertices.data(),
                 GL_STATIC_DRAW);
  }
  check_gl("colour bitmap batch upload");
  impl->vertex_count = vertices.size() / 4;
  return DrawBatchAccess::make(std::move(impl));
}

}  // namespace curvetext
