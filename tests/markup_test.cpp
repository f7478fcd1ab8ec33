// Markup (curvetext/markup.hpp): nesting keeps every enclosing style, <span>
// attributes, entities, errors with their byte position, and the limits that
// keep deep or span-heavy markup linear.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "curvetext/error.hpp"
#include "curvetext/layout.hpp"
#include "curvetext/markup.hpp"
#include "curvetext/paragraph_image.hpp"
#include "curvetext/tolerances.hpp"
#include "support/fonts.hpp"
#include "support/gpu.hpp"

namespace curvetext {
namespace {

TextStyle base_style() {
  TextStyle s;
  s.fonts = {test::kDejaVuSans};
  s.size_px = 20.0;
  return s;
}

// The style Paragraph::layout gives byte `at` (later spans win).
TextStyle style_at(const MarkupText& m, std::size_t at, const TextStyle& base) {
  TextStyle s = base;
  for (const TextSpan& span : m.spans)
    if (span.start <= at && at < span.end) s = span.style;
  return s;
}

bool is_bold(const TextStyle& s) {
  return !s.fonts.empty() && s.fonts.front().find("weight=bold") != std::string::npos;
}
bool is_italic(const TextStyle& s) {
  return !s.fonts.empty() && s.fonts.front().find("slant=italic") != std::string::npos;
}

// Where two elements nest, the inner text keeps the outer element's style too.
TEST(Markup, NestingKeepsEveryEnclosingStyle) {
  const TextStyle base = base_style();
  {
    const MarkupText m = parse_markup("<color=red>red <b>bold</b></color>", base);
    ASSERT_EQ(m.text, "red bold");
    const TextStyle bold = style_at(m, 5, base);
    EXPECT_TRUE(is_bold(bold));
    EXPECT_EQ(bold.color.r, 1.0f);
    EXPECT_EQ(bold.color.g, 0.0f);
    EXPECT_FALSE(is_bold(style_at(m, 0, base)));
    EXPECT_EQ(style_at(m, 0, base).color.r, 1.0f);
  }
  {
    const MarkupText m = parse_markup("<u>under <b>bold</b> after</u>", base);
    const TextStyle bold = style_at(m, 7, base);
    EXPECT_TRUE(is_bold(bold));
    EXPECT_TRUE(bold.underline);
    EXPECT_TRUE(style_at(m, 12, base).underline);
    EXPECT_FALSE(is_bold(style_at(m, 12, base)));
  }
  {
    const MarkupText m = parse_markup("<i>it <s>struck</s></i>", base);
    const TextStyle struck = style_at(m, 4, base);
    EXPECT_TRUE(struck.strikethrough);
    EXPECT_TRUE(is_italic(struck));
  }
  {
    // Bold inside italic is one bold italic face, not two fonts in turn.
    const MarkupText m = parse_markup("<i><b>x</b></i>", base);
    const TextStyle s = style_at(m, 0, base);
    EXPECT_TRUE(is_bold(s));
    EXPECT_TRUE(is_italic(s));
    EXPECT_EQ(s.fonts.size(), 2u);  // the bold italic face, then the base font
  }
}

// Spans are disjoint and ordered; text outside every element has none.
TEST(Markup, SpansAreDisjointInTextOrder) {
  const MarkupText m = parse_markup("a<b>b<i>c</i>d</b>e", base_style());
  ASSERT_EQ(m.text, "abcde");
  ASSERT_EQ(m.spans.size(), 3u);
  EXPECT_EQ(m.spans[0].start, 1u);
  EXPECT_EQ(m.spans[0].end, 2u);
  EXPECT_EQ(m.spans[1].start, 2u);
  EXPECT_EQ(m.spans[1].end, 3u);
  EXPECT_EQ(m.spans[2].start, 3u);
  EXPECT_EQ(m.spans[2].end, 4u);
}

TEST(Markup, SpanAttributes) {
  const TextStyle base = base_style();
  const MarkupText m = parse_markup(
      "<span font_family='DejaVu Serif' size='30px' weight='bold' style='italic' foreground='#00ff00' "
      "background=\"blue\" underline='single' strikethrough='true' letter_spacing='2.5' word_spacing='4' "
      "font_features='-liga,smcp' lang='de'>x</span>",
      base);
  ASSERT_EQ(m.spans.size(), 1u);
  const TextStyle& s = m.spans[0].style;
  ASSERT_EQ(s.fonts.size(), 3u);
  EXPECT_EQ(s.fonts[0], "DejaVu Serif:weight=bold:slant=italic");
  EXPECT_EQ(s.fonts[1], "DejaVu Serif");
  EXPECT_EQ(s.fonts[2], test::kDejaVuSans);
  EXPECT_EQ(s.size_px, 30.0);
  EXPECT_EQ(s.color.g, 1.0f);
  EXPECT_EQ(s.background.b, 1.0f);
  EXPECT_EQ(s.background.a, 1.0f);
  EXPECT_TRUE(s.underline);
  EXPECT_TRUE(s.strikethrough);
  EXPECT_EQ(s.letter_spacing, 2.5);
  EXPECT_EQ(s.word_spacing, 4.0);
  ASSERT_EQ(s.features.size(), 2u);
  EXPECT_EQ(s.features[0].tag, "liga");
  EXPECT_EQ(s.features[0].value, 0u);
  EXPECT_EQ(s.language, "de");
  // Numeric weights go to the nearest fontconfig weight; normal undoes bold.
  // A font file asks for the style itself (FontCollection::resolve finds its
  // family's face or synthesises one).
  EXPECT_EQ(parse_markup("<span weight='600'>x</span>", base).spans[0].style.fonts[0],
            std::string(test::kDejaVuSans) + ":weight=semibold");
  EXPECT_FALSE(is_bold(parse_markup("<b><span weight='normal'>x</span></b>", base).spans[0].style));
}

// Bold asks fontconfig for the family's bold face: the layout draws it.
TEST(Markup, OutlineAndShadowAttributes) {
  const TextStyle base = base_style();
  const MarkupText m = parse_markup(
      "a <span outline=\"2.5 #ff0000\" shadow=\"1 -2px  3 #00000080\">fx <span shadow=\"0 0 6 "
      "blue\">glow</span></span>",
      base);
  ASSERT_EQ(m.text, "a fx glow");
  EXPECT_FALSE(style_at(m, 0, base).effects.any());
  const TextEffects fx = style_at(m, 2, base).effects;
  EXPECT_EQ(fx.outline_width, 2.5);
  EXPECT_EQ(fx.outline_color.r, 1.0f);
  EXPECT_EQ(fx.shadow.dx, 1.0);
  EXPECT_EQ(fx.shadow.dy, -2.0);
  EXPECT_EQ(fx.shadow.blur, 3.0);
  EXPECT_NEAR(fx.shadow.color.a, 128.0 / 255.0, 1e-6);
  // The inner span keeps the outline and replaces the shadow: a glow.
  const TextEffects glow = style_at(m, 5, base).effects;
  EXPECT_EQ(glow.outline_width, 2.5);
  EXPECT_EQ(glow.shadow.dx, 0.0);
  EXPECT_EQ(glow.shadow.blur, 6.0);
  EXPECT_EQ(glow.shadow.color.b, 1.0f);
  for (const char* bad :
       {"<span outline=\"2\">x</span>", "<span outline=\"-1 red\">x</span>", "<span shadow=\"1 1 red\">x</span>",
        "<span shadow=\"1 1 inf red\">x</span>", "<span outline=\"2 nocolour\">x</span>"}) {
    try {
      (void)parse_markup(bad, base);
      ADD_FAILURE() << "accepted " << bad;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("markup, byte"), std::string::npos) << e.what();
    }
  }
}

TEST(Markup, BoldLaysOutInTheBoldFace) {
  FontCollection fonts;
  ParagraphStyle style;
  style.default_style = base_style();
  const MarkupText m = parse_markup("<color=red>red <b>bold</b></color>", style.default_style);
  const Paragraph p = Paragraph::layout(fonts, m.text, m.spans, style);
  // Every weight name gives a pattern fontconfig reads.
  for (const char* weight : {"thin", "ultralight", "light", "semilight", "book", "normal", "medium", "semibold", "bold",
                             "ultrabold", "heavy", "ultraheavy", "100", "1000"}) {
    SCOPED_TRACE(weight);
    const MarkupText w = parse_markup(std::string("<span weight='") + weight + "'>x</span>", style.default_style);
    EXPECT_NO_THROW(Paragraph::layout(fonts, w.text, w.spans, style));
  }
  bool bold_run = false;
  for (const GlyphRun& run : p.lines()[0].runs)
    if (run.start == 4) {
      bold_run = true;
      EXPECT_NE(run.font->path().find("Bold"), std::string::npos) << run.font->path();
      EXPECT_EQ(p.styles()[run.style].color.r, 1.0f);
    }
  EXPECT_TRUE(bold_run);
}

TEST(Markup, Entities) {
  const MarkupText m = parse_markup("&lt;&gt;&amp;&quot;&apos;&#65;&#x42;&#x1F600;&#233;", base_style());
  EXPECT_EQ(m.text, "<>&\"'AB\xF0\x9F\x98\x80\xC3\xA9");
  const MarkupText attr = parse_markup("<span font_family='A&amp;B'>x</span>", base_style());
  EXPECT_EQ(attr.spans[0].style.fonts[0], "A&B");
}

// Every error names the byte where the problem is.
TEST(Markup, ErrorsNameTheirPosition) {
  const std::pair<const char*, const char*> cases[] = {
      {"<b>open", "byte 0: <b> is not closed"},
      {"a</b>", "byte 1: </b> closes no open element"},
      {"<b><i>x</b></i>", "byte 7: </b> does not close <i> (opened at byte 3)"},
      {"x < y", "byte 2: '<' does not start a tag"},
      {"x &bogus; y", "byte 2: unknown entity &bogus;"},
      {"&#xD800;", "byte 0: unknown entity"},
      {"&#0;", "byte 0: unknown entity"},
      {"&#x110000;", "byte 0: unknown entity"},
      {"a & b", "byte 2: '&' does not start an entity"},
      {"<blink>x</blink>", "byte 0: unknown tag <blink>"},
      {"<b=1>x</b>", "byte 0: <b> takes no value"},
      {"<color>x</color>", "byte 0: <color> needs a value"},
      {"<span rise='3'>x</span>", "byte 6: span attribute rise is not supported"},
      {"<span size=3>x</span>", "byte 11: the value of size needs quotes"},
      {"<span size='3'", "byte 0: '<' without a closing '>'"},
      {"<span size='big'>x</span>", "byte 6: size needs a number of pixels"},
      {"<span weight='fat'>x</span>", "byte 6: weight needs"},
      {"<span underline='double'>x</span>", "byte 6: underline needs none or single"},
      {"<span foreground='teal'>x</span>", "byte 6: foreground: "},
      {"<span font_features='kern[3:5]'>x</span>", "byte 6: font_features: "},
      {"ab\xff", "byte 2: "},
  };
  for (const auto& [markup, message] : cases) {
    SCOPED_TRACE(markup);
    try {
      parse_markup(markup, base_style());
      ADD_FAILURE() << "no error";
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), ErrorCode::InvalidText);
      EXPECT_NE(std::string(e.what()).find(message), std::string::npos) << e.what();
    }
  }
}

