// Fonts and shaping: opening every supported flavour, variations, outlines,
// metrics, shaping with features, UTF-8 validation and error reporting.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

#include "curvetext/default_font.hpp"
#include "curvetext/error.hpp"
#include "curvetext/font.hpp"
#include "curvetext/shaping.hpp"
#include "curvetext/version.hpp"
#include "font/default_font_lookup.hpp"
#include "font/font_impl.hpp"

#include FT_MULTIPLE_MASTERS_H
#include FT_OUTLINE_H
#include FT_TRUETYPE_TABLES_H

namespace ct = curvetext;
namespace fs = std::filesystem;

namespace {

const std::string kDejaVu = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
const std::string kNoto = "/usr/share/fonts/truetype/noto/NotoSans-Regular.ttf";
const std::string kNimbus = "/usr/share/fonts/opentype/urw-base35/NimbusRoman-Regular.otf";
const std::string kInter = "/usr/share/fonts/truetype/inter-vf/Inter-roman.var.ttf";
const std::string kTestFonts = std::string(CURVETEXT_SOURCE_DIR) + "/fonts/test/";
const std::string kCff2 = kTestFonts + "CurvetextTest-CFF2.otf";
const std::string kCff2Var = kTestFonts + "CurvetextTestVar-CFF2.otf";
const std::string kTtc = kTestFonts + "CurvetextTest.ttc";

template <typename F>
ct::ErrorCode error_code_of(F&& f) {
  try {
    f();
  } catch (const ct::Error& e) {
    return e.code();
  }
  ADD_FAILURE() << "no curvetext::Error thrown";
  return ct::ErrorCode::InvalidArgument;
}

struct SegmentCounts {
  int lines = 0, conics = 0, cubics = 0;
};

SegmentCounts count_segments(const ct::Outline& outline) {
  SegmentCounts n;
  for (const auto& c : outline.contours())
    for (const auto& s : c.segments) {
      if (s.kind == ct::Segment::Kind::Line) ++n.lines;
      if (s.kind == ct::Segment::Kind::Conic) ++n.conics;
      if (s.kind == ct::Segment::Kind::Cubic) ++n.cubics;
    }
  return n;
}

// Every contour closed and continuous, every value finite.
void expect_well_formed(const ct::Outline& outline) {
  EXPECT_TRUE(outline.is_finite());
  for (const auto& c : outline.contours()) {
    ASSERT_FALSE(c.segments.empty());
    for (std::size_t i = 0; i < c.segments.size(); ++i) {
      const auto& next = c.segments[(i + 1) % c.segments.size()];
      EXPECT_EQ(c.segments[i].end(), next.start());
    }
  }
}

ct::Outline outline_of(const ct::Font& font, char32_t cp) {
  const std::uint32_t gid = font.glyph_for_codepoint(cp);
  EXPECT_NE(gid, 0u) << "no glyph for U+" << std::hex << static_cast<unsigned>(cp);
  return font.glyph_outline(gid);
}

std::string temp_file(const std::string& name, const std::string& contents) {
  const fs::path path = fs::temp_directory_path() / ("curvetext_font_test_" + name);
  std::ofstream(path, std::ios::binary) << contents;
  return path.string();
}

}  // namespace

TEST(Font, OpensTrueTypeAndReadsMetrics) {
  const ct::Font font = ct::Font::open(kDejaVu);
  EXPECT_EQ(font.family_name(), "DejaVu Sans");
  EXPECT_EQ(font.face_index(), 0);
  EXPECT_EQ(font.path(), kDejaVu);
  const FT_Face face = ct::FontAccess::impl(font).ft_face;
  EXPECT_EQ(font.glyph_count(), static_cast<unsigned>(face->num_glyphs));
  const ct::FontMetrics m = font.metrics();
  EXPECT_EQ(m.units_per_em, 2048);
  EXPECT_EQ(m.ascender, face->ascender);
  EXPECT_EQ(m.descender, face->descender);
  EXPECT_LT(m.descender, 0.0);
  EXPECT_EQ(m.ascender - m.descender + m.line_gap, face->height);
  EXPECT_EQ(font.glyph_for_codepoint(U'A'), FT_Get_Char_Index(face, 'A'));
  EXPECT_EQ(font.glyph_for_codepoint(0x10FFFD), 0u);
}

