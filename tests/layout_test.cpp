// Paragraph layout: bidi order, complex scripts, fallback, line breaking,
// ellipsis, tabs, justification, hit testing, errors. Fonts from Debian's
// fonts-dejavu-core, fonts-noto-core and fonts-noto-cjk.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include <hb.h>

#include <cstdio>

#include "curvetext/error.hpp"
#include "font/harfbuzz_font.hpp"
#include "curvetext/layout.hpp"
#include "curvetext/line_break.hpp"
#include "curvetext/tolerances.hpp"
#include "font/utf8.hpp"
#include "support/fonts.hpp"
#include "support/layout_support.hpp"

namespace curvetext {
namespace {

ParagraphStyle style_with(std::vector<std::string> fonts, double size, double width = 0) {
  ParagraphStyle s;
  s.default_style.fonts = std::move(fonts);
  s.default_style.size_px = size;
  s.width = width;
  return s;
}

// Code point index of every byte offset.
std::vector<std::size_t> cp_index_of_bytes(const std::string& text) {
  std::vector<std::size_t> idx(text.size() + 1, 0);
  std::size_t cp = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if ((static_cast<unsigned char>(text[i]) & 0xC0) != 0x80 && i > 0) ++cp;
    idx[i] = cp;
  }
  idx[text.size()] = cp + 1;
  return idx;
}

// Glyph clusters of a line, left to right, deduplicated.
std::vector<std::size_t> visual_clusters(const LayoutLine& line) {
  std::vector<std::size_t> out;
  for (const GlyphRun& r : line.runs)
    for (const PositionedGlyph& g : r.glyphs)
      if (out.empty() || out.back() != g.cluster) out.push_back(g.cluster);
  return out;
}

void expect_increasing_x(const LayoutLine& line) {
  double last = -1e9;
  for (const GlyphRun& r : line.runs) {
    double pen = r.x;
    for (const PositionedGlyph& g : r.glyphs) {
      EXPECT_GE(pen, last - 1e-9);
      last = pen;
      pen += g.advance;
    }
  }
}

TEST(Layout, MixedDirectionLtrParagraph) {
  FontCollection fonts;
  // "abc <Hebrew shalom> 123 def": after Hebrew the digits become Arabic-
  // numeral-like (W2) and the space between joins the RTL side (N1), so the
  // RTL stretch is "shalom 123", shown with the digits on its left, still
  // reading left to right (level 2).
  const std::string text = "abc \u05E9\u05DC\u05D5\u05DD 123 def";
  const Paragraph p = Paragraph::layout(fonts, text, {}, style_with({test::kNotoSans, test::kNotoHebrew}, 20));
  ASSERT_EQ(p.lines().size(), 1u);
  const LayoutLine& line = p.lines()[0];
  expect_increasing_x(line);
  const std::vector<std::size_t> want = {0, 1, 2, 3, 13, 14, 15, 12, 10, 8, 6, 4, 16, 17, 18, 19};
  EXPECT_EQ(visual_clusters(line), want);
  bool saw_rtl = false;
  for (const GlyphRun& r : line.runs)
    if (r.rtl) {
      saw_rtl = true;
      EXPECT_NE(r.font->path().find("Hebrew"), std::string::npos);  // explicit fallback list
    }
  EXPECT_TRUE(saw_rtl);
}

TEST(Layout, MixedDirectionRtlParagraphArabic) {
  FontCollection fonts;
  // Arabic paragraph with an English word and a number: the paragraph is RTL
  // (auto direction), Latin and digits read left to right inside it.
  const std::string text = "\u0645\u0631\u062D\u0628\u0627 abc 42";
  ParagraphStyle s = style_with({test::kNotoArabic, test::kNotoSans}, 24, 400);
  const Paragraph p = Paragraph::layout(fonts, text, {}, s);
  ASSERT_EQ(p.lines().size(), 1u);
  const LayoutLine& line = p.lines()[0];
  EXPECT_EQ(line.paragraph_level, 1);
  expect_increasing_x(line);
  // Start alignment of an RTL paragraph is the right edge.
  EXPECT_NEAR(line.x + line.width, 400.0, 1e-6);
  // Visually from the left: "abc 42" (the digits follow the Latin, W7), a
  // space, then the Arabic word (its clusters decreasing).
  const std::vector<std::size_t> v = visual_clusters(line);
  ASSERT_GE(v.size(), 8u);
  const std::vector<std::size_t> head(v.begin(), v.begin() + 6);
  EXPECT_EQ(head, (std::vector<std::size_t>{11, 12, 13, 14, 15, 16}));
  const std::vector<std::size_t> tail(v.end() - 3, v.end());
  EXPECT_GT(tail[0], tail[1]);
  EXPECT_GT(tail[1], tail[2]);
  EXPECT_EQ(v.back(), 0u);  // the first Arabic letter is rightmost
}

TEST(Layout, DevanagariShapesConjuncts) {
  FontCollection fonts;
  const std::string text =
      "\u0928\u092E\u0938\u094D\u0924\u0947 \u0926\u0941\u0928\u093F\u092F\u093E";  // namaste duniya
  const Paragraph p = Paragraph::layout(fonts, text, {}, style_with({test::kNotoDevanagari}, 24));
  ASSERT_EQ(p.lines().size(), 1u);
  std::size_t glyphs = 0;
  for (const GlyphRun& r : p.lines()[0].runs)
    for (const PositionedGlyph& g : r.glyphs) {
      EXPECT_NE(g.id, 0u);
      ++glyphs;
    }
  // 12 code points; the conjunct "st" and the reordered i-matra make fewer glyphs.
  EXPECT_LT(glyphs, 12u);
  // The i-matra (U+093F, byte 28) is reordered before its consonant NA (byte
  // 25): HarfBuzz merges them into NA's cluster, so no glyph has cluster 28.
  const std::vector<std::size_t> v = visual_clusters(p.lines()[0]);
  EXPECT_NE(std::find(v.begin(), v.end(), 25u), v.end());
  EXPECT_EQ(std::find(v.begin(), v.end(), 28u), v.end());
}

TEST(Layout, ThaiWrapsWithinWidth) {
  FontCollection fonts;
  // Thai has no spaces between words: UAX #14 resolves its class SA to AL
  // and leaves the word breaks to a dictionary (libthai's, as in Pango).
  // "ภาษา|ไทย|เป็น|ภาษา|ที่|สวย|งาม มาก": lines start at word boundaries only.
  const std::string text =
      "\u0E20\u0E32\u0E29\u0E32\u0E44\u0E17\u0E22\u0E40\u0E1B\u0E47\u0E19\u0E20\u0E32\u0E29\u0E32\u0E17\u0E35\u0E48"
      "\u0E2A\u0E27\u0E22\u0E07\u0E32\u0E21 \u0E21\u0E32\u0E01";
  const Paragraph p = Paragraph::layout(fonts, text, {}, style_with({test::kNotoThai}, 20, 100));
  ASSERT_GE(p.lines().size(), 2u);
  for (const LayoutLine& l : p.lines()) {
    EXPECT_LE(l.width, 100.0 + 1e-6);
    for (const GlyphRun& r : l.runs)
      for (const PositionedGlyph& g : r.glyphs) EXPECT_NE(g.id, 0u);
  }
  // No line starts with a combining vowel or tone mark, and each starts a
  // word (code point indices of the word starts above).
  const auto starts = grapheme_starts(detail::decode_utf8(text));
  const auto idx = cp_index_of_bytes(text);
  const std::set<std::size_t> words = {0, 4, 7, 11, 15, 18, 21, 25};
  for (const LayoutLine& l : p.lines()) {
    EXPECT_TRUE(starts[idx[l.start]]) << l.start;
    EXPECT_TRUE(words.count(idx[l.start])) << "line starts inside a word at code point " << idx[l.start];
  }
  // Narrow enough that the run without spaces must break inside it.
  EXPECT_GE(p.lines().size(), 3u);
}

TEST(Layout, CjkFallbackThroughFontconfigAndBreaksBetweenIdeographs) {
  FontCollection fonts;
  const std::string text =
      "Kanji: \u6F22\u5B57\u306F\u4E2D\u56FD\u304B\u3089\u6765\u305F\u6587\u5B57\u3067\u3059\u3002";
  const Paragraph p = Paragraph::layout(fonts, text, {}, style_with({test::kDejaVuSans}, 20, 120));
  ASSERT_GE(p.lines().size(), 2u);
  bool cjk = false;
  for (const LayoutLine& l : p.lines()) {
    EXPECT_LE(l.width, 120.0 + 1e-6);
    for (const GlyphRun& r : l.runs) {
      if (r.font->path().find("CJK") != std::string::npos) cjk = true;
      for (const PositionedGlyph& g : r.glyphs) EXPECT_NE(g.id, 0u);
    }
  }
  EXPECT_TRUE(cjk) << "ideographs should fall back to Noto Sans CJK";
  // U+3002 (ideographic full stop, class CL) never starts a line.
  EXPECT_NE(p.lines().back().start, text.size() - 3);
  // One fontconfig query serves every ideograph.
  EXPECT_LE(fonts.stats().fontconfig_queries, 3u);
}

// Emoji: the colour bitmap face (CBDT, Noto Color Emoji) draws them, as in
// Pango: U+1F600 (emoji presentation) from it although DejaVu Sans has an
// outline for it, and U+1F680 ROCKET, which only it has (it was the first
// font's missing glyph); the spaces stay with the text face. Positions are
// checked against HarfBuzz's advances of the faces chosen, glyph by glyph.
TEST(Layout, EmojiFallBackToTheColourFace) {
  const char* kColorEmoji = "/usr/share/fonts/truetype/noto/NotoColorEmoji.ttf";
  FILE* probe = std::fopen(kColorEmoji, "rb");
  if (!probe) GTEST_SKIP() << "fonts-noto-color-emoji is not installed (scripts/setup-debian.sh installs it)";
  std::fclose(probe);
  FontCollection fonts;
  const double size = 20.0;
  const std::string text = "Go \U0001F600 \U0001F680!";  // bytes: G0 o1 sp2 smile3-6 sp7 rocket8-11 !12
  const Paragraph p = Paragraph::layout(fonts, text, {}, style_with({test::kNotoSans}, size));
  ASSERT_EQ(p.lines().size(), 1u);
  const LayoutLine& line = p.lines()[0];
  const Font emoji = Font::open(kColorEmoji);
  const Font noto = Font::open(test::kNotoSans);
  ASSERT_EQ(noto.glyph_for_codepoint(0x1F600), 0u) << "the test needs a first font without the emoji";
  // Glyphs left to right with their face.
  struct Seen {
    std::uint32_t id, cluster;
    double x, advance;
    std::string path;
  };
  std::vector<Seen> seen;
  for (const GlyphRun& r : line.runs)
    for (const PositionedGlyph& g : r.glyphs) seen.push_back({g.id, g.cluster, g.x, g.advance, r.font->path()});
  ASSERT_EQ(seen.size(), 7u);
  const std::vector<std::uint32_t> clusters = {0, 1, 2, 3, 7, 8, 12};
  for (std::size_t k = 0; k < seen.size(); ++k) EXPECT_EQ(seen[k].cluster, clusters[k]) << k;
  const double ev = size / emoji.metrics().units_per_em;
  for (std::size_t k : {3u, 5u}) {
    EXPECT_EQ(seen[k].path, kColorEmoji) << k;
    EXPECT_EQ(seen[k].id, emoji.glyph_for_codepoint(k == 3 ? 0x1F600 : 0x1F680)) << k;
    EXPECT_NEAR(seen[k].advance, hb_font_get_glyph_h_advance(harfbuzz_font(emoji), seen[k].id) * ev, 1e-9);
  }
  for (std::size_t k : {0u, 1u, 2u, 4u, 6u}) EXPECT_EQ(seen[k].path, test::kNotoSans) << k;
  // Pen positions: each glyph starts where the previous one's advance ends.
  for (std::size_t k = 1; k < seen.size(); ++k) EXPECT_NEAR(seen[k].x, seen[k - 1].x + seen[k - 1].advance, 1e-9) << k;
  EXPECT_NEAR(seen[0].x, 0.0, 1e-9);
}

TEST(Layout, GeometryContractLineAdvance) {
  FontCollection fonts;
  const Paragraph p = Paragraph::layout(fonts, "one\ntwo\n\nfour", {}, style_with({test::kDejaVuSans}, 32));
  ASSERT_EQ(p.lines().size(), 4u);
  const Font f = Font::open(test::kDejaVuSans);
  const FontMetrics m = f.metrics();
  const double s = 32.0 / m.units_per_em;
  EXPECT_NEAR(p.lines()[0].baseline, m.ascender * s, 1e-9);
  for (std::size_t k = 1; k < 4; ++k)
    EXPECT_NEAR(p.lines()[k].baseline - p.lines()[k - 1].baseline, (m.ascender - m.descender + m.line_gap) * s, 1e-9);
  EXPECT_EQ(p.lines()[1].start, 4u);
  EXPECT_EQ(p.lines()[2].start, 8u);
  EXPECT_EQ(p.lines()[2].end, 9u);
  EXPECT_TRUE(p.lines()[2].runs.empty() || p.lines()[2].runs[0].glyphs.empty());
}

std::size_t count_glyph(const LayoutLine& l, std::uint32_t id) {
  std::size_t n = 0;
  for (const GlyphRun& r : l.runs)
    for (const PositionedGlyph& g : r.glyphs) n += g.id == id;
  return n;
}

TEST(Layout, EllipsisEndStartMiddle) {
  FontCollection fonts;
  const Font f = Font::open(test::kDejaVuSans);
  const std::uint32_t ellipsis = f.glyph_for_codepoint(0x2026);
  const std::string text = "The quick brown fox jumps over the lazy dog";
  for (Ellipsis e : {Ellipsis::End, Ellipsis::Start, Ellipsis::Middle}) {
    ParagraphStyle s = style_with({test::kDejaVuSans}, 20, 150);
    s.ellipsis = e;
    const Paragraph p = Paragraph::layout(fonts, text, {}, s);
    ASSERT_EQ(p.lines().size(), 1u);
    const LayoutLine& l = p.lines()[0];
    EXPECT_TRUE(l.ellipsized);
    EXPECT_LE(l.width, 150.0 + 1e-6);
    EXPECT_GT(l.width, 110.0);  // filled, not just the ellipsis
    EXPECT_EQ(count_glyph(l, ellipsis), 1u);
    const std::vector<std::size_t> v = visual_clusters(l);
    if (e == Ellipsis::End) {
      EXPECT_EQ(v.front(), 0u);
    }
    if (e == Ellipsis::Start) {
      EXPECT_EQ(v.back(), text.size() - 1);
    }
    if (e == Ellipsis::Middle) {
      EXPECT_EQ(v.front(), 0u);
      EXPECT_EQ(v.back(), text.size() - 1);
    }
  }
  // max_lines: two lines, the second ends with an ellipsis.
  ParagraphStyle s = style_with({test::kDejaVuSans}, 20, 150);
  s.max_lines = 2;
  s.ellipsis = Ellipsis::End;
  const Paragraph p = Paragraph::layout(fonts, text, {}, s);
  ASSERT_EQ(p.lines().size(), 2u);
  EXPECT_FALSE(p.lines()[0].ellipsized);
  EXPECT_TRUE(p.lines()[1].ellipsized);
  // Without an ellipsis, max_lines just stops.
  s.ellipsis = Ellipsis::None;
  EXPECT_EQ(Paragraph::layout(fonts, text, {}, s).lines().size(), 2u);
}

TEST(Layout, TabStops) {
  FontCollection fonts;
  ParagraphStyle s = style_with({test::kDejaVuSans}, 20);
  s.tab_stops = {100.0, 250.0};
  s.tab_interval = 50.0;
  const Paragraph p = Paragraph::layout(fonts, "a\tb\tc\td", {}, s);
  ASSERT_EQ(p.lines().size(), 1u);
  std::vector<double> xs;
  for (const GlyphRun& r : p.lines()[0].runs)
    for (const PositionedGlyph& g : r.glyphs)
      if (g.cluster == 2 || g.cluster == 4 || g.cluster == 6) xs.push_back(g.x);
  ASSERT_EQ(xs.size(), 3u);
  EXPECT_NEAR(xs[0], 100.0, 1e-9);
  EXPECT_NEAR(xs[1], 250.0, 1e-9);
  EXPECT_NEAR(xs[2], 300.0, 1e-9);  // default stops every 50 px after the last
}

// Thai with no break opportunity (no space) before the paragraph's end: the
// lines still end where libthai's dictionary puts word ends, at every width
// where the words fit, never inside a word ("จึงต้|อง").
TEST(Layout, ThaiWithoutSpacesBreaksAtDictionaryWords) {
  FontCollection fonts;
  const std::string text =
      "\u0E20\u0E32\u0E29\u0E32\u0E44\u0E17\u0E22\u0E40\u0E02\u0E35\u0E22\u0E19\u0E42\u0E14\u0E22\u0E44\u0E21\u0E48"
      "\u0E40\u0E27\u0E49\u0E19\u0E27\u0E23\u0E23\u0E04\u0E01\u0E32\u0E23\u0E15\u0E31\u0E14\u0E04\u0E33\u0E08\u0E36"
      "\u0E07\u0E15\u0E49\u0E2D\u0E07\u0E43\u0E0A\u0E49\u0E1E\u0E08\u0E19\u0E32\u0E19\u0E38\u0E01\u0E23\u0E21";
  const std::u32string cps = detail::decode_utf8(text);
  std::vector<BreakAction> words = line_breaks(cps);
  for (std::size_t i = 0; i + 1 < words.size(); ++i) ASSERT_EQ(words[i], BreakAction::None) << i;
  add_dictionary_breaks(cps, words);
  const auto idx = cp_index_of_bytes(text);
  for (const double width : {110.0, 140.0, 180.0, 240.0}) {
    const Paragraph p = Paragraph::layout(fonts, text, {}, style_with({test::kNotoThai}, 20, width));
    ASSERT_GE(p.lines().size(), 2u) << width;
    for (std::size_t k = 1; k < p.lines().size(); ++k) {
      const std::size_t at = idx[p.lines()[k].start];
      EXPECT_NE(words[at - 1], BreakAction::None) << "width " << width << ": line starts inside a word at " << at;
    }
  }
}

// Lao, Khmer and Myanmar need a dictionary too (UAX #14 class SA), but none
// is installed (libthai knows Thai only, and Pango has none for them either):
// they break at spaces, and a run without one longer than the line breaks
// between grapheme clusters, every line within the width.
TEST(Layout, LaoKhmerMyanmarWithoutSpacesBreakBetweenClusters) {
  FontCollection fonts;
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"/usr/share/fonts/truetype/noto/NotoSansLao-Regular.ttf",
       "\u0E9E\u0EB2\u0EAA\u0EB2\u0EA5\u0EB2\u0EA7\u0EC0\u0E9B\u0EB1\u0E99\u0E9E\u0EB2\u0EAA\u0EB2\u0E97\u0EB2\u0E87"
       "\u0E81\u0EB2\u0E99"},
      {"/usr/share/fonts/truetype/noto/NotoSansKhmer-Regular.ttf",
       "\u1797\u17B6\u179F\u17B6\u1781\u17D2\u1798\u17C2\u179A\u1782\u17BA\u1787\u17B6\u1797\u17B6\u179F\u17B6"
       "\u1795\u17D2\u179B\u17BC\u179C\u1780\u17B6\u179A"},
      {"/usr/share/fonts/truetype/noto/NotoSansMyanmar-Regular.ttf",
       "\u1019\u103C\u1014\u103A\u1019\u102C\u1018\u102C\u101E\u102C\u1005\u1000\u102C\u1038\u101E\u100A\u103A"},
  };
  for (const auto& [font, text] : cases) {
    const std::u32string cps = detail::decode_utf8(text);
    const auto clusters = grapheme_starts(cps);
    const auto idx = cp_index_of_bytes(text);
    const Paragraph p = Paragraph::layout(fonts, text, {}, style_with({font}, 20, 70));
    ASSERT_GE(p.lines().size(), 2u) << font;
    for (const LayoutLine& l : p.lines()) {
      EXPECT_LE(l.width, 70.0 + 1e-6) << font;
      EXPECT_TRUE(clusters[idx[l.start]]) << font << ": line starts inside a cluster at byte " << l.start;
      for (const GlyphRun& r : l.runs)
        for (const PositionedGlyph& g : r.glyphs) EXPECT_NE(g.id, 0u) << font;
    }
  }
}

