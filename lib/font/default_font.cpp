#include "curvetext/default_font.hpp"

#include <dlfcn.h>
#include <fontconfig/fontconfig.h>
#include <link.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>
#include <system_error>

#include "curvetext/error.hpp"
#include "font/default_font_lookup.hpp"

// Set by lib/CMakeLists.txt: the installed font's place relative to the
// installed library and programs (the build tree has the same layout). No
// absolute path: an installed tree can be moved, and names no build tree.
#ifndef CURVETEXT_FONT_FROM_LIBDIR
#define CURVETEXT_FONT_FROM_LIBDIR "../share/curvetext/fonts"
#endif
#ifndef CURVETEXT_FONT_FROM_BINDIR
#define CURVETEXT_FONT_FROM_BINDIR "../share/curvetext/fonts"
#endif

namespace curvetext {

namespace fs = std::filesystem;

namespace detail {

namespace {
// Its address tells dladdr which loaded file holds this code.
const char kAnchor = 0;
}  // namespace

std::string library_file() {
  Dl_info info{};
  link_map* map = nullptr;
  if (dladdr1(&kAnchor, &info, reinterpret_cast<void**>(&map), RTLD_DL_LINKMAP) != 0 && map != nullptr &&
      map->l_name != nullptr && map->l_name[0] != '\0')
    return map->l_name;
  // The main program has no name in the link map (dladdr would give argv[0]).
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  return ec ? std::string() : exe.string();
}

std::vector<std::string> default_font_candidates(const std::string& build_dir_hint) {
  std::vector<std::string> out;
  auto add = [&out](const fs::path& p) {
    const std::string s = p.lexically_normal().string();
    for (const std::string& o : out)
      if (o == s) return;
    out.push_back(s);
  };
  if (const char* env = std::getenv("CURVETEXT_DEFAULT_FONT"); env != nullptr && *env != '\0') add(env);
  if (!build_dir_hint.empty()) add(fs::path(build_dir_hint) / kDefaultFontFile);
  if (const std::string lib = library_file(); !lib.empty()) {
    const fs::path dir = fs::path(lib).parent_path();
    add(dir / CURVETEXT_FONT_FROM_LIBDIR / kDefaultFontFile);
    add(dir / CURVETEXT_FONT_FROM_BINDIR / kDefaultFontFile);
  }
  return out;
}

std::string fontconfig_default_font() {
  if (!FcInit()) return {};
  struct PatternDeleter {
    void operator()(FcPattern* p) const noexcept { FcPatternDestroy(p); }
  };
  using PatternPtr = std::unique_ptr<FcPattern, PatternDeleter>;
  PatternPtr pattern(FcPatternCreate());
  if (!pattern) return {};
  FcPatternAddString(pattern.get(), FC_FAMILY, reinterpret_cast<const FcChar8*>(kDefaultFontFamily));
  FcPatternAddBool(pattern.get(), FC_SCALABLE, FcTrue);
  FcConfigSubstitute(nullptr, pattern.get(), FcMatchPattern);
  FcDefaultSubstitute(pattern.get());
  FcResult result = FcResultNoMatch;
  PatternPtr match(FcFontMatch(nullptr, pattern.get(), &result));
  if (!match) return {};
  bool family_matches = false;
  FcChar8* family = nullptr;
  for (int i = 0; FcPatternGetString(match.get(), FC_FAMILY, i, &family) == FcResultMatch; ++i)
    if (std::strcmp(reinterpret_cast<const char*>(family), kDefaultFontFamily) == 0) family_matches = true;
  FcChar8* file = nullptr;
  if (!family_matches || FcPatternGetString(match.get(), FC_FILE, 0, &file) != FcResultMatch) return {};
  std::error_code ec;
  const std::string path = reinterpret_cast<const char*>(file);
  return fs::is_regular_file(path, ec) ? path : std::string();
}

std::string find_default_font(const std::vector<std::string>& candidates, bool ask_fontconfig) {
  std::error_code ec;
  std::string looked;
  for (const std::string& p : candidates) {
    if (fs::is_regular_file(p, ec)) return p;
    looked += (looked.empty() ? "" : ", ") + p;
  }
  if (ask_fontconfig) {
    if (std::string p = fontconfig_default_font(); !p.empty()) return p;
  }
  std::string message = std::string("default font ") + kDefaultFontFamily + " (" + kDefaultFontFile + ") not found";
  if (!looked.empty()) message += " in " + looked;
  if (ask_fontconfig) message += std::string(looked.empty() ? "" : " or") + " through fontconfig";
  message +=
      "; install it (Debian: fonts-dejavu-core) or pass a font file instead (Font::open(path), "
      "TextStyle::fonts, FontCollection(path), or $CURVETEXT_DEFAULT_FONT)";
  throw Error(ErrorCode::FontNotFound, message);
}

}  // namespace detail

std::string default_font_path(const std::string& build_dir_hint) {
  return detail::find_default_font(detail::default_font_candidates(build_dir_hint), true);
}

}  // namespace curvetext
