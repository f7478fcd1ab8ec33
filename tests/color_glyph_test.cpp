// Colour glyphs (color_glyph.hpp): bitmap emoji (CBDT, Debian's Noto Color
// Emoji) opened by name and reached through fallback, ZWJ and skin-tone
// sequences shaped as one glyph, drawn as textured quads against the strike's
// bitmap scaled by exact area; COLR v0 and v1 layers (fonts/test, made by
// tests/fixtures/make_color_test_fonts.py) drawn against the exact area
// coverage of each layer composited in order; COLR v1 paints not supported
// refused by name.
#include <gtest/gtest.h>

#include <hb.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "curvetext/error.hpp"
#include "curvetext/layout.hpp"
#include "curvetext/paragraph_image.hpp"
#include "curvetext/text_block.hpp"
#include "curvetext/text_image.hpp"
#include "font/harfbuzz_font.hpp"
#include "layout/emoji.hpp"
#include "support/fonts.hpp"
#include "support/gpu.hpp"
#include "support/layout_support.hpp"
#include "support/union_coverage.hpp"

namespace curvetext {
namespace {

const char* kColorEmoji = "/usr/share/fonts/truetype/noto/NotoColorEmoji.ttf";
const std::string kTestFonts = std::string(CURVETEXT_SOURCE_DIR) + "/fonts/test/";
const std::string kColrV0 = kTestFonts + "CurvetextColor-COLRv0.ttf";
const std::string kColrV1 = kTestFonts + "CurvetextColor-COLRv1.ttf";
constexpr double kMargin = 16.0;

bool have_emoji_font() {
  std::ifstream in(kColorEmoji);
  return in.good();
}
#define REQUIRE_EMOJI_FONT() \
  if (!have_emoji_font())    \
  GTEST_SKIP() << "fonts-noto-color-emoji is not installed (scripts/setup-debian.sh installs it)"

ParagraphStyle style_with(const std::vector<std::string>& fonts, double size, Color color = {0, 0, 0, 1}) {
  ParagraphStyle s;
  s.default_style.fonts = fonts;
  s.default_style.size_px = size;
  s.default_style.color = color;
  return s;
}

// An RGB image in [0, 1] per channel (straight colour over an opaque background).
struct Rgb {
  int width = 0, height = 0;
  std::vector<double> v;  // 3 per pixel
  Rgb(int w, int h, double fill) : width(w), height(h), v(static_cast<std::size_t>(w) * h * 3, fill) {}
  double* at(int x, int y) { return &v[(static_cast<std::size_t>(y) * width + x) * 3]; }
  const double* at(int x, int y) const { return &v[(static_cast<std::size_t>(y) * width + x) * 3]; }
};

Rgb from_image(const Image& image) {
  Rgb out(image.width, image.height, 0.0);
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x)
      for (int c = 0; c < 3; ++c) out.at(x, y)[c] = image.pixel(x, y)[c] / 255.0;
  return out;
}

// Mean absolute error per channel over the pixels where either image differs
// from the white background, and the largest.
struct RgbStats {
  double mean = 0.0, max = 0.0;
  std::size_t pixels = 0;
};
RgbStats compare(const Rgb& result, const Rgb& reference) {
  RgbStats s;
  double sum = 0.0;
  for (int y = 0; y < result.height; ++y)
    for (int x = 0; x < result.width; ++x) {
      const double *a = result.at(x, y), *b = reference.at(x, y);
      bool ink = false;
      for (int c = 0; c < 3; ++c) ink = ink || a[c] < 1.0 - 1e-9 || b[c] < 1.0 - 1e-9;
      if (!ink) continue;
      ++s.pixels;
      for (int c = 0; c < 3; ++c) {
        const double e = std::abs(a[c] - b[c]);
        sum += e;
        s.max = std::max(s.max, e);
      }
    }
  s.mean = s.pixels ? sum / (3.0 * static_cast<double>(s.pixels)) : 0.0;
  return s;
}

// The strike's bitmap (premultiplied) placed at the glyph origin (px, y down)
// and scaled by `scale`, each texel spread over the pixels it overlaps by
// exact area, composited over `image` (sRGB values, as the renderer blends).
void add_scaled_bitmap(const ColorBitmap& b, double ox, double oy, double scale, Rgb& image) {
  std::vector<double> premult(static_cast<std::size_t>(image.width) * image.height * 4, 0.0);
  const double x0 = ox + b.left * scale, y0 = oy - b.top * scale;
  for (int j = 0; j < b.height; ++j)
    for (int i = 0; i < b.width; ++i) {
      const std::uint8_t* t = &b.rgba[(static_cast<std::size_t>(j) * b.width + i) * 4];
      if (t[3] == 0) continue;
      const double tx0 = x0 + i * scale, tx1 = tx0 + scale, ty0 = y0 + j * scale, ty1 = ty0 + scale;
      for (int py = std::max(0, static_cast<int>(std::floor(ty0)));
           py < std::min(image.height, static_cast<int>(std::ceil(ty1))); ++py)
        for (int px = std::max(0, static_cast<int>(std::floor(tx0)));
             px < std::min(image.width, static_cast<int>(std::ceil(tx1))); ++px) {
          const double area = (std::min(tx1, px + 1.0) - std::max(tx0, double(px))) *
                              (std::min(ty1, py + 1.0) - std::max(ty0, double(py)));
          if (area <= 0.0) continue;
          for (int c = 0; c < 4; ++c)
            premult[(static_cast<std::size_t>(py) * image.width + px) * 4 + c] += area * t[c] / 255.0;
        }
    }
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const double* p = &premult[(static_cast<std::size_t>(y) * image.width + x) * 4];
      for (int c = 0; c < 3; ++c) image.at(x, y)[c] = p[c] + (1.0 - p[3]) * image.at(x, y)[c];
    }
}

