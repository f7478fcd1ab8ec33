// curvetext mesh: one glyph's mesh as an SVG picture, so a person can see what
// the tessellator did: interior triangles, convex and concave curved
// triangles in their own colours, and the true outline on top.
#include <cstdio>
#include <sstream>
#include <string>

#include "cli.hpp"
#include "curvetext/curves.hpp"
#include "curvetext/error.hpp"
#include "curvetext/lod.hpp"
#include "curvetext/mesh.hpp"
#include "curvetext/shaping.hpp"

namespace curvetext::cli {

namespace {

char32_t first_codepoint(const std::string& utf8) {
  validate_utf8(utf8);
  if (utf8.empty()) throw Error(ErrorCode::InvalidText, "--char needs one character");
  const auto b = [&](std::size_t i) { return static_cast<char32_t>(static_cast<unsigned char>(utf8[i])); };
  const char32_t c0 = b(0);
  if (c0 < 0x80) return c0;
  if (c0 < 0xE0) return ((c0 & 0x1F) << 6) | (b(1) & 0x3F);
  if (c0 < 0xF0) return ((c0 & 0x0F) << 12) | ((b(1) & 0x3F) << 6) | (b(2) & 0x3F);
  return ((c0 & 0x07) << 18) | ((b(1) & 0x3F) << 12) | ((b(2) & 0x3F) << 6) | (b(3) & 0x3F);
}

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f", v);
  return buf;
}
std::string pt(Vec2 p) { return num(p.x) + "," + num(-p.y); }  // SVG's y grows downward

std::string outline_path(const Outline& outline) {
  // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on "x" + string.
  std::ostringstream d;
  for (const Contour& c : outline.contours()) {
    if (c.segments.empty()) continue;
    d << 'M' << pt(c.segments.front().start());
    for (const Segment& s : c.segments) {
      switch (s.kind) {
        case Segment::Kind::Line:
          d << " L" << pt(s.p[1]);
          break;
        case Segment::Kind::Conic:
          if (s.weight == 1.0) {
            d << " Q" << pt(s.p[1]) << ' ' << pt(s.p[2]);
          } else {  // SVG has no rational curves: a fine polyline
            for (int i = 1; i <= 32; ++i) d << " L" << pt(evaluate(s, i / 32.0));
          }
          break;
        case Segment::Kind::Cubic:
          d << " C" << pt(s.p[1]) << ' ' << pt(s.p[2]) << ' ' << pt(s.p[3]);
          break;
      }
    }
    d << " Z ";
  }
  return d.str();
}

}  // namespace

int run_mesh(const std::vector<std::string>& arguments) {
  FontChoice font_choice;
  std::optional<long> glyph;
  std::optional<std::string> character, output;
  double size_px = 64.0;
  Args args(arguments);
  while (args.next()) {
    const std::string& a = args.option();
    if (font_choice.parse(args)) continue;
    if (a == "--glyph")
      glyph = parse_int(a, args.value());
    else if (a == "--char")
      character = args.value();
    else if (a == "--size")
      size_px = parse_number(a, args.value());
    else if (a == "-o" || a == "--output")
      output = args.value();
    else
      throw UsageError{"unknown option " + a};
  }
  if (glyph.has_value() == character.has_value()) throw UsageError{"give exactly one of --glyph and --char"};
  if (!output) throw UsageError{"-o MESH.svg is required"};
  if (*output != "-" && output_format(*output, std::nullopt) != OutputFormat::Svg)
    throw Error(ErrorCode::InvalidArgument, "cannot write '" + *output + "': mesh writes SVG only");

  const Font font = font_choice.open();
  std::uint32_t id = 0;
  if (character) {
    id = font.glyph_for_codepoint(first_codepoint(*character));
    if (id == 0) throw Error(ErrorCode::InvalidArgument, "the font has no glyph for '" + *character + "'");
  } else {
    if (*glyph < 0) throw Error(ErrorCode::InvalidArgument, "--glyph must be 0 or more");
    id = static_cast<std::uint32_t>(*glyph);
  }
  const Outline outline = font.glyph_outline(id);
  const double upem = font.metrics().units_per_em;
  const double tolerance = cubic_tolerance_for_lod(lod_for_scale(size_px / upem, upem), upem);
  const Mesh mesh = build_mesh(outline, {tolerance});
  const MeshCheck check = check_mesh(mesh, to_quadratic_outline(outline, tolerance));

  Box box = outline.control_box();
  if (box.empty()) box = Box{{0, 0}, {upem, upem}};
  const double pad = 0.05 * std::max(box.max.x - box.min.x, box.max.y - box.min.y) + 1;
  const double stroke = std::max(box.max.x - box.min.x, box.max.y - box.min.y) / 400.0;
  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"" << num(box.min.x - pad) << " " << num(-box.max.y - pad)
      << " " << num(box.max.x - box.min.x + 2 * pad) << " " << num(box.max.y - box.min.y + 2 * pad)
      << "\" width=\"800\" height=\"800\">\n";
  svg << "<title>glyph " << id << ": " << mesh.triangles.size() << " interior, " << mesh.curves.size()
      << " curved triangles; " << (check.ok() ? "invariants hold" : "INVARIANTS VIOLATED") << "</title>\n";
  svg << "<g stroke=\"#5b6b8c\" stroke-width=\"" << num(stroke) << "\" stroke-linejoin=\"round\">\n";
  for (const auto& t : mesh.triangles)
    svg << "<polygon fill=\"#d9e2f3\" points=\"" << pt(mesh.points[t[0]]) << " " << pt(mesh.points[t[1]]) << " "
        << pt(mesh.points[t[2]]) << "\"/>\n";
  for (const CurvedTriangle& c : mesh.curves)
    svg << "<polygon fill=\"" << (c.convex ? "#f5b971" : "#8fd18f") << "\" fill-opacity=\"0.8\" points=\""
        << pt(mesh.points[c.p0]) << " " << pt(mesh.points[c.control]) << " " << pt(mesh.points[c.p2]) << "\"/>\n";
  svg << "</g>\n<path fill=\"none\" stroke=\"#c0392b\" stroke-width=\"" << num(1.5 * stroke) << "\" d=\""
      << outline_path(outline) << "\"/>\n";
  svg << "<text x=\"" << num(box.min.x) << "\" y=\"" << num(-box.min.y + 0.8 * pad) << "\" font-size=\""
      << num(0.3 * pad) << "\" font-family=\"sans-serif\">interior (blue), convex curved (orange), concave curved "
      << "(green), outline (red)</text>\n</svg>\n";

  write_output(svg.str(), *output);
  if (!check.ok()) {
    std::fprintf(stderr, "curvetext: warning: glyph %u violates mesh invariants: %s\n", id, check.problems[0].c_str());
  }
  return 0;
}

}  // namespace curvetext::cli
