// The exact output of build_mesh, hashed, against the hashes stored in
// tests/mesh_hash/expected.txt: every glyph of a set of real fonts (a fixed
// sample of the CJK font's) and every input of the fuzz corpora that build
// meshes. Each hash covers the mesh's bytes (points, indices, weights,
// convexity) or, for a refused input, the error message. A change to the
// tessellator that is meant to keep its output must leave every hash as it
// is; one that changes output on purpose regenerates the file
// (CURVETEXT_MESH_HASH_OUTPUT=<file> writes the hashes computed) and says why
// in its commit.
//
// A font whose file is missing, or whose bytes differ from those hashed
// (another version of the package), is skipped: its meshes are not the ones
// stored.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <ostream>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

#include "curvetext/error.hpp"
#include "curvetext/font.hpp"
#include "curvetext/mesh.hpp"
#include "fuzz_support.hpp"

extern "C" int mesh_hash_outline_input(const std::uint8_t* data, std::size_t size);
extern "C" int mesh_hash_svg_path_input(const std::uint8_t* data, std::size_t size);
extern "C" int mesh_hash_nurbs_json_input(const std::uint8_t* data, std::size_t size);
extern "C" int mesh_hash_svg_input(const std::uint8_t* data, std::size_t size);
extern "C" int mesh_hash_font_input(const std::uint8_t* data, std::size_t size);

namespace curvetext {
namespace {

namespace fs = std::filesystem;

// FNV-1a, 64 bits: stable across platforms and runs, enough to tell meshes apart.
class Hash {
 public:
  void bytes(const void* data, std::size_t size) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i) value_ = (value_ ^ p[i]) * 0x100000001b3ull;
  }
  template <class T>
  void value(const T& v) {
    bytes(&v, sizeof v);
  }
  void text(std::string_view s) {
    value(s.size());
    bytes(s.data(), s.size());
  }
  // Field by field: no padding bytes enter the hash.
  void mesh(const Mesh& m) {
    value(m.points.size());
    for (const Vec2& p : m.points) value(p.x), value(p.y);
    value(m.triangles.size());
    for (const auto& t : m.triangles) value(t);
    value(m.curves.size());
    for (const CurvedTriangle& c : m.curves) {
      value(c.p0), value(c.control), value(c.p2), value(c.weight);
      value(static_cast<std::uint8_t>(c.convex));
    }
    value(m.boundary_lines.size());
    for (const auto& l : m.boundary_lines) value(l);
  }
  void error(const char* message) {
    bytes("error", 5);
    text(message);
  }
  std::uint64_t get() const { return value_; }
  std::string hex() const {
    char buffer[17];
    std::snprintf(buffer, sizeof buffer, "%016llx", static_cast<unsigned long long>(value_));
    return buffer;
  }

 private:
  std::uint64_t value_ = 0xcbf29ce484222325ull;
};

std::vector<std::uint8_t> read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// tests/mesh_hash/expected.txt: "<key> <hash...>" per line, '#' comments.
const std::map<std::string, std::string>& expected() {
  static const std::map<std::string, std::string> table = [] {
    std::map<std::string, std::string> t;
    std::ifstream in(fs::path(CURVETEXT_SOURCE_DIR) / "tests/mesh_hash/expected.txt");
    std::string line;
    while (std::getline(in, line)) {
      if (line.empty() || line[0] == '#') continue;
      const std::size_t space = line.find(' ');
      t[line.substr(0, space)] = line.substr(space + 1);
    }
    return t;
  }();
  return table;
}

// With CURVETEXT_MESH_HASH_OUTPUT set, every computed line is appended to that file.
void record(const std::string& key, const std::string& value) {
  if (const char* out = std::getenv("CURVETEXT_MESH_HASH_OUTPUT")) {
    std::ofstream(out, std::ios::app) << key << ' ' << value << '\n';
  }
}

void expect_stored(const std::string& key, const std::string& value) {
  record(key, value);
  const auto it = expected().find(key);
  ASSERT_NE(it, expected().end()) << key << " has no stored hash (computed: " << value << ")";
  EXPECT_EQ(it->second, value) << key << ": the meshes differ from the stored ones";
}

