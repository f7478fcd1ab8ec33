#!/usr/bin/python3
"""Writes the stroke target's seeds into corpus/stroke/ (binary inputs in the encoding
stroke_fuzzer.cpp decodes). Run from anywhere: /usr/bin/python3 tests/fuzz/make_stroke_seeds.py"""

import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))
MITER, MITER_CLIP, ROUND, BEVEL, ARCS = range(5)
BUTT, RCAP, SQUARE = range(3)
USER, DEVICE, HAIRLINE = range(3)


def small(v):  # Input::number case 0: a small integer
    return bytes([0, v & 0xFF])


def sixteenths(v):  # case 1: int16 / 16
    return bytes([1]) + struct.pack("<h", round(v * 16))


def style(join, cap, unit, width, miter=None, dashes=(), offset=0, path_length=None):
    kinds = join + 5 * cap + 15 * unit + (0x80 if miter is not None else 0)
    out = bytes([kinds]) + sixteenths(width) + (sixteenths(miter) if miter is not None else b"")
    out += bytes([len(dashes)]) + b"".join(sixteenths(d) for d in dashes)
    if dashes:
        out += sixteenths(offset) + (bytes([1]) + sixteenths(path_length) if path_length is not None else bytes([0]))
    return out


def contour(start, closed=False):
    return bytes([0x40 if closed else 0]) + small(start[0]) + small(start[1])


def line(p):
    return bytes([1]) + small(p[0]) + small(p[1])


def conic(c, p, w=None):
    return bytes([3 | (0x80 if w is not None else 0)]) + small(c[0]) + small(c[1]) + small(p[0]) + small(p[1]) + (
        sixteenths(w) if w is not None else b"")


def cubic(c1, c2, p):
    return bytes([5]) + b"".join(small(v) for q in (c1, c2, p) for v in q)


MODE = bytes([0])  # tolerance 1/100 of the path's reach, px_per_unit 1, full mesh check
SEEDS = {
    "zigzag-miter": style(MITER, BUTT, USER, 4, miter=4) + MODE + contour((0, 0)) + line((20, 30)) + line((40, 0)) + line((60, 30)),
    "zigzag-round-caps": style(ROUND, RCAP, USER, 6) + MODE + contour((0, 0)) + line((20, 30)) + line((40, 0)),
    "square-closed-bevel": style(BEVEL, BUTT, USER, 3) + MODE + contour((0, 0), True) + line((40, 0)) + line((40, 40)) + line((0, 40)),
    "circle-arc-dashes": style(MITER_CLIP, SQUARE, USER, 2, dashes=(5, 3), offset=2) + MODE + contour((40, 0)) +
    conic((40, 40), (0, 40), 0.7071) + conic((-40, 40), (-40, 0), 0.7071),
    "cubic-cusp-arcs": style(ARCS, RCAP, USER, 12) + MODE + contour((0, 0)) + cubic((100, 100), (0, 100), (100, 0)),
    "reversal-hairline": style(ROUND, SQUARE, HAIRLINE, 0) + MODE + contour((0, 0)) + line((30, 0)) + line((5, 0)),
    "zero-length-dots": style(MITER, RCAP, DEVICE, 5, dashes=(0, 6)) + MODE + contour((3, 3)) + line((3, 3)) +
    contour((0, 10)) + line((50, 10)),
    "path-length-dashes": style(MITER, BUTT, USER, 2, dashes=(4, 2, 1), offset=-3, path_length=100) + MODE +
    contour((0, 0)) + conic((50, 60), (100, 0), 3.0),
}

if __name__ == "__main__":
    out = os.path.join(HERE, "corpus", "stroke")
    os.makedirs(out, exist_ok=True)
    for name, data in SEEDS.items():
        with open(os.path.join(out, name), "wb") as f:
            f.write(data)
    print("wrote", len(SEEDS), "seeds to", out)
