// Every public header compiles alone: tests/CMakeLists.txt generates one
// source per header holding only its #include (built against the public
// target, without lib/ on the include path), so a header that needs another
// include first, or a private one, fails the build. At run time this checks
// that the headers compiled are every header there is, and that the
// umbrella header curvetext/curvetext.hpp includes every other one.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

// Generated: the names of the headers compiled, "curvetext/<name>.hpp".
std::vector<std::string> curvetext_compiled_headers();

namespace {

// "curvetext/<name>.hpp" for every public header (the generated one too), sorted.
std::vector<std::string> headers_on_disk() {
  std::vector<std::string> on_disk;
  for (const char* dir : {CURVETEXT_PUBLIC_INCLUDE_DIR, CURVETEXT_GENERATED_INCLUDE_DIR})
    for (const auto& entry : std::filesystem::directory_iterator(std::filesystem::path(dir) / "curvetext"))
      if (entry.path().extension() == ".hpp") on_disk.push_back("curvetext/" + entry.path().filename().string());
  std::sort(on_disk.begin(), on_disk.end());
  return on_disk;
}

TEST(PublicHeaders, EveryHeaderCompiledAlone) {
  std::vector<std::string> on_disk = headers_on_disk();
  std::vector<std::string> compiled = curvetext_compiled_headers();
  std::sort(compiled.begin(), compiled.end());
  EXPECT_EQ(compiled, on_disk);
  EXPECT_FALSE(compiled.empty());
}

TEST(PublicHeaders, UmbrellaHeaderIncludesEveryOther) {
  const std::string umbrella = "curvetext/curvetext.hpp";
  std::vector<std::string> others;
  for (const std::string& h : headers_on_disk())
    if (h != umbrella) others.push_back(h);
  std::ifstream in(std::filesystem::path(CURVETEXT_PUBLIC_INCLUDE_DIR) / umbrella);
  ASSERT_TRUE(in) << umbrella << " is missing";
  const std::regex include_line(R"(^\s*#\s*include\s*[<"](curvetext/[^>"]+)[>"])");
  std::vector<std::string> included;
  std::smatch m;
  for (std::string line; std::getline(in, line);)
    if (std::regex_search(line, m, include_line)) included.push_back(m[1]);
  std::sort(included.begin(), included.end());
  EXPECT_EQ(included, others);
}

}  // namespace
