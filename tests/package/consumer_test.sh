#!/usr/bin/env bash
# curvetext as a package: builds the library (shared, then static; the CLI
# with the shared one), installs it with `cmake --install --prefix` into
# another place than the configured prefix, checks that nothing installed
# names the build tree, deletes the build tree, moves the installed tree
# elsewhere, and from there builds and runs consumers with
# find_package(curvetext CONFIG) and with pkg-config, the installed CLI, and
# the README's first program (examples/first_window, both ways, under Xvfb
# where xvfb-run and GLFW are installed); checks where the default font is
# found from, and the error when there is none. Then configures a project
# that adds curvetext with add_subdirectory (only the library is built there
# by default).
#
#   consumer_test.sh SOURCE_DIR WORK_DIR      (CMAKE, CXX, JOBS from the environment)
#
# The two library builds are unoptimised and build the installed targets
# only: this checks packaging, not speed.
set -euo pipefail
src=$(cd "$1" && pwd)
work=$2
CMAKE=${CMAKE:-cmake}
CXX=${CXX:-c++}
JOBS=${JOBS:-2}
here="$src/tests/package"
rm -rf "$work"
mkdir -p "$work"
work=$(cd "$work" && pwd)
total_start=$SECONDS

fail() { echo "package: FAILED: $*" >&2; exit 1; }
# Runs a command with its output in a log, shown when it fails.
run() {
  local log=$1; shift
  "$@" >"$log" 2>&1 || { cat "$log" >&2; fail "$*"; }
}
expect() {  # expect WHAT TEXT PATTERN
  grep -q -- "$3" <<<"$2" || fail "$1: expected '$3' in: $2"
}

# A fontconfig that knows no font: the default font's last resort finds nothing.
mkdir -p "$work/fc-cache"
cat >"$work/no-fonts.conf" <<CONF
<?xml version="1.0"?>
<!DOCTYPE fontconfig SYSTEM "urn:fontconfig:fonts.dtd">
<fontconfig><cachedir>$work/fc-cache</cachedir></fontconfig>
CONF

# Fails when a file under $1 holds the string $2: text files as they are,
# programs and libraries stripped of their symbol tables (which may name the
# source files the compiler was given, generated ones in the build tree; what
# the code reads must not).
expect_not_named() {
  local f copy
  while IFS= read -r -d '' f; do
    copy="$work/scan.tmp"
    cp "$f" "$copy"
    if head -c 4 "$copy" | grep -q $'\x7fELF' || head -c 7 "$copy" | grep -q '!<arch>'; then
      strip --strip-all "$copy" 2>/dev/null || strip --strip-debug "$copy" 2>/dev/null || true
    fi
    if grep -q -a -F -- "$2" "$copy"; then
      rm -f "$copy"
      fail "installed file ${f#"$1"/} names the build tree ($2)"
    fi
    rm -f "$copy"
  done < <(find "$1" -type f -print0)
}

# The README's first program (examples/first_window) run for 2 frames under
# Xvfb: it must ink pixels.
run_first_window() {  # NAME PROGRAM
  local out
  out=$("$XVFB_RUN" -a -s "-screen 0 800x600x24" "$2" 2 2>&1) || fail "$1: $out"
  expect "$1" "$out" "first_window: 2 frames, then [1-9][0-9]* pixels inked"
  echo "   $1: $out"
}
XVFB_RUN=$(command -v xvfb-run || true)
first_window=yes
if [ -z "$XVFB_RUN" ] || ! pkg-config --exists glfw3; then
  first_window=no
  echo "== xvfb-run or GLFW (libglfw3-dev) missing: examples/first_window is not built here"
fi

