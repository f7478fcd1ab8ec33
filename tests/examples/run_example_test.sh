#!/usr/bin/env bash
# Runs an example app under Xvfb for a fixed number of frames, with its text
# and without (--no-text), saving the last frame of each, then checks the
# screenshots with check_example_screenshot.
#
#   run_example_test.sh APP CHECKER SCENE GL_VERSION_TEXT OUT_DIR
#
# XVFB_RUN: the xvfb-run to use (default: from PATH). FRAMES: frames per run (default 30).
set -euo pipefail
app=$1 checker=$2 scene=$3 gl=$4 out=$5
frames=${FRAMES:-30}
xvfb_run=${XVFB_RUN:-xvfb-run}

# In the sanitizer build: X11, GLX, D-Bus and SDL keep allocations until exit
# whose stacks LeakSanitizer cannot attribute (no symbols), so the apps run
# without leak checking; AddressSanitizer's and UBSan's other checks stay on,
# and curvetext's own leaks are the unit tests' to find. (Later options win.)
app_asan_options="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0"

rm -rf "$out"
mkdir -p "$out"
# One X server for both runs; its own error output is kept for a failure.
ASAN_OPTIONS=$app_asan_options "$xvfb_run" -a -e "$out/xvfb.log" -s "-screen 0 1280x800x24" bash -c '
  set -e
  "$1" --frames "$3" --screenshot "$2/text.png"
  "$1" --frames "$3" --no-text --screenshot "$2/no-text.png"
' run "$app" "$out" "$frames" || { echo "the app failed; Xvfb said:"; cat "$out/xvfb.log"; exit 1; }
"$checker" --scene "$scene" --text "$out/text.png" --no-text "$out/no-text.png" --out "$out" --expect-gl "$gl"
