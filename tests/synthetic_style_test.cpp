// Synthetic bold and slant (FontSynthesis, docs/markup.md): a face that lacks
// the weight or slant asked for is emboldened and sheared as fontconfig and
// Pango do; a family with a real bold or italic face keeps using it.
// Fonts: Noto Music and DejaVu Math TeX Gyre (Debian families with a Regular
// face only), the CFF2 test font (outlines from HarfBuzz, a family fontconfig
// does not know) and DejaVu Sans (a real bold and oblique).
#include <ft2build.h>
#include FT_OUTLINE_H
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "curvetext/curves.hpp"
#include "curvetext/error.hpp"
#include "curvetext/font_collection.hpp"
#include "curvetext/layout.hpp"
#include "curvetext/markup.hpp"
#include "curvetext/mesh.hpp"
#include "curvetext/shaping.hpp"
#include "curvetext/text_image.hpp"
#include "curvetext/tolerances.hpp"
#include "font/font_impl.hpp"
#include "font/harfbuzz_font.hpp"
#include "support/coverage.hpp"
#include "support/fonts.hpp"
#include "support/gpu.hpp"

namespace curvetext {
namespace {

const std::string kCff2 = std::string(CURVETEXT_SOURCE_DIR) + "/fonts/test/CurvetextTest-CFF2.otf";
const std::string kColr = std::string(CURVETEXT_SOURCE_DIR) + "/fonts/test/CurvetextColor-COLRv0.ttf";
constexpr const char* kNotoMusic = "/usr/share/fonts/truetype/noto/NotoMusic-Regular.ttf";
constexpr const char* kDejaVuMath = "/usr/share/fonts/truetype/dejavu/DejaVuMathTeXGyre.ttf";
constexpr const char* kDejaVuSansBold = "/usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf";
constexpr const char* kDejaVuSansOblique = "/usr/share/fonts/truetype/dejavu/DejaVuSans-Oblique.ttf";

const FontSynthesis kBold{tolerance::kSyntheticEmboldenEm, 0.0};
const FontSynthesis kSlant{0.0, tolerance::kSyntheticSlant};

Font open_with(const std::string& path, const FontSynthesis& synthesis) {
  Font font = Font::open(path);
  font.set_synthesis(synthesis);
  return font;
}

// Every point of every segment (control points too), in order.
std::vector<Vec2> points_of(const Outline& outline) {
  std::vector<Vec2> points;
  for (const Contour& c : outline.contours())
    for (const Segment& s : c.segments) {
      const int n = s.kind == Segment::Kind::Line ? 2 : s.kind == Segment::Kind::Conic ? 3 : 4;
      for (int i = 0; i < n; ++i) points.push_back(s.p[i]);
    }
  return points;
}

// Emboldening by s font units: the advance of every glyph with one grows by
// s, 'H' and 'I' (straight stems) keep their left side and baseline and grow
// by s to the right and at the top, and every outline gains area. Both
// outline sources: FreeType (glyf) and HarfBuzz (CFF2).
TEST(FontSynthesis, EmboldeningWidensAdvancesAndOutlines) {
  for (const std::string& path : {std::string(kDejaVuMath), kCff2}) {
    SCOPED_TRACE(path);
    const Font plain = Font::open(path);
    const Font bold = open_with(path, kBold);
    const double s = std::round(tolerance::kSyntheticEmboldenEm * plain.metrics().units_per_em);
    EXPECT_EQ(bold.synthetic_strength(), s);
    const ShapedLine a = shape_line(plain, "HIO H");
    const ShapedLine b = shape_line(bold, "HIO H");
    ASSERT_EQ(a.glyphs.size(), b.glyphs.size());
    for (std::size_t i = 0; i < a.glyphs.size(); ++i)
      EXPECT_EQ(b.glyphs[i].x_advance, a.glyphs[i].x_advance + (a.glyphs[i].x_advance != 0 ? s : 0.0)) << i;
    for (char32_t c : {U'H', U'I', U'O'}) {
      const std::uint32_t g = plain.glyph_for_codepoint(c);
      ASSERT_NE(g, 0u);
      const Outline o = plain.glyph_outline(g), e = bold.glyph_outline(g);
      EXPECT_GT(std::abs(e.signed_area()), std::abs(o.signed_area()) + 0.5 * s * o.control_box().max.y);
      if (c == U'O') continue;
      const Box ob = o.control_box(), eb = e.control_box();
      EXPECT_NEAR(eb.min.x, ob.min.x, 1e-9);
      EXPECT_NEAR(eb.min.y, ob.min.y, 1e-9);
      EXPECT_NEAR(eb.max.x, ob.max.x + s, 1e-9);
      EXPECT_NEAR(eb.max.y, ob.max.y + s, 1e-9);
      // Layout's ink boxes come from HarfBuzz's extents, which grow alike.
      hb_glyph_extents_t pe{}, be{};
      ASSERT_TRUE(hb_font_get_glyph_extents(harfbuzz_font(plain), g, &pe));
      ASSERT_TRUE(hb_font_get_glyph_extents(harfbuzz_font(bold), g, &be));
      EXPECT_EQ(be.x_bearing, pe.x_bearing);
      EXPECT_EQ(be.width, pe.width + s);
      EXPECT_EQ(be.y_bearing, pe.y_bearing + s);
      EXPECT_EQ(be.height, pe.height - s);
    }
  }
}

// FreeType's outline (26.6 at the font's unit scale) as ours, in font units.
Outline from_freetype(const FT_Outline& source) {
  struct Pen {
    Outline out;
    static Vec2 at(const FT_Vector* v) { return {static_cast<double>(v->x) / 64.0, static_cast<double>(v->y) / 64.0}; }
  } pen;
  FT_Outline_Funcs funcs{};
  funcs.move_to = [](const FT_Vector* to, void* user) {
    static_cast<Pen*>(user)->out.move_to(Pen::at(to));
    return 0;
  };
  funcs.line_to = [](const FT_Vector* to, void* user) {
    static_cast<Pen*>(user)->out.line_to(Pen::at(to));
    return 0;
  };
  funcs.conic_to = [](const FT_Vector* c, const FT_Vector* to, void* user) {
    static_cast<Pen*>(user)->out.conic_to(Pen::at(c), Pen::at(to));
    return 0;
  };
  funcs.cubic_to = [](const FT_Vector* c1, const FT_Vector* c2, const FT_Vector* to, void* user) {
    static_cast<Pen*>(user)->out.cubic_to(Pen::at(c1), Pen::at(c2), Pen::at(to));
    return 0;
  };
  EXPECT_EQ(FT_Outline_Decompose(const_cast<FT_Outline*>(&source), &funcs, &pen), 0);
  pen.out.close();
  return pen.out;
}

// Our emboldening against FreeType's FT_Outline_EmboldenXY on TrueType
// glyphs: the same algorithm, except that FreeType moves the on-curve point
// implied between two off-curve points with them (as their midpoint) where
// ours moves it as a corner of its own, and rounds to 1/64 unit. Over an
// alphabet, areas agree within 0.1% and boxes within 0.05 unit (of 1000);
// measured: 0.005% and 0.006 unit.
TEST(FontSynthesis, EmboldeningFollowsFreeType) {
  const Font plain = Font::open(kDejaVuMath);
  const Font bold = open_with(kDejaVuMath, kBold);
  const FT_Pos strength = static_cast<FT_Pos>(bold.synthetic_strength() * 64.0);
  double worst_area = 0.0, worst_box = 0.0;
  for (char32_t c : std::u32string(U"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789&@%")) {
    const std::uint32_t g = plain.glyph_for_codepoint(c);
    const FontAccess::Impl& im = FontAccess::impl(plain);
    ASSERT_EQ(FT_Load_Glyph(im.ft_face, g, FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP), 0);
    ASSERT_EQ(FT_Outline_EmboldenXY(&im.ft_face->glyph->outline, strength, strength), 0);
    const Outline reference = from_freetype(im.ft_face->glyph->outline);
    const Outline ours = bold.glyph_outline(g);
    const double area = std::abs(ours.signed_area() / reference.signed_area() - 1.0);
    const Box a = ours.control_box(), b = reference.control_box();
    const double box = std::max({std::abs(a.min.x - b.min.x), std::abs(a.min.y - b.min.y), std::abs(a.max.x - b.max.x),
                                 std::abs(a.max.y - b.max.y)});
    EXPECT_LT(area, 0.001) << "U+" << std::hex << static_cast<unsigned>(c);
    EXPECT_LE(box, 0.05) << "U+" << std::hex << static_cast<unsigned>(c);
    worst_area = std::max(worst_area, area);
    worst_box = std::max(worst_box, box);
  }
  std::printf("[synthetic] against FT_Outline_EmboldenXY: area within %.5f, boxes within %.3f units\n", worst_area,
              worst_box);
}

// Slant: every outline point's x moves by 0.2 y; a raised mark's offset
// follows the shear (x_offset += 0.2 y_offset); advances stay.
TEST(FontSynthesis, SlantShearsOutlinesAndMarkOffsets) {
  for (const std::string& path : {std::string(kDejaVuMath), kCff2}) {
    SCOPED_TRACE(path);
    const Font plain = Font::open(path);
    const Font slanted = open_with(path, kSlant);
    const std::uint32_t g = plain.glyph_for_codepoint(U'H');
    const std::vector<Vec2> a = points_of(plain.glyph_outline(g)), b = points_of(slanted.glyph_outline(g));
    ASSERT_EQ(a.size(), b.size());
    ASSERT_FALSE(a.empty());
    bool raised = false;
    for (std::size_t i = 0; i < a.size(); ++i) {
      EXPECT_EQ(b[i].y, a[i].y);
      EXPECT_NEAR(b[i].x, a[i].x + tolerance::kSyntheticSlant * a[i].y, 1e-9);
      raised = raised || a[i].y > 0;
    }
    EXPECT_TRUE(raised);
    // HarfBuzz's extents (layout's ink boxes) hold the sheared outline.
    const Box box = slanted.glyph_outline(g).control_box();
    hb_glyph_extents_t e{};
    ASSERT_TRUE(hb_font_get_glyph_extents(harfbuzz_font(slanted), g, &e));
    EXPECT_LE(e.x_bearing, box.min.x);
    EXPECT_GE(e.x_bearing + e.width, box.max.x);
    EXPECT_LT(e.x_bearing + e.width, box.max.x + 1.0);
  }
  const Font plain = Font::open(test::kDejaVuSans);
  const Font slanted = open_with(test::kDejaVuSans, kSlant);
  const ShapedLine a = shape_line(plain, "H\u0301");
  const ShapedLine b = shape_line(slanted, "H\u0301");
  ASSERT_EQ(a.glyphs.size(), 2u);
  ASSERT_EQ(b.glyphs.size(), 2u);
  ASSERT_GT(a.glyphs[1].y_offset, 0.0);
  EXPECT_EQ(b.glyphs[0].x_advance, a.glyphs[0].x_advance);
  EXPECT_DOUBLE_EQ(b.glyphs[1].x_offset, a.glyphs[1].x_offset + tolerance::kSyntheticSlant * a.glyphs[1].y_offset);
}

// Meshes are cached by Font::cache_key: a synthesised face must never share
// a plain one's entries, and equal syntheses share.
TEST(FontSynthesis, CacheKeysTellSynthesisApart) {
  const Font plain = Font::open(kNotoMusic);
  const Font bold = open_with(kNotoMusic, kBold);
  const Font slant = open_with(kNotoMusic, kSlant);
  const Font both = open_with(kNotoMusic, {tolerance::kSyntheticEmboldenEm, tolerance::kSyntheticSlant});
  EXPECT_NE(plain.cache_key(), bold.cache_key());
  EXPECT_NE(plain.cache_key(), slant.cache_key());
  EXPECT_NE(bold.cache_key(), slant.cache_key());
  EXPECT_NE(both.cache_key(), bold.cache_key());
  EXPECT_EQ(bold.cache_key(), open_with(kNotoMusic, kBold).cache_key());
  Font undone = open_with(kNotoMusic, kBold);
  undone.set_synthesis({});
  EXPECT_EQ(undone.cache_key(), plain.cache_key());
}

TEST(FontSynthesis, BadValuesAndColourFacesAreRefused) {
  Font font = Font::open(kNotoMusic);
  for (const FontSynthesis bad : {FontSynthesis{-0.01, 0.0}, FontSynthesis{0.3, 0.0}, FontSynthesis{NAN, 0.0},
                                  FontSynthesis{0.0, 1.5}, FontSynthesis{0.0, -INFINITY}}) {
    try {
      font.set_synthesis(bad);
      ADD_FAILURE() << "no error for " << bad.embolden_em << ", " << bad.slant;
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), ErrorCode::InvalidArgument) << e.what();
    }
  }
  EXPECT_EQ(font.synthesis(), FontSynthesis{});
  Font colour = Font::open(kColr);
  try {
    colour.set_synthesis(kBold);
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::FontInvalid) << e.what();
  }
}

