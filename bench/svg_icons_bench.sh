#!/usr/bin/env bash
# A set of SVG icons to 96 x 96 PNGs: one `curvetext shape --jobs` process
# (parse, mesh, draw, encode each icon) against one `rsvg-convert` process per
# icon (the incumbent, librsvg with cairo) and one `curvetext shape` process
# per icon. The icons: every N-th icon of Debian's Breeze, Tango and Adwaita
# themes that curvetext draws (scripts/svg_corpus.py's sampling), ICONS of
# them. Prints each way's wall time, the median of ROUNDS rounds (the ways
# interleaved in each), and the ratios.
#
#   bench/svg_icons_bench.sh [CURVETEXT] [ICONS] [ROUNDS]
#
# CURVETEXT defaults to build/bin/curvetext, ICONS to 100, ROUNDS to 3.
# Needs rsvg-convert (Debian: librsvg2-bin) and the icon themes.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
curvetext=${1:-$here/../build/bin/curvetext}
icons=${2:-100}
rounds=${3:-3}
command -v rsvg-convert >/dev/null || { echo "needs rsvg-convert (Debian: librsvg2-bin)" >&2; exit 1; }
[ -x "$curvetext" ] || { echo "no curvetext binary at $curvetext" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

python3 - "$curvetext" "$icons" "$rounds" "$work" <<'PY'
import json, os, statistics, subprocess, sys, time

curvetext, icons, rounds, work = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), sys.argv[4]
themes = ["/usr/share/icons/breeze", "/usr/share/icons/Tango", "/usr/share/icons/Adwaita"]
files = []
for root in themes:
    found = sorted(os.path.join(d, n) for d, _, ns in os.walk(root) for n in ns
                   if n.endswith(".svg") and not os.path.islink(os.path.join(d, n)))
    files += found[::17]
# Only icons curvetext draws: the comparison is of the same work.
jobs = os.path.join(work, "probe.txt")
with open(jobs, "w") as f:
    for i, p in enumerate(files):
        f.write(json.dumps({"input": p, "output": os.path.join(work, "p%d.png" % i), "size": "96x96"}) + "\n")
report = subprocess.run([curvetext, "shape", "--jobs", jobs], capture_output=True, text=True).stdout.splitlines()
drawn = [files[json.loads(l)["line"] - 1] for l in report if "error" not in json.loads(l)][:icons]
print("%d icons (every 17th of each theme that curvetext draws)" % len(drawn))
with open(jobs, "w") as f:
    for i, p in enumerate(drawn):
        f.write(json.dumps({"input": p, "output": os.path.join(work, "c%d.png" % i), "size": "96x96"}) + "\n")

def timed(run):
    t = time.perf_counter()
    run()
    return time.perf_counter() - t

def ct_jobs():
    subprocess.run([curvetext, "shape", "--jobs", jobs], check=True, capture_output=True)

def ct_each():
    for i, p in enumerate(drawn):
        subprocess.run([curvetext, "shape", "-i", p, "--size", "96x96", "-o", os.path.join(work, "e%d.png" % i)],
                       check=True, capture_output=True)

def rsvg_each():
    for i, p in enumerate(drawn):
        subprocess.run(["rsvg-convert", "-w", "96", "-h", "96", "-o", os.path.join(work, "r%d.png" % i), p],
                       check=True, capture_output=True)

ways = {"curvetext shape --jobs (1 process)": ct_jobs, "curvetext shape (a process each)": ct_each,
        "rsvg-convert (a process each)": rsvg_each}
times = {k: [] for k in ways}
for _ in range(rounds):
    for k, run in ways.items():
        times[k].append(timed(run))
base = statistics.median(times["rsvg-convert (a process each)"])
for k in ways:
    m = statistics.median(times[k])
    print("%-38s %7.3f s  %6.2f ms/icon  %.2fx rsvg-convert's time" % (k, m, 1000 * m / len(drawn), m / base))
PY
