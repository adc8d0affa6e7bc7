#!/usr/bin/env python3
"""fgsg evolve: each GA option has its effect on the run it reports (#51: the crossover
test inverted was caught only by a hash of the tool's own output). The runs are seeded,
so each effect is exact; each check is paired with a run where the option differs.

  --crossover 0 --mutation 0  children are copies of parents: the best never changes
  --crossover 1 --mutation 0  children are crossed: the best improves
  --parents 1                 every child copies the best: generation 1 is all the best
  --elite 1                   the best survives: the best fitness never falls (it does
                              with --elite 0 under heavy mutation)
  --threshold F               the run stops at the first generation whose best reaches F
  --axiom-side A              the pattern is A * k^generation cells a side
  --cell-pixels N             the preview is N pixels per cell

Usage: evolve_options.py FGSG SOURCE_DIR
"""
import json
import os
import struct
import subprocess
import sys
import tempfile

fgsg, root = sys.argv[1], sys.argv[2]
tiles = os.path.join(root, "examples/assets/ornament_tiles.json")
tmp = tempfile.mkdtemp(prefix="fgsg_evolve_options_")
failures = []


def check(ok, what):
    if not ok:
        failures.append(what)
        print("FAIL:", what, file=sys.stderr)


def evolve(*options):
    out = os.path.join(tmp, "run.json")
    run = subprocess.run([fgsg, "evolve", tiles, "--seed", "7", "--population", "30", "--generation", "3",
                          *options, "--json", out], capture_output=True, text=True, timeout=300)
    if run.returncode != 0:
        sys.exit(f"FAIL: fgsg evolve {' '.join(options)}: exit {run.returncode}\n{run.stderr}")
    return json.load(open(out))


def bests(run):
    return [g["best"] for g in run["history"]]


# A threshold no run here reaches (each checks it stopped at the generation limit): the
# runs go the full number of generations.
FULL = ["--threshold", "1", "--max-generations", "12"]

# --crossover: without crossover or mutation nothing new is ever made.
copies = evolve(*FULL, "--crossover", "0", "--mutation", "0")
check(len(copies["history"]) == 13 and copies["stop"] != "threshold",
      f"{len(copies['history'])} generations reported, expected 13; stopped by {copies['stop']}")
check(all(b == bests(copies)[0] for b in bests(copies)),
      f"--crossover 0 --mutation 0: the best changed: {bests(copies)}")
crossed = evolve(*FULL, "--crossover", "1", "--mutation", "0")
check(bests(crossed)[0] == bests(copies)[0], "the same seed began with another population")
check(bests(crossed)[-1] > bests(crossed)[0], f"--crossover 1: crossing never improved the best: {bests(crossed)}")

# --parents 1: every child copies the one best parent (no crossover of a parent with
# itself makes anything new), so generation 1 is the best of generation 0, P times.
single = evolve(*FULL, "--parents", "1", "--elite", "0", "--crossover", "0", "--mutation", "0")
g0, g1 = single["history"][0], single["history"][1]
check(abs(g1["mean"] - g0["best"]) <= 1e-12 and g1["best"] == g0["best"],
      f"--parents 1: generation 1 has mean {g1['mean']}, not the best of generation 0, {g0['best']}")
many = evolve(*FULL, "--parents", "20", "--elite", "0", "--crossover", "0", "--mutation", "0")
check(many["history"][1]["mean"] < many["history"][0]["best"] - 1e-6,
      "--parents 20: generation 1 is all one genome as with --parents 1")

# --elite: under heavy mutation the best falls from one generation to the next unless it
# is kept.
def falls(run):
    b = bests(run)
    return any(b[t + 1] < b[t] for t in range(len(b) - 1))


check(falls(evolve(*FULL, "--elite", "0", "--mutation", "0.9")), "--elite 0: the best never fell")
check(not falls(evolve(*FULL, "--elite", "1", "--mutation", "0.9")), "--elite 1: the best fell")

# --threshold: the first generation whose best reaches it ends the run.
b = bests(evolve("--threshold", "1", "--max-generations", "30"))
target = next(x for x in b if x > b[0])  # a fitness first reached after generation 0
stopped = evolve("--threshold", repr(target), "--max-generations", "30")
sb = bests(stopped)
check(stopped["stop"] == "threshold", f"--threshold {target}: stopped by {stopped['stop']}")
check(sb[-1] >= target and all(x < target for x in sb[:-1]),
      f"--threshold {target}: bests {sb} do not end at the first to reach it")
check(len(sb) == b.index(target) + 1, f"--threshold: {len(sb)} generations, expected {b.index(target) + 1}")

# --axiom-side: A * k^generation cells a side (k = 3, generation 3).
def cells_a_side(run):
    return len(run["pattern"])


lsystem = "{ABAA.ABBA.A}"  # the paper's Fig. 2 string: k = 2, axiom side 1
check(cells_a_side(evolve("--max-generations", "0", "--k", "3")) == 27, "axiom side 1, k 3, generation 3: not 27")
check(cells_a_side(evolve("--max-generations", "0", "--k", "3", "--axiom-side", "2")) == 54,
      "--axiom-side 2, k 3, generation 3: not 54 cells a side")


# --cell-pixels: the preview's width in its PNG header (IHDR), cells x pixels.
def png_width(*options):
    path = os.path.join(tmp, "p.png")
    subprocess.run([fgsg, "evolve", tiles, "--lsystem", lsystem, "--generation", "3", *options, "--preview", path],
                   check=True, capture_output=True, timeout=120)
    data = open(path, "rb").read(24)
    return struct.unpack(">II", data[16:24])


check(png_width() == (8 * 32, 8 * 32), f"default preview {png_width()}, expected 8 cells x 32 pixels")
check(png_width("--cell-pixels", "5") == (40, 40), f"--cell-pixels 5: {png_width('--cell-pixels', '5')}")

if failures:
    sys.exit(f"{len(failures)} check(s) failed")
print("evolve options: all checks passed")
