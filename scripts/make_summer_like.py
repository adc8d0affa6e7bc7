#!/usr/bin/env python3
"""Writes examples/synthesis/summer_like.json: a 2D tile set in the manner of Gumin's
"Summer" (WFC SimpleTiled): grass, three waters, raised ground, shores and cliffs with
sides, corners and turns, and roads over the grass, 39 labels. Its neighbour rules are
derived, not typed: every tile is drawn by the terrain at its four corners and the roads
crossing its edges, and two oriented tiles may stand side by side where the shared edge
agrees. Like Summer it has no diagonal tiles, so a corner left half water, half grass
across a diagonal has no tile, which is what makes such sets hard for a solver.

usage: scripts/make_summer_like.py > examples/synthesis/summer_like.json
"""
import json

# Corners in order NE, NW, SW, SE (counter-clockwise from +x+y); roads on edges E, N, W, S.
# A quarter turn counter-clockwise takes corner k to k+1 and edge k to k+1: orientation v
# of a tile is its base turned v times, as the tile-set reader defines it. The bases
# follow WFC's classes: L has its feature at NE (mirrored in x = turned once), T is
# symmetric in x, I in x and in a half turn.
G, W, H = "g", "w", "h"
TILES = [
    # name, symmetry, corners NE NW SW SE, road edges E N W S, colour, weight
    ("grass", "X", (G, G, G, G), (0, 0, 0, 0), "#6aa84f", 8.0),
    ("water_a", "X", (W, W, W, W), (0, 0, 0, 0), "#3d85c6", 3.0),
    ("water_b", "X", (W, W, W, W), (0, 0, 0, 0), "#2f6fad", 1.0),
    ("water_c", "X", (W, W, W, W), (0, 0, 0, 0), "#4a90d9", 1.0),
    ("waterside", "T", (W, W, G, G), (0, 0, 0, 0), "#9fc5e8", 1.0),
    ("watercorner", "L", (W, G, G, G), (0, 0, 0, 0), "#b6d7a8", 0.5),
    ("waterturn", "L", (G, W, W, W), (0, 0, 0, 0), "#6fa8dc", 0.5),
    ("high", "X", (H, H, H, H), (0, 0, 0, 0), "#93c47d", 2.0),
    ("cliff", "T", (H, H, G, G), (0, 0, 0, 0), "#7f6000", 0.5),
    ("cliffcorner", "L", (H, G, G, G), (0, 0, 0, 0), "#bf9000", 0.25),
    ("cliffturn", "L", (G, H, H, H), (0, 0, 0, 0), "#a67c00", 0.25),
    ("road", "I", (G, G, G, G), (0, 1, 0, 1), "#999999", 0.5),
    ("roadturn", "L", (G, G, G, G), (1, 1, 0, 0), "#888888", 0.25),
]
CARDINALITY = {"X": 1, "I": 2, "L": 4, "T": 4}


def turned(corners, roads, v):
    for _ in range(v):
        corners = (corners[3],) + corners[:3]
        roads = (roads[3],) + roads[:3]
    return corners, roads


def oriented():
    for name, sym, corners, roads, _, _ in TILES:
        for v in range(CARDINALITY[sym]):
            c, r = turned(corners, roads, v)
            yield ("%s %d" % (name, v) if v else name), c, r


def main():
    tiles = [{"name": n, "symmetry": s, "asset": "quad", "color": col, "weight": w}
             for n, s, _, _, col, w in TILES]
    tiles[0]["empty"] = True
    neighbors = []
    all_oriented = list(oriented())
    for a, ca, ra in all_oriented:
        for b, cb, rb in all_oriented:
            # a's east edge (corners NE, SE) against b's west edge (NW, SW).
            if ca[0] == cb[1] and ca[3] == cb[2] and ra[0] == rb[2]:
                neighbors.append({"left": a, "right": b})
    doc = {
        "name": "summer_like",
        "comment": "A 2D tile set after Gumin's Summer (scripts/make_summer_like.py draws the tiles by "
                   "corner terrain and derives every neighbour rule). Run: fgsg synth "
                   "examples/synthesis/summer_like.json --size 100 100 1 --order entropy --labels out.txt",
        "tiles": tiles,
        "neighbors": neighbors,
    }
    print(json.dumps(doc, indent=1))


if __name__ == "__main__":
    main()
