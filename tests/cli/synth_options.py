#!/usr/bin/env python3
"""fgsg synth: each constraint option has its effect on the label grid it writes, checked
exactly against the example (#51: --symmetry mirror-x parsed as mirror-y passed every
test). Each check also runs without the option and shows the property does not hold
there by chance, so the option, not the seed, makes it.

  --symmetry mirror-x / mirror-y  the grid is its own mirror image across x (y), not y (x)
  --border FACE=LABEL             the cells on that face may have LABEL beyond them
  --periodic                      the cells across the x and y seams are neighbours the
                                  example allows
  --closed                        each face holds only labels on that face of the example
  --block N                       the model is re-synthesized in the blocks docs/synthesis.md
                                  counts (starts at multiples of N/2)
  --mask image                    cells under white pixels hold empty space only
  --cell SIZE                     the written mesh is scaled by SIZE

Usage: synth_options.py FGSG SOURCE_DIR
"""
import os
import subprocess
import sys
import tempfile

fgsg, root = sys.argv[1], sys.argv[2]
tmp = tempfile.mkdtemp(prefix="fgsg_synth_options_")
failures = []


def check(ok, what):
    if not ok:
        failures.append(what)
        print("FAIL:", what, file=sys.stderr)


# Four labels, all their own mirror images (no mirror-x= / mirror-y= maps), in diagonal
# bands: nothing in the example is symmetric, so an unconstrained output is not either.
EXAMPLE = """label . none empty
label A cube
label B cube color=#c03030
label C cylinder color=#3030c0
size 8 8 1
layer 0
A A B B . . C C
A A B B . . C C
. . A A B B . .
. . A A B B . .
C C . . A A B B
C C . . A A B B
B B C C . . A A
B B C C . . A A
"""
example = os.path.join(tmp, "bands.txt")
with open(example, "w") as f:
    f.write(EXAMPLE)


def read_grid(path):
    """A label grid file (example or output) as {(x, y, z): name} and its size."""
    size, grid, z, row = None, {}, None, 0
    rows = []
    for line in open(path):
        words = line.split()
        if not words or words[0].startswith("#"):
            continue
        if words[0] == "size":
            size = tuple(int(w) for w in words[1:4])
        elif words[0] == "layer":
            z, row = int(words[1]), 0
        elif z is not None and size and len(words) == size[0]:
            rows.append((z, row, words))
            row += 1
    # Rows run from y = ny - 1 (north) down to 0, as the format says; only the order
    # within each axis matters to the checks below.
    for z, r, words in rows:
        for x, name in enumerate(words):
            grid[(x, size[1] - 1 - r, z)] = name
    return grid, size


def synth(*options, labels="out.txt", example_file=None):
    path = os.path.join(tmp, labels)
    run = subprocess.run([fgsg, "synth", example_file or example, *options, "--labels", path],
                         capture_output=True, text=True, timeout=120)
    if run.returncode != 0:
        sys.exit(f"FAIL: fgsg synth {' '.join(options)}: exit {run.returncode}\n{run.stderr}")
    return read_grid(path), run.stdout


def neighbours(grid, size, axis, wrap=False):
    """The (label, label beyond it along +axis) pairs of a grid."""
    pairs = set()
    for (x, y, z), a in grid.items():
        p = [x, y, z]
        p[axis] += 1
        if p[axis] == size[axis]:
            if not wrap:
                continue
            p[axis] = 0
        pairs.add((a, grid[tuple(p)]))
    return pairs


ex_grid, ex_size = read_grid(example)
allowed = [neighbours(ex_grid, ex_size, a) for a in (0, 1)]
SIZE = ["--size", "10", "12", "1", "--seed", "3"]


def mirrored(grid, size, axis):
    def image(c):
        p = list(c)
        p[axis] = size[axis] - 1 - p[axis]
        return tuple(p)
    return all(grid[c] == grid[image(c)] for c in grid)


# --symmetry: mirror-x mirrors across x only, mirror-y across y only.
(plain, size), _ = synth(*SIZE)
check(not mirrored(plain, size, 0) and not mirrored(plain, size, 1), "the unconstrained grid is already symmetric")
(mx, size), _ = synth(*SIZE, "--symmetry", "mirror-x")
check(mirrored(mx, size, 0), "--symmetry mirror-x: the grid is not its mirror image across x")
check(not mirrored(mx, size, 1), "--symmetry mirror-x: the grid is mirrored across y as well (mirror-y?)")
(my, size), _ = synth(*SIZE, "--symmetry", "mirror-y")
check(mirrored(my, size, 1), "--symmetry mirror-y: the grid is not its mirror image across y")
check(not mirrored(my, size, 0), "--symmetry mirror-y: the grid is mirrored across x as well (mirror-x?)")
(both, size), _ = synth(*SIZE, "--symmetry", "mirror-x", "--symmetry", "mirror-y")
check(mirrored(both, size, 0) and mirrored(both, size, 1), "two --symmetry options: not both kept")