struct HashFont {
  const char* name;
  const char* path;
  int face_index;
  double cubic_tolerance_per_em;
  float wght;                // variable fonts: the weight instance (0: default)
  std::uint32_t glyph_step;  // every glyph_step-th glyph id (1: all)
};

void PrintTo(const HashFont& font, std::ostream* os) { *os << font.name; }

class MeshHashFonts : public ::testing::TestWithParam<HashFont> {};

TEST_P(MeshHashFonts, EveryGlyphMeshIsTheStoredOne) {
  const HashFont& spec = GetParam();
  if (!fs::exists(spec.path)) GTEST_SKIP() << spec.path << " not installed";
  const std::vector<std::uint8_t> file = read_file(spec.path);
  Hash file_hash;
  file_hash.bytes(file.data(), file.size());
  const std::string key = std::string("font.") + spec.name;
  const auto it = expected().find(key);
  if (it != expected().end() && it->second.rfind(file_hash.hex(), 0) != 0) {
    GTEST_SKIP() << spec.path << " is not the file the stored hashes were made from";
  }

  Font font = Font::open(spec.path, spec.face_index);
  if (spec.wght > 0.0f) font.set_variations({{"wght", spec.wght}});
  const MeshOptions options{spec.cubic_tolerance_per_em * font.metrics().units_per_em};
  Hash meshes;
  Outline outline;
  Mesh mesh;  // reused, as a glyph cache does
  std::size_t glyphs = 0;
  for (std::uint32_t gid = 0; gid < font.glyph_count(); gid += spec.glyph_step, ++glyphs) {
    font.glyph_outline(gid, outline);
    try {
      build_mesh(outline, options, mesh);
      meshes.mesh(mesh);
    } catch (const Error& e) {
      meshes.error(e.what());
    }
  }
  expect_stored(key, file_hash.hex() + ' ' + std::to_string(glyphs) + ' ' + meshes.hex());
}

INSTANTIATE_TEST_SUITE_P(
    Fonts, MeshHashFonts,
    ::testing::Values(
        HashFont{"DejaVuSans", "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf", 0, 1.0 / 1000.0, 0.0f, 1},
        HashFont{"DejaVuSerifBold", "/usr/share/fonts/truetype/dejavu/DejaVuSerif-Bold.ttf", 0, 1.0 / 1000.0, 0.0f, 1},
        HashFont{"NimbusRoman", "/usr/share/fonts/opentype/urw-base35/NimbusRoman-Regular.otf", 0, 1.0 / 1000.0, 0.0f,
                 1},
        // Cubics approximated coarsely (few quadratics per cubic).
        HashFont{"NimbusRomanCoarse", "/usr/share/fonts/opentype/urw-base35/NimbusRoman-Regular.otf", 0, 1.0 / 64.0,
                 0.0f, 1},
        HashFont{"NimbusSansBoldItalic", "/usr/share/fonts/opentype/urw-base35/NimbusSans-BoldItalic.otf", 0,
                 1.0 / 1000.0, 0.0f, 1},
        HashFont{"URWBookmanLight", "/usr/share/fonts/opentype/urw-base35/URWBookman-Light.otf", 0, 1.0 / 1000.0, 0.0f,
                 1},
        HashFont{"NotoSans", "/usr/share/fonts/truetype/noto/NotoSans-Regular.ttf", 0, 1.0 / 1000.0, 0.0f, 1},
        // Inter's glyphs overlap their own contours: the crossing resolver.
        HashFont{"InterWght100", "/usr/share/fonts/truetype/inter-vf/Inter.var.ttf", 0, 1.0 / 1000.0, 100.0f, 1},
        HashFont{"InterWght400", "/usr/share/fonts/truetype/inter-vf/Inter.var.ttf", 0, 1.0 / 1000.0, 400.0f, 1},
        HashFont{"InterWght900", "/usr/share/fonts/truetype/inter-vf/Inter.var.ttf", 0, 1.0 / 1000.0, 900.0f, 1},
        HashFont{"InterItalicWght700", "/usr/share/fonts/truetype/inter-vf/Inter-italic.var.ttf", 0, 1.0 / 1000.0,
                 700.0f, 1},
        HashFont{"NotoSansCJK", "/usr/share/fonts/opentype/noto/NotoSansCJK-Regular.ttc", 0, 1.0 / 1000.0, 0.0f, 4},
        HashFont{"NotoSerifCJKBold", "/usr/share/fonts/opentype/noto/NotoSerifCJK-Bold.ttc", 0, 1.0 / 1000.0, 0.0f, 16},
        HashFont{"CurvetextTestCFF2", CURVETEXT_SOURCE_DIR "/fonts/test/CurvetextTest-CFF2.otf", 0, 1.0 / 1000.0, 0.0f,
                 1},
        HashFont{"CurvetextTestVarCFF2", CURVETEXT_SOURCE_DIR "/fonts/test/CurvetextTestVar-CFF2.otf", 0, 1.0 / 1000.0,
                 0.0f, 1}),
    [](const ::testing::TestParamInfo<HashFont>& param_info) { return std::string(param_info.param.name); });

