#!/usr/bin/env python3
"""fgsg field --length/--step and fgsg atlas --paint-slab/--mask-size take effect (#51),
measured on what they write:

  field --length L --step S   on a plane, every streamline (a chain of OBJ `l` segments)
                              runs at most L either way of its seed, so at most 2L in all,
                              the longest nearly that, its points S apart (the last of
                              each way may be closer)
  atlas --mask-size N         the mask is N x N pixels
  atlas --paint-slab ...,w    the white part of the mask is the surface within w of the
                              plane: on a flat square cut square to a side, 2w / side of
                              what a slab over everything paints (within 5 %), nothing for
                              a slab off the mesh

Usage: field_atlas_options.py FGSG SOURCE_DIR
"""
import math
import os
import struct
import subprocess
import sys
import tempfile
import zlib
from collections import defaultdict

fgsg, root = sys.argv[1], sys.argv[2]
tmp = tempfile.mkdtemp(prefix="fgsg_field_atlas_options_")
failures = []


def check(ok, what):
    if not ok:
        failures.append(what)
        print("FAIL:", what, file=sys.stderr)


def run(*args):
    r = subprocess.run([fgsg, *args], capture_output=True, text=True, timeout=300)
    if r.returncode != 0:
        sys.exit(f"FAIL: fgsg {' '.join(args)}: exit {r.returncode}\n{r.stderr}")
    return r.stdout


# ---- field ---------------------------------------------------------------------------
grammar = os.path.join(tmp, "plane.fgsg")
with open(grammar, "w") as f:
    f.write("surface plane(10, 10, 24);\n"
            "field F = design tensor { wedge at (-2, 0, 0) decay 1; regular at (0, -4, 0) angle 0 decay 0.5; };\n"
            "Axiom ~> I(\"cube\");\n")


def streamlines(length, step):
    """The streamlines of `fgsg field` as lists of points, from its OBJ's `l` segments."""
    path = os.path.join(tmp, "field.obj")
    run("field", grammar, "--seeds", "40", "--length", str(length), "--step", str(step), "-o", path)
    vertices, links = [], defaultdict(list)
    for line in open(path):
        w = line.split()
        if w and w[0] == "v":
            vertices.append(tuple(float(x) for x in w[1:4]))
        elif w and w[0] == "l":
            a, b = int(w[1]) - 1, int(w[2]) - 1
            links[a].append(b), links[b].append(a)
    lines, seen = [], set()
    for start in links:  # walk each chain from one of its two ends
        if start in seen or len(links[start]) != 1:
            continue
        chain, prev, at = [start], None, start
        while True:
            seen.add(at)
            nxt = [n for n in links[at] if n != prev]
            if not nxt:
                break
            prev, at = at, nxt[0]
            chain.append(at)
        lines.append([vertices[i] for i in chain])
    return lines


def check_streamlines(length, step):
    lines = streamlines(length, step)
    check(len(lines) >= 20, f"--length {length} --step {step}: {len(lines)} streamlines from 40 seeds")
    totals, gaps = [], []
    for pts in lines:
        segs = [math.dist(a, b) for a, b in zip(pts, pts[1:])]
        totals.append(sum(segs))
        gaps += segs
    check(max(totals) <= 2 * length * (1 + 1e-4), f"--length {length}: a streamline {max(totals):.4f} long")
    check(max(totals) >= 1.9 * length, f"--length {length}: the longest streamline is {max(totals):.4f}")
    # (The OBJ's coordinates have 6 or 7 significant digits.)
    check(max(gaps) <= step * (1 + 1e-4), f"--step {step}: points {max(gaps):.7f} apart")
    gaps.sort()
    median = gaps[len(gaps) // 2]
    check(abs(median - step) <= 0.01 * step, f"--step {step}: the median spacing is {median:.5f}")


check_streamlines(1.0, 0.05)
check_streamlines(2.0, 0.2)


# ---- atlas ---------------------------------------------------------------------------
def png(path):
    """Width, height and the 8-bit grey (or first channel) pixels of a PNG, unfiltered."""
    data = open(path, "rb").read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", path
    at, idat = 8, b""
    while at < len(data):
        n, kind = struct.unpack(">I4s", data[at:at + 8])
        body = data[at + 8:at + 8 + n]
        if kind == b"IHDR":
            width, height, depth, colour = struct.unpack(">IIBB", body[:10])
            assert depth == 8, "8-bit PNGs only"
            channels = {0: 1, 2: 3, 4: 2, 6: 4}[colour]
        elif kind == b"IDAT":
            idat += body
        at += 12 + n
    raw, stride = zlib.decompress(idat), width * channels
    rows, prev = [], bytearray(stride)
    for y in range(height):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - channels] if i >= channels else 0
            b, c = prev[i], prev[i - channels] if i >= channels else 0
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
        rows.append(line[::channels])
        prev = line
    return width, height, rows


# A flat 4 x 4 square of 8 x 8 quads in the XY plane, no texture coordinates of its own.
square = os.path.join(tmp, "square.obj")
with open(square, "w") as f:
    n = 8
    for j in range(n + 1):
        for i in range(n + 1):
            f.write(f"v {4.0 * i / n} {4.0 * j / n} 0\n")
    for j in range(n):
        for i in range(n):
            a = j * (n + 1) + i + 1
            f.write(f"f {a} {a + 1} {a + n + 2} {a + n + 1}\n")


def white(slab, size="256"):
    mask = os.path.join(tmp, "mask.png")
    env_run = subprocess.run([fgsg, "atlas", square, "--paint-slab", slab, "--mask", mask, "--mask-size", size],
                             capture_output=True, text=True, timeout=300, env={**os.environ, "FGSG_CACHE_DIR": "off"})
    if env_run.returncode != 0:
        sys.exit(f"FAIL: fgsg atlas --paint-slab {slab}: exit {env_run.returncode}\n{env_run.stderr}")
    w, h, rows = png(mask)
    return (w, h), sum(1 for r in rows for p in r if p >= 128)


dims, everything = white("2,2,0,1,0,0,10")
check(dims == (256, 256), f"--mask-size 256: the mask is {dims}")
check(white("2,2,0,1,0,0,10", "64")[0] == (64, 64), "--mask-size 64: not 64 x 64")
check(everything > 0.3 * 256 * 256, f"a slab over the whole square paints {everything} of 65536 pixels")
check(white("20,2,0,1,0,0,1")[1] == 0, "a slab beside the square paints something")
for half_width in (0.2, 0.5):  # the band x in [2 - w, 2 + w] of the 4-wide square
    for normal in ("1,0,0", "0,1,0"):
        _, band = white(f"2,2,0,{normal},{half_width}")
        expected = everything * 2 * half_width / 4
        check(abs(band - expected) <= 0.05 * expected,
              f"--paint-slab normal {normal} half width {half_width}: {band} white pixels, expected {expected:.0f}")

if failures:
    sys.exit(f"{len(failures)} check(s) failed")
print("field and atlas options: all checks passed")
