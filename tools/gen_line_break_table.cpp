// Build-time generator (not part of the library): turns the Unicode Character
// Database files of Debian's unicode-data package into the compact line break
// class table that lib/layout/line_break.cpp includes.
//
//   gen_line_break_table LineBreak.txt EastAsianWidth.txt UnicodeData.txt emoji-data.txt OUT.inc
//
// One byte per code point, stored as a two-stage table (blocks of 128 code
// points, identical blocks shared):
//   bits 0-5  Line_Break class after UAX #14 LB1 (AI, SG, XX -> AL; SA -> CM
//             for Mn/Mc, else AL; CJ -> NS), numbered as kClassNames below
//   bit 6     East_Asian_Width is F, W or H (LB30)
//   bit 7     Extended_Pictographic and unassigned (Cn) (LB30b)
#include <array>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace {

// Must match enum class Lb in line_break.cpp.
const char* const kClassNames[] = {"BK", "CR", "LF", "NL", "SP", "ZW", "WJ", "GL", "CM", "ZWJ", "OP",
                                   "CL", "CP", "QU", "IS", "SY", "NS", "EX", "BA", "BB", "B2",  "HY",
                                   "CB", "HL", "AL", "NU", "PR", "PO", "ID", "EB", "EM", "IN",  "H2",
                                   "H3", "JL", "JV", "JT", "RI", "AK", "AP", "AS", "VI", "VF"};
constexpr std::uint32_t kMax = 0x110000;

struct Line {
  std::uint32_t first, last;
  std::string value;
};

std::string trim(const std::string& s) {
  const auto a = s.find_first_not_of(" \t");
  if (a == std::string::npos) return {};
  const auto b = s.find_last_not_of(" \t");
  return s.substr(a, b - a + 1);
}

