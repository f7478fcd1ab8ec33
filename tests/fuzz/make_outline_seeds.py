#!/usr/bin/python3
"""Writes the outline target's seeds into corpus/outline/ (binary inputs in
the encoding outline_fuzzer.cpp decodes), or prints what an input decodes to.
Run from anywhere:

    /usr/bin/python3 tests/fuzz/make_outline_seeds.py
    /usr/bin/python3 tests/fuzz/make_outline_seeds.py --decode FILE
"""

import math
import os
import struct
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
MOVE, LINE, CONIC, CUBIC, CLOSE = 0, 1, 3, 4, 5


def small(v):  # Input::number case 0: a small integer
    return bytes([0, v & 0xFF])


def sixteenths(v):  # case 1: int16 / 16
    return bytes([1]) + struct.pack("<h", round(v * 16))


def scaled(mantissa, exponent_byte):  # case 2: mantissa * 2^(8 * e - 50)
    return bytes([2]) + struct.pack("<hb", mantissa, exponent_byte)


def raw(v):  # case 3: the double's bits
    return bytes([3]) + struct.pack("<d", v)


def op(kind, *numbers, weight=None):
    out = bytes([kind]) + b"".join(numbers)
    if kind == CONIC:
        out += bytes([0]) if weight is None else bytes([1]) + weight
    return out


def square(n, x=small, offset=0):
    return (op(MOVE, x(offset), x(offset)) + op(LINE, x(offset + n), x(offset)) + op(LINE, x(offset + n), x(offset + n)) +
            op(LINE, x(offset), x(offset + n)) + op(CLOSE))


SEEDS = {
    "square": bytes([0]) + square(10),
    "two-overlapping-squares": bytes([0]) + square(10) + square(10, offset=5),
    "square-with-hole": bytes([0]) + square(20) + op(MOVE, small(5), small(5)) + op(LINE, small(5), small(15)) +
    op(LINE, small(15), small(15)) + op(LINE, small(15), small(5)),
    "conic-circle-quarter": bytes([0]) + op(MOVE, small(0), small(0)) + op(LINE, small(100), small(0)) +
    op(CONIC, small(100), small(100), small(0), small(100), weight=raw(0.7071067811865476)),
    "cubic-s": bytes([0]) + op(MOVE, sixteenths(0), sixteenths(0)) +
    op(CUBIC, sixteenths(40.5), sixteenths(-20), sixteenths(-20.25), sixteenths(60), sixteenths(30), sixteenths(30)),
    "bow-tie": bytes([0]) + op(MOVE, small(0), small(0)) + op(LINE, small(10), small(10)) + op(LINE, small(10), small(0)) +
    op(LINE, small(0), small(10)),
    "square-2e30": bytes([0]) + square(1, x=lambda v: scaled(v, 10)),
    "raw-1e150": bytes([0]) + op(MOVE, raw(0), raw(0)) + op(LINE, raw(1e150), raw(0)) + op(LINE, raw(0), raw(1e150)),
    "nan": bytes([0]) + op(MOVE, raw(0), raw(0)) + op(LINE, raw(float("nan")), raw(1)) + op(LINE, small(1), small(1)),
    "tolerance-zero-cubic": bytes([1]) + small(0) + op(MOVE, small(0), small(0)) +
    op(CUBIC, small(10), small(20), small(30), small(-20), small(40), small(0)),
}

class Reader:
    """outline_fuzzer.cpp's decoding (fuzz_support.hpp's Input), in Python."""

    def __init__(self, data):
        self.data, self.pos = data, 0

    def empty(self):
        return self.pos >= len(self.data)

    def byte(self):
        if self.empty():
            return 0
        self.pos += 1
        return self.data[self.pos - 1]

    def int16(self):
        low = self.byte()
        return struct.unpack("<h", bytes([low, self.byte()]))[0]

    def number(self):
        case = self.byte() % 4
        if case == 0:
            return struct.unpack("<b", bytes([self.byte()]))[0]
        if case == 1:
            return self.int16() / 16.0
        if case == 2:
            mantissa = self.int16()
            return math.ldexp(mantissa, struct.unpack("<b", bytes([self.byte()]))[0] * 8 - 50)
        return struct.unpack("<d", bytes(self.byte() for _ in range(8)))[0]

    def point(self):
        x = self.number()
        return (x, self.number())


def decode(data):
    r = Reader(data)
    mode = r.byte()
    print("tolerance", r.number() if mode & 1 else 0.25, "| check_mesh", "no" if mode & 2 else "yes")
    for _ in range(256):
        if r.empty():
            break
        kind = r.byte() % 6
        if kind == 0:
            print("move_to", r.point())
        elif kind in (1, 2):
            print("line_to", r.point())
        elif kind == 3:
            control, end = r.point(), r.point()
            print("conic_to", control, end, "weight", r.number() if r.byte() & 1 else 1.0)
        elif kind == 4:
            print("cubic_to", r.point(), r.point(), r.point())
        else:
            print("close")


if __name__ == "__main__":
    if len(sys.argv) == 3 and sys.argv[1] == "--decode":
        with open(sys.argv[2], "rb") as f:
            decode(f.read())
        sys.exit(0)
    out = os.path.join(HERE, "corpus", "outline")
    os.makedirs(out, exist_ok=True)
    for name, data in SEEDS.items():
        with open(os.path.join(out, name), "wb") as f:
            f.write(data)
