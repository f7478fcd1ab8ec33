// curvetext render: one line of text to a PNG (DESIGN.md section 6).
#include <algorithm>
#include <cmath>

#include "cli.hpp"
#include "gl_session.hpp"
#include "curvetext/error.hpp"
#include "curvetext/image.hpp"
#include "curvetext/paragraph_image.hpp"
#include "curvetext/text_image.hpp"
#include "layout_options.hpp"
#include "style_options.hpp"

namespace curvetext::cli {

int run_render(const std::vector<std::string>& arguments) {
  FontChoice font_choice;
  std::optional<std::string> text, text_file, output, features;
  std::optional<double> size;
  TextImageOptions options;
  StyleCli style(/*scale_is_transform=*/true);
  LayoutCli paragraph;

  Args args(arguments);
  while (args.next()) {
    const std::string& a = args.option();
    if (style.parse(args, options)) continue;
    if (paragraph.parse(args)) continue;
    if (font_choice.parse(args)) continue;
    if (a == "--size")
      size = parse_number(a, args.value());
    else if (a == "--text")
      text = args.value();
    else if (a == "--text-file")
      text_file = args.value();
    else if (a == "-o" || a == "--output")
      output = args.value();
    else if (a == "--margin")
      options.margin_px = parse_number(a, args.value());
    else if (a == "--features")
      features = args.value();
    else if (a == "--fg")
      options.foreground = parse_color(args.value());
    else
      throw UsageError{"unknown option " + a};
  }
  if (!size) throw UsageError{"--size is required"};
  if (text.has_value() == text_file.has_value()) throw UsageError{"give exactly one of --text and --text-file"};
  if (!output) throw UsageError{"-o OUT.png is required"};
  options.size_px = *size;
  if (text_file) text = read_text_file(*text_file);
  if (features) options.shaping.features = parse_features(*features);

  if (paragraph.fonts.size() == 1) font_choice.path = paragraph.fonts.front();

  if (paragraph.used) {
    // Paragraph layout (--width, --align, fallback fonts, markup, ...): lines
    // advance by A - D + line gap; drawn through the same renderer with the
    // same style and transform as a single line.
    FontCollection fonts(default_font());
    if (text->empty()) throw Error(ErrorCode::InvalidText, "the text is empty");
    // --fg colours text outside markup colour spans.
    paragraph.style.default_style.color = options.foreground;
    const Paragraph p =
        layout_from_cli(fonts, paragraph, font_choice, options.size_px, options.shaping.features, *text);
    ParagraphImageOptions image_options;
    static_cast<ImageStyle&>(image_options) = options;
    image_options.margin_px = options.margin_px;
    image_options.transform = Transform{};
    if (style.perspective_pending()) {
      const ImageSize plain = paragraph_image_size(p, image_options);
      image_options.transform = style.transform(plain.width, plain.height);
    } else {
      image_options.transform = style.transform(0, 0);
    }
    paragraph_image_size(p, image_options);  // size errors before needing a GL device
    GlSession& gl = gl_session();
    write_png(render_paragraph_image(gl.renderer, gl.cache, p, image_options), *output);
    return 0;
  }

  const Font font = font_choice.open();
  if (style.perspective_pending()) {
    const TextImageLayout plain = layout_text_image(font, *text, options);
    options.transform = style.transform(plain.width, plain.height);
  } else {
    options.transform = style.transform(0, 0);
  }
  // Everything that can be checked without a GL device is checked first.
  const TextImageLayout layout = layout_text_image(font, *text, options);
  GlSession& gl = gl_session();
  write_png(render_text_image(gl.renderer, gl.cache, font, layout, options), *output);
  return 0;
}

}  // namespace curvetext::cli
