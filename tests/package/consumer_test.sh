#!/usr/bin/env bash
# curvetext as a package: builds and installs the library (shared, then
# static) into a temporary prefix, deletes the build, and builds and runs a
# consumer against the installed tree with find_package(curvetext CONFIG)
# and with pkg-config; checks where the default font is found from, and the
# error when there is none. Then configures a project that adds curvetext
# with add_subdirectory (only the library is built there by default).
#
#   consumer_test.sh SOURCE_DIR WORK_DIR      (CMAKE, CXX, JOBS from the environment)
#
# The two library builds are unoptimised and build the library target only:
# this checks packaging, not speed.
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

for kind in shared static; do
  shared=$([ $kind = shared ] && echo ON || echo OFF)
  build="$work/build-$kind"
  prefix="$work/prefix-$kind"
  start=$SECONDS
  run "$work/$kind-configure.log" "$CMAKE" -S "$src" -B "$build" -DBUILD_SHARED_LIBS="$shared" \
    -DCMAKE_BUILD_TYPE=Debug -DCMAKE_CXX_FLAGS_DEBUG=-O0 -DCMAKE_INSTALL_PREFIX="$prefix" \
    -DCURVETEXT_BUILD_TESTS=OFF -DCURVETEXT_BUILD_BENCH=OFF -DCURVETEXT_BUILD_CLI=OFF -DCURVETEXT_INSTALL=ON
  run "$work/$kind-build.log" "$CMAKE" --build "$build" -j"$JOBS" --target curvetext
  run "$work/$kind-install.log" "$CMAKE" --install "$build"
  rm -rf "$build"  # from here on only the installed tree (its default font too)
  echo "== $kind: built and installed in $((SECONDS - start)) s"

  export PKG_CONFIG_PATH="$prefix/lib/pkgconfig"
  libdir=$(pkg-config --variable=libdir curvetext)
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

  if [ $kind = shared ]; then
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

rm -rf "$work"/cmake-* "$work/subdirectory" "$work/fc-cache"
echo "package: passed in $((SECONDS - total_start)) s"
