#!/usr/bin/env python3
"""Draws the previews of docs/cga_tutorials.md: each tutorial of examples/cga_tutorials run
with `fgsg run ... --preview` (800 x 600), then scaled to 480 x 360 (area average) so the
docs stay small. Pure Python (zlib only): fgsg's previews are 8-bit RGB or RGBA PNGs.

    scripts/make_cga_tutorial_previews.py build/bin/fgsg      (from the repository root)
"""
import os
import struct
import subprocess
import sys
import tempfile
import zlib

T = "examples/cga_tutorials"
L = T + "/lots"
# name: the arguments after `fgsg run` (the same commands docs/cga_tutorials.md shows)
TUTORIALS = {
    "01": [T + "/01_mass_model.cga", "--lots", L + "/lot20x12.geojson"],
    "02": [T + "/02_facade.cga", "--lots", L + "/lot20x12.geojson"],
    "03": [T + "/03_setbacks.cga", "--lots", L + "/block.geojson"],
    "04": [T + "/04_roofs.cga", "--lots", L + "/row34x10.geojson"],
    "05": [T + "/05_parametric_stochastic.cga", "--lots", L + "/street36x10.geojson", "--seed", "7"],
    "06": [T + "/06_trees.cga", "--lots", L + "/block.geojson"],
    "07": [T + "/07_floor_area_report.cga", "--lots", L + "/block.geojson"],
    "08": [T + "/08_attributes_import.cga", "--set", "floors=4", "--set", "roof_style=hip"],
    "09": [T + "/09_materials_textures.cga", "--lots", L + "/lot20x12.geojson"],
    "10": [T + "/10_mass_modeling.cga", "--lots", L + "/mass_lots.geojson", "--camera", "azimuth=300,elevation=40"],
    "11": [T + "/11_street.cga", "--lots", L + "/street40x12.geojson"],
    "12": [T + "/12_zoning.cga", "--lots", L + "/block.geojson"],
    "13": [T + "/13_courtyard.cga", "--lots", L + "/block30x24.geojson"],
    "14": [T + "/14_roof_overhangs.cga", "--lots", L + "/lot20x12.geojson"],
    "15": [T + "/15_scatter_trees.cga", "--lots", L + "/block.geojson"],
}
SIZE = (480, 360)


def read_png(path):
    """(width, height, channels, rows of bytes) of a non-interlaced 8-bit RGB/RGBA PNG."""
    with open(path, "rb") as f:
        data = f.read()
    pos, idat, width = 8, b"", 0
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour, _, _, interlace = struct.unpack(">IIBBBBB", body)
            if depth != 8 or colour not in (2, 6) or interlace:
                sys.exit("%s: not an 8-bit RGB(A) PNG without interlacing" % path)
            channels = 3 if colour == 2 else 4
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    raw, stride, rows, prev = zlib.decompress(idat), width * channels, [], bytearray(width * channels)
    for y in range(height):
        kind, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for x in range(stride):
            a = line[x - channels] if x >= channels else 0
            b, c = prev[x], prev[x - channels] if x >= channels else 0
            if kind == 1:
                line[x] = (line[x] + a) & 255
            elif kind == 2:
                line[x] = (line[x] + b) & 255
            elif kind == 3:
                line[x] = (line[x] + (a + b) // 2) & 255
            elif kind == 4:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                line[x] = (line[x] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        rows.append(line)
        prev = line
    return width, height, channels, rows


def shrink(width, height, channels, rows, size):
    """RGB rows of `size`, each pixel the average of the source area it covers."""
    w2, h2 = size
    out = []
    for y2 in range(h2):
        y0, y1 = y2 * height / h2, (y2 + 1) * height / h2
        line = bytearray()
        for x2 in range(w2):
            x0, x1 = x2 * width / w2, (x2 + 1) * width / w2
            acc, total = [0.0, 0.0, 0.0], 0.0
            for y in range(int(y0), min(height, int(-(-y1 // 1)))):
                wy = min(y + 1, y1) - max(y, y0)
                row = rows[y]
                for x in range(int(x0), min(width, int(-(-x1 // 1)))):
                    wgt = wy * (min(x + 1, x1) - max(x, x0))
                    for k in range(3):
                        acc[k] += wgt * row[x * channels + k]
                    total += wgt
            line += bytes(min(255, int(round(v / total))) for v in acc)
        out.append(line)
    return out


def write_png(path, size, rows):
    def chunk(kind, body):
        return struct.pack(">I", len(body)) + kind + body + struct.pack(">I", zlib.crc32(kind + body))
    raw = b"".join(b"\x00" + bytes(r) for r in rows)
    with open(path, "wb") as f:
        f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", size[0], size[1], 8, 2, 0, 0, 0))
                + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def main():
    if len(sys.argv) != 2:
        print(__doc__)
        return 2
    fgsg = sys.argv[1]
    os.makedirs("docs/images/cga_tutorials", exist_ok=True)
    with tempfile.TemporaryDirectory() as work:
        for name, args in TUTORIALS.items():
            big = os.path.join(work, name + ".png")
            subprocess.run([fgsg, "run"] + args + ["-o", os.path.join(work, name + ".glb"), "-q",
                                                   "--preview", big], check=True)
            out = "docs/images/cga_tutorials/%s.png" % name
            write_png(out, SIZE, shrink(*read_png(big), SIZE))
            print("wrote", out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
