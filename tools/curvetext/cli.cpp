#include "cli.hpp"

#include <fontconfig/fontconfig.h>
#include <unistd.h>

#include <cctype>
#include <charconv>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "curvetext/default_font.hpp"
#include "curvetext/error.hpp"
#include "curvetext/tolerances.hpp"

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
  const bool from_stdin = path == "-";
  const std::string name = from_stdin ? std::string("standard input") : "text file " + path;
  std::FILE* in = from_stdin ? stdin : std::fopen(path.c_str(), "rb");
  if (!in) throw Error(ErrorCode::Io, "cannot read " + name);
  // Chunk by chunk up to the limit and a line break (which is dropped): an
  // endless file (/dev/zero, a pipe) stops there.
  std::string text;
  char chunk[1 << 16];
  std::size_t n = 0;
  while (text.size() <= tolerance::kMaxTextBytes + 2 && (n = std::fread(chunk, 1, sizeof chunk, in)) > 0)
    text.append(chunk, n);
  const bool failed = std::ferror(in) != 0;
  if (!from_stdin) std::fclose(in);
  if (text.size() > tolerance::kMaxTextBytes + 2)
    throw Error(ErrorCode::InvalidText,
                name + " is larger than the limit of " + std::to_string(tolerance::kMaxTextBytes) + " bytes");
  if (failed) throw Error(ErrorCode::Io, "cannot read " + name);
  if (!text.empty() && text.back() == '\n') text.pop_back();
  if (!text.empty() && text.back() == '\r') text.pop_back();
  return text;
}

bool Args::next() {
  if (inline_value_ && !inline_taken_) throw UsageError{option_ + " takes no value, got '" + *inline_value_ + "'"};
  inline_value_.reset();
  inline_taken_ = false;
  if (++index_ >= args_.size()) return false;
  const std::string& arg = args_[index_];
  const std::size_t eq = arg.find('=');
  if (arg.rfind("--", 0) == 0 && eq != std::string::npos) {
    option_ = arg.substr(0, eq);
    inline_value_ = arg.substr(eq + 1);
  } else {
    option_ = arg;
  }
  return true;
}

const std::string& Args::value() {
  if (inline_value_) {
    inline_taken_ = true;
    return *inline_value_;
  }
  if (index_ + 1 >= args_.size()) throw UsageError{option_ + " needs a value"};
  return args_[++index_];
}

OutputFormat output_format(const std::string& path, const std::optional<std::string>& format) {
  std::string kind;
  if (format) {
    kind = *format;
  } else if (path == "-") {
    kind = "png";
  } else {
    const std::size_t dot = path.find_last_of("./");
    if (dot != std::string::npos && path[dot] == '.') kind = path.substr(dot + 1);
    for (char& c : kind) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  if (kind == "png") return OutputFormat::Png;
  if (kind == "svg") return OutputFormat::Svg;
  if (format) throw UsageError{"--format needs png or svg, got '" + *format + "'"};
  throw Error(ErrorCode::InvalidArgument,
              "cannot write '" + path + "': the output must end in .png or .svg (or give --format png|svg)");
}

void write_output(std::string_view bytes, const std::string& path) {
  const bool to_stdout = path == "-";
  std::FILE* out = to_stdout ? stdout : std::fopen(path.c_str(), "wb");
  if (!out) throw Error(ErrorCode::Io, "cannot write " + path);
  bool ok = std::fwrite(bytes.data(), 1, bytes.size(), out) == bytes.size();
  ok = (to_stdout ? std::fflush(out) : std::fclose(out)) == 0 && ok;
  if (!ok) throw Error(ErrorCode::Io, "cannot write " + std::string(to_stdout ? "standard output" : path));
}

void write_png_output(const Image& image, const std::string& path) {
  if (path != "-") return write_png(image, path);
  if (isatty(STDOUT_FILENO)) throw Error(ErrorCode::Io, "standard output is a terminal: not writing a PNG there");
  const std::vector<std::uint8_t> bytes = encode_png(image);
  write_output(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), "-");
}

namespace {

// Family names compare as fontconfig compares them: case and blanks ignored.
std::string family_key(const FcChar8* name) {
  std::string key;
  for (const FcChar8* c = name; *c; ++c)
    if (*c != ' ') key += static_cast<char>(std::tolower(*c));
  return key;
}

}  // namespace

bool is_font_file(const std::string& name) {
  std::string path = name;
  if (const std::size_t hash = name.rfind('#'); hash != std::string::npos && hash + 1 < name.size() &&
                                                name.find_first_not_of("0123456789", hash + 1) == std::string::npos)
    path = name.substr(0, hash);
  std::error_code ec;
  return path.find('/') != std::string::npos || std::filesystem::exists(path, ec);
}

void check_font_family(const std::string& pattern) {
  using Pattern = std::unique_ptr<FcPattern, decltype(&FcPatternDestroy)>;
  Pattern asked(FcNameParse(reinterpret_cast<const FcChar8*>(pattern.c_str())), &FcPatternDestroy);
  FcChar8* family = nullptr;
  if (!asked || FcPatternGetString(asked.get(), FC_FAMILY, 0, &family) != FcResultMatch) return;
  for (const char* generic :
       {"sans-serif", "sans", "serif", "monospace", "mono", "cursive", "fantasy", "emoji", "math", "system-ui"})
    if (FcStrCmpIgnoreCase(family, reinterpret_cast<const FcChar8*>(generic)) == 0) return;
  Pattern query(FcPatternDuplicate(asked.get()), &FcPatternDestroy);
  FcConfigSubstitute(nullptr, query.get(), FcMatchPattern);
  FcDefaultSubstitute(query.get());
  FcResult result = FcResultNoMatch;
  Pattern match(FcFontMatch(nullptr, query.get(), &result), &FcPatternDestroy);
  FcChar8* name = nullptr;
  for (int i = 0; match && FcPatternGetString(match.get(), FC_FAMILY, i, &name) == FcResultMatch; ++i)
    if (family_key(name) == family_key(family)) return;
  throw Error(ErrorCode::FontNotFound,
              "no font family '" + std::string(reinterpret_cast<const char*>(family)) +
                  "' (fontconfig); give a font file or an installed family (fc-list : family)");
}

std::string default_font() {
  try {
    return default_font_path();
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