// 1,000 nested <b> (7 KB) cost about depth^3 (33 s, 1.7 GB): now the depth
// is limited, and 64 levels of every kind of element stay cheap.
TEST(Markup, NestingDepthIsLimited) {
  std::string deep;
  for (int i = 0; i < 1000; ++i) deep += "<b>";
  deep += "x";
  for (int i = 0; i < 1000; ++i) deep += "</b>";
  try {
    parse_markup(deep, base_style());
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::InvalidText);
    EXPECT_NE(std::string(e.what()).find("nested deeper than 64"), std::string::npos) << e.what();
  }
  std::string ok;
  const std::size_t depth = tolerance::kMaxMarkupDepth;
  for (std::size_t i = 0; i < depth; ++i) ok += i % 2 ? "<b>" : "<font=DejaVu Sans>";
  ok += "x";
  for (std::size_t i = depth; i-- > 0;) ok += i % 2 ? "</b>" : "</font>";
  const MarkupText m = parse_markup(ok, base_style());
  ASSERT_EQ(m.spans.size(), 1u);
  EXPECT_TRUE(is_bold(m.spans[0].style));
  // The bold face once, then the fonts of the <font> elements and the base.
  EXPECT_EQ(m.spans[0].style.fonts.size(), depth / 2 + 2);
}