// Games pack their assets: a font opened from bytes in memory behaves as the
// same file does, the bytes may go once it is open, and its glyphs are cached
// apart from other fonts (its key differs from the file's and from other
// bytes' under the same name).
TEST(Font, OpensFromMemory) {
  std::ifstream in(kDejaVu, std::ios::binary);
  std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  ASSERT_GT(bytes.size(), 1000u);
  const ct::Font file = ct::Font::open(kDejaVu);
  const ct::Font memory = ct::Font::open_memory(bytes, "packed/DejaVuSans.ttf");
  const ct::Font again = ct::Font::open_memory(bytes, "packed/DejaVuSans.ttf");
  bytes.assign(bytes.size(), 0);  // the font keeps its own copy
  EXPECT_EQ(memory.family_name(), "DejaVu Sans");
  EXPECT_EQ(memory.path(), "packed/DejaVuSans.ttf");
  EXPECT_EQ(memory.metrics().units_per_em, file.metrics().units_per_em);
  const ct::ShapedLine a = ct::shape_line(file, "Assets");
  const ct::ShapedLine b = ct::shape_line(memory, "Assets");
  ASSERT_EQ(a.glyphs.size(), b.glyphs.size());
  for (std::size_t i = 0; i < a.glyphs.size(); ++i) {
    EXPECT_EQ(a.glyphs[i].glyph_id, b.glyphs[i].glyph_id);
    EXPECT_EQ(a.glyphs[i].x_advance, b.glyphs[i].x_advance);
  }
  EXPECT_EQ(outline_of(memory, U'g').contours().size(), outline_of(file, U'g').contours().size());
  EXPECT_NE(memory.cache_key(), file.cache_key());
  EXPECT_EQ(memory.cache_key(), again.cache_key());
  const std::vector<std::uint8_t> other = {'n', 'o', 't', ' ', 'a', ' ', 'f', 'o', 'n', 't'};
  EXPECT_EQ(error_code_of([&] { (void)ct::Font::open_memory(other, "packed/DejaVuSans.ttf"); }),
            ct::ErrorCode::FontInvalid);
  EXPECT_EQ(error_code_of([&] { (void)ct::Font::open_memory({}, "empty"); }), ct::ErrorCode::FontInvalid);
}

TEST(Font, TrueTypeOutlines) {
  const ct::Font font = ct::Font::open(kDejaVu);
  const ct::Outline h = outline_of(font, U'H');
  ASSERT_EQ(h.contours().size(), 1u);
  const SegmentCounts hn = count_segments(h);
  EXPECT_EQ(hn.lines, 12);
  EXPECT_EQ(hn.conics + hn.cubics, 0);
  expect_well_formed(h);

  const ct::Outline o = outline_of(font, U'O');
  EXPECT_EQ(o.contours().size(), 2u);
  EXPECT_GT(count_segments(o).conics, 0);
  EXPECT_FALSE(o.has_cubics());
  expect_well_formed(o);
  // A ring: outer and inner contours wind in opposite directions.
  EXPECT_GT(std::abs(o.signed_area()), 0.0);

  EXPECT_TRUE(outline_of(font, U' ').empty());
  EXPECT_EQ(error_code_of([&] { (void)font.glyph_outline(font.glyph_count()); }), ct::ErrorCode::FontInvalid);
}

// The outline loaded into a reused Outline (what the glyph cache does) is the
// outline loaded fresh, for TrueType (FreeType's path) and CFF (HarfBuzz's),
// whatever the reused one held before.
TEST(Font, GlyphOutlineIntoReusedOutline) {
  for (const std::string& path : {kDejaVu, kNimbus}) {
    const ct::Font font = ct::Font::open(path);
    ct::Outline reused;
    std::size_t contours = 0;
    for (std::uint32_t g = 0; g < std::min(font.glyph_count(), 400u); ++g) {
      const ct::Outline fresh = font.glyph_outline(g);
      font.glyph_outline(g, reused);
      ASSERT_EQ(reused.contours().size(), fresh.contours().size()) << path << " glyph " << g;
      for (std::size_t c = 0; c < fresh.contours().size(); ++c) {
        const auto& a = fresh.contours()[c].segments;
        const auto& b = reused.contours()[c].segments;
        ASSERT_EQ(a.size(), b.size()) << path << " glyph " << g;
        for (std::size_t k = 0; k < a.size(); ++k) {
          EXPECT_EQ(a[k].kind, b[k].kind);
          for (int i = 0; i < 4; ++i) EXPECT_EQ(a[k].p[i], b[k].p[i]) << path << " glyph " << g;
          EXPECT_EQ(a[k].weight, b[k].weight);
        }
      }
      contours += fresh.contours().size();
    }
    EXPECT_GT(contours, 300u) << path;  // the comparison saw real outlines
  }
}