// CJK and Thai lines have no spaces to stretch: a justified line is spread
// between its clusters (equal gaps), so both edges line up.
TEST(Layout, JustifyWithoutSpacesSpreadsBetweenClusters) {
  FontCollection fonts;
  const std::string cjk =
      "\u5317\u4EAC\u662F\u4E2D\u534E\u4EBA\u6C11\u5171\u548C\u56FD\u7684\u9996\u90FD\uFF0C\u4E5F\u662F\u5168\u56FD"
      "\u7684\u653F\u6CBB\u3001\u6587\u5316\u548C\u56FD\u9645\u4EA4\u5F80\u4E2D\u5FC3\u3002";
  const std::string thai =
      "\u0E20\u0E32\u0E29\u0E32\u0E44\u0E17\u0E22\u0E40\u0E02\u0E35\u0E22\u0E19\u0E42\u0E14\u0E22\u0E44\u0E21\u0E48"
      "\u0E40\u0E27\u0E49\u0E19\u0E27\u0E23\u0E23\u0E04";
  const std::vector<std::pair<std::string, std::string>> cases = {{std::string(test::kNotoCjk) + "#2", cjk},
                                                                  {test::kNotoThai, thai}};
  for (const auto& [font, t] : cases) {
    ParagraphStyle s = style_with({font}, 20, 157);
    s.align = Align::Justify;
    const Paragraph p = Paragraph::layout(fonts, t, {}, s);
    ASSERT_GE(p.lines().size(), 2u);
    for (std::size_t k = 0; k + 1 < p.lines().size(); ++k) {
      const LayoutLine& l = p.lines()[k];
      EXPECT_NEAR(l.x + l.width, 157.0, 1e-6) << font << " line " << k;
      // The ink ends at the right edge too: the last glyph's pen end.
      const PositionedGlyph& last = l.runs.back().glyphs.back();
      EXPECT_NEAR(last.x + last.advance, 157.0, 1e-6) << font << " line " << k;
    }
    EXPECT_LT(p.lines().back().x + p.lines().back().width, 157.0 - 1.0);
  }
  // Equal gaps: each ideograph of a justified line advances by the same
  // amount more than unjustified (one gap after each but the last).
  ParagraphStyle plain = style_with({std::string(test::kNotoCjk) + "#2"}, 20, 157);
  ParagraphStyle justified = plain;
  justified.align = Align::Justify;
  const Paragraph u = Paragraph::layout(fonts, cjk, {}, plain), j = Paragraph::layout(fonts, cjk, {}, justified);
  const std::vector<PositionedGlyph>& ug = u.lines()[0].runs[0].glyphs;
  const std::vector<PositionedGlyph>& jg = j.lines()[0].runs[0].glyphs;
  ASSERT_EQ(ug.size(), jg.size());
  const double gap = (157.0 - u.lines()[0].width) / static_cast<double>(ug.size() - 1);
  for (std::size_t k = 0; k + 1 < ug.size(); ++k) EXPECT_NEAR(jg[k].advance - ug[k].advance, gap, 1e-9) << k;
  EXPECT_NEAR(jg.back().advance, ug.back().advance, 1e-9);
}