// --- Opening bitmap colour fonts -----------------------------------------------

// Naming a CBDT font was refused ("font has no scalable outlines").
TEST(ColorFont, BitmapEmojiFontOpensByPathAndByName) {
  REQUIRE_EMOJI_FONT();
  const Font font = Font::open(kColorEmoji);
  EXPECT_EQ(font.color_format(), ColorFormat::Bitmap);
  EXPECT_EQ(font.metrics().units_per_em, 2048);
  ASSERT_EQ(font.color_bitmap_strikes(), std::vector<double>{109.0});
  const std::uint32_t smile = font.glyph_for_codepoint(0x1F600);
  ASSERT_NE(smile, 0u);
  const ColorBitmap b = font.color_bitmap(smile, 20.0);
  EXPECT_EQ(b.strike_ppem, 109.0);
  EXPECT_EQ(b.width, 136);
  EXPECT_EQ(b.height, 128);
  ASSERT_EQ(b.rgba.size(), 136u * 128u * 4u);
  std::size_t opaque = 0;
  for (std::size_t i = 0; i < b.rgba.size(); i += 4) {
    for (int c = 0; c < 3; ++c) ASSERT_LE(b.rgba[i + c], b.rgba[i + 3]) << "not premultiplied";
    opaque += b.rgba[i + 3] == 255;
  }
  EXPECT_GT(opaque, 5000u);
  // No outline: a clear error, not a blank glyph.
  try {
    (void)font.glyph_outline(smile);
    ADD_FAILURE() << "a bitmap glyph gave an outline";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::FontInvalid);
    EXPECT_NE(std::string(e.what()).find("colour bitmaps"), std::string::npos) << e.what();
  }
  FontCollection fonts;
  EXPECT_EQ(fonts.resolve("Noto Color Emoji")->color_format(), ColorFormat::Bitmap);
  EXPECT_THROW((void)font.color_bitmap(smile, 0.0), Error);
  EXPECT_THROW((void)font.color_bitmap(font.glyph_count(), 20.0), Error);
}

// --- Layout: fallback, ZWJ and modifiers ----------------------------------------

// The glyphs HarfBuzz gives for `text` in the emoji font alone.
std::vector<std::uint32_t> emoji_font_glyphs(const std::u32string& text) {
  const Font font = Font::open(kColorEmoji);
  hb_buffer_t* buf = hb_buffer_create();
  hb_buffer_add_utf32(buf, reinterpret_cast<const std::uint32_t*>(text.data()), static_cast<int>(text.size()), 0, -1);
  hb_buffer_guess_segment_properties(buf);
  hb_shape(harfbuzz_font(font), buf, nullptr, 0);
  unsigned n = 0;
  const hb_glyph_info_t* info = hb_buffer_get_glyph_infos(buf, &n);
  std::vector<std::uint32_t> out;
  for (unsigned i = 0; i < n; ++i) out.push_back(info[i].codepoint);
  hb_buffer_destroy(buf);
  return out;
}

