// Font file bytes -> a face -> metrics, shaping, glyph outlines -> meshes
// (what a text block does before it uploads). The whole input is the font;
// a variable font is also tried at a variation.
#include <algorithm>
#include <span>
#include <vector>

#include "curvetext/font.hpp"
#include "curvetext/font_collection.hpp"
#include "curvetext/lod.hpp"
#include "curvetext/shaping.hpp"
#include "fuzz_support.hpp"

namespace {

// Glyphs meshed per input: the first ids (composites, .notdef) and those the
// texts shape to. Bounded so one input stays fast.
constexpr unsigned kFirstGlyphs = 12;
constexpr const char* kTexts[] = {"HIO. Hello, world! fi ffl", "\u0627\u0644\u0639\u0631\u0628\u064a\u0629 1.5",
                                  "\u0915\u094d\u0937\u093f \u0e01\u0e34\u0e19"};

void mesh_glyphs(const curvetext::Font& font) {
  using namespace curvetext;
  const FontMetrics metrics = font.metrics();
  std::vector<std::uint32_t> glyphs;
  for (std::uint32_t g = 0; g < std::min(font.glyph_count(), kFirstGlyphs); ++g) glyphs.push_back(g);
  for (const char* text : kTexts) {
    try {
      for (const ShapedGlyph& g : shape_line(font, text).glyphs) glyphs.push_back(g.glyph_id);
    } catch (const Error&) {
    }
  }
  std::sort(glyphs.begin(), glyphs.end());
  glyphs.erase(std::unique(glyphs.begin(), glyphs.end()), glyphs.end());
  // The level of detail of 64 px/em, as a text block at that size uses.
  const double tolerance =
      cubic_tolerance_for_lod(lod_for_scale(64.0 / metrics.units_per_em, metrics.units_per_em), metrics.units_per_em);
  Outline outline;
  for (std::uint32_t g : glyphs) {
    try {
      font.glyph_outline(g, outline);
    } catch (const Error&) {
      continue;
    }
    fuzz::mesh_and_check(outline, tolerance, true);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace curvetext;
  try {
    Font font = Font::open_memory(std::span(data, size), "fuzz input");
    (void)font.family_name();
    (void)has_outlines(font);
    mesh_glyphs(font);
    font.set_variations({{"wght", 900.0f}});
    mesh_glyphs(font);
  } catch (const Error&) {
  }
  return 0;
}