// A negative first-line indent hangs: the first line at the box's start
// edge, the others indented by its size, none outside the box.
TEST(Layout, NegativeIndentHangs) {
  FontCollection fonts;
  for (const Align align : {Align::Start, Align::Justify}) {
    ParagraphStyle s = style_with({test::kDejaVuSans}, 16, 200);
    s.first_line_indent = -30;
    s.align = align;
    const Paragraph p =
        Paragraph::layout(fonts, "A hanging indent: the first line sticks out and the rest of it is indented.", {}, s);
    ASSERT_GE(p.lines().size(), 3u);
    EXPECT_NEAR(p.lines()[0].x, 0.0, 1e-9);
    for (std::size_t k = 1; k < p.lines().size(); ++k) EXPECT_NEAR(p.lines()[k].x, 30.0, 1e-9) << k;
    for (const LayoutLine& l : p.lines()) EXPECT_LE(l.x + l.width, 200.0 + 1e-6);
    EXPECT_GE(p.ink_bounds().x, 0.0);
  }
}

// Bold text stays bold in the scripts its font lacks: the fallback face is
// the same family's bold face where one is installed (here DejaVu Sans Bold,
// fontconfig's fallback family for Hebrew and Arabic), not the Regular one
// fontconfig finds by coverage.
TEST(Layout, BoldAppliesToFallbackFaces) {
  FontCollection fonts;
  const std::string bold = "/usr/share/fonts/truetype/noto/NotoSans-Bold.ttf";
  for (const std::string& text :
       {std::string("Bold \u05E9\u05DC\u05D5\u05DD"), std::string("Bold \u0645\u0631\u062D\u0628\u0627")}) {
    const Paragraph p = Paragraph::layout(fonts, text, {}, style_with({bold}, 20));
    ASSERT_EQ(p.lines().size(), 1u);
    std::size_t fallback_runs = 0;
    for (const GlyphRun& r : p.lines()[0].runs) {
      const float weight = hb_style_get_value(harfbuzz_font(*r.font), HB_STYLE_TAG_WEIGHT);
      EXPECT_GE(weight, 600.0f) << r.font->path();
      for (const PositionedGlyph& g : r.glyphs) EXPECT_NE(g.id, 0u) << r.font->path();
      fallback_runs += r.font->path() != bold;
    }
    EXPECT_GE(fallback_runs, 1u) << text;
  }
  // Italic too (DejaVu Sans Oblique, which has the italic bit).
  const Paragraph italic = Paragraph::layout(fonts, "Italic \u05E9\u05DC\u05D5\u05DD", {},
                                             style_with({"/usr/share/fonts/truetype/noto/NotoSans-Italic.ttf"}, 20));
  for (const GlyphRun& r : italic.lines()[0].runs) {
    EXPECT_GT(hb_style_get_value(harfbuzz_font(*r.font), HB_STYLE_TAG_ITALIC), 0.0f) << r.font->path();
  }
  // Regular text keeps the Regular fallback faces.
  const Paragraph p =
      Paragraph::layout(fonts, "Regular \u05E9\u05DC\u05D5\u05DD", {}, style_with({test::kNotoSans}, 20));
  for (const GlyphRun& r : p.lines()[0].runs)
    EXPECT_LT(hb_style_get_value(harfbuzz_font(*r.font), HB_STYLE_TAG_WEIGHT), 500.0f) << r.font->path();
}

