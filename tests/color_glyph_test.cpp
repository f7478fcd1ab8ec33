// Colour glyphs (color_glyph.hpp): bitmap emoji (CBDT, Debian's Noto Color
// Emoji) opened by name and reached through fallback, ZWJ and skin-tone
// sequences shaped as one glyph, drawn as textured quads against the strike's
// bitmap scaled by exact area; COLR v0 and v1 layers (fonts/test, made by
// tests/fixtures/make_color_test_fonts.py) drawn against the exact area
// coverage of each layer composited in order; COLR v1 gradients (linear,
// two-circle radial, sweep, under transforms) against the exact coverage
// times the gradient evaluated from the paint's definition at each pixel's
// centre; COLR v1 paints not supported refused by name.
#include <gtest/gtest.h>

#include <hb.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "curvetext/error.hpp"
#include "curvetext/layout.hpp"
#include "curvetext/image.hpp"
#include "curvetext/image_style.hpp"
#include "curvetext/paint.hpp"
#include "curvetext/paragraph_image.hpp"
#include "curvetext/shape_image.hpp"
#include "curvetext/shapes.hpp"
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
// base glyph's outline in the text colour): variable paints, a transform
// around a glyph, a colour line past the stops the shader holds; a cycle,
// and a graph of 255^5 paints (layer lists referring to layer lists), end
// in bounded time.
TEST(ColorFont, ColrV1VariablePaintsOuterTransformsAndCyclesAreRefusedByName) {
  const Font font = Font::open(kColrV1);
  const std::vector<std::pair<char32_t, std::string>> cases = {{'V', "variable linear gradient"},
                                                               {'T', "transform around a glyph"},
                                                               {'M', "17 stops"},
                                                               {'Y', "nested deeper"},
                                                               {'E', "16384 paints"}};
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
  const Paragraph p = Paragraph::layout(fonts, "AV", {}, style_with({kColrV1}, 32.0));
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
        if (layers.empty()) layers.push_back(ColorLayer{g.id, Color{0, 0, 0, 1}, true, std::nullopt, 0});
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

// --- COLR v1 gradients -----------------------------------------------------------

// Straight-alpha colour, and a colour line's stops at their offsets.
struct Rgba {
  double r = 0, g = 0, b = 0, a = 0;
};
Rgba mix(const Rgba& p, const Rgba& q, double t) {
  return {p.r + (q.r - p.r) * t, p.g + (q.g - p.g) * t, p.b + (q.b - p.b) * t, p.a + (q.a - p.a) * t};
}
enum class Extend { Pad, Repeat, Reflect };
struct Line {
  std::vector<std::pair<double, Rgba>> stops;  // sorted by offset, as the spec orders them
  Extend extend = Extend::Pad;
  // The colour at t: t brought into [first, last] by the extend mode, then
  // the stops interpolated (OpenType COLR, ColorLine).
  Rgba at(double t) const {
    const double first = stops.front().first, last = stops.back().first, span = last - first;
    if (extend == Extend::Pad) {
      t = std::clamp(t, first, last);
    } else {
      double u = (t - first) / span;
      if (extend == Extend::Repeat) {
        u -= std::floor(u);
      } else {
        u = std::fmod(std::abs(u), 2.0);
        if (u > 1.0) u = 2.0 - u;
      }
      t = first + u * span;
    }
    if (t <= first) return stops.front().second;
    for (std::size_t k = 1; k < stops.size(); ++k)
      if (t <= stops[k].first)
        return mix(stops[k - 1].second, stops[k].second,
                   (t - stops[k - 1].first) / (stops[k].first - stops[k - 1].first));
    return stops.back().second;
  }
};

// The test font's palette (make_color_test_fonts.py) and a text colour.
const Rgba kRed{1, 0, 0, 1}, kHalfBlue{0, 0, 1, 128 / 255.0}, kGreen{0, 160 / 255.0, 0, 1};
const Rgba kText{0.2, 0.4, 0.9, 1.0};

// The two-point conical gradient at u: the largest t whose circle
// (c0 + t (c1 - c0), r0 + t (r1 - r0)) passes through u with a radius >= 0;
// nullopt where there is none.
std::optional<double> conical_t(Vec2 u, Vec2 c0, double r0, Vec2 c1, double r1) {
  const Vec2 cd = c1 - c0, pd = u - c0;
  const double dr = r1 - r0, a = dot(cd, cd) - dr * dr, b = dot(pd, cd) + r0 * dr, c = dot(pd, pd) - r0 * r0;
  std::vector<double> roots;
  if (std::abs(a) < 1e-12) {
    if (b != 0.0) roots.push_back(c / (2.0 * b));
  } else if (b * b - a * c >= 0.0) {
    const double s = std::sqrt(b * b - a * c);
    roots = {(b + s) / a, (b - s) / a};
  }
  std::sort(roots.rbegin(), roots.rend());
  for (double t : roots)
    if (r0 + t * dr >= 0.0) return t;
  return std::nullopt;
}

// Degrees in [0, 360) from +x towards +y.
double angle_of(Vec2 d) {
  double a = std::atan2(d.y, d.x) * 180.0 / std::numbers::pi;
  return a < 0.0 ? a + 360.0 : a;
}

// The paint of each gradient glyph of the test font at u (the glyph's font
// units, y up), from the paint tables' values as the generator writes them.
Rgba colr_gradient(char glyph, Vec2 u) {
  if (glyph == 'G') {  // p0 (150, 100), p1 (550, 50), p2 (250, 500): u = p0 + t (p1 - p0) + s (p2 - p0)
    const Vec2 p0{150, 100}, d1 = Vec2{550, 50} - p0, d2 = Vec2{250, 500} - p0;
    const double t = cross(u - p0, d2) / cross(d1, d2);
    const Rgba text_half{kText.r, kText.g, kText.b, 0.5 * kText.a};
    return Line{{{0.0, kRed}, {0.25, text_half}, {0.75, kGreen}}, Extend::Reflect}.at(t);
  }
  if (glyph == 'R' || glyph == 'Q') {
    const bool cone = glyph == 'R';
    const std::optional<double> t =
        cone ? conical_t(u, {250, 300}, 50, {550, 300}, 150) : conical_t(u, {400, 300}, 40, {430, 320}, 200);
    if (!t) return Rgba{};
    if (cone) return Line{{{0.0, kRed}, {1.0, kGreen}}, Extend::Pad}.at(*t);
    return Line{{{-0.25, kRed}, {0.5, kHalfBlue}, {1.25, kGreen}}, Extend::Repeat}.at(*t);
  }
  if (glyph == 'W') {
    const double t = (angle_of(u - Vec2{400, 300}) - 45.0) / (270.0 - 45.0);
    return Line{{{0.0, kRed}, {0.5, kText}, {1.0, kGreen}}, Extend::Pad}.at(t);
  }
  if (glyph == 'K') {
    // Undo PaintTranslate (20, -10), PaintScaleAroundCenter (1.25, 0.75
    // about (400, 300)), PaintSkew (x 15, y -10 degrees: x' = x + tan(-15) y,
    // y' = tan(-10) x + y) and PaintScaleUniform (0.9), outermost first.
    Vec2 v = u - Vec2{20, -10};
    v = Vec2{(v.x - 400) / 1.25 + 400, (v.y - 300) / 0.75 + 300};
    const double kx = std::tan(-15.0 * std::numbers::pi / 180), ky = std::tan(-10.0 * std::numbers::pi / 180);
    const double kd = 1.0 - kx * ky;
    v = Vec2{(v.x - kx * v.y) / kd, (-ky * v.x + v.y) / kd} / 0.9;
    const Vec2 p0{250, 300}, d1 = Vec2{550, 300} - p0, d2 = Vec2{250, 500} - p0;
    return Line{{{0.0, kRed}, {0.5, kGreen}, {1.0, kHalfBlue}}, Extend::Pad}.at(cross(v - p0, d2) / cross(d1, d2));
  }
  // 'X': the sweep's space reaches the glyph through PaintTransform after
  // PaintRotateAroundCenter(45 degrees about (400, 300)); undo both.
  const double xx = 0.9, yx = 0.2, xy = -0.1, yy = 1.1, dx = 30, dy = -20, det = xx * yy - xy * yx;
  const Vec2 v{u.x - dx, u.y - dy};
  const Vec2 w{(yy * v.x - xy * v.y) / det, (-yx * v.x + xx * v.y) / det};
  const double c = std::cos(-std::numbers::pi / 4), s = std::sin(-std::numbers::pi / 4);
  const Vec2 r = w - Vec2{400, 300};
  const Vec2 g{c * r.x - s * r.y, s * r.x + c * r.y};
  return Line{{{0.0, kRed}, {1.0, kHalfBlue}}, Extend::Reflect}.at(angle_of(g) / 90.0);
}

// Where the paint jumps within a pixel (a hard stop, a repeat's seam, the
// sweep's seam, the cone's edge; or turns, at a reflection) the value at the
// pixel's centre is ill-conditioned: such pixels are counted apart. Found by
// the second difference over half a pixel either side, which is near 0
// where the paint is smooth however steep.
template <class F>
bool jumps(F&& paint, Vec2 u, double half_pixel) {
  const Rgba c = paint(u);
  for (Vec2 d : {Vec2{half_pixel, 0}, Vec2{0, half_pixel}}) {
    const Rgba e = paint(u + d), f = paint(u - d);
    auto second = [&](double pe, double pf, double pc) { return std::abs(pe + pf - 2.0 * pc); };
    if (second(e.r * e.a, f.r * f.a, c.r * c.a) + second(e.g * e.a, f.g * f.a, c.g * c.a) +
            second(e.b * e.a, f.b * f.a, c.b * c.a) + second(e.a, f.a, c.a) >
        0.05)
      return true;
  }
  return false;
}

// "GRQWXK": each glyph's layer is its outline's exact area coverage times
// the gradient at the pixel's centre (stops interpolated in straight
// alpha), over white. Pixels where the paint jumps within the pixel are
// left out of the largest difference, not of the mean (at most kJumpShare
// of the ink); so are msaa's edge pixels (it samples coverage, its edges are
// the coverage tests' business). Measured (llvmpipe, 64 px): mean 0.0015 /
// 0.0015 / 0.0065 and max 0.0065 / 0.0038 / 0.0038 (full / vbaa / msaa);
// turned 25 degrees and skewed 12, full: mean 0.0015, max 0.0065.
constexpr double kGradientMeanLimit = 0.004;
constexpr double kGradientMsaaMeanLimit = 0.01;
constexpr double kGradientMaxLimit = 0.015;
constexpr double kJumpShare = 0.1;  // measured 0.066: Q's rings, X's and G's reflections
// The reference of "GRQWXK" drawn with its glyphs at `run`'s positions and
// the image's pixels mapped by `frame` (untransformed -> final, affine), and
// where the paint jumps.
struct GradientReference {
  Rgb image;
  std::vector<char> jump;
  std::vector<char> edge;  // partly covered by the glyph
};
GradientReference gradient_reference(const GlyphRun& run, double s, const Transform& frame, int width, int height) {
  const std::size_t n = static_cast<std::size_t>(width) * height;
  GradientReference ref{Rgb(width, height, 1.0), std::vector<char>(n, 0), std::vector<char>(n, 0)};
  const auto& m = frame.m;
  const double det = m[0] * m[4] - m[1] * m[3];
  const double stretch = std::sqrt(std::abs(det));  // enough for a half pixel's reach in font units
  const char* names = "GRQWXK";
  for (std::size_t k = 0; k < run.glyphs.size(); ++k) {
    const PositionedGlyph& g = run.glyphs[k];
    const std::vector<ColorLayer> layers = run.font->color_layers(g.id);
    EXPECT_EQ(layers.size(), 1u);
    EXPECT_TRUE(layers[0].gradient.has_value()) << names[k];
    Outline outline = placed(*run.font, layers[0].glyph_id, g.x, g.y, s);
    for (Contour& c : outline.contours())
      for (Segment& seg : c.segments)
        for (Vec2& q : seg.p) q = frame.apply(q);  // affine: conics stay exact
    const test::Coverage cov = test::union_coverage(outline, width, height);
    auto paint = [&](Vec2 u) { return colr_gradient(names[k], u); };
    for (int y = 0; y < height; ++y)
      for (int x = 0; x < width; ++x) {
        if (cov.at(x, y) <= 0.0f) continue;
        if (cov.at(x, y) < 1.0f) ref.edge[static_cast<std::size_t>(y) * width + x] = 1;
        // The pixel's centre in the untransformed image, then in font units.
        const double px = x + 0.5 - m[2], py = y + 0.5 - m[5];
        const Vec2 q{(m[4] * px - m[1] * py) / det, (-m[3] * px + m[0] * py) / det};
        const Vec2 u{(q.x - kMargin - g.x) / s, -(q.y - kMargin - g.y) / s};
        const Rgba c = paint(u);
        if (jumps(paint, u, 0.5 / (s * stretch))) ref.jump[static_cast<std::size_t>(y) * width + x] = 1;
        const double a = c.a * cov.at(x, y);
        double* out = ref.image.at(x, y);
        const double rgb[3] = {c.r, c.g, c.b};
        for (int i = 0; i < 3; ++i) out[i] = rgb[i] * a + out[i] * (1.0 - a);
      }
  }
  return ref;
}

TEST(ColorRender, ColrV1GradientsMatchCoverageTimesThePaint) {
  test::Gpu& gpu = test::gpu();
  const double size = 64.0;
  const Color text{static_cast<float>(kText.r), static_cast<float>(kText.g), static_cast<float>(kText.b), 1.0f};
  FontCollection fonts;
  const Paragraph p = Paragraph::layout(fonts, "GRQWXK", {}, style_with({kColrV1}, size, text));
  const GlyphRun& run = p.lines()[0].runs.at(0);
  ASSERT_EQ(run.glyphs.size(), 6u);
  const double s = size / run.font->metrics().units_per_em;
  // Upright in every offscreen mode, and turned and skewed (the gradient
  // follows the placement's transform as the outline does) in full.
  struct Setup {
    const char* name;
    Transform transform;
    AntiAliasing aa;
  };
  const Transform turned = Transform::rotation(25.0) * Transform::skew(12.0, 0.0);
  for (const Setup& setup :
       {Setup{"full", Transform{}, AntiAliasing::Full}, Setup{"vbaa", Transform{}, AntiAliasing::Vbaa},
        Setup{"msaa", Transform{}, AntiAliasing::Msaa}, Setup{"full, turned and skewed", turned, AntiAliasing::Full}}) {
    ParagraphImageOptions options;
    options.margin_px = kMargin;
    const ImageSize upright = paragraph_image_size(p, options);
    options.antialiasing = setup.aa;
    options.transform = setup.transform;
    const ImageFrame frame = transform_frame(upright.width, upright.height, setup.transform);
    const GradientReference ref = gradient_reference(run, s, frame.transform, frame.width, frame.height);
    const Image image = render_paragraph_image(gpu.renderer, gpu.cache, p, options);
    ASSERT_EQ(image.width, frame.width);
    const Rgb result = from_image(image);
    double sum = 0.0, worst = 0.0;
    std::size_t ink = 0, jumped = 0;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) {
        const double *a = result.at(x, y), *b = ref.image.at(x, y);
        double e = 0.0;
        for (int i = 0; i < 3; ++i) e = std::max(e, std::abs(a[i] - b[i]));
        const bool is_ink = b[0] < 1.0 - 1e-9 || b[1] < 1.0 - 1e-9 || b[2] < 1.0 - 1e-9 || e > 1e-9;
        if (!is_ink) continue;
        ++ink;
        sum += e;
        const std::size_t i = static_cast<std::size_t>(y) * image.width + x;
        if (ref.jump[i]) {
          ++jumped;
          continue;
        }
        if (setup.aa == AntiAliasing::Msaa && ref.edge[i]) continue;  // msaa samples coverage
        worst = std::max(worst, e);
      }
    const double mean = sum / static_cast<double>(std::max<std::size_t>(ink, 1));
    std::printf("COLR v1 gradients, %s: mean %.4f max %.4f over %zu px (%zu where the paint jumps)\n", setup.name, mean,
                worst, ink, jumped);
    const bool msaa = setup.aa == AntiAliasing::Msaa;
    const double mean_limit = msaa ? kGradientMsaaMeanLimit : kGradientMeanLimit;
    const double max_limit = kGradientMaxLimit;
    if (mean >= mean_limit || worst >= max_limit)
      write_png(image, std::string(CURVETEXT_TEST_OUTPUT_DIR) + "/colr-gradients-aa" +
                           std::to_string(static_cast<int>(setup.aa)) +
                           (setup.transform.is_identity() ? "" : "-turned") + ".png");
    EXPECT_GT(ink, 5000u) << setup.name;
    EXPECT_LT(mean, mean_limit) << setup.name;
    EXPECT_LT(worst, max_limit) << setup.name;
    EXPECT_LT(static_cast<double>(jumped), kJumpShare * static_cast<double>(ink)) << setup.name;
  }
}