// Every glyph of the fonts, emboldened and slanted, through build_mesh +
// check_mesh (as tests/mesh_corpus_test.cpp does for plain faces).
TEST(FontSynthesis, EveryGlyphMeshesCleanly) {
  for (const std::string& path : {std::string(kNotoMusic), std::string(kDejaVuMath), kCff2}) {
    for (const FontSynthesis& synthesis : {kBold, FontSynthesis{tolerance::kSyntheticEmboldenEm, 0.2}}) {
      const Font font = open_with(path, synthesis);
      const double tolerance = 0.25 / 64.0 * font.metrics().units_per_em;  // 1/16 px at 256 px/em
      std::size_t failures = 0, meshed = 0;
      for (std::uint32_t g = 0; g < font.glyph_count(); ++g) {
        const Outline outline = font.glyph_outline(g);
        if (outline.empty()) continue;
        ++meshed;
        try {
          const Mesh mesh = build_mesh(outline, {tolerance});
          const MeshCheck check = check_mesh(mesh, to_quadratic_outline(outline, tolerance));
          if (!check.ok() && failures++ < 5) ADD_FAILURE() << path << " glyph " << g << ": " << check.problems.front();
        } catch (const Error& e) {
          if (failures++ < 5) ADD_FAILURE() << path << " glyph " << g << " threw: " << e.what();
        }
      }
      std::printf("[synthetic] %s slant %.1f: %zu glyphs meshed, %zu failures\n", path.c_str(), synthesis.slant, meshed,
                  failures);
      EXPECT_EQ(failures, 0u);
      EXPECT_GE(meshed, 5u);
    }
  }
}

