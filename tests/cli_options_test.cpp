// The CLI's option values (tools/curvetext/option_values.hpp), its argument
// walker and output formats (cli.hpp), the paragraph options
// (layout_options.hpp), SVG output (svg_output.hpp) and job lines (jobs.hpp):
// what each accepts and the errors it gives. The CLI's own behaviour is tests/cli/cli_test.sh.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "curvetext/error.hpp"
#include "curvetext/renderer.hpp"
#include "curvetext/tolerances.hpp"
#include "cli.hpp"
#include "jobs.hpp"
#include "curvetext/layout.hpp"
#include "curvetext/paragraph_image.hpp"
#include "curvetext/shapes.hpp"
#include "layout_options.hpp"
#include "option_values.hpp"
#include "svg_output.hpp"

namespace curvetext::cli {
namespace {

TEST(CliOptions, AntialiasingAndCurveModes) {
  EXPECT_EQ(parse_antialiasing("none"), AntiAliasing::None);
  EXPECT_EQ(parse_antialiasing("curves"), AntiAliasing::Curves);
  EXPECT_EQ(parse_antialiasing("full"), AntiAliasing::Full);
  EXPECT_EQ(parse_antialiasing("vbaa"), AntiAliasing::Vbaa);
  EXPECT_EQ(parse_antialiasing("msaa"), AntiAliasing::Msaa);
  EXPECT_EQ(parse_antialiasing("auto"), AntiAliasing::Auto);
  EXPECT_EQ(parse_curve_mode("exact"), CurveMode::Exact);
  EXPECT_EQ(parse_curve_mode("paper"), CurveMode::Paper);
  for (const char* bad : {"", "Full", "ssaa", "vbaa2"}) {
    try {
      parse_antialiasing(bad);
      FAIL() << bad;
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), ErrorCode::InvalidArgument);
    }
  }
  try {
    parse_curve_mode("loop-blinn");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::InvalidArgument);
  }
}

TEST(CliOptions, BlendingFilterAndGamma) {
  EXPECT_EQ(parse_blending("linear"), Blending::Linear);
  EXPECT_EQ(parse_blending("srgb"), Blending::Srgb);
  EXPECT_THROW(parse_blending("gamma"), Error);
  EXPECT_EQ(parse_vbaa_filter("box"), 0.0f);
  EXPECT_EQ(parse_vbaa_filter("paper"), tolerance::kVbaaPaperRing);
  EXPECT_EQ(parse_vbaa_filter("0.25"), 0.25f);
  EXPECT_THROW(parse_vbaa_filter("nan"), Error);
  EXPECT_THROW(parse_vbaa_filter("1.5"), Error);
  EXPECT_NO_THROW(check_gamma(1.8, "--gamma"));
  EXPECT_THROW(check_gamma(std::nan(""), "--gamma"), Error);
  EXPECT_THROW(check_gamma(0.0, "--gamma"), Error);
  try {
    check_gamma(100.0, "--gamma");
    FAIL();
  } catch (const Error& e) {
    EXPECT_EQ(e.code(), ErrorCode::InvalidArgument);
    EXPECT_EQ(std::string(e.what()).rfind("--gamma must be a number from 0.25 to 4", 0), 0u) << e.what();
  }
}

// Each option of `args` with the value it takes (empty for a flag: those
// named in `flags`).
std::vector<std::pair<std::string, std::string>> walk(std::vector<std::string> args,
                                                      const std::vector<std::string>& flags = {}) {
  Args walker(std::move(args));
  std::vector<std::pair<std::string, std::string>> out;
  while (walker.next()) {
    const std::string name = walker.option();
    const bool flag = std::find(flags.begin(), flags.end(), name) != flags.end();
    out.emplace_back(name, flag ? std::string() : walker.value());
  }
  return out;
}

TEST(CliArgs, EqualsFormTakesTheValue) {
  using V = std::vector<std::pair<std::string, std::string>>;
  EXPECT_EQ(walk({"--size=20", "--text", "hi"}), (V{{"--size", "20"}, {"--text", "hi"}}));
  EXPECT_EQ(walk({"--text=a=b", "-o", "-"}), (V{{"--text", "a=b"}, {"-o", "-"}}));
  EXPECT_EQ(walk({"--text=", "--debug"}, {"--debug"}), (V{{"--text", ""}, {"--debug", ""}}));
  // A value that looks like "--x=y" after a separate option name stays a value.
  EXPECT_EQ(walk({"--text", "--a=b"}), (V{{"--text", "--a=b"}}));
}

