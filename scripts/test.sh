#!/usr/bin/env bash
# The README's test command: installs what is missing, checks the C++ files'
# format (.clang-format) and that no lib/ folder includes another's private
# header (scripts/check-private-includes.sh), builds, runs every test;
# then builds a second tree with AddressSanitizer + UndefinedBehaviorSanitizer
# (build-sanitize/, scripts/test-sanitize.sh) and runs the unit tests and a
# subset of the glyph corpus there (and replays the fuzz corpora, tests/fuzz/).
# CURVETEXT_SANITIZE_TESTS=0 skips that half. Last, scripts/fuzz.sh builds the
# library and the fuzz targets with clang (build-clang/) and runs each target
# over a fixed number of inputs (FUZZ_RUNS=ci), at most CURVETEXT_FUZZ_SECONDS
# (default 60) each; CURVETEXT_FUZZ_SECONDS=0 skips it.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup-debian.sh
status=0
scripts/check-format.sh || status=1
scripts/check-private-includes.sh || status=1
scripts/build.sh -DCURVETEXT_BUILD_TESTS=ON -DCURVETEXT_BUILD_BENCH=ON
ctest --test-dir "${BUILD_DIR:-build}" --output-on-failure -j"${JOBS:-2}" --timeout 900 || status=1
if [ "${CURVETEXT_SANITIZE_TESTS:-1}" != 0 ]; then
  scripts/test-sanitize.sh || status=1
fi
if [ "${CURVETEXT_FUZZ_SECONDS:-60}" != 0 ]; then
  FUZZ_RUNS=${FUZZ_RUNS:-ci} scripts/fuzz.sh "${CURVETEXT_FUZZ_SECONDS:-60}" || status=1
fi
exit $status
