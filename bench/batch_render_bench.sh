#!/usr/bin/env bash
# Many one-line PNGs: one `curvetext render --jobs` process against one
# `curvetext render` process per image and one `pango-view` process per image
# (the incumbent: Pango's layout and cairo's rasteriser), on the same texts
# and font (DejaVu Sans, 16 px, 16 px margins). Prints each way's wall time
# and peak resident memory (the largest of its processes), the median of
# ROUNDS rounds (the three ways interleaved in each), and the ratios.
#
#   bench/batch_render_bench.sh [CURVETEXT] [IMAGES] [ROUNDS]
#
# CURVETEXT defaults to build/bin/curvetext, IMAGES to 100, ROUNDS to 3.
# Needs python3 and pango-view (Debian: pango1.0-tools).
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
curvetext=${1:-$here/../build/bin/curvetext}
images=${2:-100}
rounds=${3:-3}
command -v pango-view >/dev/null || { echo "needs pango-view (Debian: pango1.0-tools)" >&2; exit 1; }
[ -x "$curvetext" ] || { echo "no curvetext binary at $curvetext" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

python3 - "$curvetext" "$images" "$rounds" "$work" <<'PY'
import json, os, statistics, subprocess, sys, time

curvetext, images, rounds, work = sys.argv[1], int(sys.argv[2]), int(sys.argv[3]), sys.argv[4]
font = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf"
# Distinct labels, as a job drawing map or chart labels has: each image's glyphs
# differ a little from the last one's.
texts = [f"Label {i}: the quick brown fox jumps over {i * 7 % 100} lazy dogs" for i in range(images)]


def run(argv, stdin=None):
    """Runs one process; its (wall seconds, peak RSS in KiB)."""
    start = time.perf_counter()
    p = subprocess.Popen(argv, stdin=subprocess.PIPE if stdin is not None else subprocess.DEVNULL,
                         stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    if stdin is not None:
        p.stdin.write(stdin)
        p.stdin.close()
    err = p.stderr.read()
    _, status, usage = os.wait4(p.pid, 0)
    p.returncode = os.waitstatus_to_exitcode(status)
    seconds = time.perf_counter() - start
    if p.returncode != 0:
        sys.exit(f"{argv[0]} failed ({p.returncode}): {err.decode(errors='replace')[:500]}")
    return seconds, usage.ru_maxrss


def batch(out):
    jobs = "".join(json.dumps({"text": t, "font": font, "size": 16, "margin": 16,
                               "output": f"{out}/{i}.png"}) + "\n" for i, t in enumerate(texts))
    return run([curvetext, "render", "--jobs", "-"], jobs.encode())


def one_each(argv_of, out):
    seconds, peak = 0.0, 0
    for i, t in enumerate(texts):
        s, m = run(argv_of(t, f"{out}/{i}.png"))
        seconds, peak = seconds + s, max(peak, m)
    return seconds, peak


def curvetext_each(out):
    return one_each(lambda t, o: [curvetext, "render", "--font", font, "--size", "16", "--margin", "16",
                                  "--text", t, "-o", o], out)


def pango_each(out):
    # --dpi 72: a size of 16 points is 16 px.
    return one_each(lambda t, o: ["pango-view", "-q", "--dpi=72", "--font=DejaVu Sans 16", "--margin=16",
                                  f"--text={t}", f"--output={o}"], out)


ways = [("curvetext render --jobs (1 process)", batch),
        (f"curvetext render ({images} processes)", curvetext_each),
        (f"pango-view ({images} processes)", pango_each)]
results = {name: [] for name, _ in ways}
load_before = os.getloadavg()[0]
for r in range(rounds):
    for k, (name, fn) in enumerate(ways):
        out = f"{work}/{r}-{k}"
        os.makedirs(out)
        results[name].append(fn(out))
        if len(os.listdir(out)) != images:
            sys.exit(f"{name}: {len(os.listdir(out))} images, want {images}")

print(f"{images} one-line PNGs (DejaVu Sans 16 px), median of {rounds} rounds, {os.cpu_count()} CPUs, "
      f"load average {load_before:.1f} before and {os.getloadavg()[0]:.1f} after:")
print("| | wall time | per image | peak memory | time / pango-view | memory / pango-view |")
print("| --- | --- | --- | --- | --- | --- |")
pango = ways[2][0]
ref_t = statistics.median(s for s, _ in results[pango])
ref_m = statistics.median(m for _, m in results[pango])
for name, _ in ways:
    t = statistics.median(s for s, _ in results[name])
    m = statistics.median(m for _, m in results[name])
    print(f"| {name} | {t:.2f} s | {1000 * t / images:.1f} ms | {m / 1024:.1f} MiB | {t / ref_t:.2f}x | {m / ref_m:.2f}x |")
batch_t = statistics.median(s for s, _ in results[ways[0][0]])
each_t = statistics.median(s for s, _ in results[ways[1][0]])
print(f"one --jobs process against {images} curvetext processes: {each_t / batch_t:.1f}x faster")
PY
