// curvetext render: one line of text to a PNG (DESIGN.md section 6).
#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "cli.hpp"
#include "curvetext/default_font.hpp"
#include "curvetext/error.hpp"
#include "curvetext/headless.hpp"
#include "curvetext/image.hpp"
#include "curvetext/renderer.hpp"
#include "curvetext/paragraph_image.hpp"
#include "curvetext/text_image.hpp"
#include "layout_options.hpp"

#ifndef CURVETEXT_BUILD_FONT_DIR
#define CURVETEXT_BUILD_FONT_DIR ""
#endif

namespace curvetext::cli {

namespace {

std::string read_text_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(ErrorCode::Io, "cannot read text file " + path);
  std::ostringstream ss;
  ss << in.rdbuf();
  std::string text = ss.str();
  // One line of text: a trailing line break is the file's, not the text's.
  if (!text.empty() && text.back() == '\n') text.pop_back();
  if (!text.empty() && text.back() == '\r') text.pop_back();
  return text;
}

std::vector<double> parse_numbers(const std::string& option, const std::string& text, std::size_t lo, std::size_t hi) {
  std::vector<double> values;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = text.find(',', start);
    values.push_back(parse_number(option, text.substr(start, comma == std::string::npos ? std::string::npos : comma - start)));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  if (values.size() < lo || values.size() > hi)
    throw UsageError{option + " takes " + (lo == hi ? std::to_string(lo) : std::to_string(lo) + " or " + std::to_string(hi)) +
                     " comma-separated numbers, got " + std::to_string(values.size())};
  for (double v : values)
    if (!std::isfinite(v)) throw Error(ErrorCode::InvalidArgument, option + " needs finite numbers, got '" + text + "'");
  return values;
}

// --rotate DEG, --scale SX[,SY], --skew AX[,AY], --perspective DEG[,DIST],
// --transform a,b,c,d,e,f[,g,h,i]: each applied after those before it, about
// the image centre. True when `args.option()` was one of them.
bool parse_transform(Args& args, Transform& t, bool& perspective_pending, double& perspective_degrees,
                     double& perspective_distance) {
  const std::string o = args.option();
  Transform step;
  if (o == "--rotate") {
    step = Transform::rotation(parse_numbers(o, args.value(), 1, 1)[0]);
  } else if (o == "--scale") {
    const auto v = parse_numbers(o, args.value(), 1, 2);
    step = Transform::scale(v[0], v.size() > 1 ? v[1] : v[0]);
  } else if (o == "--skew") {
    const auto v = parse_numbers(o, args.value(), 1, 2);
    if (std::abs(v[0]) >= 89.0 || (v.size() > 1 && std::abs(v[1]) >= 89.0))
      throw Error(ErrorCode::InvalidArgument, "--skew angles must be within (-89, 89) degrees");
    step = Transform::skew(v[0], v.size() > 1 ? v[1] : 0.0);
  } else if (o == "--perspective") {
    const auto v = parse_numbers(o, args.value(), 1, 2);
    if (std::abs(v[0]) >= 90.0) throw Error(ErrorCode::InvalidArgument, "--perspective angle must be within (-90, 90) degrees");
    if (v.size() > 1 && !(v[1] > 0.0)) throw Error(ErrorCode::InvalidArgument, "--perspective distance must be positive");
    // The default distance depends on the image size, known only later.
    if (v.size() == 1) {
      if (!t.is_identity()) throw UsageError{"--perspective without a distance must come first (or give DEG,DIST)"};
      perspective_pending = true;
      perspective_degrees = v[0];
      return true;
    }
    step = Transform::perspective(v[0], v[1]);
  } else if (o == "--transform") {
    const auto v = parse_numbers(o, args.value(), 6, 9);
    if (v.size() == 6) step = Transform{{v[0], v[1], v[2], v[3], v[4], v[5], 0, 0, 1}};
    else step = Transform{{v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8]}};
  } else {
    return false;
  }
  (void)perspective_distance;
  step.validate();
  t = step * t;
  return true;
}

}  // namespace

