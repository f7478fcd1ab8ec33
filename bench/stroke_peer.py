#!/usr/bin/python3
"""Strokes against Cairo (librsvg's rsvg-convert), same inputs, same run (docs/performance.md, "Strokes").

  /usr/bin/python3 bench/stroke_peer.py [--curvetext build/bin/curvetext] [--quality] [--sheet N] [--rounds R]
                                        [--aa full|vbaa|auto|...]

--quality: every case of tests/fixtures/strokes (path, style and the GEOS oracle region) drawn by
`curvetext shape` (as NURBS JSON, full antialiasing) and by rsvg-convert (as SVG), each compared with
the exact area coverage of the oracle (shapely: the area of each pixel's square inside the region),
with the tests' figures: mean error over the edge band (pixels where either image is strictly between
0.02 and 0.98, dilated by one) and ink ratio.

--sheet N: a CAD-like sheet of N stroked lines and circle arcs (widths 0.5-4 px, a quarter dashed,
butt and round caps) at 2048 x 1536 px, grouped into one path per style, written as JSON and SVG;
the wall time of `curvetext shape` and of rsvg-convert (median of R rounds, interleaved) and their
ratio. Needs python3-shapely, python3-numpy, librsvg2-bin.
"""
import argparse
import json
import math
import os
import random
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, os.path.join(ROOT, "tests", "fixtures", "strokes"))


def read_case(path):
    case = {"subpaths": [], "rings": []}
    for line in open(path):
        f = line.split()
        if not f or f[0].startswith("#"):
            continue
        if f[0] == "size":
            case["size"] = (int(f[1]), int(f[2]))
        elif f[0] == "style":
            st, i = {}, 1
            while i < len(f):
                if f[i] == "dashes":
                    st["dashes"] = [float(v) for v in f[i + 1:]]
                    break
                st[f[i]] = f[i + 1]
                i += 2
            case["style"] = st
        elif f[0] == "subpath":
            case["subpaths"].append({"closed": f[1] == "closed", "start": (float(f[2]), float(f[3])), "cmds": []})
        elif f[0] in "LQC":
            case["subpaths"][-1]["cmds"].append((f[0], [float(v) for v in f[1:]]))
        elif f[0] == "ring":
            v = [float(x) for x in f[1:]]
            case["rings"].append(list(zip(v[0::2], v[1::2])))
    return case


def case_json(case):
    st = case["style"]
    contours = []
    for sp in case["subpaths"]:
        items, pen = [], sp["start"]
        for kind, v in sp["cmds"]:
            if kind == "L":
                items.append({"line": [list(pen), v[0:2]]})
                pen = tuple(v[0:2])
            elif kind == "Q":
                items.append({"bezier": {"points": [list(pen), v[0:2], v[2:4]], "weights": [1, v[4], 1]}})
                pen = tuple(v[2:4])
            else:
                items.append({"bezier": {"points": [list(pen), v[0:2], v[2:4], v[4:6]]}})
                pen = tuple(v[4:6])
        contours.append({"items": items, "closed": sp["closed"]})
    stroke = {"width": float(st["width"]), "join": st["join"], "cap": st["cap"], "miter_limit": float(st["miter"]),
              "dashes": st["dashes"], "dash_offset": float(st["offset"]), "path_length": float(st["pathlength"])}
    w, h = case["size"]
    return json.dumps({"size": [w, h], "view": [0, 0, w, h],
                       "shapes": [{"fill": False, "stroke": stroke, "contours": contours}]})


def conic_as_cubic_or_arc(p0, c, p2, w):
    """SVG has no rational quadratic: w = 1 is a Q, a circle or ellipse arc an A command."""
    if abs(w - 1.0) < 1e-12:
        return "Q %r %r %r %r" % (c[0], c[1], p2[0], p2[1])
    l0, l2 = math.dist(p0, c), math.dist(c, p2)
    if abs(l0 - l2) < 1e-9 * l0 and abs(w - math.dist(p0, p2) / (2 * l0)) < 1e-9:
        half = math.acos(w)
        r = l0 / math.tan(half)
        sweep = 1 if (c[0] - p0[0]) * (p2[1] - c[1]) - (c[1] - p0[1]) * (p2[0] - c[0]) > 0 else 0
        return "A %r %r 0 0 %d %r %r" % (r, r, sweep, p2[0], p2[1])
    # An ellipse arc: its conjugate diameters give the SVG arc (via the conic's implicit form).
    return ellipse_arc(p0, c, p2, w)