// "XXXX..YYYY;value # comment" or "XXXX;value"
std::vector<Line> read_ranges(const char* path) {
  std::ifstream in(path);
  if (!in) {
    std::fprintf(stderr, "gen_line_break_table: cannot read %s (Debian package unicode-data)\n", path);
    std::exit(1);
  }
  std::vector<Line> out;
  std::string line;
  while (std::getline(in, line)) {
    line = line.substr(0, line.find('#'));
    const auto semi = line.find(';');
    if (semi == std::string::npos) continue;
    const std::string range = trim(line.substr(0, semi));
    const auto dots = range.find("..");
    Line l;
    l.first = static_cast<std::uint32_t>(std::stoul(range.substr(0, dots), nullptr, 16));
    l.last = dots == std::string::npos ? l.first
                                       : static_cast<std::uint32_t>(std::stoul(range.substr(dots + 2), nullptr, 16));
    l.value = trim(line.substr(semi + 1));
    out.push_back(l);
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 6) {
    std::fprintf(stderr, "usage: %s LineBreak.txt EastAsianWidth.txt UnicodeData.txt emoji-data.txt OUT.inc\n",
                 argv[0]);
    return 2;
  }
  std::map<std::string, int> class_of;
  for (int i = 0; i < static_cast<int>(std::size(kClassNames)); ++i) class_of[kClassNames[i]] = i;
  class_of["AI"] = class_of["SG"] = class_of["XX"] = class_of["AL"];
  class_of["CJ"] = class_of["NS"];
  const int sa = 100;
  class_of["SA"] = sa;

  // General categories (UnicodeData.txt; "<..., First>"/"<..., Last>" pairs are ranges).
  std::vector<std::string> gc(kMax, "Cn");
  {
    std::ifstream in(argv[3]);
    if (!in) {
      std::fprintf(stderr, "gen_line_break_table: cannot read %s\n", argv[3]);
      return 1;
    }
    std::string line;
    std::uint32_t range_first = 0;
    while (std::getline(in, line)) {
      std::vector<std::string> f;
      std::istringstream s(line);
      std::string field;
      while (std::getline(s, field, ';')) f.push_back(field);
      if (f.size() < 3) continue;
      const auto c = static_cast<std::uint32_t>(std::stoul(f[0], nullptr, 16));
      if (f[1].find(", First>") != std::string::npos) {
        range_first = c;
        continue;
      }
      const std::uint32_t from = f[1].find(", Last>") != std::string::npos ? range_first : c;
      for (std::uint32_t k = from; k <= c; ++k) gc[k] = f[2];
    }
  }

  // Line_Break: @missing default XX (-> AL), the defaults UAX #14 / the file
  // header give for unlisted code points, then the listed values.
  std::vector<int> lb(kMax, class_of["AL"]);
  const std::array<std::pair<std::uint32_t, std::uint32_t>, 7> id_ranges = {{{0x3400, 0x4DBF},
                                                                             {0x4E00, 0x9FFF},
                                                                             {0xF900, 0xFAFF},
                                                                             {0x20000, 0x2FFFD},
                                                                             {0x30000, 0x3FFFD},
                                                                             {0x1F000, 0x1FAFF},
                                                                             {0x1FC00, 0x1FFFD}}};
  for (const auto& [a, b] : id_ranges)
    for (std::uint32_t c = a; c <= b; ++c) lb[c] = class_of["ID"];
  for (std::uint32_t c = 0x20A0; c <= 0x20CF; ++c) lb[c] = class_of["PR"];
  for (const Line& l : read_ranges(argv[1])) {
    const auto it = class_of.find(l.value);
    if (it == class_of.end()) {
      std::fprintf(stderr, "gen_line_break_table: unknown class %s\n", l.value.c_str());
      return 1;
    }
    for (std::uint32_t c = l.first; c <= l.last; ++c) lb[c] = it->second;
  }
  for (std::uint32_t c = 0; c < kMax; ++c)
    if (lb[c] == sa) lb[c] = gc[c] == "Mn" || gc[c] == "Mc" ? class_of["CM"] : class_of["AL"];

  // East_Asian_Width F, W or H (unlisted CJK ranges default to W).
  std::vector<bool> wide(kMax, false);
  for (const auto& [a, b] : id_ranges)
    if (a < 0x1F000)
      for (std::uint32_t c = a; c <= b; ++c) wide[c] = true;
  for (const Line& l : read_ranges(argv[2]))
    for (std::uint32_t c = l.first; c <= l.last; ++c) wide[c] = l.value == "F" || l.value == "W" || l.value == "H";

  std::vector<bool> pict_cn(kMax, false);
  for (const Line& l : read_ranges(argv[4]))
    if (l.value == "Extended_Pictographic")
      for (std::uint32_t c = l.first; c <= l.last; ++c) pict_cn[c] = gc[c] == "Cn";

  constexpr std::uint32_t kBlock = 128;
  std::vector<std::uint16_t> stage1;
  std::vector<std::vector<std::uint8_t>> blocks;
  std::map<std::string, std::uint16_t> index;
  for (std::uint32_t b = 0; b < kMax / kBlock; ++b) {
    std::vector<std::uint8_t> block(kBlock);
    for (std::uint32_t k = 0; k < kBlock; ++k) {
      const std::uint32_t c = b * kBlock + k;
      block[k] = static_cast<std::uint8_t>(lb[c] | (wide[c] ? 0x40 : 0) | (pict_cn[c] ? 0x80 : 0));
    }
    auto [it, inserted] =
        index.emplace(std::string(block.begin(), block.end()), static_cast<std::uint16_t>(blocks.size()));
    if (inserted) blocks.push_back(block);
    stage1.push_back(it->second);
  }

  std::FILE* out = std::fopen(argv[5], "w");
  if (!out) {
    std::fprintf(stderr, "gen_line_break_table: cannot write %s\n", argv[5]);
    return 1;
  }
  std::fprintf(out, "// Generated by tools/gen_line_break_table.cpp from %s, %s, %s and %s. Do not edit.\n", argv[1],
               argv[2], argv[3], argv[4]);
  std::fprintf(out, "constexpr unsigned kLbBlockShift = 7;\n");
  std::fprintf(out, "constexpr unsigned char kLbBlocks[%zu][%u] = {\n", blocks.size(), kBlock);
  for (const auto& block : blocks) {
    std::fprintf(out, "{");
    for (std::uint32_t k = 0; k < kBlock; ++k) std::fprintf(out, "%u,", block[k]);
    std::fprintf(out, "},\n");
  }
  std::fprintf(out, "};\nconstexpr unsigned short kLbStage1[%zu] = {", stage1.size());
  for (std::size_t i = 0; i < stage1.size(); ++i) std::fprintf(out, "%s%u,", i % 32 == 0 ? "\n" : "", stage1[i]);
  std::fprintf(out, "\n};\n");
  std::fclose(out);
  std::printf("gen_line_break_table: %zu blocks of %u, %zu bytes\n", blocks.size(), kBlock,
              blocks.size() * kBlock + stage1.size() * 2);
  return 0;
}
