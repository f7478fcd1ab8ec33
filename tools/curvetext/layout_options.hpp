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

// Markup for spans (documented in the usage text):
//   <b>bold</b> <i>italic</i> <u>underline</u> <s>strike</s>
//   <color=#c00>red</color> <size=24>bigger</size> <font=Noto Serif>..</font>
//   &lt; &gt; &amp; for the characters < > &.
// Returns the plain text and fills `spans`. Throws Error(InvalidArgument) for
// unknown or unbalanced tags.
std::string parse_markup(const std::string& markup, const TextStyle& base, std::vector<TextSpan>& spans);

// Builds the paragraph for the options (fonts, markup, text).
Paragraph layout_from_cli(FontCollection& fonts, const LayoutCli& options, const FontChoice& font_choice,
                          double size_px, const std::vector<Feature>& features, const std::string& text);

int run_layout(const std::vector<std::string>& args);

}  // namespace curvetext::cli