def ellipse_arc(p0, c, p2, w):
    m = ((p0[0] + p2[0]) / 2, (p0[1] + p2[1]) / 2)
    # Centre of the ellipse through p0, p2 with tangents towards c, weight w: on the line c -> m.
    k = 1.0 / (1.0 - w * w)
    centre = (c[0] + (m[0] - c[0]) * k, c[1] + (m[1] - c[1]) * k)
    # Conjugate semi-diameters: u = p0 - centre, v with the tangent direction at p0.
    u = (p0[0] - centre[0], p0[1] - centre[1])
    t = (c[0] - p0[0], c[1] - p0[1])
    # v is along t with length such that centre + u cos + v sin passes through p2.
    a = (p2[0] - centre[0], p2[1] - centre[1])
    # Solve a = u cos(phi) + v sin(phi), v = s t.
    det = u[0] * t[1] - u[1] * t[0]
    cos_phi = (a[0] * t[1] - a[1] * t[0]) / det
    s_sin = (u[0] * a[1] - u[1] * a[0]) / det
    sin_phi = math.sqrt(max(0.0, 1 - cos_phi * cos_phi))
    v = (t[0] * s_sin / sin_phi, t[1] * s_sin / sin_phi)
    # Axes from the conjugate diameters (Rytz): eigen-decomposition of M M^T, M = [u v].
    a11, a12, a22 = u[0] ** 2 + v[0] ** 2, u[0] * u[1] + v[0] * v[1], u[1] ** 2 + v[1] ** 2
    tr, dt = a11 + a22, a11 * a22 - a12 * a12
    l1 = tr / 2 + math.sqrt(max(0.0, tr * tr / 4 - dt))
    l2 = tr / 2 - math.sqrt(max(0.0, tr * tr / 4 - dt))
    angle = math.degrees(0.5 * math.atan2(2 * a12, a11 - a22))
    sweep = 1 if (c[0] - p0[0]) * (p2[1] - c[1]) - (c[1] - p0[1]) * (p2[0] - c[0]) > 0 else 0
    return "A %r %r %r 0 %d %r %r" % (math.sqrt(l1), math.sqrt(l2), angle, sweep, p2[0], p2[1])


def case_svg(case):
    """The case in SVG's y-down frame: a group flipping y keeps the path data in document units."""
    st = case["style"]
    w, h = case["size"]
    d = []
    for sp in case["subpaths"]:
        pen = sp["start"]
        d.append("M %r %r" % pen)
        for kind, v in sp["cmds"]:
            if kind == "L":
                d.append("L %r %r" % tuple(v[0:2]))
                pen = tuple(v[0:2])
            elif kind == "Q":
                d.append(conic_as_cubic_or_arc(pen, v[0:2], v[2:4], v[4]))
                pen = tuple(v[2:4])
            else:
                d.append("C %r %r %r %r %r %r" % tuple(v))
                pen = tuple(v[4:6])
        if sp["closed"]:
            d.append("Z")
    dash = " ".join(repr(x) for x in st["dashes"]) or "none"
    pl = float(st["pathlength"])
    return ('<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" viewBox="0 0 %d %d">'
            '<rect width="%d" height="%d" fill="white"/><g transform="matrix(1 0 0 -1 0 %d)">'
            '<path d="%s" fill="none" stroke="black" stroke-width="%s" stroke-linejoin="%s" stroke-linecap="%s" '
            'stroke-miterlimit="%s" stroke-dasharray="%s" stroke-dashoffset="%s"%s/></g></svg>') % (
        w, h, w, h, w, h, h, " ".join(d), st["width"], st["join"], st["cap"], st["miter"], dash, st["offset"],
        ' pathLength="%r"' % pl if pl > 0 else "")


def read_grey(path):
    """Coverage of black on white from a PNG: 1 - red / 255 (numpy array, row 0 on top)."""
    import numpy as np
    import zlib
    import struct
    data = open(path, "rb").read()
    pos, idat = 8, b""
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            w, h, depth, ctype, _, _, _ = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    n = {0: 1, 2: 3, 4: 2, 6: 4}[ctype]
    raw, stride = zlib.decompress(idat), w * n
    out, prev = np.zeros((h, w)), bytearray(stride)
    for y in range(h):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - n] if i >= n else 0
            b, c = prev[i], prev[i - n] if i >= n else 0
            if f == 1:
                line[i] = (line[i] + a) & 255
            elif f == 2:
                line[i] = (line[i] + b) & 255
            elif f == 3:
                line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        out[y] = [1.0 - line[x * n] / 255.0 for x in range(w)]
        prev = line
    return out


