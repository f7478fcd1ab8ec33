// The default font installed with curvetext (DejaVu Sans, from Debian's
// fonts-dejavu-core; see fonts/README.md).
#pragma once

#include <string>

#include "curvetext/export.hpp"

namespace curvetext {

// Found at run time, so an installed tree can move: the first existing of
// $CURVETEXT_DEFAULT_FONT, `build_dir_hint`/DejaVuSans.ttf (when given),
// share/curvetext/fonts/DejaVuSans.ttf of the prefix the library (or the
// program a static curvetext is linked into) lies in, the build tree's copy,
// and then fontconfig's file for "DejaVu Sans" (that family only). Throws
// Error(FontNotFound) naming the font, where it looked and how to pass a font
// file instead. Reads the environment and the file system on each call.
CURVETEXT_API std::string default_font_path(const std::string& build_dir_hint = {});

}  // namespace curvetext
