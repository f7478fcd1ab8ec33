// Helpers for the layout tests: Unicode conformance files, skip lists, UTF-8.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace curvetext::test {

inline constexpr const char* kBidiCharacterTest = "/usr/share/unicode/BidiCharacterTest.txt";
inline constexpr const char* kLineBreakTest = "/usr/share/unicode/auxiliary/LineBreakTest.txt";
inline constexpr const char* kNotoArabic = "/usr/share/fonts/truetype/noto/NotoSansArabic-Regular.ttf";
inline constexpr const char* kNotoHebrew = "/usr/share/fonts/truetype/noto/NotoSansHebrew-Regular.ttf";
inline constexpr const char* kNotoDevanagari = "/usr/share/fonts/truetype/noto/NotoSansDevanagari-Regular.ttf";
inline constexpr const char* kNotoThai = "/usr/share/fonts/truetype/noto/NotoSansThai-Regular.ttf";
inline constexpr const char* kNotoCjk = "/usr/share/fonts/opentype/noto/NotoSansCJK-Regular.ttc";

// A skip list: "<line number><TAB><reason>" per line, '#' comments. Maps the
// line number of a conformance case to why it is skipped.
std::map<int, std::string> read_skip_list(const std::string& path);

// Path of a file under tests/fixtures/layout/.
std::string layout_fixture(const std::string& name);

std::string utf8_encode(const std::u32string& text);

}  // namespace curvetext::test
