// Shared pieces of the curvetext CLI's subcommands.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "curvetext/font.hpp"
#include "curvetext/image.hpp"

namespace curvetext::cli {

// A mistake in how the command was called: exit status 2 with the usage text.
struct UsageError {
  std::string message;
};

double parse_number(std::string_view option, std::string_view text);
int parse_int(std::string_view option, std::string_view text);

// The text of --text-file: the file's bytes without one trailing line break
// (the file's, not the text's); "-" reads standard input. Error(Io) when it
// cannot be read, Error(InvalidText) past tolerance::kMaxTextBytes.
std::string read_text_file(const std::string& path);

// Whether --font NAME names a file, as FontCollection::resolve decides: a
// path with '/' or an existing file (a "#N" face suffix aside); otherwise it
// is a fontconfig pattern.
bool is_font_file(const std::string& name);
// fontconfig always answers a pattern with its best match, even for a family
// it does not have: throws Error(FontNotFound) when the pattern's family is
// neither one of the match's family names nor a generic alias (sans-serif,
// serif, monospace, ...), so a misspelt family is refused, not replaced.
void check_font_family(const std::string& pattern);

// default_font_path() (found relative to the program), its error naming the
// CLI's way to pass a font.
std::string default_font();

// The text size when --size is not given: pixels per em.
inline constexpr double kDefaultSizePx = 32.0;

// Walks argv-style arguments. "--name=VALUE" is the option "--name" with its
// value; otherwise `value()` takes the next argument. Throws UsageError
// naming the option when its value is missing, or (from next()) when
// "=VALUE" was given to an option that takes none.
class Args {
 public:
  explicit Args(std::vector<std::string> args) : args_(std::move(args)) {}
  bool next();
  const std::string& option() const { return option_; }
  const std::string& value();

 private:
  std::vector<std::string> args_;
  std::size_t index_ = static_cast<std::size_t>(-1);
  std::string option_;
  std::optional<std::string> inline_value_;
  bool inline_taken_ = false;
};

// What `-o` writes: from the file's extension (.png or .svg, any case), or
// `format` ("png" | "svg") when given; "-" (standard output) is PNG unless
// `format` says otherwise. Throws Error(InvalidArgument) for anything else,
// naming the path.
enum class OutputFormat { Png, Svg };
OutputFormat output_format(const std::string& path, const std::optional<std::string>& format);

// Writes the bytes to `path`, or to standard output for "-". Throws Error(Io)
// naming the path.
void write_output(std::string_view bytes, const std::string& path);
// write_png, or encode_png's bytes to standard output for "-" (refused when
// it is a terminal).
void write_png_output(const Image& image, const std::string& path);

// Options that pick a face: --font FILE, --face-index N, --variations LIST.
struct FontChoice {
  std::optional<std::string> path;
  int face_index = 0;
  std::optional<std::string> variations;
  // True when `args.option()` was one of the font options (consumed).
  bool parse(Args& args);
  // Opens the face (the default font without --font) at the variations.
  Font open() const;
};

int run_render(const std::vector<std::string>& args);
int run_check(const std::vector<std::string>& args);
int run_mesh(const std::vector<std::string>& args);
int run_layout(const std::vector<std::string>& args);
int run_shape(const std::vector<std::string>& args);

}  // namespace curvetext::cli