for kind in shared static; do
  shared=$([ $kind = shared ] && echo ON || echo OFF)
  build="$work/build-$kind"
  staged="$work/staged-$kind"  # where `cmake --install --prefix` puts it
  prefix="$work/prefix-$kind"  # where it is used from, moved there afterwards
  start=$SECONDS
  targets=(curvetext)
  [ $kind = shared ] && targets+=(curvetext_cli)
  # The configured prefix is never written: --prefix at install time decides.
  run "$work/$kind-configure.log" "$CMAKE" -S "$src" -B "$build" -DBUILD_SHARED_LIBS="$shared" \
    -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG=-O0 -DCMAKE_INSTALL_PREFIX="$work/configured-prefix" \
    -DCURVETEXT_BUILD_TESTS=OFF -DCURVETEXT_BUILD_BENCH=OFF -DCURVETEXT_BUILD_EXAMPLES=OFF \
    -DCURVETEXT_BUILD_CLI="$shared" -DCURVETEXT_INSTALL=ON
  run "$work/$kind-build.log" "$CMAKE" --build "$build" -j"$JOBS" --target "${targets[@]}"
  run "$work/$kind-install.log" "$CMAKE" --install "$build" --prefix "$staged"
  [ ! -e "$work/configured-prefix" ] || fail "$kind: installed into the configured prefix, not --prefix"
  expect_not_named "$staged" "$build"
  rm -rf "$build"  # from here on only the installed tree (its default font too) ...
  mv "$staged" "$prefix"  # ... moved away from where it was installed
  echo "== $kind: built, installed with --prefix and moved in $((SECONDS - start)) s; no installed file names the build tree"

  export PKG_CONFIG_PATH="$prefix/lib/pkgconfig"
  libdir=$(pkg-config --variable=libdir curvetext)
  # The .pc file's paths lead into the moved tree (relative to itself).
  [ "$(readlink -f "$libdir")" = "$(readlink -f "$prefix/lib")" ] || fail "$kind: pkg-config libdir $libdir"
  includedir=$(pkg-config --variable=includedir curvetext)
  [ -f "$includedir/curvetext/curvetext.hpp" ] || fail "$kind: pkg-config includedir $includedir"
  [ -f "$libdir/cmake/curvetext/curvetextConfig.cmake" ] || fail "$kind: no $libdir/cmake/curvetext/curvetextConfig.cmake"
  [ -f "$prefix/share/curvetext/fonts/DejaVuSans.ttf" ] || fail "$kind: default font not installed"
  if [ $kind = shared ]; then
    so=$(readlink -f "$libdir/libcurvetext.so")
    [ -f "$so" ] || fail "shared: no libcurvetext.so"
    soname=$(readelf -d "$so" | sed -n 's/.*(SONAME).*\[\(.*\)\]/\1/p')
    [ -n "$soname" ] || fail "shared: $so has no SONAME"
    exported=$(nm -D --defined-only "$so" | c++filt | grep -c ' curvetext::' || true)
    internal=$(nm -D --defined-only "$so" | c++filt | grep -Ec 'curvetext::(detail|[a-z_]+::)|Impl::' || true)
    echo "   $(basename "$so"), SONAME $soname, $exported curvetext:: symbols exported, $internal of them internal"
    [ "$internal" -eq 0 ] || fail "shared: internal symbols exported"
    [ ! -e "$libdir/libcurvetext.a" ] || fail "shared: a static library was installed too"
  else
    [ -f "$libdir/libcurvetext.a" ] || fail "static: no libcurvetext.a"
  fi

  # find_package(curvetext CONFIG) + curvetext::curvetext
  run "$work/$kind-cmake-consumer.log" "$CMAKE" -S "$here" -B "$work/cmake-$kind" -DCMAKE_PREFIX_PATH="$prefix"
  run "$work/$kind-cmake-consumer-build.log" "$CMAKE" --build "$work/cmake-$kind"
  # pkg-config --cflags --libs (--static for the static library)
  pc_args=(--cflags --libs)
  extra=()
  if [ $kind = static ]; then pc_args+=(--static); else extra+=("-Wl,-rpath,$libdir"); fi
  read -r -a pc_flags <<<"$(pkg-config "${pc_args[@]}" curvetext)"
  run "$work/$kind-pc-consumer.log" "$CXX" -std=c++20 "$here/consumer.cpp" -o "$work/pc-$kind" \
    "${pc_flags[@]}" "${extra[@]}"

  for consumer in "$work/cmake-$kind/consumer" "$work/pc-$kind"; do
    name="$kind, $([ "$consumer" = "$work/pc-$kind" ] && echo pkg-config || echo find_package)"
    if [ $kind = static ]; then
      # A program linked with the static library finds the font from its own
      # place: installed in the prefix's bin/.
      mkdir -p "$prefix/bin"
      cp "$consumer" "$prefix/bin/"
      consumer="$prefix/bin/$(basename "$consumer")"
    fi
    out=$("$consumer" "$work/$(basename "$consumer")-$kind.png") || fail "$name: $out"
    echo "   $name: $out" | sed '2,$s/^/     /'
    expect "$name" "$out" "default font: $prefix/share/curvetext/fonts/DejaVuSans.ttf"
    expect "$name" "$out" "16 glyphs"
  done

  if [ $first_window = yes ]; then
    run "$work/$kind-first-cmake.log" "$CMAKE" -S "$src/examples/first_window" -B "$work/first-cmake-$kind" \
      -DCMAKE_PREFIX_PATH="$prefix"
    run "$work/$kind-first-cmake-build.log" "$CMAKE" --build "$work/first-cmake-$kind"
    read -r -a app_flags <<<"$(pkg-config --cflags --libs glfw3 glesv2)"
    run "$work/$kind-first-pc.log" "$CXX" -std=c++20 "$src/examples/first_window/main.cpp" -o "$work/first-pc-$kind" \
      "${pc_flags[@]}" "${app_flags[@]}" "${extra[@]}"
    run_first_window "$kind, first_window, find_package" "$work/first-cmake-$kind/first_window"
    run_first_window "$kind, first_window, pkg-config" "$work/first-pc-$kind"
  fi

  if [ $kind = shared ]; then
    # The installed CLI renders a PNG from the moved tree, with its default
    # font (fontconfig knows none) and the library found through its RPATH.
    out=$(FONTCONFIG_FILE="$work/no-fonts.conf" "$prefix/bin/curvetext" render --text "Installed" \
      -o "$work/cli-shared.png" 2>&1) || fail "installed CLI: $out"
    [ "$(head -c 8 "$work/cli-shared.png" | od -An -tx1 | tr -d ' ')" = "89504e470d0a1a0a" ] ||
      fail "installed CLI: $work/cli-shared.png is not a PNG"
    echo "   shared, installed CLI: rendered $(stat -c %s "$work/cli-shared.png") bytes of PNG"

    # The shared library finds its own font wherever the program is, fontconfig or not.
    out=$(FONTCONFIG_FILE="$work/no-fonts.conf" "$work/pc-shared" --default-font) || fail "no fontconfig: $out"
    expect "shared, no fontconfig" "$out" "default font: $prefix/share/curvetext/fonts/DejaVuSans.ttf"
  else
    # Away from the prefix a static program asks fontconfig ...
    out=$("$work/pc-static" --default-font) || fail "static, fontconfig: $out"
    expect "static, fontconfig" "$out" "default font: /.*/DejaVuSans.ttf"
    echo "   static, outside the prefix: $out"
    # ... and without fontconfig's fonts the error names the font and how to pass one.
    status=0
    out=$(FONTCONFIG_FILE="$work/no-fonts.conf" "$work/pc-static" --default-font) || status=$?
    [ $status -eq 3 ] || fail "static, no font: exit status $status: $out"
    expect "static, no font" "$out" "(font not found)"
    expect "static, no font" "$out" "DejaVu Sans"
    expect "static, no font" "$out" "Font::open"
    echo "   static, no font anywhere: $out"
  fi
done

# add_subdirectory: curvetext::curvetext exists; tests, benchmarks and the CLI are not built.
run "$work/subdirectory.log" "$CMAKE" -S "$here/subdirectory" -B "$work/subdirectory" -DCURVETEXT_SOURCE="$src"
targets=$("$CMAKE" --build "$work/subdirectory" --target help)
for t in consumer curvetext; do expect "add_subdirectory" "$targets" "\.\.\. $t\$"; done
for t in curvetext_cli curvetext_test_support font_test layout_bench; do
  ! grep -q -- "\.\.\. $t\$" <<<"$targets" || fail "add_subdirectory: $t is built by default"
done
[ ! -e "$work/subdirectory/curvetext/CTestTestfile.cmake" ] || fail "add_subdirectory: tests configured"
echo "== add_subdirectory: curvetext::curvetext linked, no tests, benchmarks or CLI"

rm -rf "$work"/cmake-* "$work"/first-cmake-* "$work/subdirectory" "$work/fc-cache"
echo "package: passed in $((SECONDS - total_start)) s"
