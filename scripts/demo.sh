#!/usr/bin/env bash
# The README's first command: installs what is missing, builds, and renders
# "Hello, world" to hello.png with curvetext's own pipeline.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup-debian.sh
scripts/build.sh -DCURVETEXT_BUILD_TESTS=OFF -DCURVETEXT_BUILD_BENCH=OFF
"${BUILD_DIR:-build}/bin/curvetext" render --size 48 --text "${1:-Hello, world}" -o "${2:-hello.png}"
echo "wrote ${2:-hello.png}"
