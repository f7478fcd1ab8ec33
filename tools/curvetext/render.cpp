// curvetext render: text to a PNG or SVG. Every render is a paragraph
// (bidi, script itemisation, font fallback through fontconfig); without
// --width it has no wrapping, one line per paragraph. With --jobs, many
// renders in one process (jobs.hpp).
#include "cli.hpp"
#include "curvetext/error.hpp"
#include "curvetext/image.hpp"
#include "curvetext/paragraph_image.hpp"
#include "curvetext/text_effect_style.hpp"
#include "gl_session.hpp"
#include "jobs.hpp"
#include "layout_options.hpp"
#include "style_options.hpp"
#include "svg_output.hpp"

namespace curvetext::cli {

namespace {

void write_png_image(const Paragraph& p, const StyleCli& style, ParagraphImageOptions options,
                     const std::string& output) {
  if (style.perspective_pending()) {
    const ImageSize plain = paragraph_image_size(p, options);
    options.transform = style.transform(plain.width, plain.height);
  } else {
    options.transform = style.transform(0, 0);
  }
  paragraph_image_size(p, options);  // size errors before needing a GL device
  GlSession& gl = gl_session();
  write_png_output(render_paragraph_image(gl.renderer, gl.cache, p, options), output);
}

// One render, from the command line or a job. Each has a font collection of
// its own, so fallback does not depend on the jobs before it (a collection
// tries the faces it handed out first); the GL context and the glyph cache
// (keyed by font content) are shared.
void render(const std::vector<std::string>& arguments) {
  FontChoice font_choice;
  TextCli input;
  LayoutCli paragraph;
  StyleCli style(/*scale_is_transform=*/true);
  ParagraphImageOptions options;
  std::optional<std::string> output, format;

  Args args(arguments);
  while (args.next()) {
    const std::string& a = args.option();
    if (style.parse(args, options)) continue;
    if (paragraph.parse(args)) continue;
    if (input.parse(args)) continue;
    if (font_choice.parse(args)) continue;
    if (a == "-o" || a == "--output")
      output = args.value();
    else if (a == "--format")
      format = args.value();
    else if (a == "--margin")
      options.margin_px = parse_number(a, args.value());
    else if (a == "--fg")  // colours text outside markup colour spans
      paragraph.style.default_style.color = parse_color(args.value());
    else if (a == "--outline")  // W,COLOR: text outside markup outline spans
      parse_outline(args.value(), ',', paragraph.style.default_style.effects);
    else if (a == "--shadow")  // DX,DY,BLUR,COLOR
      paragraph.style.default_style.effects.shadow = parse_shadow(args.value(), ',');
    else if (a == "--jobs")
      throw UsageError{kJobsAlone};
    else
      throw UsageError{"unknown option " + a};
  }
  if (!output) throw UsageError{"-o OUT.png, -o OUT.svg or -o - is required"};
  const OutputFormat kind = output_format(*output, format);
  if (kind == OutputFormat::Svg && !style.raster_option().empty())
    throw Error(ErrorCode::InvalidArgument,
                "SVG output is the outlines themselves: " + style.raster_option() + " applies to PNG output only");
  const std::string text = input.read();
  if (text.empty()) throw Error(ErrorCode::InvalidText, "the text is empty");
  FontCollection fonts(default_font());
  const std::vector<Feature> features = input.features ? parse_features(*input.features) : std::vector<Feature>{};
  const Paragraph p = layout_from_cli(fonts, paragraph, font_choice, input.size_px, features, text);
  if (kind == OutputFormat::Svg) {
    for (const TextStyle& st : p.styles())
      if (st.effects.any())
        throw Error(ErrorCode::InvalidArgument,
                    "SVG output is the outlines themselves: text outlines and shadows (--outline, --shadow, markup "
                    "outline= and shadow=) apply to PNG output only");
    write_output(paragraph_svg(p, options.margin_px, options.background), *output);
  } else
    write_png_image(p, style, options, *output);
}

}  // namespace

int run_render(const std::vector<std::string>& arguments) {
  if (const std::optional<std::string> jobs = jobs_source(arguments)) return run_jobs(*jobs, render);
  render(arguments);
  return 0;
}

}  // namespace curvetext::cli
