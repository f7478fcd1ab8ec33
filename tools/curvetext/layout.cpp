// curvetext layout: a paragraph's lines and positioned glyphs as JSON; and the
// paragraph options and markup shared with `render`.
#include <cmath>
#include <cstdio>
#include <sstream>

#include "curvetext/error.hpp"
#include "curvetext/markup.hpp"
#include "layout_options.hpp"

namespace curvetext::cli {

namespace {

Align parse_align(const std::string& s) {
  if (s == "left") return Align::Left;
  if (s == "right") return Align::Right;
  if (s == "center" || s == "centre") return Align::Center;
  if (s == "justify") return Align::Justify;
  if (s == "start") return Align::Start;
  if (s == "end") return Align::End;
  throw UsageError{"--align needs left, right, center, justify, start or end, got '" + s + "'"};
}

Ellipsis parse_ellipsis(const std::string& s) {
  if (s == "none") return Ellipsis::None;
  if (s == "start") return Ellipsis::Start;
  if (s == "middle") return Ellipsis::Middle;
  if (s == "end") return Ellipsis::End;
  throw UsageError{"--ellipsis needs none, start, middle or end, got '" + s + "'"};
}

BaseDirection parse_direction(const std::string& s) {
  if (s == "auto") return BaseDirection::Auto;
  if (s == "ltr") return BaseDirection::Ltr;
  if (s == "rtl") return BaseDirection::Rtl;
  throw UsageError{"--direction needs auto, ltr or rtl, got '" + s + "'"};
}

double positive_or_zero(std::string_view option, std::string_view text) {
  const double v = parse_number(option, text);
  if (!std::isfinite(v) || v < 0.0)
    throw UsageError{std::string(option) + " must be 0 or more, got '" + std::string(text) + "'"};
  return v;
}

// Spacing may be negative (tighter text); it must be a finite number.
double finite_number(std::string_view option, std::string_view text) {
  const double v = parse_number(option, text);
  if (!std::isfinite(v))
    throw UsageError{std::string(option) + " must be a finite number, got '" + std::string(text) + "'"};
  return v;
}

void json_string(std::string& out, const std::string& s) {
  out += '"';
  for (unsigned char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += static_cast<char>(c);
    } else if (c < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      out += buf;
    } else {
      out += static_cast<char>(c);
    }
  }
  out += '"';
}

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3f", v);
  std::string s(buf);
  // Trim trailing zeros: "12.500" -> "12.5", "3.000" -> "3".
  while (!s.empty() && s.back() == '0') s.pop_back();
  if (!s.empty() && s.back() == '.') s.pop_back();
  if (s == "-0") s = "0";
  return s;
}

}  // namespace

bool LayoutCli::parse(Args& args) {
  const std::string& a = args.option();
  if (a == "--font")
    fonts.push_back(args.value());
  else if (a == "--width")
    style.width = positive_or_zero(a, args.value());
  else if (a == "--align")
    style.align = parse_align(args.value());
  else if (a == "--line-height") {
    // "1.5" is a multiple of the natural line height, "24px" a fixed advance.
    std::string v = args.value();
    if (v.size() > 2 && v.substr(v.size() - 2) == "px")
      style.line_height_px = positive_or_zero(a, v.substr(0, v.size() - 2));
    else
      style.line_height = positive_or_zero(a, v);
    if (style.line_height > 100.0) throw UsageError{"--line-height multiple must be at most 100"};
  } else if (a == "--max-lines") {
    style.max_lines = parse_int(a, args.value());
    if (style.max_lines < 0) throw UsageError{"--max-lines must be 0 or more"};
  } else if (a == "--ellipsis")
    style.ellipsis = parse_ellipsis(args.value());
  else if (a == "--direction")
    style.direction = parse_direction(args.value());
  else if (a == "--language")
    style.language = args.value();
  else if (a == "--indent")
    style.first_line_indent = parse_number(a, args.value());
  else if (a == "--tab-stops") {
    std::stringstream ss(args.value());
    std::string item;
    while (std::getline(ss, item, ',')) style.tab_stops.push_back(positive_or_zero(a, item));
  } else if (a == "--markup")
    markup = true;
  else if (a == "--letter-spacing")
    style.default_style.letter_spacing = finite_number(a, args.value());
  else if (a == "--word-spacing")
    style.default_style.word_spacing = finite_number(a, args.value());
  else
    return false;
  return true;
}

bool TextCli::parse(Args& args) {
  const std::string& a = args.option();
  if (a == "--size")
    size_px = parse_number(a, args.value());
  else if (a == "--text")
    text = args.value();
  else if (a == "--text-file")
    text_file = args.value();
  else if (a == "--features")
    features = args.value();
  else
    return false;
  return true;
}

