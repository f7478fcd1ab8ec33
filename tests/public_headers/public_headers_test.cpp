// Every public header compiles alone: tests/CMakeLists.txt generates one
// source per header holding only its #include (built against the public
// target, without lib/ on the include path), so a header that needs another
// include first, or a private one, fails the build. At run time this checks
// that the headers compiled are every header there is.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

// Generated: the names of the headers compiled, "curvetext/<name>.hpp".
std::vector<std::string> curvetext_compiled_headers();

namespace {

TEST(PublicHeaders, EveryHeaderCompiledAlone) {
  std::vector<std::string> on_disk;
  for (const char* dir : {CURVETEXT_PUBLIC_INCLUDE_DIR, CURVETEXT_GENERATED_INCLUDE_DIR})
    for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(dir) / "curvetext"))
      if (entry.path().extension() == ".hpp") on_disk.push_back("curvetext/" + entry.path().filename().string());
  std::vector<std::string> compiled = curvetext_compiled_headers();
  std::sort(on_disk.begin(), on_disk.end());
  std::sort(compiled.begin(), compiled.end());
  EXPECT_EQ(compiled, on_disk);
  EXPECT_FALSE(compiled.empty());
}

}  // namespace