TEST(Font, TrueTypeOutlineMatchesFreeTypeUnscaled) {
  // Our unit-scale load must reproduce FT_LOAD_NO_SCALE exactly for a static
  // TrueType font (the control box is a cheap proxy for every point).
  const ct::Font font = ct::Font::open(kDejaVu);
  for (char32_t cp : {U'H', U'O', U'g', U'&', U'\u00e9'}) {
    const std::uint32_t gid = font.glyph_for_codepoint(cp);
    const ct::Box box = font.glyph_outline(gid).control_box();
    FT_Face face = ct::FontAccess::impl(font).ft_face;
    ASSERT_EQ(FT_Load_Glyph(face, gid, FT_LOAD_NO_SCALE | FT_LOAD_NO_HINTING | FT_LOAD_NO_BITMAP), 0);
    FT_BBox ref;
    FT_Outline_Get_CBox(&face->glyph->outline, &ref);
    EXPECT_EQ(box.min.x, static_cast<double>(ref.xMin));
    EXPECT_EQ(box.min.y, static_cast<double>(ref.yMin));
    EXPECT_EQ(box.max.x, static_cast<double>(ref.xMax));
    EXPECT_EQ(box.max.y, static_cast<double>(ref.yMax));
  }
}

TEST(Font, NotoSans) {
  const ct::Font font = ct::Font::open(kNoto);
  EXPECT_EQ(font.family_name(), "Noto Sans");
  EXPECT_EQ(font.metrics().units_per_em, 1000);
  const ct::Outline o = outline_of(font, U'O');
  EXPECT_EQ(o.contours().size(), 2u);
  expect_well_formed(o);
}

TEST(Font, CffOutlinesHaveCubics) {
  const ct::Font font = ct::Font::open(kNimbus);
  EXPECT_EQ(font.metrics().units_per_em, 1000);
  const ct::Outline o = outline_of(font, U'O');
  EXPECT_EQ(o.contours().size(), 2u);
  EXPECT_TRUE(o.has_cubics());
  EXPECT_EQ(count_segments(o).conics, 0);
  expect_well_formed(o);
  EXPECT_EQ(font.metrics().ascender, ct::FontAccess::impl(font).ft_face->ascender);
  EXPECT_EQ(font.metrics().descender, ct::FontAccess::impl(font).ft_face->descender);
}

