#!/usr/bin/env python3
"""Compares two 8-bit PNGs (as curvetext writes them: grey, grey+alpha, RGB or
RGBA, not interlaced) pixel by pixel. Prints "W H MAXDIFF INK_A INK_B": the
largest difference of any channel (RGBA, 0-255) and each image's ink, the sum
of 255 - red over all pixels. Exit 1 when the sizes differ."""
import struct
import sys
import zlib

CHANNELS = {0: 1, 2: 3, 4: 2, 6: 4}


def read_png(path):
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", path + " is not a PNG"
    pos, idat = 8, b""
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            w, h, depth, ctype, _, _, interlace = struct.unpack(">IIBBBBB", body)
            assert depth == 8 and interlace == 0 and ctype in CHANNELS, path
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    n = CHANNELS[ctype]
    raw, stride, rows, prev = zlib.decompress(idat), w * n, [], bytearray(w * n)
    for y in range(h):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - n] if i >= n else 0
            b, c = prev[i], prev[i - n] if i >= n else 0
            if f == 1: line[i] = (line[i] + a) & 255
            elif f == 2: line[i] = (line[i] + b) & 255
            elif f == 3: line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        prev = line
    rgba = []
    for line in rows:
        for x in range(w):
            px = line[x * n:(x + 1) * n]
            rgba.append((px[0],) * 3 + (px[1] if n == 2 else 255,) if n <= 2 else tuple(px) + ((255,) if n == 3 else ()))
    return w, h, rgba


def main():
    wa, ha, a = read_png(sys.argv[1])
    wb, hb, b = read_png(sys.argv[2])
    if (wa, ha) != (wb, hb):
        print("size %dx%d vs %dx%d" % (wa, ha, wb, hb))
        return 1
    diff = max((abs(p - q) for pa, pb in zip(a, b) for p, q in zip(pa, pb)), default=0)
    print(wa, ha, diff, sum(255 - p[0] for p in a), sum(255 - p[0] for p in b))
    return 0


if __name__ == "__main__":
    sys.exit(main())
