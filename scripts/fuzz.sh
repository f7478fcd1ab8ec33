#!/usr/bin/env bash
# Builds the libFuzzer targets of tests/fuzz with clang (ASan + UBSan, in
# build-clang/) and runs each for SECONDS seconds (default 20), one after
# another, from its corpus: tests/fuzz/corpus/<name>/ and the other seeds the
# target lists (tests/fuzz/README.md), plus small subsets of three installed
# fonts (glyf, CFF, variable glyf) made with hb-subset. New inputs go to
# build-clang/fuzz/<name>/corpus, findings (crash-*, timeout-*, oom-*) to
# build-clang/fuzz/<name>/. Fails when a target finds anything.
#
#   scripts/fuzz.sh [SECONDS] [TARGET...]
#   FUZZ_RUNS=ci     a fixed number of inputs per target (below) instead of a
#                    time, with SECONDS as a cap: how much is fuzzed does not
#                    depend on the machine's speed
#   FUZZ_BUILD_DIR   build directory        (default build-clang)
#   FUZZ_ARGS        extra libFuzzer flags  (e.g. -runs=1000000 -fork=1 -ignore_timeouts=1)
#   JOBS             parallel build jobs    (default 2)
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-20}
shift || true
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=(font outline svg svg_path nurbs_json paragraph stroke)
build=${FUZZ_BUILD_DIR:-build-clang}
JOBS=${JOBS:-2}

# Line tables only: stack traces keep file and line, the build is faster.
CC=clang CXX=clang++ cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCURVETEXT_BUILD_FUZZERS=ON \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -gline-tables-only -DNDEBUG" -DCMAKE_C_FLAGS_RELWITHDEBINFO="-O2 -gline-tables-only -DNDEBUG" \
  -DCURVETEXT_BUILD_TESTS=OFF -DCURVETEXT_BUILD_BENCH=OFF -DCURVETEXT_BUILD_CLI=OFF -DCURVETEXT_BUILD_EXAMPLES=OFF \
  -DCURVETEXT_INSTALL=OFF >/dev/null
cmake --build "$build" -j"$JOBS" --target "${targets[@]/%/_fuzzer}"

# Font seeds cut from installed fonts (not kept in the repository).
fonts="$build/fuzz/font-seeds"
mkdir -p "$fonts"
subset() { [ -f "$fonts/$2" ] || hb-subset "$1" --text="HIO. Hello, fi ffl" -o "$fonts/$2"; }
subset /usr/share/fonts/truetype/dejavu/DejaVuSans.ttf dejavu-sans.ttf
subset /usr/share/fonts/opentype/urw-base35/NimbusRoman-Regular.otf nimbus-roman.otf
subset /usr/share/fonts/truetype/inter-vf/Inter.var.ttf inter-var.ttf

# Per input: at most 10 s and 2 GiB (a hang or a runaway allocation is a
# finding, not a stuck run); input sizes as each target needs.
declare -A max_len=([font]=65536 [outline]=4096 [svg]=8192 [svg_path]=4096 [nurbs_json]=8192 [paragraph]=2048 [stroke]=2048)
# CI's fixed runs: about 10 s per target on a 2-core machine.
declare -A ci_runs=([font]=2000 [outline]=2000 [svg]=30000 [svg_path]=20000 [nurbs_json]=30000 [paragraph]=20000 [stroke]=2000)
declare -A seeds=([font]="fonts/test $fonts" [svg]=tests/fixtures/shapes [nurbs_json]="tests/fixtures/shapes docs/shapes")
# fontconfig's own leaks at initialisation (tests/sanitizer/lsan.supp says why).
export LSAN_OPTIONS="suppressions=$PWD/tests/sanitizer/lsan.supp:print_suppressions=0"
status=0
for name in "${targets[@]}"; do
  work="$build/fuzz/$name"
  mkdir -p "$work/corpus"
  dict=tests/fuzz/dict/$name.dict
  echo "== fuzz $name: $seconds s"
  # shellcheck disable=SC2086 # seeds and FUZZ_ARGS are lists
  if ! "$build/tests/fuzz/${name}_fuzzer" "$work/corpus" "tests/fuzz/corpus/$name" ${seeds[$name]:-} \
      -max_total_time="$seconds" $( [ "${FUZZ_RUNS:-}" = ci ] && echo "-runs=${ci_runs[$name]}" ) -timeout=10 -rss_limit_mb=2048 -malloc_limit_mb=2048 -max_len="${max_len[$name]}" \
      -seed=1 -print_final_stats=1 -artifact_prefix="$work/" \
      $( [ -f "$dict" ] && echo "-dict=$dict" ) ${FUZZ_ARGS:-} 2>"$work/log"; then
    status=1
    echo "fuzz $name: FOUND something; see $work/log and $work/crash-* / timeout-* / oom-*"
    grep -E "ERROR|SUMMARY|fuzz check failed|Test unit written" "$work/log" | head -20 || true
  fi
  # Executions, coverage and findings: libFuzzer's last status line.
  grep -E "^#[0-9]+" "$work/log" | tail -1
done
exit $status