// Underline and strikeout metrics are the post and OS/2 tables' values, read
// here with a FreeType face of our own (not the Font's), at the default
// instance and, for a variable font, at another one (MVAR applied by
// FreeType on its side).
TEST(Font, DecorationMetricsMatchPostAndOs2) {
  FT_Library library = nullptr;
  ASSERT_EQ(FT_Init_FreeType(&library), 0);
  struct Case {
    std::string path;
    std::vector<ct::Variation> variations;
  };
  const std::vector<Case> cases = {
      {kDejaVu, {}}, {kNoto, {}}, {kNimbus, {}}, {kInter, {}}, {kInter, {{"wght", 900.0f}}}, {kCff2, {}}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.path + (c.variations.empty() ? "" : " wght=900"));
    ct::Font font = ct::Font::open(c.path);
    if (!c.variations.empty()) font.set_variations(c.variations);
    const ct::FontMetrics m = font.metrics();
    FT_Face face = nullptr;
    ASSERT_EQ(FT_New_Face(library, c.path.c_str(), 0, &face), 0);
    if (!c.variations.empty()) {
      FT_MM_Var* mm = nullptr;
      ASSERT_EQ(FT_Get_MM_Var(face, &mm), 0);
      std::vector<FT_Fixed> coords(mm->num_axis);
      for (FT_UInt i = 0; i < mm->num_axis; ++i)
        coords[i] = mm->axis[i].tag == FT_MAKE_TAG('w', 'g', 'h', 't') ? 900 * 65536 : mm->axis[i].def;
      FT_Done_MM_Var(library, mm);
      ASSERT_EQ(FT_Set_Var_Design_Coordinates(face, static_cast<FT_UInt>(coords.size()), coords.data()), 0);
    }
    const auto* post = static_cast<const TT_Postscript*>(FT_Get_Sfnt_Table(face, FT_SFNT_POST));
    const auto* os2 = static_cast<const TT_OS2*>(FT_Get_Sfnt_Table(face, FT_SFNT_OS2));
    ASSERT_NE(post, nullptr);
    ASSERT_NE(os2, nullptr);
    EXPECT_EQ(m.underline_position, post->underlinePosition);
    EXPECT_EQ(m.underline_thickness, post->underlineThickness);
    EXPECT_EQ(m.strikeout_position, os2->yStrikeoutPosition);
    EXPECT_EQ(m.strikeout_thickness, os2->yStrikeoutSize);
    // Below the baseline, above it, and some thickness: the tables were read
    // (the test font's post table leaves the underline at zero).
    if (c.path != kCff2) {
      EXPECT_LT(m.underline_position, 0.0);
      EXPECT_GT(m.strikeout_position, 0.0);
      EXPECT_GT(m.underline_thickness, 0.0);
    }
    FT_Done_Face(face);
  }
  FT_Done_FreeType(library);
}

TEST(Font, Cff2StaticKeepsFractionalCoordinates) {
  const ct::Font font = ct::Font::open(kCff2);
  EXPECT_EQ(font.family_name(), "Curvetext Test CFF2");
  const ct::Outline i = outline_of(font, U'I');
  const ct::Box box = i.control_box();
  EXPECT_EQ(box.min.x, 100.0);
  EXPECT_EQ(box.max.x, 180.0);
  EXPECT_EQ(box.max.y, 700.0);
  EXPECT_DOUBLE_EQ(std::abs(i.signed_area()), 80.0 * 700.0);
  // FreeType floors these to whole units; we must not.
  const ct::Box dot = outline_of(font, U'.').control_box();
  EXPECT_NEAR(dot.min.x, 100.25, 1e-4);
  EXPECT_NEAR(dot.max.x, 200.75, 1e-4);
  EXPECT_NEAR(dot.max.y, 100.75, 1e-4);
  const ct::Outline o = outline_of(font, U'O');
  EXPECT_EQ(o.contours().size(), 2u);
  EXPECT_TRUE(o.has_cubics());
  expect_well_formed(o);
  EXPECT_EQ(font.metrics().ascender, 800.0);
  EXPECT_EQ(font.metrics().descender, -200.0);
  EXPECT_EQ(font.metrics().line_gap, 90.0);
  EXPECT_EQ(error_code_of([&] {
              const_cast<ct::Font&>(font).set_variations({{"wght", 700}});
            }),
            ct::ErrorCode::FontInvalid);
}

TEST(Font, Cff2VariableAtAxisValues) {
  ct::Font font = ct::Font::open(kCff2Var);
  auto stem = [&] { return outline_of(font, U'I').control_box().max.x - 100.0; };
  EXPECT_NEAR(stem(), 41.0, 1e-3);  // default wght=100
  const std::uint64_t key_default = font.cache_key();
  font.set_variations({{"wght", 900}});
  EXPECT_NEAR(stem(), 200.0, 1e-3);
  const std::uint64_t key_900 = font.cache_key();
  font.set_variations({{"wght", 500}});
  EXPECT_NEAR(stem(), 120.5, 1e-3);  // fractional: FreeType would give 120
  EXPECT_NE(font.cache_key(), key_900);
  EXPECT_NE(key_900, key_default);
  // Clamped to the axis range.
  font.set_variations({{"wght", 5000}});
  EXPECT_NEAR(stem(), 200.0, 1e-3);
  EXPECT_EQ(font.cache_key(), key_900);
  ASSERT_EQ(font.variations().size(), 1u);
  EXPECT_EQ(font.variations()[0].value, 900.0f);
  // Back to the default instance.
  font.set_variations({});
  EXPECT_NEAR(stem(), 41.0, 1e-3);
  EXPECT_EQ(font.cache_key(), key_default);
  // Shaping follows the variation (HVAR).
  const double thin = ct::shape_line(font, "I").advance;
  font.set_variations({{"wght", 900}});
  EXPECT_DOUBLE_EQ(thin, 241.0);
  EXPECT_DOUBLE_EQ(ct::shape_line(font, "I").advance, 400.0);
}