// A ZWJ family was four .notdef boxes, and a thumbs-up with a skin tone two;
// the rocket (only in the colour face) one box. Now each is one glyph of the
// colour face, HarfBuzz's ligature.
TEST(ColorLayout, ZwjFamilyAndSkinToneAreOneGlyphOfTheColourFace) {
  REQUIRE_EMOJI_FONT();
  const std::u32string family = U"\U0001F468\u200D\U0001F469\u200D\U0001F467\u200D\U0001F466";
  const std::u32string thumbs = U"\U0001F44D\U0001F3FD";
  const std::u32string rocket = U"\U0001F680";
  for (const std::u32string& e : {family, thumbs, rocket}) {
    const std::vector<std::uint32_t> expected = emoji_font_glyphs(e);
    ASSERT_EQ(expected.size(), 1u);
    FontCollection fonts;
    const std::string text = "a" + test::utf8_encode(e) + "b";
    const Paragraph p = Paragraph::layout(fonts, text, {}, style_with({test::kNotoSans}, 20.0));
    std::vector<std::pair<std::uint32_t, const Font*>> glyphs;
    for (const GlyphRun& r : p.lines()[0].runs)
      for (const PositionedGlyph& g : r.glyphs) glyphs.emplace_back(g.id, r.font.get());
    ASSERT_EQ(glyphs.size(), 3u) << text;
    EXPECT_EQ(glyphs[1].first, expected[0]);
    EXPECT_EQ(glyphs[1].second->path(), kColorEmoji);
    EXPECT_EQ(glyphs[0].second->path(), test::kNotoSans);
  }
}

// Emoji presentation, as Pango: U+1F600 from the colour face although DejaVu
// Sans has an outline for it; U+2764 (text by default) from DejaVu, and with
// U+FE0F from the colour face.
TEST(ColorLayout, EmojiPresentationPrefersTheColourFace) {
  REQUIRE_EMOJI_FONT();
  FontCollection fonts;
  const Paragraph p =
      Paragraph::layout(fonts, "\U0001F600 \u2764 \u2764\uFE0F", {}, style_with({test::kDejaVuSans}, 20.0));
  std::vector<std::string> faces;
  for (const GlyphRun& r : p.lines()[0].runs)
    for (std::size_t k = 0; k < r.glyphs.size(); ++k) faces.push_back(r.font->path());
  ASSERT_EQ(faces.size(), 5u);
  EXPECT_EQ(faces[0], kColorEmoji);
  EXPECT_EQ(faces[2], test::kDejaVuSans);
  EXPECT_EQ(faces[4], kColorEmoji);
}

// The table of Emoji_Presentation is the one in Debian's unicode-data.
TEST(ColorLayout, EmojiPresentationTableIsUnicodes) {
  std::ifstream in("/usr/share/unicode/emoji/emoji-data.txt");
  if (!in) GTEST_SKIP() << "unicode-data is not installed";
  std::vector<bool> expected(0x110000, false);
  std::string line;
  while (std::getline(in, line)) {
    line = line.substr(0, line.find('#'));
    const std::size_t semi = line.find(';');
    if (semi == std::string::npos || line.find("Emoji_Presentation", semi) == std::string::npos) continue;
    unsigned first = 0, last = 0;
    if (std::sscanf(line.c_str(), "%x..%x", &first, &last) < 2) last = first;
    for (unsigned c = first; c <= last; ++c) expected[c] = true;
  }
  for (char32_t c = 0; c < 0x110000; ++c)
    ASSERT_EQ(detail::emoji_presentation_default(c), expected[c]) << std::hex << static_cast<unsigned>(c);
}

// --- Drawing bitmap emoji ------------------------------------------------------