def exact_coverage(case):
    import numpy as np
    from shapely.geometry import Polygon, box
    from shapely.ops import unary_union
    w, h = case["size"]
    polys = []
    # Rings: exteriors counter-clockwise, holes clockwise (make_stroke_oracles.py orients them).
    ext = [r for r in case["rings"] if Polygon(r).exterior.is_ccw]
    holes = [r for r in case["rings"] if not Polygon(r).exterior.is_ccw]
    region = unary_union([Polygon(r) for r in ext]).difference(unary_union([Polygon(r) for r in holes]))
    cov = np.zeros((h, w))
    minx, miny, maxx, maxy = region.bounds
    for y in range(max(0, int(h - maxy) - 1), min(h, int(h - miny) + 2)):
        for x in range(max(0, int(minx) - 1), min(w, int(maxx) + 2)):
            cell = box(x, h - y - 1, x + 1, h - y)
            if region.intersects(cell):
                cov[y, x] = region.intersection(cell).area
    return cov


def compare(got, ref):
    import numpy as np
    edge = ((got > 0.02) & (got < 0.98)) | ((ref > 0.02) & (ref < 0.98))
    band = edge.copy()
    band[1:, :] |= edge[:-1, :]
    band[:-1, :] |= edge[1:, :]
    band[:, 1:] |= band[:, :-1].copy()
    band[:, :-1] |= band[:, 1:].copy()
    diff = np.abs(got - ref)
    return diff[band].mean(), got.sum() / ref.sum()


def quality(curvetext):
    cases = sorted(f[:-4] for f in os.listdir(os.path.join(ROOT, "tests", "fixtures", "strokes")) if f.endswith(".txt"))
    print("| case | curvetext full: edge error | ink | rsvg-convert (Cairo): edge error | ink |")
    print("| --- | ---: | ---: | ---: | ---: |")
    with tempfile.TemporaryDirectory() as work:
        for name in cases:
            case = read_case(os.path.join(ROOT, "tests", "fixtures", "strokes", name + ".txt"))
            w, h = case["size"]
            open(os.path.join(work, "c.json"), "w").write(case_json(case))
            open(os.path.join(work, "c.svg"), "w").write(case_svg(case))
            drawn = subprocess.run([curvetext, "shape", "--input", os.path.join(work, "c.json"), "--aa", "full", "-o",
                                    os.path.join(work, "ct.png")], stderr=subprocess.DEVNULL).returncode == 0
            subprocess.run(["rsvg-convert", "-w", str(w), "-h", str(h), "-o", os.path.join(work, "rs.png"),
                            os.path.join(work, "c.svg")], check=True)
            ref = exact_coverage(case)
            e2, i2 = compare(read_grey(os.path.join(work, "rs.png")), ref)
            if drawn:
                e1, i1 = compare(read_grey(os.path.join(work, "ct.png")), ref)
                print("| %s | %.4f | %.4f | %.4f | %.4f |" % (name, e1, i1, e2, i2))
            else:
                print("| %s | refused (mesh) | | %.4f | %.4f |" % (name, e2, i2))
            sys.stdout.flush()


