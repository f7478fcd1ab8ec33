#!/usr/bin/env bash
# Full glyph corpus: every glyph of every face (each face of a collection) of
# the fonts scripts/setup-debian.sh installs: fonts-noto-core, fonts-noto-cjk
# (Sans and Serif, Regular and Bold collections), fonts-urw-base35 (OpenType
# CFF), fonts-freefont-otf, DejaVu (core and extra) and Inter variable at wght
# 100, 400 and 900 goes through
# tests/corpus/corpus_run: mesh invariants (area identity...), a coverage
# comparison with the real renderer against exact nonzero-union coverage at
# 32 px/em, and a per-glyph time bound (tests/support/glyph_corpus.hpp).
#
# Usage: scripts/corpus.sh            (prints failures, per-font lines, totals)
# Environment: CURVETEXT_BUILD_DIR (default build), CORPUS_JOBS (parallel
# processes, default 2), CORPUS_STRIDE (check every Nth glyph, default 1),
# CORPUS_HANG_SECONDS (hard bound per glyph before the process is stopped and
# resumed after it, default 60), CORPUS_LOG_DIR (per-face logs; default a
# temporary directory), CORPUS_STATS=1 (per-glyph figures next to the logs).
# Exits 0 only when no glyph failed.
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
build=${CURVETEXT_BUILD_DIR:-$root/build}
jobs=${CORPUS_JOBS:-2}
stride=${CORPUS_STRIDE:-1}
hang=${CORPUS_HANG_SECONDS:-60}
logs=${CORPUS_LOG_DIR:-$(mktemp -d /tmp/curvetext-corpus.XXXXXX)}
mkdir -p "$logs"

if ! { cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DCURVETEXT_BUILD_TESTS=ON &&
       cmake --build "$build" -j "$jobs" --target corpus_run; } >"$logs/build.log" 2>&1; then
  tail -n 30 "$logs/build.log" >&2
  echo "corpus: build failed (full log: $logs/build.log)" >&2
  exit 2
fi
runner="$build/tests/corpus_run"

# One job per line: FILE|FACE|VARIATIONS; every face of each file.
faces() {
  local f=$1 n
  [ -f "$f" ] || { echo "$f|0|"; return; }  # (named as missing below)
  n=$("$runner" --font "$f" --face-count yes)
  for ((k = 0; k < n; ++k)); do echo "$f|$k|"; done
}
list="$logs/jobs.txt"
{
  # fonts-noto-core's own files: the directory also holds other packages'
  # fonts (NotoColorEmoji.ttf from fonts-noto-color-emoji, bitmaps only).
  if dpkg-query -L fonts-noto-core >/dev/null 2>&1; then
    dpkg-query -L fonts-noto-core | grep -E '^/usr/share/fonts/truetype/noto/.*\.ttf$' | sort | while read -r f; do faces "$f"; done
  else
    for f in /usr/share/fonts/truetype/noto/*.ttf; do
      [ "$(basename "$f")" = NotoColorEmoji.ttf ] || faces "$f"
    done
  fi
  for w in Sans Serif; do
    for s in Regular Bold; do faces "/usr/share/fonts/opentype/noto/Noto${w}CJK-$s.ttc"; done
  done
  for f in /usr/share/fonts/opentype/urw-base35/*.otf; do faces "$f"; done
  for f in /usr/share/fonts/opentype/freefont/*.otf; do faces "$f"; done
  for f in /usr/share/fonts/truetype/dejavu/*.ttf; do faces "$f"; done
  for w in 100 400 900; do echo "/usr/share/fonts/truetype/inter-vf/Inter.var.ttf|0|wght=$w"; done
} >"$list"
missing=$(cut -d'|' -f1 "$list" | sort -u | while read -r f; do [ -f "$f" ] || echo "$f"; done)
if [ -n "$missing" ]; then
  echo "corpus: missing font files (install fonts-noto-core fonts-noto-cjk fonts-urw-base35 fonts-freefont-otf" \
       "fonts-dejavu-core fonts-dejavu-extra fonts-inter-variable):" >&2
  echo "$missing" >&2
  exit 2
fi

# Runs one face; after a crash (exit 3) or a hang (exit 4) the runner has
# printed a FAIL line naming the glyph and where to resume: skip that glyph
# and go on from there, so one bad glyph cannot hide the rest of the face.
run_face() {
  local spec=$1 file face vars log skip="" first=0 rc line bad resume
  IFS='|' read -r file face vars <<<"$spec"
  log="$logs/$(basename "$file")-f$face${vars:+-${vars//=/_}}.log"
  : >"$log"
  while :; do
    local args=(--font "$file" --face "$face" --stride "$stride" --first "$first" --hang-seconds "$hang")
    [ -n "$vars" ] && args+=(--variations "$vars")
    [ -n "$skip" ] && args+=(--skip "$skip")
    [ -n "${CORPUS_STATS:-}" ] && args+=(--stats "$log.stats.$first")
    rc=0
    "$runner" "${args[@]}" >>"$log" 2>>"$log.stderr" || rc=$?
    if [ "$rc" -eq 3 ] || [ "$rc" -eq 4 ]; then
      line=$(grep '^FAIL .*(resume [0-9]*)$' "$log" | tail -n 1)
      bad=$(sed -E 's/.* glyph (-?[0-9]+): .*/\1/' <<<"$line")
      resume=$(sed -E 's/.*\(resume ([0-9]+)\)$/\1/' <<<"$line")
      case ",$skip," in *",$bad,"*) echo "FAIL $file face $face $vars: glyph $bad failed twice, giving up on the face" >>"$log"; return ;; esac
      skip="${skip:+$skip,}$bad"
      first=$resume
      continue
    fi
    return
  done
}
export -f run_face
export logs stride hang runner

start=$(date +%s.%N)
tr '\n' '\0' <"$list" | xargs -0 -P "$jobs" -I{} bash -c 'run_face "$1"' _ {}
end=$(date +%s.%N)

echo "== failures (font, face, variations, glyph id: reason) =="
cat "$logs"/*.log | grep '^FAIL' || true
echo "== per face (worst figures: value@glyph; after a crash, of the resumed part) =="
cat "$logs"/*.log | grep '^RESULT' | sed -E 's/^RESULT //' | sort
awk -v t0="$start" -v t1="$end" -v dir="$logs" '
  /^CHUNK/ { g += $5; e += $7; c += $9; f += $11 }
  /^CHUNK first 0 / { faces++ }
  /^FAIL/ && /\(resume [0-9]+\)$/ { aborted++ }
  END { printf "== total: %d faces, %d glyphs (%d without contours, %d drawn and compared), %d failed glyphs, " \
               "%d crashes or hangs, %.0f s wall; logs in %s ==\n", faces, g + aborted, e, c, f + aborted, aborted, t1 - t0, dir
        exit (f + aborted > 0) }' "$logs"/*.log
