// Paths of the fonts tests use (from Debian packages installed by
// scripts/setup-debian.sh).
#pragma once

namespace curvetext::test {

inline constexpr const char* kDejaVuSans = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
inline constexpr const char* kNotoSans = "/usr/share/fonts/truetype/noto/NotoSans-Regular.ttf";
inline constexpr const char* kNimbusRoman = "/usr/share/fonts/opentype/urw-base35/NimbusRoman-Regular.otf";
inline constexpr const char* kInterVariable = "/usr/share/fonts/truetype/inter-vf/Inter.var.ttf";

}  // namespace curvetext::test