TEST(Font, CollectionFaces) {
  EXPECT_EQ(ct::Font::face_count(kTtc), 2);
  EXPECT_EQ(ct::Font::face_count(kDejaVu), 1);
  const ct::Font a = ct::Font::open(kTtc, 0);
  const ct::Font b = ct::Font::open(kTtc, 1);
  EXPECT_EQ(a.family_name(), "Curvetext TTC A");
  EXPECT_EQ(b.family_name(), "Curvetext TTC B");
  EXPECT_NE(a.cache_key(), b.cache_key());
  EXPECT_EQ(outline_of(a, U'I').control_box().max.x, 160.0);
  EXPECT_EQ(outline_of(b, U'I').control_box().max.x, 240.0);
  const ct::Outline o = outline_of(b, U'O');
  EXPECT_EQ(o.contours().size(), 2u);
  EXPECT_FALSE(o.has_cubics());
  expect_well_formed(o);
  EXPECT_EQ(ct::shape_line(b, "I").advance, 340.0);
  EXPECT_EQ(error_code_of([&] { (void)ct::Font::open(kTtc, 2); }), ct::ErrorCode::FontInvalid);
  EXPECT_EQ(error_code_of([&] { (void)ct::Font::open(kTtc, -1); }), ct::ErrorCode::FontInvalid);
  EXPECT_EQ(error_code_of([&] { (void)ct::Font::open(kTtc, 65536); }), ct::ErrorCode::FontInvalid);
  EXPECT_EQ(error_code_of([&] { (void)ct::Font::open(kDejaVu, 1); }), ct::ErrorCode::FontInvalid);
}

TEST(Font, InterVariableWeights) {
  if (!fs::exists(kInter)) GTEST_SKIP() << kInter << " missing: install fonts-inter-variable";
  ct::Font font = ct::Font::open(kInter);
  auto h_area = [&] { return std::abs(outline_of(font, U'H').signed_area()); };
  auto h_stem = [&] {
    // The left stem of 'H' starts at the box's left edge; its inner edge is
    // the second smallest x of the outline's points.
    const ct::Outline h = outline_of(font, U'H');
    double x0 = 1e300, x1 = 1e300;
    for (const auto& c : h.contours())
      for (const auto& s : c.segments) {
        const double x = s.p[0].x;
        if (x < x0) {
          x1 = x0, x0 = x;
        } else if (x > x0 && x < x1) {
          x1 = x;
        }
      }
    return x1 - x0;
  };
  const std::uint64_t key_default = font.cache_key();
  font.set_variations(ct::parse_variations("wght=100"));
  const double thin_area = h_area(), thin_stem = h_stem();
  const std::uint64_t key_thin = font.cache_key();
  font.set_variations(ct::parse_variations("wght=900"));
  const double black_area = h_area(), black_stem = h_stem();
  EXPECT_GT(black_area, 2.0 * thin_area);
  EXPECT_GT(black_stem, 4.0 * thin_stem);
  EXPECT_NEAR(thin_stem, 64.0, 1.0);
  EXPECT_NEAR(black_stem, 556.0, 1.0);
  EXPECT_NE(font.cache_key(), key_thin);
  EXPECT_NE(key_thin, key_default);
  // Intermediate instance: the outline is unrounded (FreeType would round).
  font.set_variations({{"wght", 437}});
  const ct::Box box = outline_of(font, U'O').control_box();
  EXPECT_GT(std::abs(box.max.x - std::round(box.max.x)), 0.01);
  EXPECT_EQ(error_code_of([&] { font.set_variations({{"wdth", 80}}); }), ct::ErrorCode::FontInvalid);
}

