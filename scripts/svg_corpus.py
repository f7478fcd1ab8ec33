#!/usr/bin/python3
"""Draws every N-th SVG icon of the installed icon themes with
`curvetext shape --size SxS` and with rsvg-convert at the same size, and
reports per theme how many curvetext draws, how well the two agree, and the
first refusal reason of the others, counted.

Agreement: both images are composited over white; per pixel the largest
|R|, |G| or |B| difference in [0, 1]. "mean" is the mean of the channel
differences over all pixels of an icon, "max" the largest of any pixel.
An icon matches when mean <= --mean-tolerance and max <= --max-tolerance.

  scripts/svg_corpus.py --curvetext build/tools/curvetext --step 10

With --min-match R (a fraction) it exits 1 when fewer than R of the sampled
icons draw and match, or when any icon that draws does not match (the CTest
corpus test). Needs rsvg-convert (librsvg2-bin) and python3-cairo.
"""
import argparse
import collections
import json
import os
import re
import subprocess
import sys
import tempfile

import cairo

THEMES = {
    "breeze": "/usr/share/icons/breeze",
    "tango": "/usr/share/icons/Tango",
    "adwaita": "/usr/share/icons/Adwaita",
}


def icon_files(root):
    """Regular .svg files (not links: a theme links one icon under many names), sorted."""
    found = []
    for directory, _, names in os.walk(root):
        for name in names:
            path = os.path.join(directory, name)
            if name.endswith(".svg") and not os.path.islink(path) and os.path.isfile(path):
                found.append(path)
    return sorted(found)


def load_over_white(path, size):
    """RGB floats in [0, 1] of a PNG composited over white, row-major, or None."""
    try:
        surface = cairo.ImageSurface.create_from_png(path)
    except Exception:  # noqa: BLE001 - a missing or broken PNG is "no image"
        return None
    if surface.get_width() != size or surface.get_height() != size:
        return None
    target = cairo.ImageSurface(cairo.FORMAT_RGB24, size, size)
    ctx = cairo.Context(target)
    ctx.set_source_rgb(1, 1, 1)
    ctx.paint()
    ctx.set_source_surface(surface, 0, 0)
    ctx.paint()
    target.flush()
    data = bytes(target.get_data())
    stride = target.get_stride()
    pixels = []
    for y in range(size):
        row = data[y * stride : y * stride + 4 * size]
        # FORMAT_RGB24 is native-endian 0x00RRGGBB: B, G, R, x in memory here.
        pixels.append(row)
    return pixels


def compare(a, b, size):
    total = 0
    worst = 0
    for ra, rb in zip(a, b):
        for i in range(0, 4 * size, 4):
            d = max(abs(ra[i] - rb[i]), abs(ra[i + 1] - rb[i + 1]), abs(ra[i + 2] - rb[i + 2]))
            total += abs(ra[i] - rb[i]) + abs(ra[i + 1] - rb[i + 1]) + abs(ra[i + 2] - rb[i + 2])
            worst = max(worst, d)
    return total / (3.0 * size * size * 255.0), worst / 255.0


def write_diff(a, b, size, path):
    """Grey where the images agree, darker by the largest channel difference."""
    surface = cairo.ImageSurface(cairo.FORMAT_RGB24, size, size)
    stride = surface.get_stride()
    out = bytearray(stride * size)
    for y, (ra, rb) in enumerate(zip(a, b)):
        for x in range(size):
            i = 4 * x
            d = max(abs(ra[i + k] - rb[i + k]) for k in range(3))
            out[y * stride + i : y * stride + i + 3] = bytes([255 - d] * 3)
    surface.get_data()[:] = out
    surface.mark_dirty()
    surface.write_to_png(path)


def reason_key(message):
    """The refusal reason without the file name and positions, for counting."""
    m = message
    m = re.sub(r"^curvetext: ", "", m)
    m = re.sub(r"^\S+\.svg: ", "", m)
    m = re.sub(r"line \d+, column \d+: ", "", m)
    m = re.sub(r"'[^']*'", "'...'", m)
    m = re.sub(r"\"[^\"]*\"", '"..."', m)
    m = re.sub(r"\d+(\.\d+)?", "N", m)
    return m[:140]


def run_curvetext(binary, files, out_dir, size, extra):
    """Draws every file in one process (--jobs); {file: error or None}."""
    jobs_path = os.path.join(out_dir, "jobs.txt")
    with open(jobs_path, "w") as jobs:
        for i, f in enumerate(files):
            job = {"input": f, "output": os.path.join(out_dir, "ct%d.png" % i), "size": "%dx%d" % (size, size)}
            job.update(extra)
            jobs.write(json.dumps(job) + "\n")
    run = subprocess.run([binary, "shape", "--jobs", jobs_path], capture_output=True, text=True, timeout=3600)
    results = {}
    for line in run.stdout.splitlines():
        report = json.loads(line)
        results[files[report["line"] - 1]] = report.get("error")
    return results