ParagraphStyle style_of(const std::string& font) {
  ParagraphStyle style;
  style.default_style.fonts = {font};
  style.default_style.size_px = 40;
  return style;
}

// The run of `p` that starts at byte `start`.
const GlyphRun& run_at(const Paragraph& p, std::size_t start) {
  for (const GlyphRun& r : p.lines().at(0).runs)
    if (r.start == start) return r;
  throw std::runtime_error("no run at " + std::to_string(start));
}

// <b> and <i> on a family with a Regular face only (by name: fontconfig has
// it) and on a font file whose family fontconfig does not know: the same
// face, synthesised, with advances wider by the strength: neither stays
// Regular nor takes another family's bold face (fontconfig's answer for a
// family it does not know).
TEST(SyntheticStyle, MarkupOnRegularOnlyFacesSynthesises) {
  FontCollection fonts;
  for (const std::string& font : {std::string("DejaVu Math TeX Gyre"), std::string(kDejaVuMath), kCff2}) {
    SCOPED_TRACE(font);
    const ParagraphStyle style = style_of(font);
    const MarkupText m = parse_markup("HI <b>HI</b> <i>HI</i> <b><i>HI</i></b>", style.default_style);
    const Paragraph p = Paragraph::layout(fonts, m.text, m.spans, style);
    const GlyphRun& plain = run_at(p, 0);
    const GlyphRun& bold = run_at(p, 3);
    const GlyphRun& italic = run_at(p, 6);
    const GlyphRun& both = run_at(p, 9);
    const std::string file = font[0] == '/' ? font : kDejaVuMath;
    for (const GlyphRun* r : {&plain, &bold, &italic, &both}) EXPECT_EQ(r->font->path(), file);
    EXPECT_EQ(plain.font->synthesis(), FontSynthesis{});
    EXPECT_EQ(bold.font->synthesis(), kBold);
    EXPECT_EQ(italic.font->synthesis(), kSlant);
    EXPECT_EQ(both.font->synthesis(), (FontSynthesis{tolerance::kSyntheticEmboldenEm, tolerance::kSyntheticSlant}));
    const double px = 40.0 / plain.font->metrics().units_per_em * bold.font->synthetic_strength();
    ASSERT_EQ(bold.glyphs.size(), 2u);
    for (std::size_t i = 0; i < 2; ++i) EXPECT_NEAR(bold.glyphs[i].advance, plain.glyphs[i].advance + px, 1e-9) << i;
    ASSERT_EQ(italic.glyphs.size(), 2u);
    for (std::size_t i = 0; i < 2; ++i) EXPECT_EQ(italic.glyphs[i].advance, plain.glyphs[i].advance) << i;
  }
}

