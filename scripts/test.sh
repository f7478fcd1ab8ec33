#!/usr/bin/env bash
# The README's test command: installs what is missing, checks the C++ files'
# format (.clang-format), builds, runs every test;
# then builds a second tree with AddressSanitizer + UndefinedBehaviorSanitizer
# (build-sanitize/, scripts/test-sanitize.sh) and runs the unit tests and a
# subset of the glyph corpus there. CURVETEXT_SANITIZE_TESTS=0 skips that half.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup-debian.sh
status=0
scripts/check-format.sh || status=1
scripts/build.sh -DCURVETEXT_BUILD_TESTS=ON -DCURVETEXT_BUILD_BENCH=ON
ctest --test-dir "${BUILD_DIR:-build}" --output-on-failure -j"${JOBS:-2}" --timeout 900 || status=1
if [ "${CURVETEXT_SANITIZE_TESTS:-1}" != 0 ]; then
  scripts/test-sanitize.sh || status=1
fi
exit $status
