#include "svg_output.hpp"

#include <cmath>
#include <cstdio>

#include "curvetext/error.hpp"
#include "curvetext/paragraph_image.hpp"

namespace curvetext::cli {

namespace {

// Thousandths of a pixel, trailing zeros dropped.
void num(std::string& out, double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.3f", v);
  std::string s(buf);
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  out += s == "-0" ? "0" : s;
}

void point(std::string& out, char command, Vec2 p, double ox, double oy, double scale) {
  if (command) out += command;
  num(out, ox + p.x * scale);
  out += ' ';
  num(out, oy - p.y * scale);
  out += ' ';
}

// The outline in font units (y up) with its origin at (ox, oy) px, y down.
void outline_path(std::string& out, const Outline& outline, double ox, double oy, double scale) {
  for (const Contour& contour : outline.contours()) {
    if (contour.segments.empty()) continue;
    point(out, 'M', contour.segments.front().start(), ox, oy, scale);
    for (const Segment& s : contour.segments) {
      if (s.kind == Segment::Kind::Line) {
        point(out, 'L', s.p[1], ox, oy, scale);
      } else if (s.kind == Segment::Kind::Cubic) {
        point(out, 'C', s.p[1], ox, oy, scale);
        point(out, 0, s.p[2], ox, oy, scale);
        point(out, 0, s.p[3], ox, oy, scale);
      } else if (s.weight == 1.0) {
        point(out, 'Q', s.p[1], ox, oy, scale);
        point(out, 0, s.p[2], ox, oy, scale);
      } else {
        throw Error(ErrorCode::InvalidArgument, "SVG output: a glyph has a conic of weight " +
                                                    std::to_string(s.weight) + ", which SVG paths cannot say");
      }
    }
    out += "Z ";
  }
}

void fill(std::string& out, Color c) {
  char buf[80];
  auto byte = [](float v) { return static_cast<int>(std::lround(std::fmin(std::fmax(v, 0.0f), 1.0f) * 255.0f)); };
  std::snprintf(buf, sizeof buf, "fill=\"#%02x%02x%02x\"", byte(c.r), byte(c.g), byte(c.b));
  out += buf;
  if (c.a < 1.0f) {
    std::snprintf(buf, sizeof buf, " fill-opacity=\"%.4g\"", c.a);
    out += buf;
  }
}

void refuse_decorations(const Paragraph& paragraph) {
  for (const TextStyle& style : paragraph.styles()) {
    const char* what = style.underline             ? "underline"
                       : style.strikethrough       ? "strikethrough"
                       : style.background.a > 0.0f ? "span backgrounds"
                                                   : nullptr;
    if (what)
      throw Error(ErrorCode::InvalidArgument, std::string("SVG output does not draw ") + what + " (write a .png)");
  }
}

}  // namespace

std::string paragraph_svg(const Paragraph& paragraph, double margin_px, Color background) {
  refuse_decorations(paragraph);
  ParagraphImageOptions size_options;
  size_options.margin_px = margin_px;
  const ImageSize size = paragraph_image_size(paragraph, size_options);
  const std::string w = std::to_string(size.width), h = std::to_string(size.height);
  std::string out = "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + w + "\" height=\"" + h +
                    "\" viewBox=\"0 0 " + w + " " + h + "\">\n";
  if (background.a > 0.0f) {
    out += "<path d=\"M0 0 H" + w + " V" + h + " H0 Z\" ";
    fill(out, background);
    out += "/>\n";
  }
  Outline outline;
  for (const LayoutLine& line : paragraph.lines()) {
    for (const GlyphRun& run : line.runs) {
      if (run.glyphs.empty()) continue;
      const double scale = run.size_px / run.font->metrics().units_per_em;
      std::string d;
      for (const PositionedGlyph& g : run.glyphs) {
        run.font->glyph_outline(g.id, outline);
        outline_path(d, outline, margin_px + g.x, margin_px + g.y, scale);
      }
      if (d.empty()) continue;
      d.pop_back();
      out += "<path d=\"" + d + "\" ";
      fill(out, paragraph.styles()[run.style].color);
      out += "/>\n";
    }
  }
  return out + "</svg>\n";
}

}  // namespace curvetext::cli