TEST(Font, UnknownAxisOrStaticFont) {
  ct::Font font = ct::Font::open(kCff2Var);
  try {
    font.set_variations({{"wdth", 80}});
    FAIL() << "no error";
  } catch (const ct::Error& e) {
    EXPECT_EQ(e.code(), ct::ErrorCode::FontInvalid);
    EXPECT_NE(std::string(e.what()).find("wdth"), std::string::npos) << e.what();
  }
  ct::Font dejavu = ct::Font::open(kDejaVu);
  EXPECT_EQ(error_code_of([&] { dejavu.set_variations({{"wght", 700}}); }), ct::ErrorCode::FontInvalid);
  dejavu.set_variations({});  // nothing to set: fine
}

TEST(Font, ParseVariations) {
  const auto v = ct::parse_variations(" wght = 700 , wdth=85.5");
  ASSERT_EQ(v.size(), 2u);
  EXPECT_EQ(v[0].tag, "wght");
  EXPECT_EQ(v[0].value, 700.0f);
  EXPECT_EQ(v[1].tag, "wdth");
  EXPECT_EQ(v[1].value, 85.5f);
  EXPECT_TRUE(ct::parse_variations("").empty());
  for (const char* bad : {"wght", "wght=", "wght=abc", "=700", "toolong=1", "wght=700,", "wght=1e999"})
    EXPECT_EQ(error_code_of([&] { (void)ct::parse_variations(bad); }), ct::ErrorCode::InvalidArgument) << bad;
}

TEST(Font, OpenErrors) {
  try {
    (void)ct::Font::open("/nonexistent/dir/font.ttf");
    FAIL() << "no error";
  } catch (const ct::Error& e) {
    EXPECT_EQ(e.code(), ct::ErrorCode::FontNotFound);
    EXPECT_NE(std::string(e.what()).find("/nonexistent/dir/font.ttf"), std::string::npos);
  }
  EXPECT_EQ(error_code_of([] { (void)ct::Font::face_count("/nonexistent.ttf"); }), ct::ErrorCode::FontNotFound);
  EXPECT_EQ(error_code_of([] { (void)ct::Font::open(fs::temp_directory_path().string()); }),
            ct::ErrorCode::FontNotFound);

  const std::string empty = temp_file("empty.ttf", "");
  EXPECT_EQ(error_code_of([&] { (void)ct::Font::open(empty); }), ct::ErrorCode::FontInvalid);
  EXPECT_EQ(error_code_of([&] { (void)ct::Font::face_count(empty); }), ct::ErrorCode::FontInvalid);

  std::mt19937 rng(12345);
  for (int size : {1, 4, 12, 100, 4096}) {
    std::string bytes(static_cast<std::size_t>(size), '\0');
    for (char& c : bytes) c = static_cast<char>(rng() & 0xff);
    const std::string path = temp_file("random.ttf", bytes);
    EXPECT_EQ(error_code_of([&] { (void)ct::Font::open(path); }), ct::ErrorCode::FontInvalid) << size;
  }
  // A valid sfnt header followed by garbage, and a truncated real font.
  {
    std::ifstream in(kDejaVu, std::ios::binary);
    std::string head(2000, '\0');
    in.read(head.data(), static_cast<std::streamsize>(head.size()));
    const std::string path = temp_file("truncated.ttf", head);
    EXPECT_EQ(error_code_of([&] { (void)ct::Font::open(path); }), ct::ErrorCode::FontInvalid);
    fs::remove(path);
  }
  fs::remove(empty);
  fs::remove(fs::temp_directory_path() / "curvetext_font_test_random.ttf");
}

TEST(Font, MoveKeepsFontUsable) {
  ct::Font a = ct::Font::open(kDejaVu);
  ct::Font b = std::move(a);
  EXPECT_EQ(b.family_name(), "DejaVu Sans");
  a = std::move(b);
  EXPECT_EQ(count_segments(outline_of(a, U'H')).lines, 12);
}

