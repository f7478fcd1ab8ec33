// The curvetext command-line tool. Subcommands:
//   render   one line of text to a PNG (geometry contract of DESIGN.md section 6)
// Exit status: 0 success, 1 a runtime error (bad font, bad text, no GL device,
// I/O), 2 a usage error. Errors are one line on stderr.
#include <charconv>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "curvetext/default_font.hpp"
#include "curvetext/error.hpp"
#include "curvetext/font.hpp"
#include "curvetext/headless.hpp"
#include "curvetext/image.hpp"
#include "curvetext/renderer.hpp"
#include "curvetext/text_image.hpp"

#ifndef CURVETEXT_BUILD_FONT_DIR
#define CURVETEXT_BUILD_FONT_DIR ""
#endif

namespace {

constexpr const char* kUsage =
    "usage: curvetext render [--font FILE] [--face-index N] --size PX (--text UTF8 | --text-file FILE)\n"
    "                        -o OUT.png [--margin PX] [--aa none|curves|full] [--curve exact|paper]\n"
    "                        [--variations wght=700,...] [--features \"kern,-liga\"]\n"
    "                        [--fg COLOR] [--bg COLOR]\n"
    "       curvetext --help | --version\n"
    "COLOR is #rgb, #rrggbb, #rrggbbaa or black, white, red, green, blue, transparent.\n"
    "Without --font the default font (DejaVu Sans) is used.\n";

struct UsageError {
  std::string message;
};

double parse_number(std::string_view option, std::string_view text) {
  double value = 0.0;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || ptr != text.data() + text.size())
    throw UsageError{std::string(option) + " needs a number, got '" + std::string(text) + "'"};
  return value;
}

int parse_int(std::string_view option, std::string_view text) {
  int value = 0;
  const auto [ptr, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (ec != std::errc() || ptr != text.data() + text.size())
    throw UsageError{std::string(option) + " needs a whole number, got '" + std::string(text) + "'"};
  return value;
}

std::string read_text_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw curvetext::Error(curvetext::ErrorCode::Io, "cannot read text file " + path);
  std::ostringstream ss;
  ss << in.rdbuf();
  std::string text = ss.str();
  // One line of text: a trailing line break is the file's, not the text's.
  if (!text.empty() && text.back() == '\n') text.pop_back();
  if (!text.empty() && text.back() == '\r') text.pop_back();
  return text;
}

int run_render(const std::vector<std::string>& args) {
  std::optional<std::string> font_path, text, text_file, output, variations, features;
  int face_index = 0;
  std::optional<double> size;
  curvetext::TextImageOptions options;

  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&]() -> const std::string& {
      if (i + 1 >= args.size()) throw UsageError{a + " needs a value"};
      return args[++i];
    };
    if (a == "--font") font_path = value();
    else if (a == "--face-index") face_index = parse_int(a, value());
    else if (a == "--size") size = parse_number(a, value());
    else if (a == "--text") text = value();
    else if (a == "--text-file") text_file = value();
    else if (a == "-o" || a == "--output") output = value();
    else if (a == "--margin") options.margin_px = parse_number(a, value());
    else if (a == "--aa") options.antialiasing = curvetext::parse_antialiasing(value());
    else if (a == "--curve") options.curve_mode = curvetext::parse_curve_mode(value());
    else if (a == "--variations") variations = value();
    else if (a == "--features") features = value();
    else if (a == "--fg") options.foreground = curvetext::parse_color(value());
    else if (a == "--bg") options.background = curvetext::parse_color(value());
    else throw UsageError{"unknown option " + a};
  }
  if (!size) throw UsageError{"--size is required"};
  if (text.has_value() == text_file.has_value()) throw UsageError{"give exactly one of --text and --text-file"};
  if (!output) throw UsageError{"-o OUT.png is required"};
  if (face_index < 0) throw UsageError{"--face-index must be 0 or more"};
  options.size_px = *size;
  if (text_file) text = read_text_file(*text_file);
  if (features) options.shaping.features = curvetext::parse_features(*features);

  curvetext::Font font =
      curvetext::Font::open(font_path ? *font_path : curvetext::default_font_path(CURVETEXT_BUILD_FONT_DIR),
                            face_index);
  if (variations) font.set_variations(curvetext::parse_variations(*variations));

  // Everything that can be checked without a GL device is checked first.
  const curvetext::TextImageLayout layout = curvetext::layout_text_image(font, *text, options);
  curvetext::HeadlessContext context = curvetext::HeadlessContext::create();
  curvetext::Renderer renderer;
  curvetext::GlyphCache cache;
  const curvetext::Image image = curvetext::render_text_image(renderer, cache, font, layout, options);
  curvetext::write_png(image, *output);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> args(argv + 1, argv + argc);
  try {
    if (args.empty()) throw UsageError{"no command given"};
    if (args[0] == "--help" || args[0] == "-h" || args[0] == "help") {
      std::fputs(kUsage, stdout);
      return 0;
    }
    if (args[0] == "--version") {
      std::puts("curvetext 0.1.0");
      return 0;
    }
    if (args[0] == "render") return run_render({args.begin() + 1, args.end()});
    throw UsageError{"unknown command '" + args[0] + "'"};
  } catch (const UsageError& e) {
    std::fprintf(stderr, "curvetext: %s\n%s", e.message.c_str(), kUsage);
    return 2;
  } catch (const curvetext::Error& e) {
    std::fprintf(stderr, "curvetext: error: %s\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "curvetext: error: %s\n", e.what());
    return 1;
  }
}