TEST(Layout, JustifyStretchesSpacesOnly) {
  FontCollection fonts;
  ParagraphStyle s = style_with({test::kDejaVuSans}, 18, 260);
  s.align = Align::Justify;
  const std::string text =
      "Justified text stretches the spaces between words so that both edges line up, except "
      "on the last line.";
  const Paragraph p = Paragraph::layout(fonts, text, {}, s);
  ASSERT_GE(p.lines().size(), 3u);
  const Paragraph plain = Paragraph::layout(fonts, text, {}, style_with({test::kDejaVuSans}, 18, 260));
  for (std::size_t k = 0; k < p.lines().size(); ++k) {
    const LayoutLine& l = p.lines()[k];
    if (k + 1 < p.lines().size())
      EXPECT_NEAR(l.x + l.width, 260.0, 1e-6) << k;
    else
      EXPECT_LT(l.x + l.width, 259.0);
    // Letters keep their advances: every non-space glyph has the unjustified advance.
    const LayoutLine& u = plain.lines()[k];
    ASSERT_EQ(l.start, u.start);
    for (std::size_t r = 0; r < l.runs.size() && r < u.runs.size(); ++r)
      for (std::size_t g = 0; g < l.runs[r].glyphs.size(); ++g)
        if (text[l.runs[r].glyphs[g].cluster] != ' ') {
          EXPECT_DOUBLE_EQ(l.runs[r].glyphs[g].advance, u.runs[r].glyphs[g].advance);
        }
  }
}

