// The default font installed with curvetext (DejaVu Sans, from Debian's
// fonts-dejavu-core; see fonts/README.md).
#pragma once

#include <string>

namespace curvetext {

// First existing of: $CURVETEXT_DEFAULT_FONT, `build_dir_hint` (the build
// tree's copy, when given), <exe dir>/../share/curvetext/fonts/DejaVuSans.ttf,
// and the install prefix. Throws Error(FontNotFound) listing where it looked.
std::string default_font_path(const std::string& build_dir_hint = {});

}  // namespace curvetext