// BlockColors::FromOptions draws every COLR layer in the options' colour,
// gradient layers too (a shadow of the glyphs): blue over white leaves the
// blue channel white and red equal to green. The styles (the control) draw
// the gradients.
TEST(ColorRender, ColrV1GradientLayersTakeTheOptionsColourWhenAsked) {
  test::Gpu& gpu = test::gpu();
  FontCollection fonts;
  const Paragraph p = Paragraph::layout(fonts, "GRQWXK", {}, style_with({kColrV1}, 32.0));
  const TextBlock block = TextBlock::from_paragraph(gpu.cache, p);
  for (BlockColors colors : {BlockColors::FromOptions, BlockColors::Styles}) {
    gpu.target.begin(240, 60, Color{1, 1, 1, 1});
    block.draw(gpu.renderer, Placement(1.0, 10.0, 10.0), DrawOptions(Color{0, 0, 1, 1}), colors);
    const Image image = gpu.target.read_pixels();
    int ink = 0, not_blue = 0;
    for (int y = 0; y < image.height; ++y)
      for (int x = 0; x < image.width; ++x) {
        const std::uint8_t* px = image.pixel(x, y);
        ink += px[0] < 200;
        not_blue += px[2] != 255 || std::abs(px[0] - px[1]) > 1;
      }
    EXPECT_GT(ink, 1000);
    if (colors == BlockColors::FromOptions)
      EXPECT_EQ(not_blue, 0) << "pixels in another colour than the options' blue";
    else
      EXPECT_GT(not_blue, 1000) << "the gradients were not drawn";
  }
}