// 200,000 <b>x</b> spans did not lay out in 60 s (a copy of the boxes per
// run, a font lookup per span): now linear.
TEST(Markup, ManySpansLayOutInLinearTime) {
  std::string markup;
  for (int i = 0; i < 200000; ++i) markup += "<b>x</b> ";
  ParagraphStyle style;
  style.default_style = base_style();
  const MarkupText m = parse_markup(markup, style.default_style);
  ASSERT_EQ(m.spans.size(), 200000u);
  FontCollection fonts;
  style.width = 4000;
  const Paragraph p = Paragraph::layout(fonts, m.text, m.spans, style);
  std::size_t glyphs = 0;
  for (const LayoutLine& line : p.lines())
    for (const GlyphRun& run : line.runs) glyphs += run.glyphs.size();
  EXPECT_EQ(glyphs, 2u * 200000u);
  EXPECT_GT(p.lines().size(), 100u);
}

TEST(Markup, SizeAndSpanCountAreLimited) {
  const std::string huge(tolerance::kMaxTextBytes + 1, 'a');
  EXPECT_THROW(parse_markup(huge, base_style()), Error);
  std::string many;
  for (std::size_t i = 0; i <= tolerance::kMaxSpans; ++i) many += "<u>x</u>";
  try {
    parse_markup(many, base_style());
    ADD_FAILURE() << "no error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("styled spans"), std::string::npos) << e.what();
  }
}