// The meshes one fuzz input builds, folded into one hash.
Hash* current = nullptr;
void observe(const Mesh* mesh, const char* error) {
  if (mesh)
    current->mesh(*mesh);
  else
    current->error(error);
}

struct HashTarget {
  const char* name;
  int (*run)(const std::uint8_t*, std::size_t);
  std::vector<const char*> inputs;  // folders (their files) or files, under the source tree
};

void PrintTo(const HashTarget& target, std::ostream* os) { *os << target.name; }

class MeshHashFuzzCorpus : public ::testing::TestWithParam<HashTarget> {};

TEST_P(MeshHashFuzzCorpus, EveryInputsMeshesAreTheStoredOnes) {
  const HashTarget& target = GetParam();
  std::vector<fs::path> files;
  for (const char* input : target.inputs) {
    const fs::path path = fs::path(CURVETEXT_SOURCE_DIR) / input;
    if (fs::is_directory(path)) {
      for (const auto& entry : fs::directory_iterator(path))
        if (entry.is_regular_file()) files.push_back(entry.path());
    } else {
      files.push_back(path);
    }
  }
  std::sort(files.begin(), files.end());
  ASSERT_FALSE(files.empty());
  fuzz::mesh_observer = observe;
  for (const fs::path& file : files) {
    const std::vector<std::uint8_t> bytes = read_file(file);
    Hash h;
    current = &h;
    target.run(bytes.data(), bytes.size());
    const std::string relative = fs::relative(file, CURVETEXT_SOURCE_DIR).generic_string();
    expect_stored(std::string("fuzz.") + target.name + ':' + relative, h.hex());
  }
  fuzz::mesh_observer = nullptr;
  current = nullptr;
}

INSTANTIATE_TEST_SUITE_P(
    Targets, MeshHashFuzzCorpus,
    ::testing::Values(
        HashTarget{"outline", mesh_hash_outline_input, {"tests/fuzz/corpus/outline"}},
        HashTarget{"svg_path", mesh_hash_svg_path_input, {"tests/fuzz/corpus/svg_path", "tests/fuzz/slow/svg_path"}},
        HashTarget{"nurbs_json",
                   mesh_hash_nurbs_json_input,
                   {"tests/fuzz/corpus/nurbs_json", "tests/fixtures/shapes", "docs/shapes/handle-weights.json",
                    "docs/shapes/weights-triangle.json"}},
        HashTarget{"svg", mesh_hash_svg_input, {"tests/fuzz/corpus/svg", "tests/fixtures/shapes"}},
        HashTarget{"font", mesh_hash_font_input, {"tests/fuzz/corpus/font", "fonts/test"}}),
    [](const ::testing::TestParamInfo<HashTarget>& param_info) { return std::string(param_info.param.name); });

}  // namespace
}  // namespace curvetext