TEST(CliArgs, FlagGivenAValueAndMissingValueAreUsageErrors) {
  for (const std::vector<std::string>& args :
       {std::vector<std::string>{"--debug=1"}, std::vector<std::string>{"--debug=yes", "--size", "3"}}) {
    try {
      walk(args, {"--debug"});
      FAIL() << args[0];
    } catch (const UsageError& e) {
      EXPECT_EQ(e.message, "--debug takes no value, got '" + args[0].substr(8) + "'");
    }
  }
  try {
    walk({"--size"});
    FAIL();
  } catch (const UsageError& e) {
    EXPECT_EQ(e.message, "--size needs a value");
  }
}

TEST(CliOutput, FormatFromTheExtension) {
  EXPECT_EQ(output_format("a.png", std::nullopt), OutputFormat::Png);
  EXPECT_EQ(output_format("dir.d/A.PNG", std::nullopt), OutputFormat::Png);
  EXPECT_EQ(output_format("a.svg", std::nullopt), OutputFormat::Svg);
  EXPECT_EQ(output_format("-", std::nullopt), OutputFormat::Png);
  EXPECT_EQ(output_format("-", std::string("svg")), OutputFormat::Svg);
  EXPECT_EQ(output_format("a.out", std::string("png")), OutputFormat::Png);
  for (const char* bad : {"a.jpg", "a", "dir.png/a", "a.png.txt", "a."}) {
    try {
      output_format(bad, std::nullopt);
      FAIL() << bad;
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), ErrorCode::InvalidArgument);
      EXPECT_NE(std::string(e.what()).find(bad), std::string::npos) << e.what();
    }
  }
  EXPECT_THROW(output_format("a.png", std::string("gif")), UsageError);
}

TEST(CliOptions, TextDefaultsAndSpacing) {
  TextCli input;
  LayoutCli layout;
  Args args({"--letter-spacing=2.5", "--word-spacing", "-1", "--text", "hi"});
  while (args.next()) ASSERT_TRUE(layout.parse(args) || input.parse(args)) << args.option();
  EXPECT_EQ(input.size_px, kDefaultSizePx);
  EXPECT_EQ(input.read(), "hi");
  EXPECT_EQ(layout.style.default_style.letter_spacing, 2.5);
  EXPECT_EQ(layout.style.default_style.word_spacing, -1.0);
  Args nan_spacing({"--letter-spacing", "nan"});
  nan_spacing.next();
  EXPECT_THROW(layout.parse(nan_spacing), UsageError);
  EXPECT_THROW(TextCli{}.read(), UsageError);  // neither --text nor --text-file
}

// The SVG's path data read back with parse_svg_path covers the glyphs' own
// area, placed where the layout put them.
TEST(CliSvg, PathsHaveTheGlyphAreaAtTheLayoutPositions) {
  FontCollection fonts;
  ParagraphStyle style;
  style.default_style.size_px = 40.0;
  const Paragraph p = Paragraph::layout(fonts, "Bag o", {}, style);
  const std::string svg = paragraph_svg(p, 10.0, Color{0, 0, 0, 0});
  double want = 0.0;
  for (const GlyphRun& run : p.lines()[0].runs) {
    const double scale = run.size_px / run.font->metrics().units_per_em;
    for (const PositionedGlyph& g : run.glyphs) want += run.font->glyph_outline(g.id).signed_area() * scale * scale;
  }
  double got = 0.0, min_x = 1e9, max_x = -1e9;
  for (std::size_t at = svg.find(" d=\""); at != std::string::npos; at = svg.find(" d=\"", at + 1)) {
    const std::size_t end = svg.find('"', at + 4);
    Shape shape;
    shape.contours = parse_svg_path(svg.substr(at + 4, end - at - 4));
    const Outline outline = shape_outline(shape, 1e-3);
    got += outline.signed_area();
    min_x = std::min(min_x, outline.control_box().min.x);
    max_x = std::max(max_x, outline.control_box().max.x);
  }
  ASSERT_GT(std::abs(want), 100.0);
  // y is flipped (the SVG is y down), so the signed areas have opposite signs;
  // coordinates are rounded to 1/1000 px.
  EXPECT_NEAR(-got, want, 1e-4 * std::abs(want));
  const Rect ink = p.ink_bounds();
  EXPECT_NEAR(min_x, 10.0 + ink.x, 0.01);
  EXPECT_NEAR(max_x, 10.0 + ink.x + ink.width, 0.01);
  EXPECT_NE(svg.find("width=\"" + std::to_string(paragraph_image_size(p, {}).width - 12) + "\""), std::string::npos)
      << svg.substr(0, 200);
}

using Strings = std::vector<std::string>;

Strings args_of(std::string_view line) { return parse_job(line).arguments; }