TEST(Font, HarfBuzzFontOutlivesFont) {
  hb_font_t* hb = nullptr;
  {
    const ct::Font font = ct::Font::open(kDejaVu);
    hb = hb_font_reference(ct::FontAccess::impl(font).hb_font);
  }
  // The blob keeps the bytes alive.
  hb_codepoint_t gid = 0;
  EXPECT_TRUE(hb_font_get_nominal_glyph(hb, 'A', &gid));
  EXPECT_GT(hb_font_get_glyph_h_advance(hb, gid), 0);
  hb_font_destroy(hb);
}

TEST(Shaping, KerningChangesAdvance) {
  const ct::Font font = ct::Font::open(kDejaVu);
  ct::ShapeOptions kern, nokern;
  kern.features = ct::parse_features("kern");
  nokern.features = ct::parse_features("-kern");
  const ct::ShapedLine a = ct::shape_line(font, "AV", kern);
  const ct::ShapedLine b = ct::shape_line(font, "AV", nokern);
  ASSERT_EQ(a.glyphs.size(), 2u);
  EXPECT_LT(a.advance, b.advance);
  double sum = 0;
  for (const auto& g : b.glyphs) sum += g.x_advance;
  EXPECT_EQ(b.advance, sum);
  // Unkerned advances are the hmtx advances in font units.
  EXPECT_EQ(b.glyphs[0].x_advance,
            static_cast<double>(hb_font_get_glyph_h_advance(ct::FontAccess::impl(font).hb_font, b.glyphs[0].glyph_id)));
}

TEST(Shaping, Ligatures) {
  const ct::Font font = ct::Font::open(kDejaVu);
  ct::ShapeOptions liga, noliga;
  liga.features = ct::parse_features("liga");
  noliga.features = ct::parse_features("-liga");
  EXPECT_EQ(ct::shape_line(font, "fi", liga).glyphs.size(), 1u);
  EXPECT_EQ(ct::shape_line(font, "fi", noliga).glyphs.size(), 2u);
  EXPECT_EQ(ct::shape_line(font, "fi").glyphs.size(), 1u);  // on by default
}

TEST(Shaping, ClustersAreByteOffsets) {
  const ct::Font font = ct::Font::open(kDejaVu);
  const ct::ShapedLine line = ct::shape_line(font, "a\u00e9\u20ac\U0001D11E");
  ASSERT_EQ(line.glyphs.size(), 4u);
  const std::uint32_t expected[] = {0, 1, 3, 6};
  for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(line.glyphs[i].cluster, expected[i]) << i;
  EXPECT_TRUE(ct::shape_line(font, "").glyphs.empty());
}

TEST(Shaping, RightToLeftAndOptions) {
  const ct::Font font = ct::Font::open(kDejaVu);
  ct::ShapeOptions rtl;
  rtl.direction = "rtl";
  rtl.script = "Latn";
  rtl.language = "en";
  const ct::ShapedLine line = ct::shape_line(font, "ab", rtl);
  ASSERT_EQ(line.glyphs.size(), 2u);
  EXPECT_EQ(line.glyphs[0].cluster, 1u);  // visual order
  ct::ShapeOptions bad;
  bad.direction = "sideways";
  EXPECT_EQ(error_code_of([&] { (void)ct::shape_line(font, "a", bad); }), ct::ErrorCode::InvalidArgument);
  bad = {};
  bad.script = "L";
  EXPECT_EQ(error_code_of([&] { (void)ct::shape_line(font, "a", bad); }), ct::ErrorCode::InvalidArgument);
  bad = {};
  bad.features = {{"toolong", 1}};
  EXPECT_EQ(error_code_of([&] { (void)ct::shape_line(font, "a", bad); }), ct::ErrorCode::InvalidArgument);
}

TEST(Shaping, ParseFeatures) {
  const auto f = ct::parse_features("kern, -liga,+smcp,aalt=2");
  ASSERT_EQ(f.size(), 4u);
  EXPECT_EQ(f[0].tag, "kern");
  EXPECT_EQ(f[0].value, 1u);
  EXPECT_EQ(f[1].tag, "liga");
  EXPECT_EQ(f[1].value, 0u);
  EXPECT_EQ(f[2].tag, "smcp");
  EXPECT_EQ(f[3].value, 2u);
  EXPECT_TRUE(ct::parse_features("").empty());
  for (const char* bad : {"kern,,liga", "=2", "kern[1:2]", "kern=x", ","})
    EXPECT_EQ(error_code_of([&] { (void)ct::parse_features(bad); }), ct::ErrorCode::InvalidArgument) << bad;
}

