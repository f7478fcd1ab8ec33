// Shared pieces of the curvetext CLI's subcommands.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "curvetext/font.hpp"

namespace curvetext::cli {

// A mistake in how the command was called: exit status 2 with the usage text.
struct UsageError {
  std::string message;
};

double parse_number(std::string_view option, std::string_view text);
int parse_int(std::string_view option, std::string_view text);

// The text of --text-file: the file's bytes without one trailing line break
// (the file's, not the text's). Error(Io) when it cannot be read.
std::string read_text_file(const std::string& path);

// default_font_path() (the build tree's copy first), its error naming the
// CLI's way to pass a font.
std::string default_font();

// Walks argv-style arguments; `value()` takes the option's value or throws
// UsageError naming the option.
class Args {
 public:
  explicit Args(std::vector<std::string> args) : args_(std::move(args)) {}
  bool next() { return ++index_ < args_.size(); }
  const std::string& option() const { return args_[index_]; }
  const std::string& value() {
    if (index_ + 1 >= args_.size()) throw UsageError{args_[index_] + " needs a value"};
    return args_[++index_];
  }

 private:
  std::vector<std::string> args_;
  std::size_t index_ = static_cast<std::size_t>(-1);
};

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