TEST(Layout, SoftHyphenDrawsHyphenWhenUsed) {
  FontCollection fonts;
  const std::string text = "extra\u00ADordinarily";
  const Paragraph p = Paragraph::layout(fonts, text, {}, style_with({test::kDejaVuSans}, 20, 80));
  ASSERT_GE(p.lines().size(), 2u);
  EXPECT_TRUE(p.lines()[0].hyphenated);
  EXPECT_EQ(p.lines()[1].start, 7u);
  const Font f = Font::open(test::kDejaVuSans);
  const std::uint32_t hyphen =
      f.glyph_for_codepoint(0x2010) ? f.glyph_for_codepoint(0x2010) : f.glyph_for_codepoint('-');
  EXPECT_EQ(count_glyph(p.lines()[0], hyphen), 1u);
  // Unused soft hyphens draw nothing visible.
  const Paragraph wide = Paragraph::layout(fonts, text, {}, style_with({test::kDejaVuSans}, 20, 0));
  ASSERT_EQ(wide.lines().size(), 1u);
  EXPECT_EQ(count_glyph(wide.lines()[0], hyphen), 0u);
}

TEST(Layout, SpansStylesAndSpacing) {
  FontCollection fonts;
  const std::string text = "small BIG small";
  TextStyle big;
  big.fonts = {test::kDejaVuSans};
  big.size_px = 40;
  big.letter_spacing = 5;
  ParagraphStyle s = style_with({test::kDejaVuSans}, 16);
  const Paragraph p = Paragraph::layout(fonts, text, {{6, 9, big}}, s);
  ASSERT_EQ(p.lines().size(), 1u);
  // The line is as tall as its tallest font.
  const FontMetrics m = Font::open(test::kDejaVuSans).metrics();
  EXPECT_NEAR(p.lines()[0].ascent, m.ascender * 40.0 / m.units_per_em, 1e-9);
  std::size_t big_runs = 0;
  for (const GlyphRun& r : p.lines()[0].runs) big_runs += r.size_px == 40.0;
  EXPECT_EQ(big_runs, 1u);
}

