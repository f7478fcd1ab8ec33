// The glyph cache's budget (glyph_cache.hpp) without a GL context: meshes are
// built and counted on the CPU; nothing is uploaded.
#include <gtest/gtest.h>

#include "curvetext/font.hpp"
#include "gpu/batch_impl.hpp"
#include "support/fonts.hpp"

namespace curvetext {
namespace {

// Every entry costs at least its bookkeeping: empty glyphs (a space at
// thousands of variation settings, each its own cache key) counted as 0
// bytes stayed cached without end under any budget.
TEST(GlyphCache, EmptyGlyphsCountAgainstTheBudget) {
  Font font = Font::open(test::kInterVariable);
  const std::uint32_t space = font.glyph_for_codepoint(U' ');
  ASSERT_NE(space, 0u);
  ASSERT_TRUE(font.glyph_outline(space).empty());
  constexpr std::size_t kBudget = 64 * 1024;
  constexpr int kSettings = 4000;
  GlyphCache cache(kBudget);
  for (int i = 0; i < kSettings; ++i) {
    font.set_variations({{"wght", 100.0f + 0.2f * static_cast<float>(i)}});
    GlyphCacheAccess::impl(cache).get(font, space, 16.0);
  }
  const GlyphCache::Stats stats = cache.stats();
  EXPECT_EQ(stats.misses, static_cast<std::size_t>(kSettings));
  EXPECT_LE(stats.bytes, kBudget);
  EXPECT_LT(stats.glyphs, static_cast<std::size_t>(kSettings));
  // At least a list node, an index node and the shared glyph per entry.
  EXPECT_GE(stats.bytes / stats.glyphs, sizeof(gpu::CachedGlyph) + 4 * sizeof(void*));
}

}  // namespace
}  // namespace curvetext