// A family with a real bold and oblique face uses them: no synthesis.
TEST(SyntheticStyle, RealBoldAndObliqueFacesAreNotSynthesised) {
  FontCollection fonts;
  for (const std::string& font : {std::string("DejaVu Sans"), std::string(test::kDejaVuSans)}) {
    SCOPED_TRACE(font);
    const ParagraphStyle style = style_of(font);
    const MarkupText m = parse_markup("HI <b>HI</b> <i>HI</i>", style.default_style);
    const Paragraph p = Paragraph::layout(fonts, m.text, m.spans, style);
    EXPECT_EQ(run_at(p, 3).font->path(), kDejaVuSansBold);
    EXPECT_EQ(run_at(p, 3).font->synthesis(), FontSynthesis{});
    EXPECT_EQ(run_at(p, 6).font->path(), kDejaVuSansOblique);
    EXPECT_EQ(run_at(p, 6).font->synthesis(), FontSynthesis{});
  }
  // A pattern asking for bold of a family that has it: the real face.
  EXPECT_EQ(fonts.resolve("DejaVu Sans:bold")->synthesis(), FontSynthesis{});
  EXPECT_EQ(fonts.resolve("DejaVu Math TeX Gyre:bold")->synthesis(), kBold);
}

// A variable family's bold is a named instance (fontconfig gives Inter's as
// face index 7 << 16): the face at that instance's axis values, neither
// refused as an out-of-range face index nor synthesised.
TEST(SyntheticStyle, NamedInstancesOfVariableFamilies) {
  FontCollection fonts;
  const std::shared_ptr<const Font> bold = fonts.resolve("Inter:bold");
  EXPECT_EQ(bold->synthesis(), FontSynthesis{});
  bool heavy = false;
  for (const Variation& v : bold->variations()) heavy = heavy || (v.tag == "wght" && v.value == 700.0f);
  EXPECT_TRUE(heavy);
  // Asked-for axis values win over the instance's.
  const std::shared_ptr<const Font> light = fonts.resolve("Inter:bold", {{"wght", 300.0f}});
  for (const Variation& v : light->variations())
    if (v.tag == "wght") EXPECT_EQ(v.value, 300.0f);
  const ParagraphStyle style = style_of("Inter");
  const MarkupText m = parse_markup("HI <b>HI</b>", style.default_style);
  const Paragraph p = Paragraph::layout(fonts, m.text, m.spans, style);
  EXPECT_GT(run_at(p, 3).glyphs.at(0).advance, run_at(p, 0).glyphs.at(0).advance);
}