std::string TextCli::read() const {
  if (text.has_value() == text_file.has_value()) throw UsageError{"give exactly one of --text and --text-file"};
  if (text_file) return read_text_file(*text_file);
  return *text == "-" ? read_text_file("-") : *text;
}

Paragraph layout_from_cli(FontCollection& fonts, const LayoutCli& options, const FontChoice& font_choice,
                          double size_px, const std::vector<Feature>& features, const std::string& text) {
  ParagraphStyle style = options.style;
  style.default_style.size_px = size_px;
  style.default_style.features = features;
  for (const std::string& f : options.fonts)
    if (!is_font_file(f)) check_font_family(f);
  if (font_choice.face_index && !options.fonts.empty() && !is_font_file(options.fonts.front()))
    throw Error(ErrorCode::InvalidArgument,
                "--face-index picks a face of a font file, not of the family '" + options.fonts.front() + "'");
  for (const std::string& f : options.fonts)
    style.default_style.fonts.push_back(
        font_choice.face_index && &f == &options.fonts.front() ? f + "#" + std::to_string(font_choice.face_index) : f);
  if (style.default_style.fonts.empty())
    style.default_style.fonts.push_back(
        font_choice.face_index ? default_font() + "#" + std::to_string(font_choice.face_index) : default_font());
  if (font_choice.variations) style.default_style.variations = parse_variations(*font_choice.variations);
  if (!options.markup) return Paragraph::layout(fonts, text, {}, style);
  const MarkupText marked = parse_markup(text, style.default_style);
  return Paragraph::layout(fonts, marked.text, marked.spans, style);
}

int run_layout(const std::vector<std::string>& arguments) {
  FontChoice font_choice;
  LayoutCli options;
  TextCli input;
  Args args(arguments);
  while (args.next()) {
    const std::string& a = args.option();
    if (options.parse(args)) continue;
    if (input.parse(args)) continue;
    if (font_choice.parse(args)) continue;
    if (a != "--json") throw UsageError{"unknown option " + a};  // JSON is the only output; --json is accepted
  }
  const std::string text = input.read();
  FontCollection fonts(default_font());
  const Paragraph p = layout_from_cli(fonts, options, font_choice, input.size_px,
                                      input.features ? parse_features(*input.features) : std::vector<Feature>{}, text);
  std::string out = "{\"text_bytes\":" + std::to_string(p.text().size());
  const Rect logical = p.logical_bounds();
  const Rect ink = p.ink_bounds();
  out += ",\"logical\":[" + num(logical.x) + "," + num(logical.y) + "," + num(logical.width) + "," +
         num(logical.height) + "]";
  out += ",\"ink\":[" + num(ink.x) + "," + num(ink.y) + "," + num(ink.width) + "," + num(ink.height) + "]";
  out += ",\"lines\":[";
  for (std::size_t k = 0; k < p.lines().size(); ++k) {
    const LayoutLine& l = p.lines()[k];
    if (k) out += ",";
    out += "{\"start\":" + std::to_string(l.start) + ",\"end\":" + std::to_string(l.end) +
           ",\"baseline\":" + num(l.baseline) + ",\"top\":" + num(l.top) + ",\"height\":" + num(l.height) +
           ",\"x\":" + num(l.x) + ",\"width\":" + num(l.width);
    if (l.ellipsized) out += ",\"ellipsized\":true";
    if (l.hyphenated) out += ",\"hyphenated\":true";
    out += ",\"runs\":[";
    for (std::size_t r = 0; r < l.runs.size(); ++r) {
      const GlyphRun& run = l.runs[r];
      if (r) out += ",";
      out += "{\"font\":";
      json_string(out, run.font->path());
      if (run.font->face_index()) out += ",\"face_index\":" + std::to_string(run.font->face_index());
      out += ",\"size\":" + num(run.size_px) + ",\"direction\":\"" + (run.rtl ? "rtl" : "ltr") + "\",\"glyphs\":[";
      for (std::size_t g = 0; g < run.glyphs.size(); ++g) {
        const PositionedGlyph& pg = run.glyphs[g];
        if (g) out += ",";
        out += "{\"id\":" + std::to_string(pg.id) + ",\"cluster\":" + std::to_string(pg.cluster) +
               ",\"x\":" + num(pg.x) + ",\"y\":" + num(pg.y) + "}";
      }
      out += "]}";
    }
    out += "]}";
  }
  out += "]}\n";
  std::fputs(out.c_str(), stdout);
  return 0;
}

}  // namespace curvetext::cli