TEST(Shaping, InvalidUtf8) {
  const ct::Font font = ct::Font::open(kDejaVu);
  const std::string cases[] = {
      std::string("\xC0\xAF"),          // overlong '/'
      std::string("\xE0\x80\xAF"),      // overlong, 3 bytes
      std::string("\xED\xA0\x80"),      // surrogate U+D800
      std::string("\xE2\x82"),          // truncated euro sign
      std::string("\xF4\x90\x80\x80"),  // U+110000
      std::string("\xF5\x80\x80\x80"),  // lead byte past U+10FFFF
      std::string("\x80"),              // stray continuation
      std::string("a\xE2\x82"
                  "b"),  // truncated in the middle
  };
  for (const std::string& text : cases) {
    EXPECT_EQ(error_code_of([&] { ct::validate_utf8(text); }), ct::ErrorCode::InvalidText);
    EXPECT_EQ(error_code_of([&] { (void)ct::shape_line(font, text); }), ct::ErrorCode::InvalidText);
  }
  try {
    ct::validate_utf8("ab\xED\xA0\x80");
    FAIL() << "no error";
  } catch (const ct::Error& e) {
    EXPECT_NE(std::string(e.what()).find("byte offset 2"), std::string::npos) << e.what();
  }
  ct::validate_utf8("a\u00e9\u20ac\U0001D11E\U0010FFFF\uFFFF");
  ct::validate_utf8(std::string("nul\0inside", 10));
}

// Found at run time: the test programs lie in build/tests/, so the lookup
// beside the program finds the build tree's copy.
TEST(DefaultFont, FoundFromTheProgramsPlace) {
  const std::string path = ct::default_font_path();
  EXPECT_TRUE(fs::is_regular_file(path)) << path;
  EXPECT_EQ(fs::path(path).filename(), "DejaVuSans.ttf");
  EXPECT_EQ(ct::Font::open(path).family_name(), "DejaVu Sans");

  const std::vector<std::string> candidates = ct::detail::default_font_candidates("");
  const fs::path beside =
      fs::path(ct::detail::library_file()).parent_path() / "../share/curvetext/fonts/DejaVuSans.ttf";
  EXPECT_NE(std::find(candidates.begin(), candidates.end(), beside.lexically_normal().string()), candidates.end());
}

TEST(DefaultFont, Fontconfig) {
  // fonts-dejavu-core is installed (scripts/setup-debian.sh).
  const std::string path = ct::detail::fontconfig_default_font();
  ASSERT_FALSE(path.empty());
  EXPECT_EQ(ct::Font::open(path).family_name(), "DejaVu Sans");
  EXPECT_EQ(ct::detail::find_default_font({"/nonexistent/DejaVuSans.ttf"}, true), path);
}

TEST(DefaultFont, MissingIsAnErrorThatSaysWhatToDo) {
  try {
    (void)ct::detail::find_default_font({"/nonexistent/a/DejaVuSans.ttf", "/nonexistent/b/DejaVuSans.ttf"}, false);
    FAIL() << "no error";
  } catch (const ct::Error& e) {
    const std::string message = e.what();
    EXPECT_EQ(e.code(), ct::ErrorCode::FontNotFound);
    for (const char* part : {"DejaVu Sans", "DejaVuSans.ttf", "/nonexistent/a/DejaVuSans.ttf",
                             "/nonexistent/b/DejaVuSans.ttf", "fonts-dejavu-core", "Font::open"})
      EXPECT_NE(message.find(part), std::string::npos) << part << " not in: " << message;
    EXPECT_EQ(message.find("--font"), std::string::npos) << "a command-line option in a library error: " << message;
  }
}

TEST(Version, MacrosAndLibraryAgree) {
  EXPECT_STREQ(ct::version(), CURVETEXT_VERSION_STRING);
  EXPECT_EQ(CURVETEXT_VERSION,
            CURVETEXT_VERSION_MAJOR * 10000 + CURVETEXT_VERSION_MINOR * 100 + CURVETEXT_VERSION_PATCH);
}
