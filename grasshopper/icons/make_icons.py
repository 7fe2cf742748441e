#!/usr/bin/env python3
"""Draws the 24 x 24 component icons as PNG files (line glyphs, no
dependencies): python3 make_icons.py <output folder>. The PNGs are committed
and embedded in the .gha; re-run after changing a glyph."""
import struct
import sys
import zlib
from pathlib import Path

SIZE = 24
INK = (40, 44, 52, 255)
ACCENT = (214, 84, 40, 255)

# Each glyph: lists of polylines (pixel coordinates) with a colour.
GLYPHS = {
    "catmull_clark": [(INK, [(3, 3), (20, 3), (20, 20), (3, 20), (3, 3)]),
                      (ACCENT, [(11, 3), (11, 20)]), (ACCENT, [(3, 11), (20, 11)])],
    "loop": [(INK, [(2, 20), (21, 20), (11, 3), (2, 20)]),
             (ACCENT, [(6, 11), (16, 11), (11, 20), (6, 11)])],
    "join": [(INK, [(2, 6), (13, 6), (13, 17), (2, 17), (2, 6)]),
             (ACCENT, [(10, 9), (21, 9), (21, 20), (10, 20), (10, 9)])],
    "cull": [(INK, [(2, 5), (21, 5), (21, 18), (2, 18), (2, 5)]),
             (ACCENT, [(11, 5), (11, 18)]), (ACCENT, [(8, 9), (14, 15)]), (ACCENT, [(14, 9), (8, 15)])],
    "triangulate": [(INK, [(3, 3), (20, 3), (20, 20), (3, 20), (3, 3)]), (ACCENT, [(3, 20), (20, 3)])],
    "weld": [(INK, [(2, 4), (11, 12), (2, 20), (2, 4)]), (INK, [(21, 4), (12, 12), (21, 20), (21, 4)]),
             (ACCENT, [(10, 11), (13, 11), (13, 13), (10, 13), (10, 11)])],
    "orient": [(INK, [(3, 6), (20, 6), (20, 18), (3, 18), (3, 6)]),
               (ACCENT, [(7, 12), (16, 12)]), (ACCENT, [(13, 9), (16, 12), (13, 15)])],
    "weft": [(INK, [(2, 7), (21, 7)]), (INK, [(2, 16), (21, 16)]),
             (ACCENT, [(7, 2), (7, 21)]), (ACCENT, [(16, 2), (16, 21)])],
}


def draw(glyph):
    pixels = [[(0, 0, 0, 0)] * SIZE for _ in range(SIZE)]
    for colour, points in glyph:
        for (x0, y0), (x1, y1) in zip(points, points[1:]):
            steps = max(abs(x1 - x0), abs(y1 - y0), 1)
            for s in range(steps + 1):
                x = round(x0 + (x1 - x0) * s / steps)
                y = round(y0 + (y1 - y0) * s / steps)
                for dx, dy in ((0, 0), (1, 0), (0, 1), (1, 1)):  # 2-pixel pen
                    if 0 <= x + dx < SIZE and 0 <= y + dy < SIZE:
                        pixels[y + dy][x + dx] = colour
    return pixels


def png(pixels):
    raw = b"".join(b"\x00" + b"".join(bytes(p) for p in row) for row in pixels)

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data))

    header = struct.pack(">IIBBBBB", SIZE, SIZE, 8, 6, 0, 0, 0)
    return b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b"")


def main():
    out = Path(sys.argv[1])
    out.mkdir(parents=True, exist_ok=True)
    for name, glyph in GLYPHS.items():
        (out / f"{name}.png").write_bytes(png(draw(glyph)))


if __name__ == "__main__":
    main()