# --border xmin=C: in the example only C and empty space follow C along +x.
after_c = {b for a, b in allowed[0] if a == "C"}
check(after_c == {"C", "."}, f"the example's labels after C are {after_c}")
first_column = lambda g: {g[c] for c in g if c[0] == 0}
check(not first_column(plain) <= after_c, "without --border the first column already fits beyond C")
(bordered, size), _ = synth(*SIZE, "--border", "xmin=C")
check(first_column(bordered) <= after_c, f"--border xmin=C: first column {first_column(bordered)}")
(bordered_max, size), _ = synth(*SIZE, "--border", "xmax=C")
before_c = {a for a, b in allowed[0] if b == "C"}
last_column = {bordered_max[c] for c in bordered_max if c[0] == size[0] - 1}
check(last_column <= before_c, f"--border xmax=C: last column {last_column}, allowed {before_c}")

# --periodic: the seams in x and y join neighbours the example allows.
def seams_fit(grid, size):
    return all(neighbours(grid, size, a, wrap=True) <= allowed[a] for a in (0, 1))


check(all(neighbours(plain, size, a) <= allowed[a] for a in (0, 1)), "the unconstrained grid has foreign neighbours")
check(not seams_fit(plain, size), "without --periodic the seams already fit")
(periodic, size), _ = synth(*SIZE, "--periodic")
check(seams_fit(periodic, size), "--periodic: a seam joins labels the example never puts side by side")

# --closed: every face of the city holds only labels on that face of the example.
city = os.path.join(root, "examples/synthesis/city.txt")
city_grid, city_size = read_grid(city)


def faces_like_example(grid, size):
    for axis in (0, 1):  # z is left out: the example's own borders fix zmax already
        for end in (0, 1):
            face = lambda g, s: {g[c] for c in g if c[axis] == (0 if end == 0 else s[axis] - 1)}
            if not face(grid, size) <= face(city_grid, city_size):
                return False
    return True


CITY = ["--size", "20", "20", "5", "--block", "10", "--seed", "2"]
(open_city, size), _ = synth(*CITY, example_file=city)
check(not faces_like_example(open_city, size), "without --closed the city's faces already match the example's")
(closed_city, size), stats = synth(*CITY, "--closed", "--stats", example_file=city)
check(faces_like_example(closed_city, size), "--closed: a face holds a label the example's face does not")

# --block N: blocks start at multiples of N/2 and the last one ends at or before the grid's
# end, so 20 x 20 x 5 in blocks of 10 is 3 x 3 x 1 blocks (z: one block, clipped), and
# 10 x 12 x 1 in blocks of 4 is 4 x 5 x 1 (starts 0 2 4 6 in x, 0 2 4 6 8 in y).
check("blocks 9\n" in stats, "--block 10 on 20 x 20 x 5: not 9 blocks")
_, stats = synth(*SIZE, "--block", "4", "--stats")
check("blocks 20\n" in stats, "--block 4 on 10 x 12 x 1: not 20 blocks")
_, stats = synth(*SIZE, "--stats")
check("blocks 0\n" in stats, "without --block the whole grid is one synthesis (0 blocks)")

# --mask: a picture black on its left half, white on its right (a PPM, 2 x 1 pixels).
mask = os.path.join(tmp, "left.ppm")
with open(mask, "wb") as f:
    f.write(b"P6\n2 1\n255\n" + bytes([0, 0, 0, 255, 255, 255]))
(masked, size), _ = synth(*SIZE, "--mask", mask)
right = {masked[c] for c in masked if c[0] >= size[0] // 2}
left = {masked[c] for c in masked if c[0] < size[0] // 2}
check(right == {"."}, f"--mask: the white half holds {right}")
check(left - {"."}, "--mask: the black half is empty")

# --cell SIZE: the same model, every vertex scaled by SIZE.
def obj_vertices(*options):
    path = os.path.join(tmp, "cells.obj")
    subprocess.run([fgsg, "synth", example, *SIZE, *options, "-o", path], check=True, capture_output=True, timeout=120)
    return [tuple(float(v) for v in line.split()[1:4]) for line in open(path) if line.startswith("v ")]


unit = obj_vertices()
scaled = obj_vertices("--cell", "2.5")
check(len(unit) == len(scaled) and len(unit) > 0, f"--cell: {len(unit)} vertices, then {len(scaled)}")
check(all(abs(2.5 * a - b) <= 1e-4 * max(1.0, abs(b)) for u, s in zip(unit, scaled) for a, b in zip(u, s)),
      "--cell 2.5: the vertices are not 2.5 times those of --cell 1")
extent = max(abs(v) for p in scaled for v in p)
check(abs(extent - 2.5 * max(abs(v) for p in unit for v in p)) < 1e-3, "--cell 2.5: the model's extent")

if failures:
    sys.exit(f"{len(failures)} check(s) failed")
print("synth options: all checks passed")
