// curvetext shape: a shape document (NURBS JSON or SVG) to a PNG; with
// --jobs, many in one process (jobs.hpp).
#include <cmath>

#include "cli.hpp"
#include "gl_session.hpp"
#include "jobs.hpp"
#include "curvetext/error.hpp"
#include "curvetext/image.hpp"
#include "curvetext/shape_image.hpp"
#include "curvetext/shapes.hpp"
#include "style_options.hpp"

namespace curvetext::cli {

namespace {

// "WxH", both whole numbers of pixels.
void parse_size(const std::string& text, int& width, int& height) {
  const std::size_t x = text.find('x');
  if (x == std::string::npos) throw UsageError{"--size needs WxH, got '" + text + "'"};
  width = parse_int("--size", std::string_view(text).substr(0, x));
  height = parse_int("--size", std::string_view(text).substr(x + 1));
  if (width < 1 || height < 1)
    throw Error(ErrorCode::InvalidArgument, "--size " + text + ": sides must be at least 1 px");
}

void shape(const std::vector<std::string>& arguments) {
  std::optional<std::string> input, output;
  std::optional<Color> foreground;
  SvgOptions svg;
  ShapeImageOptions options;
  StyleCli style(/*scale_is_transform=*/false);

  Args args(arguments);
  while (args.next()) {
    const std::string& a = args.option();
    if (style.parse(args, options)) continue;
    if (a == "--input" || a == "-i")
      input = args.value();
    else if (a == "-o" || a == "--output")
      output = args.value();
    else if (a == "--size")
      parse_size(args.value(), options.width, options.height);
    else if (a == "--scale") {
      options.scale = parse_number(a, args.value());
      if (!(options.scale > 0.0) || !std::isfinite(options.scale))
        throw Error(ErrorCode::InvalidArgument, "--scale must be a positive number of pixels per unit");
    } else if (a == "--fg")
      foreground = parse_color(args.value());
    else if (a == "--current-color")
      svg.current_color = parse_color(args.value());
    else if (a == "--jobs")
      throw UsageError{kJobsAlone};
    else
      throw UsageError{"unknown option " + a};
  }
  if (!input) throw UsageError{"--input FILE is required"};
  if (!output) throw UsageError{"-o OUT.png is required"};
  if (output_format(*output, std::nullopt) != OutputFormat::Png)
    throw Error(ErrorCode::InvalidArgument, "cannot write '" + *output + "': shape writes PNG only");

  ShapeDocument doc = read_shape_file(*input, svg);
  if (foreground)
    for (Shape& s : doc.shapes) {
      s.color = *foreground;
      s.gradient.reset();
      s.stroke_gradient.reset();
      if (s.stroke) s.stroke->color = *foreground;
    }
  // Everything that can be checked without a GL device is checked first.
  if (style.perspective_pending()) {
    const ShapeImageLayout plain = layout_shape_image(doc, options);
    options.transform = style.transform(plain.width, plain.height);
  } else {
    options.transform = style.transform(0, 0);
  }
  const ShapeImageLayout layout = layout_shape_image(doc, options);
  write_png_output(render_shape_image(gl_session().renderer, doc, layout, options), *output);
}

}  // namespace

int run_shape(const std::vector<std::string>& arguments) {
  if (const std::optional<std::string> jobs = jobs_source(arguments)) return run_jobs(*jobs, shape);
  shape(arguments);
  return 0;
}

}  // namespace curvetext::cli
