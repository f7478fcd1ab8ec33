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
    "usage: curvetext render (--text UTF8 | --text-file FILE) -o OUT.png|OUT.svg|- [options]\n"
    "  --text UTF8 | --text-file FILE   the text; '-' for either reads standard input\n"
    "  -o, --output FILE        .png or .svg (from the extension); '-' standard output (PNG)\n"
    "  --format png|svg         output format                       (default: from -o)\n"
    "  --font FILE|FAMILY       a font file or fontconfig family name; repeat for the\n"
    "                           fallback order, then fontconfig's   (default: DejaVu Sans)\n"
    "  --face-index N           face of the first font's collection (default: 0)\n"
    "  --variations LIST        axis values, wght=700,wdth=85       (default: the font's)\n"
    "  --size PX                pixels per em                       (default: 32)\n"
    "  --features LIST          OpenType features, kern,-liga       (default: HarfBuzz's)\n"
    "  --letter-spacing PX      added after every character         (default: 0)\n"
    "  --word-spacing PX        added to every space                (default: 0)\n"
    "  --margin PX              around the text                     (default: 16)\n"
    "  --fg COLOR               text colour                         (default: black)\n"
    "  --bg COLOR               background                          (default: white)\n"
    "  --outline W,COLOR        text outline W px outside the glyphs (PNG only)\n"
    "  --shadow DX,DY,BLUR,COLOR  text shadow, blur sigma BLUR/2 px (PNG only; 0,0: a glow)\n"
    "  --width PX               wrap width, 0 no wrapping           (default: 0)\n"
    "  --align A                left|right|center|justify|start|end (default: start)\n"
    "  --line-height X|Npx      multiple of the line, or px         (default: 1)\n"
    "  --max-lines N            0 unlimited                         (default: 0)\n"
    "  --ellipsis E             none|start|middle|end               (default: none)\n"
    "  --direction D            auto|ltr|rtl                        (default: auto)\n"
    "  --language BCP47         breaking and shaping language       (default: none)\n"
    "  --indent PX              first-line indent                   (default: 0)\n"
    "  --tab-stops PX,...       tab stops                           (default: every 8 spaces)\n"
    "  --markup                 <b> <i> <u> <s> <color=C> <size=PX> <font=NAME> <span ...>\n"
    "                           (docs/markup.md)                    (default: off)\n"
    "  PNG only:\n"
    "  --aa none|curves|full|vbaa|msaa|auto  antialiasing           (default: full)\n"
    "  --curve exact|paper      curve test                          (default: exact)\n"
    "  --blend srgb|linear      blending                            (default: srgb)\n"
    "  --gamma G                coverage gamma, 0.25-4              (default: 1)\n"
    "  --debug                  discarded pixels orange, edges blue (default: off)\n"
    "  --vbaa-filter box|paper|RING  vbaa's filter, RING 0-1        (default: box)\n"
    "  --rotate DEG, --scale SX[,SY], --skew AX[,AY], --perspective DEG[,DIST],\n"
    "  --transform a,b,c,d,e,f[,g,h,i]  about the image centre, in the order given;\n"
    "                           the image grows to fit              (default: none)\n"
    "       curvetext render --jobs FILE|-   many images in one process: FILE holds one job per\n"
    "                        line, a JSON object of the options above (\"output\" for -o):\n"
    "                        {\"text\": \"Hi\", \"size\": 24, \"markup\": true, \"output\": \"hi.png\"};\n"
    "                        each job reported on stdout as {\"line\":N,\"output\"|\"error\":...}\n"
    "       curvetext layout (--text UTF8 | --text-file FILE) [the text, font and paragraph\n"
    "                        options of render] [--json]: the layout as JSON (the only output)\n"
    "       curvetext check  [--font FILE] [--face-index N] [--variations ...] [--size PX (64)]\n"
    "                        [--max-glyphs N (all)] [--json]\n"
    "       curvetext mesh   [--font FILE] [--face-index N] [--variations ...] (--glyph ID | --char C)\n"
    "                        [--size PX (64)] -o MESH.svg\n"
    "       curvetext shape  --input FILE(.json|.svg) -o OUT.png [--size WxH (from the file, else 512\n"
    "                        on the longer side)] [--scale PX_PER_UNIT (fit)] [--fg COLOR (each shape's)]\n"
    "                        [--bg COLOR] [--current-color COLOR (SVG currentColor where the file sets\n"
    "                        no color; black)] [the PNG-only options of render] (--scale is pixels per unit)\n"
    "       curvetext shape  --jobs FILE|-   shape's options per job line, as render --jobs\n"
    "       curvetext --help | --version\n"
    "Every option also takes the form --option=VALUE.\n"
    "COLOR is #rgb, #rrggbb, #rrggbbaa or black, white, red, green, blue, transparent.\n";

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