def sheet(n, seed=1):
    rng = random.Random(seed)
    W, H = 2048, 1536
    widths = [0.5, 1.0, 1.5, 2.0, 3.0, 4.0]
    groups = {}
    for i in range(n):
        width = rng.choice(widths)
        dashed = rng.random() < 0.25
        cap = "round" if rng.random() < 0.3 else "butt"
        key = (width, dashed, cap)
        x, y = rng.uniform(20, W - 20), rng.uniform(20, H - 20)
        if rng.random() < 0.7:  # a line, mostly axis-aligned as drawings are
            length = rng.uniform(10, 200)
            angle = rng.choice([0, math.pi / 2]) if rng.random() < 0.7 else rng.uniform(0, math.pi)
            x2 = min(W - 5, max(5, x + length * math.cos(angle)))
            y2 = min(H - 5, max(5, y + length * math.sin(angle)))
            item = ("L", (x, y), (x2, y2))
        else:  # a circle arc of 30-90 degrees
            r = rng.uniform(5, 80)
            a0, span = rng.uniform(0, 2 * math.pi), math.radians(rng.uniform(30, 90))
            p0 = (x + r * math.cos(a0), y + r * math.sin(a0))
            p2 = (x + r * math.cos(a0 + span), y + r * math.sin(a0 + span))
            c = (x + r / math.cos(span / 2) * math.cos(a0 + span / 2), y + r / math.cos(span / 2) * math.sin(a0 + span / 2))
            item = ("A", p0, c, p2, math.cos(span / 2), r)
        groups.setdefault(key, []).append(item)
    shapes, paths = [], []
    for (width, dashed, cap), items in sorted(groups.items()):
        contours, d = [], []
        for it in items:
            if it[0] == "L":
                contours.append({"items": [{"line": [list(it[1]), list(it[2])]}], "closed": False})
                d.append("M %.3f %.3f L %.3f %.3f" % (it[1][0], H - it[1][1], it[2][0], H - it[2][1]))
            else:
                _, p0, c, p2, w, r = it
                contours.append({"items": [{"bezier": {"points": [list(p0), list(c), list(p2)], "weights": [1, w, 1]}}],
                                 "closed": False})
                d.append("M %.3f %.3f A %.3f %.3f 0 0 0 %.3f %.3f" % (p0[0], H - p0[1], r, r, p2[0], H - p2[1]))
        stroke = {"width": width, "cap": cap, "color": "#000000"}
        attrs = 'stroke-width="%r" stroke-linecap="%s"' % (width, cap)
        if dashed:
            stroke["dashes"] = [6 * width, 3 * width]
            attrs += ' stroke-dasharray="%r %r"' % (6 * width, 3 * width)
        shapes.append({"fill": False, "stroke": stroke, "contours": contours})
        paths.append('<path fill="none" stroke="black" %s d="%s"/>' % (attrs, " ".join(d)))
    doc = {"size": [W, H], "view": [0, 0, W, H], "shapes": shapes}
    svg = ('<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" viewBox="0 0 %d %d">'
           '<rect width="%d" height="%d" fill="white"/>%s</svg>') % (W, H, W, H, W, H, "".join(paths))
    return json.dumps(doc), svg, (W, H), len(groups)


def timed(argv):
    t = time.perf_counter()
    p = subprocess.run(argv, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE)
    if p.returncode != 0:
        return None, p.stderr.decode().strip()
    return time.perf_counter() - t, ""


def sheet_bench(curvetext, n, rounds, aa):
    doc, svg, (W, H), groups = sheet(n)
    with tempfile.TemporaryDirectory() as work:
        jp, sp = os.path.join(work, "sheet.json"), os.path.join(work, "sheet.svg")
        open(jp, "w").write(doc)
        open(sp, "w").write(svg)
        ct, rs, err = [], [], ""
        for _ in range(rounds):
            t, e = timed([curvetext, "shape", "--input", jp, "--aa", aa, "-o", os.path.join(work, "ct.png")])
            if t is None:
                err = e
            else:
                ct.append(t)
            t, e = timed(["rsvg-convert", "-w", str(W), "-h", str(H), "-o", os.path.join(work, "rs.png"), sp])
            rs.append(t)
        print("| sheet: %d strokes in %d paths, %dx%d px | wall s (median of %d) |" % (n, groups, W, H, rounds))
        print("| --- | ---: |")
        print("| curvetext shape (JSON, --aa %s) | %s |" % (aa, "%.2f" % statistics.median(ct) if ct else "refused: " + err))
        print("| rsvg-convert (Cairo, same drawing as SVG) | %.2f |" % statistics.median(rs))
        if ct:
            print("| ratio curvetext / Cairo | %.2f |" % (statistics.median(ct) / statistics.median(rs)))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--curvetext", default=os.path.join(ROOT, "build", "bin", "curvetext"))
    ap.add_argument("--quality", action="store_true")
    ap.add_argument("--sheet", type=int, default=0)
    ap.add_argument("--rounds", type=int, default=3)
    ap.add_argument("--aa", default="full", help="curvetext's antialiasing for the sheet")
    a = ap.parse_args()
    if a.quality:
        quality(a.curvetext)
    if a.sheet:
        sheet_bench(a.curvetext, a.sheet, a.rounds, a.aa)


if __name__ == "__main__":
    main()