TEST(Layout, HitTestingAndCarets) {
  FontCollection fonts;
  const std::string text = "Hello e\u0301t\u00E9 world";  // e + combining acute is one grapheme
  const Paragraph p = Paragraph::layout(fonts, text, {}, style_with({test::kDejaVuSans}, 20));
  // Caret positions increase along an LTR line and map back through hit testing.
  double last = -1;
  for (std::size_t i = 0; i <= text.size(); i = p.next_boundary(i)) {
    const Caret c = p.caret(i);
    EXPECT_GT(c.strong_x, last) << i;
    last = c.strong_x;
    EXPECT_EQ(p.hit_test(c.strong_x + 0.01, 5).index, i) << i;
    if (i == text.size()) break;
  }
  // No caret position inside the grapheme "e + U+0301" (bytes 6..9).
  EXPECT_EQ(p.next_boundary(6), 9u);
  EXPECT_EQ(p.caret(7).strong_x, p.caret(6).strong_x);
  // Selection of "llo" is one rectangle as wide as the three letters.
  const auto rects = p.selection_rects(2, 5);
  ASSERT_EQ(rects.size(), 1u);
  EXPECT_NEAR(rects[0].x, p.caret(2).strong_x, 1e-9);
  EXPECT_NEAR(rects[0].x + rects[0].width, p.caret(5).strong_x, 1e-9);
}

