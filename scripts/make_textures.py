#!/usr/bin/env python3
"""Writes the example textures (examples/textures/*.png): small procedural pictures made
here, so no third-party image is committed. Deterministic: the test suite reruns this
into a temporary folder and checks the committed files are the same bytes.

    python3 scripts/make_textures.py [OUT_DIR]
"""
import os
import struct
import sys
import zlib


def png(path, width, height, pixel):
    """An 8-bit RGB PNG whose pixel (x, y) (y down from the top) is pixel(x, y)."""
    raw = bytearray()
    for y in range(height):
        raw.append(0)  # filter: none
        for x in range(width):
            raw.extend(max(0, min(255, int(c))) for c in pixel(x, y))

    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)

    header = struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0)
    data = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) + chunk(b"IDAT", zlib.compress(bytes(raw), 9)) + \
        chunk(b"IEND", b"")
    with open(path, "wb") as f:
        f.write(data)


def noise(*k):
    """A repeatable value in [0, 1) from integers."""
    h = 2166136261
    for v in k:
        h = ((h ^ (v & 0xFFFFFFFF)) * 16777619) & 0xFFFFFFFF
    h ^= h >> 13
    h = (h * 0x5BD1E995) & 0xFFFFFFFF
    return (h ^ (h >> 15)) / 2.0 ** 32


def brick(x, y):
    """Running bond: 4 courses of 2 bricks per tile (a tile is 2 m x 1 m on a facade)."""
    course = y // 32
    shift = 32 if course % 2 else 0
    column = ((x + shift) % 128) // 64
    in_mortar = y % 32 < 3 or (x + shift) % 64 < 3
    if in_mortar:
        g = 190 + 20 * noise(x, y, 7)
        return (g, g - 4, g - 12)
    tint = noise(course, column, 1) * 40 - 20
    grain = noise(x, y, 3) * 18
    return (150 + tint + grain, 70 + tint / 2 + grain, 52 + grain)


def roof(x, y):
    """Clay tiles: rows of rounded tiles, darker at each row's lower edge."""
    row = y // 16
    shift = 8 if row % 2 else 0
    u = ((x + shift) % 16) / 16.0
    v = (y % 16) / 16.0
    shade = 1.0 - 0.45 * v * v - 0.25 * abs(u - 0.5)
    grain = noise(x, y, 5) * 16
    return (170 * shade + grain, 78 * shade + grain / 2, 55 * shade)


def plaster(x, y):
    n = noise(x // 2, y // 2, 11) * 14 + noise(x, y, 12) * 8
    return (214 + n, 204 + n, 180 + n)


def window(x, y):
    """A window tile: a frame, two panes, a sill."""
    frame = x < 10 or x > 117 or y < 10 or y > 117 or 60 <= x < 68 or 60 <= y < 66
    if frame:
        return (236, 234, 226)
    sky = 1.0 - y / 128.0
    return (70 + 60 * sky, 100 + 70 * sky, 130 + 80 * sky)


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "examples", "textures")
    os.makedirs(out, exist_ok=True)
    png(os.path.join(out, "brick.png"), 128, 128, brick)
    png(os.path.join(out, "roof_tiles.png"), 64, 64, roof)
    png(os.path.join(out, "plaster.png"), 64, 64, plaster)
    png(os.path.join(out, "window.png"), 128, 128, window)


if __name__ == "__main__":
    main()