// <span background=...> fills each run's box, line high, behind the text;
// two runs side by side with one background show no seam between them.
TEST(Markup, BackgroundFillsTheRunBoxes) {
  FontCollection fonts;
  ParagraphStyle style;
  style.default_style = base_style();
  const MarkupText m = parse_markup(
      "ab <span background='#0000ff'><color=red>cde</color><color=green>f</color></span> gh", style.default_style);
  const Paragraph p = Paragraph::layout(fonts, m.text, m.spans, style);
  const LayoutLine& line = p.lines()[0];
  double x0 = 1e9, x1 = -1e9;
  for (const GlyphRun& run : line.runs)
    if (p.styles()[run.style].background.a > 0) {
      x0 = std::min(x0, run.x);
      x1 = std::max(x1, run.x + run.width);
    }
  ASSERT_LT(x0, x1);
  // The runs meet inside a pixel (two rectangles would each cover part of it).
  const double seam = line.runs[2].x;
  ASSERT_GT(std::abs(seam - std::round(seam)), 0.1);
  ParagraphImageOptions options;
  options.background = Color{1, 1, 1, 1};
  const Image image = render_paragraph_image(test::gpu().renderer, test::gpu().cache, p, options);
  // A row just below the line's top: above every glyph's ink.
  const int y = static_cast<int>(options.margin_px + line.top) + 1;
  auto rgb = [&](int x) {
    const std::uint8_t* px = image.pixel(x, y);
    return std::array<int, 3>{px[0], px[1], px[2]};
  };
  const int first = static_cast<int>(std::ceil(options.margin_px + x0));
  const int last = static_cast<int>(std::floor(options.margin_px + x1)) - 1;
  for (int x = first; x <= last; ++x) EXPECT_EQ(rgb(x), (std::array<int, 3>{0, 0, 255})) << "x = " << x;
  EXPECT_EQ(rgb(first - 3), (std::array<int, 3>{255, 255, 255}));
  EXPECT_EQ(rgb(last + 3), (std::array<int, 3>{255, 255, 255}));
}

}  // namespace
}  // namespace curvetext
