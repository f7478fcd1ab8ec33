#!/usr/bin/env bash
# Installs the Debian 12 packages curvetext needs to build, test and run
# (only those missing). Runs as root, or through sudo when available.
set -euo pipefail

packages=(
  # toolchain (also what the package test's consumers build with: cmake, pkg-config, binutils),
  # and the formatter scripts/check-format.sh runs
  build-essential cmake pkg-config clang-format
  # fonts and text: outlines, shaping, bidi, line breaking, fallback
  libfreetype-dev libharfbuzz-dev libfribidi-dev libunibreak-dev libfontconfig-dev
  # Thai word boundaries (a dictionary; UAX #14 leaves them to one)
  libthai-dev
  # Unicode Character Database: the line break class table is generated from it at build time,
  # and the conformance tests read its test files
  unicode-data
  # headless GL: EGL + GLES2, Mesa's llvmpipe on machines without a GPU
  libegl-dev libgles-dev libegl-mesa0 libgl1-mesa-dri
  # images
  libpng-dev
  # tests and benchmarks
  googletest libgtest-dev libbenchmark-dev
  # fuzzing (scripts/fuzz.sh): clang 14 with its libFuzzer and sanitizer runtimes, and
  # hb-subset, which cuts the font target's seeds from installed fonts
  clang libclang-rt-14-dev libharfbuzz-bin
  # the incumbent layout engine the benchmarks compare with, and its pango-view
  # (bench/batch_render_bench.sh)
  libpango1.0-dev pango1.0-tools
  # the stroke oracles and the stroke peer (tests/fixtures/strokes/make_stroke_oracles.py,
  # bench/stroke_peer.py): GEOS through shapely, numpy, and librsvg's rsvg-convert (Cairo)
  python3-shapely python3-numpy librsvg2-bin
  # fonts: the default font (DejaVu Sans) and the test corpus
  fonts-dejavu-core fonts-dejavu-extra fonts-noto-core fonts-noto-cjk fonts-urw-base35
  fonts-inter-variable
  # more CFF (OpenType) outlines for the corpus: FreeSerif had a glyph meshed short of its area
  fonts-freefont-otf
  # a colour bitmap (CBDT) emoji face: drawn from its bitmaps, through fallback and by name
  fonts-noto-color-emoji
  # fontTools, to regenerate the test fonts in fonts/test (tests/fixtures/make_*test_fonts.py)
  python3-fonttools
  # the example apps (examples/): windows and GL contexts, the camera's maths, and the
  # virtual X server (with xauth for xvfb-run) that their tests run them in
  libglfw3-dev libsdl2-dev libglm-dev xvfb xauth
  # SVG: the XML parser the reader is built on; the icon themes of the SVG corpus test, the
  # reference renderer it compares with, and the PNG reader of its script (scripts/svg_corpus.py)
  libexpat1-dev breeze-icon-theme tango-icon-theme adwaita-icon-theme librsvg2-bin python3-cairo
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#packages[@]} packages present"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null; then SUDO="sudo"; else
    echo "setup: need root (or sudo) to install: ${missing[*]}" >&2; exit 1
  fi
fi
echo "setup: installing ${missing[*]}"
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
