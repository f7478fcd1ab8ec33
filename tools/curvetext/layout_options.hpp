// Paragraph layout options shared by `curvetext render` and `curvetext layout`.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "cli.hpp"
#include "curvetext/layout.hpp"

namespace curvetext::cli {

// Every paragraph option; --font (a file or a fontconfig family name) is
// repeated for the fallback order.
struct LayoutCli {
  std::vector<std::string> fonts;  // --font, repeated: fallback order
  ParagraphStyle style;
  bool markup = false;
  // True when args.option() was a layout option (consumed).
  bool parse(Args& args);
};

// What is laid out: --size (default kDefaultSizePx), --text or --text-file
// ("-" for either reads standard input), --features.
struct TextCli {
  std::optional<std::string> text, text_file, features;
  double size_px = kDefaultSizePx;
  // True when args.option() was one of the options above (consumed).
  bool parse(Args& args);
  // The text given. Throws UsageError unless exactly one of --text and
  // --text-file was given, and read_text_file's errors.
  std::string read() const;
};

// Builds the paragraph for the options (fonts, markup as curvetext/markup.hpp reads it, text).
Paragraph layout_from_cli(FontCollection& fonts, const LayoutCli& options, const FontChoice& font_choice,
                          double size_px, const std::vector<Feature>& features, const std::string& text);

int run_layout(const std::vector<std::string>& args);

}  // namespace curvetext::cli
