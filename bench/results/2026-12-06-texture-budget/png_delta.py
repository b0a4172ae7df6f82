#!/usr/bin/env python3
"""Per-pixel Δ (max channel difference, levels 0-255) between two 8-bit RGB/RGBA PNGs of the same
size: prints max Δ, mean Δ and the share of pixels with Δ > 3. Standard library only.

usage: png_delta.py A.png B.png"""
import struct, sys, zlib


def read(path):
    data = open(path, "rb").read()
    pos, idat, w = 8, b"", 0
    while pos < len(data):
        n, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if kind == b"IHDR":
            w, h, depth, ctype = struct.unpack(">IIBB", body[:10])
            assert depth == 8 and ctype in (2, 6), "8-bit RGB or RGBA only"
            bpp = 3 if ctype == 2 else 4
        elif kind == b"IDAT":
            idat += body
        pos += 12 + n
    raw, rows, prev = zlib.decompress(idat), [], bytearray(w * bpp)
    stride = w * bpp
    for y in range(h):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b, c = prev[i], prev[i - bpp] if i >= bpp else 0
            if f == 1: line[i] = (line[i] + a) & 255
            elif f == 2: line[i] = (line[i] + b) & 255
            elif f == 3: line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        prev = line
    return w, h, bpp, rows


wa, ha, ba, ra = read(sys.argv[1])
wb, hb, bb, rb = read(sys.argv[2])
assert (wa, ha) == (wb, hb), "sizes differ"
deltas = [max(abs(ra[y][x * ba + c] - rb[y][x * bb + c]) for c in range(3)) for y in range(ha) for x in range(wa)]
print("max %d, mean %.4f, share > 3: %.4f %%" % (max(deltas), sum(deltas) / len(deltas),
                                                  100.0 * sum(d > 3 for d in deltas) / len(deltas)))
