// The search behind default_font_path() (curvetext/default_font.hpp), in
// pieces so that tests can run it over places of their choosing.
#pragma once

#include <string>
#include <vector>

namespace curvetext::detail {

inline constexpr const char* kDefaultFontFamily = "DejaVu Sans";
inline constexpr const char* kDefaultFontFile = "DejaVuSans.ttf";

// The file holding curvetext's code: the shared library, or the program a
// static curvetext is linked into. Empty when it cannot be told.
std::string library_file();

// The files default_font_path() tries, in order, before asking fontconfig.
std::vector<std::string> default_font_candidates(const std::string& build_dir_hint);

// fontconfig's file for kDefaultFontFamily; empty when fontconfig's best
// match is another family (a substitute would make "the default font" differ
// from machine to machine).
std::string fontconfig_default_font();

// The first candidate that is a file, else (with `ask_fontconfig`)
// fontconfig's. Throws Error(FontNotFound) naming the font, where it looked
// and how to pass a font instead.
std::string find_default_font(const std::vector<std::string>& candidates, bool ask_fontconfig);

}  // namespace curvetext::detail
