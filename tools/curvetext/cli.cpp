#include "cli.hpp"

#include <charconv>
#include <fstream>

#include "curvetext/default_font.hpp"
#include "curvetext/error.hpp"
#include "curvetext/tolerances.hpp"

#ifndef CURVETEXT_BUILD_FONT_DIR
#define CURVETEXT_BUILD_FONT_DIR ""
#endif

namespace curvetext::cli {

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
  if (!in) throw Error(ErrorCode::Io, "cannot read text file " + path);
  // Chunk by chunk up to the limit and a line break (which is dropped): an
  // endless file (/dev/zero, a pipe) stops there.
  std::string text;
  char chunk[1 << 16];
  while (in.read(chunk, sizeof chunk) || in.gcount() > 0) {
    text.append(chunk, static_cast<std::size_t>(in.gcount()));
    if (text.size() > tolerance::kMaxTextBytes + 2)
      throw Error(ErrorCode::InvalidText, "text file " + path + " is larger than the limit of " +
                                              std::to_string(tolerance::kMaxTextBytes) + " bytes");
  }
  if (in.bad()) throw Error(ErrorCode::Io, "cannot read text file " + path);
  if (!text.empty() && text.back() == '\n') text.pop_back();
  if (!text.empty() && text.back() == '\r') text.pop_back();
  return text;
}

std::string default_font() {
  try {
    return default_font_path(CURVETEXT_BUILD_FONT_DIR);
  } catch (const Error& e) {
    if (e.code() != ErrorCode::FontNotFound) throw;
    throw Error(e.code(), std::string(e.what()) + "; on the command line: --font FILE");
  }
}

bool FontChoice::parse(Args& args) {
  const std::string& o = args.option();
  if (o == "--font")
    path = args.value();
  else if (o == "--face-index")
    face_index = parse_int(o, args.value());
  else if (o == "--variations")
    variations = args.value();
  else
    return false;
  if (face_index < 0) throw UsageError{"--face-index must be 0 or more"};
  return true;
}

Font FontChoice::open() const {
  Font font = Font::open(path ? *path : default_font(), face_index);
  if (variations) font.set_variations(parse_variations(*variations));
  return font;
}

}  // namespace curvetext::cli