// Bold text falling back to a face whose family has no bold face covering
// the character (U+1D11E MUSICAL SYMBOL G CLEF: FreeSerif, whose Bold lacks
// it, or Noto Music, Regular only) stays bold: that face, synthesised.
TEST(SyntheticStyle, FallbackFacesAreSynthesisedToo) {
  FontCollection fonts;
  const ParagraphStyle style = style_of(test::kDejaVuSans);
  const MarkupText m = parse_markup("<b>H\U0001D11E</b> <i>H\U0001D11E</i>", style.default_style);
  const Paragraph p = Paragraph::layout(fonts, m.text, m.spans, style);
  std::size_t fallback_runs = 0;
  for (const GlyphRun& r : p.lines().at(0).runs) {
    if (r.font->path() == kDejaVuSansBold || r.font->path() == kDejaVuSansOblique || r.start == 5) continue;
    ++fallback_runs;
    SCOPED_TRACE(r.font->path());
    EXPECT_EQ(r.font->synthesis(), r.start < 5 ? kBold : kSlant);
    for (const PositionedGlyph& g : r.glyphs) EXPECT_NE(g.id, 0u);
  }
  EXPECT_EQ(fallback_runs, 2u);
}

// An emboldened and slanted glyph line drawn through the whole pipeline
// matches the exact coverage of the synthesised outlines, and holds visibly
// more ink than the plain face's. The plain face is drawn first with the
// same glyph cache: its meshes must not stand in for the synthesised ones.
TEST(SyntheticStyle, RenderedGlyphsMatchExactCoverageOfTheSynthesisedOutlines) {
  const Font plain = Font::open(kDejaVuMath);
  const Font font = open_with(kDejaVuMath, {tolerance::kSyntheticEmboldenEm, tolerance::kSyntheticSlant});
  TextImageOptions options;
  options.size_px = 32;
  options.antialiasing = AntiAliasing::Full;
  render_text_image(test::gpu().renderer, test::gpu().cache, plain,
                    layout_text_image(plain, "Hamburgefontsiv", options), options);
  const TextImageLayout layout = layout_text_image(font, "Hamburgefontsiv", options);
  const Image image = render_text_image(test::gpu().renderer, test::gpu().cache, font, layout, options);
  const test::Coverage result = test::coverage_from_black_on_white(image);
  const test::Coverage reference = test::freetype_reference(test::line_outline(font, layout.line), layout.placement,
                                                            layout.width, layout.height, 16);
  const test::CoverageStats stats = test::compare(result, reference);
  test::expect_coverage("synthetic_bold_slant_32px", result, reference, stats, 0.03, 0.03);
  // The plain outlines at the same pen positions: about 10% less ink.
  const test::Coverage plain_reference = test::freetype_reference(test::line_outline(plain, layout.line),
                                                                  layout.placement, layout.width, layout.height, 16);
  EXPECT_GT(test::compare(result, plain_reference).ink_ratio, 1.08);
}

}  // namespace
}  // namespace curvetext