// Emoji drawn in a paragraph against the strike's bitmap scaled to the size by
// exact area. The renderer samples the atlas level just above the size (the
// strike halved while it stays larger, box-filtered) linearly, so its result
// is a resampling of the same bitmap: bounds below, and the same comparison
// with the reference moved by a pixel must be at least three times worse.
// Measured (llvmpipe): mean 0.003-0.016, max 0.12-0.33 (single pixels of
// fine detail at 14 px, where linear sampling of the 2:1 level reads 2 x 2
// of the 4 x 4 texels an exact resampling averages).
constexpr double kBitmapMeanLimit = 0.02;
constexpr double kBitmapMaxLimit = 0.4;
TEST(ColorRender, BitmapEmojiMatchTheStrikeScaledByArea) {
  REQUIRE_EMOJI_FONT();
  test::Gpu& gpu = test::gpu();
  const std::string text = "\U0001F600\U0001F680\U0001F44D\U0001F3FD";
  for (double size : {14.0, 20.0, 32.0, 48.0, 80.0, 150.0}) {
    FontCollection fonts;
    const Paragraph p = Paragraph::layout(fonts, text, {}, style_with({kColorEmoji}, size));
    ParagraphImageOptions options;
    options.margin_px = kMargin;
    const Image image = render_paragraph_image(gpu.renderer, gpu.cache, p, options);
    Rgb reference(image.width, image.height, 1.0), shifted(image.width, image.height, 1.0);
    std::size_t glyphs = 0;
    for (const GlyphRun& r : p.lines()[0].runs)
      for (const PositionedGlyph& g : r.glyphs) {
        const ColorBitmap b = r.font->color_bitmap(g.id, size);
        ASSERT_GT(b.width, 0);
        const double s = size / b.strike_ppem;
        add_scaled_bitmap(b, kMargin + g.x, kMargin + g.y, s, reference);
        add_scaled_bitmap(b, kMargin + g.x + 1.0, kMargin + g.y, s, shifted);
        ++glyphs;
      }
    ASSERT_EQ(glyphs, 3u);
    const Rgb result = from_image(image);
    const RgbStats st = compare(result, reference), control = compare(result, shifted);
    std::printf("emoji %5.1f px: mean %.4f max %.3f over %zu px; moved a pixel: mean %.4f\n", size, st.mean, st.max,
                st.pixels, control.mean);
    EXPECT_LT(st.mean, kBitmapMeanLimit) << size;
    EXPECT_LT(st.max, kBitmapMaxLimit) << size;
    EXPECT_GT(control.mean, 3.0 * st.mean) << size;
  }
}

// The CLI's single-line path (render_text_image) with the emoji font named.
TEST(ColorRender, SingleLineImageOfTheEmojiFontDrawsTheBitmaps) {
  REQUIRE_EMOJI_FONT();
  test::Gpu& gpu = test::gpu();
  const Font font = Font::open(kColorEmoji);
  TextImageOptions options;
  options.size_px = 32.0;
  const TextImageLayout layout = layout_text_image(font, "\U0001F680", options);
  const Image image = render_text_image(gpu.renderer, gpu.cache, font, layout, options);
  Rgb reference(image.width, image.height, 1.0);
  const ColorBitmap b = font.color_bitmap(font.glyph_for_codepoint(0x1F680), 32.0);
  add_scaled_bitmap(b, layout.placement.origin_x, layout.placement.origin_y, 32.0 / b.strike_ppem, reference);
  const RgbStats st = compare(from_image(image), reference);
  EXPECT_GT(st.pixels, 500u);
  EXPECT_LT(st.mean, 0.02);
}

// --- COLR -----------------------------------------------------------------------

TEST(ColorFont, ColrLayersFromThePaletteInOrder) {
  for (const std::string& path : {kColrV0, kColrV1}) {
    const Font font = Font::open(path);
    EXPECT_EQ(font.color_format(), ColorFormat::Layers) << path;
    const std::vector<ColorLayer> a = font.color_layers(font.glyph_for_codepoint('A'));
    ASSERT_EQ(a.size(), 3u) << path;
    EXPECT_FALSE(a[0].foreground);
    EXPECT_EQ(a[0].color.r, 1.0f);
    EXPECT_EQ(a[0].color.a, 1.0f);
    EXPECT_EQ(a[1].color.b, 1.0f);
    EXPECT_NEAR(a[1].color.a, 128.0 / 255.0, 1e-6);
    EXPECT_TRUE(a[2].foreground);
    EXPECT_NEAR(a[2].color.a, path == kColrV1 ? 0.5 : 1.0, 1e-4);
    const std::vector<ColorLayer> b = font.color_layers(font.glyph_for_codepoint('B'));
    ASSERT_EQ(b.size(), 1u) << path;
    EXPECT_NEAR(b[0].color.g, 160.0 / 255.0, 1e-6);
    EXPECT_TRUE(font.color_layers(font.glyph_for_codepoint('C')).empty());
  }
}