TEST(Layout, CaretsAtBidiBoundaries) {
  FontCollection fonts;
  const std::string text = "abc \u05D0\u05D1\u05D2 def";  // aleph bet gimel at bytes 4..10
  const Paragraph p = Paragraph::layout(fonts, text, {}, style_with({test::kDejaVuSans}, 20));
  // At byte 4 (after "abc ", before the Hebrew), as Pango places them: the
  // strong caret after the space (text of the paragraph's direction goes
  // there), the weak one at the Hebrew word's leading (right) edge.
  const Caret c = p.caret(4);
  EXPECT_FALSE(c.strong_rtl);
  EXPECT_TRUE(c.weak_rtl);
  EXPECT_GT(c.weak_x, c.strong_x + 5.0);
  // Selecting the space and the first Hebrew letter gives two rectangles.
  EXPECT_EQ(p.selection_rects(3, 6).size(), 2u);
  // Hitting the right half of the first Hebrew letter gives its start.
  const Caret a = p.caret(4);
  EXPECT_EQ(p.hit_test(a.weak_x - 0.5, 5).index, 4u);
}

TEST(Layout, BadInput) {
  FontCollection fonts;
  const ParagraphStyle s = style_with({test::kDejaVuSans}, 20);
  EXPECT_THROW(Paragraph::layout(fonts, "bad \xC3\x28", {}, s), Error);
  ParagraphStyle w = s;
  w.width = -5;
  EXPECT_THROW(Paragraph::layout(fonts, "x", {}, w), Error);
  w.width = std::nan("");
  EXPECT_THROW(Paragraph::layout(fonts, "x", {}, w), Error);
  TextSpan cut{1, 2, s.default_style};
  EXPECT_THROW(Paragraph::layout(fonts, "\u00E9x", {cut}, s), Error);  // inside a 2-byte sequence
  TextSpan outside{0, 99, s.default_style};
  EXPECT_THROW(Paragraph::layout(fonts, "x", {outside}, s), Error);
  ParagraphStyle missing = style_with({"/nonexistent/font.ttf"}, 20);
  try {
    Paragraph::layout(fonts, "x", {}, missing);
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::FontNotFound);
  }
  // Regional indicators (a flag) do not crash libunibreak 1.1.
  EXPECT_NO_THROW(Paragraph::layout(fonts, "flag \U0001F1E9\U0001F1EA ok", {}, s));
  // Empty text is one empty line.
  EXPECT_EQ(Paragraph::layout(fonts, "", {}, s).lines().size(), 1u);
}

