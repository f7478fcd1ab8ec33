#!/usr/bin/env bash
# The sanitizer half of CI: builds curvetext with AddressSanitizer (+ LeakSanitizer)
# and UndefinedBehaviorSanitizer (-DCURVETEXT_SANITIZE=ON, RelWithDebInfo: -O2 -g,
# every UBSan check fatal) in its own directory, then runs every test except the
# full glyph corpus (label mesh_corpus) and the package test (label package,
# which builds its own unsanitized trees) -- the unit tests, the CLI test, the
# replay of the fuzz corpora (label fuzz, tests/fuzz/) and the corpus subset
# (label corpus_coverage, where present) -- plus three fonts of the
# full corpus test (a TrueType, a CFF and a variable font with overlapping
# contours). Any sanitizer report fails the run. Then a ThreadSanitizer build
# of the library runs the two-thread test (tests/threads_test.cpp).
#
#   SAN_BUILD_DIR   build directory               (default build-sanitize)
#   SAN_CORPUS      ctest -R regex of corpus tests (default: DejaVuSans, NimbusRoman, InterWght400)
#   JOBS            parallel build and test jobs  (default 2)
set -euo pipefail
cd "$(dirname "$0")/.."
SAN_BUILD_DIR=${SAN_BUILD_DIR:-build-sanitize}
SAN_CORPUS=${SAN_CORPUS:-'MeshCorpus\.[A-Za-z]+/(DejaVuSans|NimbusRoman|InterWght400)( |$)'}
JOBS=${JOBS:-2}

cmake -S . -B "$SAN_BUILD_DIR" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCURVETEXT_SANITIZE=ON -DCURVETEXT_BUILD_EXAMPLES=OFF \
      -DCURVETEXT_BUILD_TESTS=ON -DCURVETEXT_BUILD_BENCH=OFF
cmake --build "$SAN_BUILD_DIR" -j"$JOBS"

# halt_on_error: the first report ends the test (and fails it); detect_leaks: LSan
# at exit, with Mesa's own leaks (llvmpipe, EGL, LLVM) suppressed by module only.
# intercept_tls_get_addr=0: GCC 12's runtime (as LLVM's before 17) mistakes some
# dynamic TLS blocks for pre-2.25 glibc ones, and LSan's tracer then dies with
# "Tracer caught signal 11" after the test has passed: here on the render tests
# of Greek text (the GL tests, which load Mesa's TLS-using libraries), depending
# only on the memory layout (argv, environment). See google/sanitizers#1409 and
# LLVM D147459. Turning the interceptor off only stops LSan using those blocks
# as roots (no leak is hidden by it).
supp="$PWD/tests/sanitizer/lsan.supp"
export ASAN_OPTIONS="detect_leaks=1:halt_on_error=1:detect_stack_use_after_return=1:check_initialization_order=1:strict_init_order=1:strict_string_checks=1:print_summary=1:intercept_tls_get_addr=0"
export LSAN_OPTIONS="suppressions=$supp:print_suppressions=0"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1:print_summary=1"

status=0
echo "== sanitizers: every test but the full glyph corpus and the package test"
ctest --test-dir "$SAN_BUILD_DIR" --output-on-failure -j"$JOBS" --timeout 900 -LE '^(mesh_corpus|package)$' || status=1
echo "== sanitizers: full glyph corpus test, three fonts ($SAN_CORPUS)"
ctest --test-dir "$SAN_BUILD_DIR" --output-on-failure -j"$JOBS" --timeout 900 -L '^mesh_corpus$' -R "$SAN_CORPUS" \
      --no-tests=error || status=1

# ThreadSanitizer: objects used on distinct threads with distinct contexts
# (tests/threads_test.cpp) must not race in the library. Its own tree, only that
# test; reports inside Mesa and its JIT are suppressed (tests/sanitizer/tsan.supp).
echo "== ThreadSanitizer: two threads, two contexts"
TSAN_BUILD_DIR=${TSAN_BUILD_DIR:-build-tsan}
cmake -S . -B "$TSAN_BUILD_DIR" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCURVETEXT_SANITIZE_THREAD=ON \
      -DCURVETEXT_BUILD_TESTS=ON -DCURVETEXT_BUILD_BENCH=OFF -DCURVETEXT_BUILD_CLI=OFF -DCURVETEXT_BUILD_EXAMPLES=OFF
cmake --build "$TSAN_BUILD_DIR" -j"$JOBS" --target threads_test
TSAN_OPTIONS="halt_on_error=1:suppressions=$PWD/tests/sanitizer/tsan.supp" "$TSAN_BUILD_DIR/tests/threads_test" || status=1
exit $status
