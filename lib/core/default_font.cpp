#include "curvetext/default_font.hpp"

#include <cstdlib>
#include <filesystem>
#include <system_error>
#include <vector>

#include "curvetext/error.hpp"

#ifndef CURVETEXT_INSTALL_FONT_DIR
#define CURVETEXT_INSTALL_FONT_DIR "/usr/local/share/curvetext/fonts"
#endif

namespace curvetext {

std::string default_font_path(const std::string& build_dir_hint) {
  namespace fs = std::filesystem;
  const char* file = "DejaVuSans.ttf";
  std::vector<fs::path> candidates;
  if (const char* env = std::getenv("CURVETEXT_DEFAULT_FONT"); env && *env) candidates.emplace_back(env);
  if (!build_dir_hint.empty()) candidates.push_back(fs::path(build_dir_hint) / file);
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) candidates.push_back(exe.parent_path().parent_path() / "share/curvetext/fonts" / file);
  candidates.push_back(fs::path(CURVETEXT_INSTALL_FONT_DIR) / file);

  std::string looked;
  for (const fs::path& p : candidates) {
    if (fs::is_regular_file(p, ec)) return p.string();
    looked += (looked.empty() ? "" : ", ") + p.string();
  }
  throw Error(ErrorCode::FontNotFound, "default font not found (looked in " + looked + "); pass --font FILE");
}

}  // namespace curvetext