// COLR v1 paints not drawn yet are refused by name (they were drawn as the
// base glyph's outline in the text colour); a cycle, and a graph of 255^5
// paints (layer lists referring to layer lists), end in bounded time.
TEST(ColorFont, ColrV1GradientsTransformsAndCyclesAreRefusedByName) {
  const Font font = Font::open(kColrV1);
  const std::vector<std::pair<char32_t, std::string>> cases = {
      {'G', "linear gradient"}, {'T', "transformed paint"}, {'Y', "nested deeper"}, {'E', "16384 paints"}};
  for (const auto& [c, words] : cases) {
    try {
      (void)font.color_layers(font.glyph_for_codepoint(c));
      ADD_FAILURE() << "glyph for " << static_cast<char>(c) << " was not refused";
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), ErrorCode::FontInvalid);
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("COLR v1"), std::string::npos) << e.what();
    }
  }
  test::Gpu& gpu = test::gpu();
  FontCollection fonts;
  const Paragraph p = Paragraph::layout(fonts, "AG", {}, style_with({kColrV1}, 32.0));
  EXPECT_THROW((void)TextBlock::from_paragraph(gpu.cache, p), Error);
}

// A glyph's outline in image pixels at its pen position.
Outline placed(const Font& font, std::uint32_t id, double x, double y, double scale) {
  Outline out = font.glyph_outline(id);
  for (Contour& c : out.contours())
    for (Segment& seg : c.segments)
      for (Vec2& q : seg.p) q = Vec2{kMargin + x + scale * q.x, kMargin + y - scale * q.y};
  return out;
}

// "ABC" in black and in a translucent orange: each layer's exact area
// coverage composited in the layers' order over white, the foreground layer
// in the text's colour, C (no colour record) its own outline in it.
TEST(ColorRender, ColrLayersMatchExactCoveragePerLayer) {
  test::Gpu& gpu = test::gpu();
  for (const std::string& path : {kColrV0, kColrV1})
    for (const Color text : {Color{0, 0, 0, 1}, Color{1.0f, 0.5f, 0.0f, 0.75f}}) {
      FontCollection fonts;
      const double size = 48.0;
      const Paragraph p = Paragraph::layout(fonts, "ABC", {}, style_with({path}, size, text));
      ParagraphImageOptions options;
      options.margin_px = kMargin;
      const Image image = render_paragraph_image(gpu.renderer, gpu.cache, p, options);
      Rgb reference(image.width, image.height, 1.0);
      const GlyphRun& run = p.lines()[0].runs.at(0);
      const Font& font = *run.font;
      const double s = size / font.metrics().units_per_em;
      // Glyphs do not overlap: each is composited alone, layer by layer.
      for (const PositionedGlyph& g : run.glyphs) {
        std::vector<ColorLayer> layers = font.color_layers(g.id);
        if (layers.empty()) layers.push_back(ColorLayer{g.id, Color{0, 0, 0, 1}, true});
        for (const ColorLayer& l : layers) {
          const Color c = l.foreground ? Color{text.r, text.g, text.b, text.a * l.color.a} : l.color;
          const test::Coverage cov =
              test::union_coverage(placed(font, l.glyph_id, g.x, g.y, s), image.width, image.height);
          for (int y = 0; y < image.height; ++y)
            for (int x = 0; x < image.width; ++x) {
              const double a = c.a * cov.at(x, y);
              double* px = reference.at(x, y);
              const float rgb[3] = {c.r, c.g, c.b};
              for (int k = 0; k < 3; ++k) px[k] = rgb[k] * a + px[k] * (1.0 - a);
            }
        }
      }
      const RgbStats st = compare(from_image(image), reference);
      std::printf("%s text alpha %.2f: mean %.4f max %.3f over %zu px\n", path.c_str(), text.a, st.mean, st.max,
                  st.pixels);
      EXPECT_GT(st.pixels, 2000u);
      EXPECT_LT(st.mean, 0.01) << path;
      EXPECT_LT(st.max, 0.25) << path;
    }
}

}  // namespace
}  // namespace curvetext