TEST(CliJobs, LineToArguments) {
  EXPECT_EQ(args_of(R"({"text": "Hi", "size": 24, "markup": true, "debug": false, "output": "a.png"})"),
            (Strings{"--text", "Hi", "--size", "24", "--markup", "-o", "a.png"}));
  // Arrays repeat the option in order; numbers stay as written.
  EXPECT_EQ(args_of(R"( {"font":["A","B"],"rotate":-1.5e1,"scale":[2, 0.5]} )"),
            (Strings{"--font", "A", "--font", "B", "--rotate", "-1.5e1", "--scale", "2", "--scale", "0.5"}));
  EXPECT_EQ(args_of("{}"), Strings{});
  EXPECT_EQ(args_of(R"({"font": []})"), Strings{});
  // Escapes, a surrogate pair among them, decoded to UTF-8.
  EXPECT_EQ(args_of(R"({"text": "a\"b\\c\/\n\t\u00e9\u4e2d\ud83d\ude00"})"),
            (Strings{"--text", "a\"b\\c/\n\t\xc3\xa9\xe4\xb8\xad\xf0\x9f\x98\x80"}));
  // "-" is only refused where it means a standard stream.
  EXPECT_EQ(args_of(R"({"align": "-"})"), (Strings{"--align", "-"}));
}

TEST(CliJobs, OutputIsTheOutputKeys) {
  EXPECT_EQ(parse_job(R"({"text": "-o", "output": "x.png"})").output, "x.png");
  EXPECT_EQ(parse_job(R"({"output": ["a.png", "b.png"]})").output, "b.png");  // the last -o wins
  EXPECT_EQ(parse_job(R"({"text": "a"})").output, "");
}

TEST(CliJobs, BadLinesNameTheColumn) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"", "column 1: expected '{'"},
      {"[1]", "column 1: expected '{'"},
      {R"({"text": "a")", "column 13: expected ',' or '}'"},
      {R"({"text": "a"} x)", "column 15: text after"},
      {R"({"text": "a)", "column 12: string not closed"},
      {R"({text: 1})", "column 2: expected a key"},
      {R"({"Size": 1})", "key \"Size\" is not an option name"},
      {R"({"--size": 1})", "is not an option name"},
      {R"({"size": 1, "size": 2})", "given twice"},
      {R"({"jobs": "x"})", "cannot name more jobs"},
      {R"({"size": null})", "expected a string, a number, true or false"},
      {R"({"size": {"a": 1}})", "nested objects"},
      {R"({"font": [["a"]]})", "nested arrays"},
      {R"({"markup": [true]})", "expected a string, a number"},
      {R"({"size": 01})", "bad number"},
      {R"({"size": 1.})", "bad number"},
      {R"({"size": -})", "bad number"},
      {R"({"text": "\x"})", "bad escape \\x"},
      {R"({"text": "\u12"})", "four hex digits"},
      {R"({"text": "\ud83d"})", "high surrogate alone"},
      {R"({"text": "\ude00"})", "low surrogate alone"},
      {"{\"text\": \"a\tb\"}", "control character"},
      {R"({"output": "-"})", "\"output\": \"-\" (standard input or output)"},
      {R"({"text": "-"})", "not available to a job"},
      {R"({"text-file": "-"})", "not available to a job"},
      {R"({"input": "-"})", "not available to a job"},
  };
  for (const auto& [line, part] : cases) {
    try {
      parse_job(line);
      ADD_FAILURE() << "no error for " << line;
    } catch (const Error& e) {
      EXPECT_EQ(e.code(), ErrorCode::InvalidArgument) << line;
      EXPECT_NE(std::string(e.what()).find(part), std::string::npos) << line << ": " << e.what();
    }
  }
}

TEST(CliJobs, JobsComeAlone) {
  EXPECT_EQ(jobs_source({"--jobs", "list.jsonl"}), std::optional<std::string>("list.jsonl"));
  EXPECT_EQ(jobs_source({"--jobs=-"}), std::optional<std::string>("-"));
  EXPECT_EQ(jobs_source({"--text", "--jobs"}), std::nullopt);  // the text "--jobs"
  EXPECT_EQ(jobs_source({}), std::nullopt);
  for (const Strings& args : {Strings{"--jobs", "a", "--size", "3"}, Strings{"--jobs=a", "b"}}) {
    try {
      jobs_source(args);
      ADD_FAILURE() << "no error";
    } catch (const UsageError& e) {
      EXPECT_NE(e.message.find("takes no other options"), std::string::npos) << e.message;
    }
  }
  try {
    jobs_source({"--jobs"});
    ADD_FAILURE() << "no error";
  } catch (const UsageError& e) {
    EXPECT_NE(e.message.find("needs a value"), std::string::npos) << e.message;
  }
}

}  // namespace
}  // namespace curvetext::cli