int run_render(const std::vector<std::string>& arguments) {
  FontChoice font_choice;
  std::optional<std::string> text, text_file, output, features;
  std::optional<double> size;
  TextImageOptions options;
  LayoutCli paragraph;

  Transform transform;
  bool perspective_pending = false;
  double perspective_degrees = 0.0, perspective_distance = 0.0;
  bool transformed = false;
  bool styled = false;  // --blend, --gamma, --debug, --vbaa-filter: single lines only
  Args args(arguments);
  while (args.next()) {
    const std::string& a = args.option();
    if (parse_transform(args, transform, perspective_pending, perspective_degrees, perspective_distance)) {
      transformed = true;
      continue;
    }
    if (paragraph.parse(args)) continue;
    if (font_choice.parse(args)) continue;
    if (a == "--size") size = parse_number(a, args.value());
    else if (a == "--text") text = args.value();
    else if (a == "--text-file") text_file = args.value();
    else if (a == "-o" || a == "--output") output = args.value();
    else if (a == "--margin") options.margin_px = parse_number(a, args.value());
    else if (a == "--aa") options.antialiasing = parse_antialiasing(args.value());
    else if (a == "--curve") options.curve_mode = parse_curve_mode(args.value());
    else if (a == "--features") features = args.value();
    else if (a == "--fg") options.foreground = parse_color(args.value());
    else if (a == "--bg") options.background = parse_color(args.value());
    else if (a == "--blend") options.blending = parse_blending(args.value());
    else if (a == "--gamma") {
      options.gamma = static_cast<float>(parse_number(a, args.value()));
      check_coverage_gamma(options.gamma, "--gamma");
      styled = true;
    }
    else if (a == "--debug") options.debug = true;
    else if (a == "--vbaa-filter") options.vbaa_ring = parse_vbaa_filter(args.value());
    else throw UsageError{"unknown option " + a};
    if (a == "--blend" || a == "--debug" || a == "--vbaa-filter") styled = true;
  }
  if (!size) throw UsageError{"--size is required"};
  if (text.has_value() == text_file.has_value()) throw UsageError{"give exactly one of --text and --text-file"};
  if (!output) throw UsageError{"-o OUT.png is required"};
  options.size_px = *size;
  if (text_file) text = read_text_file(*text_file);
  if (features) options.shaping.features = parse_features(*features);

  if (paragraph.fonts.size() == 1) font_choice.path = paragraph.fonts.front();

  if (paragraph.used && transformed)
    throw UsageError{"--rotate/--scale/--skew/--perspective/--transform work on single lines (not with paragraph options)"};

  if (paragraph.used && styled)
    throw UsageError{"--blend/--gamma/--debug/--vbaa-filter work on single lines (not with paragraph options)"};

  if (paragraph.used) {
    // Paragraph layout (--width, --align, fallback fonts, markup, ...): lines
    // advance by A - D + line gap; drawn through the same renderer.
    FontCollection fonts(default_font_path(CURVETEXT_BUILD_FONT_DIR));
    if (text->empty()) throw Error(ErrorCode::InvalidText, "the text is empty");
    // --fg colours text outside markup colour spans.
    paragraph.style.default_style.color = options.foreground;
    const Paragraph p = layout_from_cli(fonts, paragraph, font_choice, options.size_px, options.shaping.features, *text);
    ParagraphImageOptions image_options;
    image_options.margin_px = options.margin_px;
    image_options.background = options.background;
    image_options.antialiasing = options.antialiasing;
    image_options.curve_mode = options.curve_mode;
    paragraph_image_size(p, image_options);  // size errors before needing a GL device
    HeadlessContext context = HeadlessContext::create();
    Renderer renderer;
    GlyphCache cache;
    write_png(render_paragraph_image(renderer, cache, p, image_options), *output);
    return 0;
  }

  const Font font = font_choice.open();
  if (perspective_pending) {
    // Seen from twice the untransformed image's larger side.
    const TextImageLayout plain = layout_text_image(font, *text, options);
    const double distance = 2.0 * std::max(plain.width, plain.height);
    transform = transform * Transform::perspective(perspective_degrees, distance);
  }
  options.transform = transform;
  // Everything that can be checked without a GL device is checked first.
  const TextImageLayout layout = layout_text_image(font, *text, options);
  HeadlessContext context = HeadlessContext::create();
  Renderer renderer;
  GlyphCache cache;
  const Image image = render_text_image(renderer, cache, font, layout, options);
  write_png(image, *output);
  return 0;
}

}  // namespace curvetext::cli
