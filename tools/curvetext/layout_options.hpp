// Paragraph layout options shared by `curvetext render` and `curvetext layout`.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "cli.hpp"
#include "curvetext/layout.hpp"

namespace curvetext::cli {

struct LayoutCli {
  std::vector<std::string> fonts;  // --font, repeated: fallback order
  ParagraphStyle style;
  bool markup = false;
  bool used = false;  // a paragraph option was given (render switches to paragraph layout)
  // True when args.option() was a layout option (consumed).
  bool parse(Args& args);
};

// Builds the paragraph for the options (fonts, markup as curvetext/markup.hpp reads it, text).
Paragraph layout_from_cli(FontCollection& fonts, const LayoutCli& options, const FontChoice& font_choice,
                          double size_px, const std::vector<Feature>& features, const std::string& text);

int run_layout(const std::vector<std::string>& args);

}  // namespace curvetext::cli