// The single-pass modes have no per-pixel paint: a block of gradient glyphs
// drawn with curves or none draws its gradient layers with full (the same
// pixels as full there), rather than refusing the text.
TEST(ColorRender, ColrV1GradientLayersDrawWithFullInSinglePassModes) {
  test::Gpu& gpu = test::gpu();
  FontCollection fonts;
  const Paragraph p = Paragraph::layout(fonts, "GR", {}, style_with({kColrV1}, 32.0));
  const TextBlock block = TextBlock::from_paragraph(gpu.cache, p);
  const auto draw = [&](AntiAliasing aa) {
    gpu.target.begin(100, 60, Color{1, 1, 1, 1});
    block.draw(gpu.renderer, Placement(1.0, 10.0, 10.0), DrawOptions(Color{0, 0, 0, 1}, aa));
    return gpu.target.read_pixels();
  };
  const Image full = draw(AntiAliasing::Full);
  for (AntiAliasing aa : {AntiAliasing::Curves, AntiAliasing::None}) {
    Image image;
    ASSERT_NO_THROW(image = draw(aa));
    EXPECT_EQ(image.rgba, full.rgba);
  }
}

// The shader's evaluation of the kinds COLR added, on a rectangle's inner
// pixels (an SVG rectangle, its paint replaced; y down): a two-circle gradient whose
// first circle is not inside the second (the cone, transparent outside it),
// one with r0 > 0 inside, and a sweep; against the same definitions in
// double precision. Pixels where the paint jumps are left out.
TEST(ColorRender, ShaderEvaluatesTwoCircleAndSweepGradients) {
  ShapeDocument doc = parse_svg(
      "<svg width='90' height='70' viewBox='0 0 90 70'><rect x='5' y='5' width='80' height='60' fill='red'/></svg>");
  ASSERT_EQ(doc.shapes.size(), 1u);
  auto stops = [](Extend e) {
    Line l{{{0.0, {1, 0.8, 0, 1}}, {0.4, {0, 0.3, 1, 0.6}}, {1.0, {0.1, 0.7, 0.2, 1}}}, e};
    return l;
  };
  auto to_gradient = [](const Line& l, Gradient g) {
    g.from_outline = Transform::scale(1.0, -1.0);  // a document's y-up units to the SVG's y-down pixels
    for (const auto& [o, c] : l.stops)
      g.stops.push_back(GradientStop{static_cast<float>(o), Color{static_cast<float>(c.r), static_cast<float>(c.g),
                                                                  static_cast<float>(c.b), static_cast<float>(c.a)}});
    g.spread = l.extend == Extend::Pad      ? Gradient::Spread::Pad
               : l.extend == Extend::Repeat ? Gradient::Spread::Repeat
                                            : Gradient::Spread::Reflect;
    return g;
  };
  struct Case {
    const char* name;
    Gradient gradient;
    std::function<Rgba(Vec2)> paint;
  };
  std::vector<Case> cases;
  {
    Gradient g;
    g.kind = Gradient::Kind::Radial;
    g.focus = {20, 30};
    g.focal_radius = 6;
    g.centre = {60, 40};
    g.radius = 18;
    const Line l = stops(Extend::Pad);
    cases.push_back({"cone", to_gradient(l, g), [l](Vec2 u) {
                       const std::optional<double> t = conical_t(u, {20, 30}, 6, {60, 40}, 18);
                       return t ? l.at(*t) : Rgba{};
                     }});
    g.focus = {40, 33};
    g.focal_radius = 9;
    g.centre = {46, 36};
    g.radius = 25;
    const Line r = stops(Extend::Reflect);
    cases.push_back({"two circles, reflect", to_gradient(r, g), [r](Vec2 u) {
                       const std::optional<double> t = conical_t(u, {40, 33}, 9, {46, 36}, 25);
                       return t ? r.at(*t) : Rgba{};
                     }});
  }
  {
    Gradient g;
    g.kind = Gradient::Kind::Sweep;
    g.centre = {47, 31};
    g.start_angle = -30;
    g.end_angle = 200;
    const Line l = stops(Extend::Repeat);
    cases.push_back({"sweep, repeat", to_gradient(l, g), [l](Vec2 u) {
                       return l.at((angle_of(u - Vec2{47, 31}) + 30) / 230);
                     }});
  }
  ShapeImageOptions options;
  const ShapeImageLayout layout = layout_shape_image(doc, options);
  for (const Case& c : cases) {
    doc.shapes[0].gradient = c.gradient;
    const Image image = render_shape_image(test::gpu().renderer, doc, layout, options);
    double worst = 0.0;
    int checked = 0, jumped = 0;
    for (int y = 6; y < 64; ++y)
      for (int x = 6; x < 84; ++x) {
        const Vec2 u{x + 0.5, y + 0.5};  // document units are pixels, y down
        if (jumps(c.paint, u, 0.5)) {
          ++jumped;
          continue;
        }
        const Rgba p = c.paint(u);
        const double want[3] = {p.r * p.a + (1 - p.a), p.g * p.a + (1 - p.a), p.b * p.a + (1 - p.a)};
        for (int k = 0; k < 3; ++k) worst = std::max(worst, std::abs(image.pixel(x, y)[k] / 255.0 - want[k]));
        ++checked;
      }
    std::printf("%s: %d pixels, largest difference %.4f (%d where the paint jumps)\n", c.name, checked, worst, jumped);
    if (worst > 2.5 / 255)
      write_png(image, std::string(CURVETEXT_TEST_OUTPUT_DIR) + "/gradient-kind-" + std::to_string(&c - cases.data()) +
                           ".png");
    EXPECT_GT(checked, 4000) << c.name;
    EXPECT_LE(worst, 2.5 / 255) << c.name;  // 8-bit rounding of the target, float32 evaluation
  }
  // What validate_gradient refuses of the new kinds, by name.
  Gradient same;
  same.kind = Gradient::Kind::Radial;
  same.stops = {GradientStop{0.0f, Color{1, 0, 0, 1}}};
  same.focus = same.centre = {3, 4};
  same.focal_radius = same.radius = 2;
  Gradient flat;
  flat.kind = Gradient::Kind::Sweep;
  flat.stops = same.stops;
  flat.start_angle = flat.end_angle = 40;
  for (const auto& [g, words] : std::vector<std::pair<Gradient, std::string>>{{same, "circles are the same"},
                                                                              {flat, "start_angle != end_angle"}}) {
    try {
      validate_gradient(g);
      ADD_FAILURE() << words;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace curvetext