// An 80,000-letter word at --width 0.001 took 13 s (each line measured the
// rest of the word to find its end, then each break tried every cut from the
// line start): now one pass, each line one cluster.
TEST(Layout, LongWordBreaksInLinearTime) {
  FontCollection fonts;
  const std::string word(80000, 'x');
  const Paragraph thin = Paragraph::layout(fonts, word, {}, style_with({test::kDejaVuSans}, 16, 0.001));
  ASSERT_EQ(thin.lines().size(), word.size());
  EXPECT_EQ(thin.lines()[1234].end - thin.lines()[1234].start, 1u);
  const Paragraph narrow = Paragraph::layout(fonts, word, {}, style_with({test::kDejaVuSans}, 16, 100));
  std::size_t end = 0;
  for (const LayoutLine& line : narrow.lines()) {
    EXPECT_LE(line.width, 100.0 + 1e-6);
    EXPECT_EQ(line.start, end);
    end = line.end;
  }
  EXPECT_EQ(end, word.size());
  // As many letters on a line as fit: the next one would not.
  const double advance = narrow.lines()[0].width / static_cast<double>(narrow.lines()[0].end);
  EXPECT_GT(narrow.lines()[0].width + advance, 100.0);
}

// Ellipsizing the last line measured every cut from the line start (end and
// start ellipses of a 200,000-letter word did not finish in 60 s).
TEST(Layout, EllipsisOfALongParagraphIsLinear) {
  FontCollection fonts;
  std::string text(200000, 'x');
  text[1000] = ' ';
  for (Ellipsis e : {Ellipsis::End, Ellipsis::Start, Ellipsis::Middle}) {
    ParagraphStyle s = style_with({test::kDejaVuSans}, 16, 300);
    s.max_lines = 1;
    s.ellipsis = e;
    const Paragraph p = Paragraph::layout(fonts, text, {}, s);
    ASSERT_EQ(p.lines().size(), 1u);
    EXPECT_TRUE(p.lines()[0].ellipsized);
    EXPECT_LE(p.lines()[0].width, 300.0 + 1e-6);
    EXPECT_GT(p.lines()[0].width, 280.0);
  }
}

// "a" and 20,000 combining marks took 9-14 s to shape (HarfBuzz attaches
// each mark by looking back over the others): such clusters are refused.
TEST(Layout, LongGraphemeClustersAreRefused) {
  FontCollection fonts;
  const ParagraphStyle s = style_with({test::kDejaVuSans}, 16);
  std::string marks = "ok a";
  for (int i = 0; i < 20000; ++i) marks += "\u0301";
  try {
    Paragraph::layout(fonts, marks, {}, s);
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::InvalidText);
    EXPECT_NE(std::string(e.what()).find("grapheme cluster of 20001 code points"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("at byte 3"), std::string::npos) << e.what();
  }
  std::string stacked = "a";
  for (std::size_t i = 1; i < tolerance::kMaxClusterCodePoints; ++i) stacked += "\u0301";
  EXPECT_EQ(Paragraph::layout(fonts, stacked, {}, s).lines().size(), 1u);
}

TEST(Layout, TextSizeAndSpanCountAreLimited) {
  FontCollection fonts;
  const ParagraphStyle s = style_with({test::kDejaVuSans}, 16);
  try {
    Paragraph::layout(fonts, std::string(tolerance::kMaxTextBytes + 1, 'a'), {}, s);
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::InvalidText);
    EXPECT_NE(std::string(e.what()).find("over the limit"), std::string::npos) << e.what();
  }
  const std::vector<TextSpan> spans(tolerance::kMaxSpans + 1, TextSpan{0, 1, s.default_style});
  try {
    Paragraph::layout(fonts, "x", spans, s);
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::InvalidArgument);
    EXPECT_NE(std::string(e.what()).find("spans are over the limit"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace curvetext