def run_rsvg(f, png, size):
    r = subprocess.run(["rsvg-convert", "-w", str(size), "-h", str(size), "-o", png, f], capture_output=True)
    return r.returncode == 0


def measure_theme(args, name, root, out_dir):
    files = icon_files(root)[:: args.step]
    if args.limit:
        files = files[: args.limit]
    extra = {"current-color": args.current_color} if args.current_color else {}
    errors = run_curvetext(args.curvetext, files, out_dir, args.size, extra)
    stats = {"sampled": len(files), "drawn": 0, "matched": 0, "means": [], "maxes": [], "reasons": collections.Counter()}
    stats["mismatched"] = []
    for i, f in enumerate(files):
        error = errors.get(f, "no report")
        if error:
            stats["reasons"][reason_key(error)] += 1
            continue
        stats["drawn"] += 1
        ref = os.path.join(out_dir, "rsvg%d.png" % i)
        if not run_rsvg(f, ref, args.size):
            stats["reasons"]["rsvg-convert failed"] += 1
            continue
        a = load_over_white(os.path.join(out_dir, "ct%d.png" % i), args.size)
        b = load_over_white(ref, args.size)
        if a is None or b is None:
            stats["mismatched"].append((f, float("nan"), float("nan")))
            continue
        mean, worst = compare(a, b, args.size)
        stats["means"].append(mean)
        stats["maxes"].append(worst)
        if mean <= args.mean_tolerance and worst <= args.max_tolerance:
            stats["matched"] += 1
        else:
            stats["mismatched"].append((f, mean, worst))
            if args.keep:
                os.makedirs(args.keep, exist_ok=True)
                base = os.path.join(args.keep, "%s-%d" % (name, i))
                os.replace(os.path.join(out_dir, "ct%d.png" % i), base + "-curvetext.png")
                os.replace(ref, base + "-rsvg.png")
                write_diff(a, b, args.size, base + "-diff.png")
    return stats


def report(name, s):
    n = s["sampled"]
    pct = 100.0 * s["matched"] / n if n else 0.0
    line = "%-8s sampled %4d  drawn %4d  matched %4d (%.1f%%)" % (name, n, s["drawn"], s["matched"], pct)
    if s["means"]:
        means = sorted(s["means"])
        line += "  mean|RGB| median %.4f worst %.4f  max px median %.3f worst %.3f" % (
            means[len(means) // 2], means[-1], sorted(s["maxes"])[len(means) // 2], max(s["maxes"]))
    print(line)
    for f, mean, worst in s["mismatched"]:
        print("    differs: %s mean %.4f max %.3f" % (f, mean, worst))
    for reason, count in s["reasons"].most_common():
        print("    %4d  %s" % (count, reason))


def main():
    p = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--curvetext", required=True)
    p.add_argument("--step", type=int, default=10, help="every N-th icon of each theme (sorted paths)")
    p.add_argument("--limit", type=int, default=0, help="at most this many icons per theme (0: all)")
    p.add_argument("--size", type=int, default=96)
    p.add_argument("--themes", default="breeze,tango,adwaita", help="theme names or folders of .svg files")
    p.add_argument("--mean-tolerance", type=float, default=0.004)
    p.add_argument("--max-tolerance", type=float, default=0.35)
    p.add_argument("--current-color", default="", help="passed to curvetext shape --current-color")
    p.add_argument("--min-match", type=float, default=None)
    p.add_argument("--keep", default="", help="folder for both images of each icon that differs")
    args = p.parse_args()
    total = matched = 0
    bad_drawn = 0
    with tempfile.TemporaryDirectory() as tmp:
        for name in args.themes.split(","):
            # A theme's name, or a folder of SVG files (named by its last part).
            label = os.path.basename(name.rstrip("/"))
            out_dir = os.path.join(tmp, label)
            os.makedirs(out_dir)
            s = measure_theme(args, label, THEMES.get(name, name), out_dir)
            report(label, s)
            total += s["sampled"]
            matched += s["matched"]
            bad_drawn += len(s["mismatched"])
    print("all      sampled %4d  matched %4d (%.1f%%)" % (total, matched, 100.0 * matched / max(total, 1)))
    if args.min_match is not None and (matched < args.min_match * total or bad_drawn):
        sys.exit(1)


if __name__ == "__main__":
    main()
