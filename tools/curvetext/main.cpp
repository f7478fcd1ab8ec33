// The curvetext command-line tool. Exit status: 0 success, 1 a runtime error
// (bad font, bad text, no GL device, I/O, or `check` finding failures), 2 a
// usage error. Errors are one line on stderr.
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "cli.hpp"
#include "curvetext/error.hpp"
#include "curvetext/version.hpp"

namespace {

constexpr const char* kUsage =
    "usage: curvetext render [--font FILE] [--face-index N] --size PX (--text UTF8 | --text-file FILE)\n"
    "                        -o OUT.png [--margin PX] [--aa none|curves|full|vbaa|msaa|auto] [--curve exact|paper]\n"
    "                        [--variations wght=700,...] [--features \"kern,-liga\"]\n"
    "                        [--fg COLOR] [--bg COLOR] [--blend srgb|linear] [--gamma G (0.25-4)]\n"
    "                        [--debug] (discarded curve pixels orange, triangle edges blue)\n"
    "                        [--vbaa-filter box|paper|RING (0-1)]\n"
    "                        [--rotate DEG] [--scale SX[,SY]] [--skew AX[,AY]] [--perspective DEG[,DIST]]\n"
    "                        [--transform a,b,c,d,e,f[,g,h,i]] (row-major pixel matrix; each about the\n"
    "                        image centre, in the order given; the image grows to fit)\n"
    "       paragraphs take every option above too\n"
    "       render paragraph options: --width PX --align left|right|center|justify|start|end\n"
    "                        --line-height X|Npx --max-lines N --ellipsis none|start|middle|end\n"
    "                        --direction auto|ltr|rtl --language BCP47 --indent PX --tab-stops PX,...\n"
    "                        --font repeated (fallback order) --markup (<b> <i> <u> <s> <color=C>\n"
    "                        <size=PX> <font=NAME> <span ...>, entities; docs/markup.md)\n"
    "       curvetext layout [--font FILE]... --size PX [--width PX] (--text UTF8 | --text-file FILE)\n"
    "                        [paragraph options] --json\n"
    "       curvetext check  [--font FILE] [--face-index N] [--variations ...] [--size PX]\n"
    "                        [--max-glyphs N] [--json]\n"
    "       curvetext mesh   [--font FILE] [--face-index N] [--variations ...] (--glyph ID | --char C)\n"
    "                        -o MESH.svg\n"
    "       curvetext shape  --input FILE(.json|.svg) -o OUT.png [--size WxH] [--scale PX_PER_UNIT]\n"
    "                        [--aa none|curves|full|vbaa|msaa|auto] [--curve exact|paper] [--fg COLOR] [--bg COLOR]\n"
    "                        [--blend srgb|linear] [--gamma G] [--debug] [--vbaa-filter box|paper|RING]\n"
    "                        [--rotate DEG] [--skew AX[,AY]] [--perspective DEG[,DIST]] [--transform ...]\n"
    "                        (--scale is pixels per unit here)\n"
    "       curvetext --help | --version\n"
    "COLOR is #rgb, #rrggbb, #rrggbbaa or black, white, red, green, blue, transparent.\n"
    "Without --font the default font (DejaVu Sans) is used.\n";

}  // namespace

int main(int argc, char** argv) {
  using namespace curvetext::cli;
  std::vector<std::string> args(argv + 1, argv + argc);
  try {
    if (args.empty()) throw UsageError{"no command given"};
    const std::string command = args[0];
    const std::vector<std::string> rest(args.begin() + 1, args.end());
    if (command == "--help" || command == "-h" || command == "help") {
      std::fputs(kUsage, stdout);
      return 0;
    }
    if (command == "--version") {
      std::printf("curvetext %s\n", curvetext::version());
      return 0;
    }
    if (command == "render") return run_render(rest);
    if (command == "check") return run_check(rest);
    if (command == "mesh") return run_mesh(rest);
    if (command == "layout") return run_layout(rest);
    if (command == "shape") return run_shape(rest);
    throw UsageError{"unknown command '" + command + "'"};
  } catch (const UsageError& e) {
    std::fprintf(stderr, "curvetext: %s\n%s", e.message.c_str(), kUsage);
    return 2;
  } catch (const curvetext::Error& e) {
    std::fprintf(stderr, "curvetext: error: %s\n", e.what());
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "curvetext: error: %s\n", e.what());
    return 1;
  }
}
