#!/usr/bin/env python3
# Writes the building lots of a small city district as a GeoJSON FeatureCollection in local
# metres (x east, y north; runtime/io/geojson_lots.h reads it), deterministically:
#   python3 scripts/make_city_lots.py [--seed N] [--count N] [-o FILE] [--check]
#
# A grid of blocks of about 60 x 40 m between 12 m streets; each block's lots tile a band
# of one depth (15-20 m) along its edges, leaving a yard in the middle. The lots along a
# side have frontages of 8-20 m; the corner lots are squares, lengthened along one street
# into rectangles or along both into L shapes where they take the short ends of a side;
# some lots along the long sides have a courtyard (a hole). Outer rings counter-clockwise,
# holes clockwise, rings closed (RFC 7946); coordinates to the centimetre. Ids "L0001", ...;
# properties "height" (m, 6-30), "floors", "usage" and "roof". The last block is left
# part-built when --count ends in it.
#
# --check reads the written file back and asserts that every lot is a simple polygon of
# that orientation with its holes strictly inside, that no two lots overlap, and that the
# lots of each whole block cover its band exactly.
import argparse
import json
import math
import os
import random

STREET = 1200  # all lengths in centimetres, so that the checks are exact
FRONTAGE = (800, 2000)
DEPTH = (1500, 2000)


def cut(rng, length, lo=FRONTAGE[0], hi=FRONTAGE[1]):
    """Offsets cutting `length` into pieces of lo..hi (length >= lo), ending at length."""
    count = rng.randint(math.ceil(length / hi), length // lo)
    for _ in range(100):
        widths = [rng.uniform(lo, hi) for _ in range(count)]
        scale = length / sum(widths)
        if all(lo <= w * scale <= hi for w in widths):
            break
    else:
        widths, scale = [1.0] * count, length / count
    offsets, run = [], 0.0
    for w in widths[:-1]:
        run += w * scale
        offsets.append(round(run))
    return offsets + [length]


def rectangle(x0, y0, x1, y1):
    return [(x0, y0), (x1, y0), (x1, y1), (x0, y1)]


def corner_lot(cx, cy, sx, sy, depth, along_x, along_y):
    """The lot at block corner (cx, cy), the block lying towards (sx, sy) (each +-1): the
    depth x depth square, lengthened by along_x on the x street and along_y on the y one."""
    if along_x and along_y:
        local = [(0, 0), (depth + along_x, 0), (depth + along_x, depth), (depth, depth),
                 (depth, depth + along_y), (0, depth + along_y)]
    else:
        local = rectangle(0, 0, depth + along_x, depth + along_y)
    ring = [(cx + sx * u, cy + sy * v) for u, v in local]
    return ring if sx * sy > 0 else ring[:1] + ring[:0:-1]  # a mirror image turns round


def side_lots(rng, start, end, outer, inner):
    """Lots along an x street, from x = `start` to `end`, between the street line y =
    `outer` and the band's inner line y = `inner`; counter-clockwise whichever side."""
    lots, step = [], 1 if end > start else -1
    at = start
    for offset in cut(rng, abs(end - start)):
        nxt = start + step * offset
        lo, hi = sorted((at, nxt))
        a, b = sorted((outer, inner))
        ring = rectangle(lo, a, hi, b)
        hole = None
        # Courtyards where the walls round them stay at least 4 m thick.
        if hi - lo >= 1400 and b - a >= 1500 and rng.random() < 0.4:
            w, d = round((hi - lo) * rng.uniform(0.3, 0.4)), round((b - a) * rng.uniform(0.3, 0.4))
            u0, v0 = (lo + hi - w) // 2, (a + b - d) // 2
            hole = rectangle(u0, v0, u0 + w, v0 + d)
            hole = hole[:1] + hole[:0:-1]  # clockwise
        lots.append((ring, [hole] if hole else []))
        at = nxt
    return lots


def split_short_side(rng, length):
    """How a short side (between two corner squares) goes to its two corners."""
    share = rng.choice(["first", "second", "both"] if length >= 600 else ["first", "second"])
    if share == "both":
        half = round(length * rng.uniform(0.4, 0.6))
        return half, length - half
    return (length, 0) if share == "first" else (0, length)


def block_lots(rng, x0, y0, width, height):
    """The lots of one block, going round it counter-clockwise from its south-west corner."""
    x1, y1 = x0 + width, y0 + height
    depth = rng.randint(DEPTH[0], min(DEPTH[1], height // 2 - 200))
    # Corners SW, SE, NE, NW: how far each reaches along its x street (east-west) and its y street.
    along_x = [rng.randint(400, 800) if rng.random() < 0.35 else 0 for _ in range(4)]
    for south, north in ((0, 1), (3, 2)):  # the x streets need >= one frontage between the corners
        if width - 2 * depth - along_x[south] - along_x[north] < FRONTAGE[0]:
            along_x[south] = along_x[north] = 0
    along_y = [0, 0, 0, 0]
    short = height - 2 * depth
    own_lot = {}
    for side, (south, north) in (("east", (1, 2)), ("west", (0, 3))):
        own_lot[side] = short >= FRONTAGE[0] and rng.random() < 0.5
        if not own_lot[side]:
            along_y[south], along_y[north] = split_short_side(rng, short)

    corner = [
        corner_lot(x0, y0, 1, 1, depth, along_x[0], along_y[0]),
        corner_lot(x1, y0, -1, 1, depth, along_x[1], along_y[1]),
        corner_lot(x1, y1, -1, -1, depth, along_x[2], along_y[2]),
        corner_lot(x0, y1, 1, -1, depth, along_x[3], along_y[3]),
    ]
    lots = [(corner[0], [])]
    lots += side_lots(rng, x0 + depth + along_x[0], x1 - depth - along_x[1], y0, y0 + depth)
    lots.append((corner[1], []))
    if own_lot["east"]:
        lots.append((rectangle(x1 - depth, y0 + depth, x1, y1 - depth), []))
    lots.append((corner[2], []))
    lots += side_lots(rng, x1 - depth - along_x[2], x0 + depth + along_x[3], y1, y1 - depth)
    lots.append((corner[3], []))
    if own_lot["west"]:
        lots.append((rectangle(x0, y0 + depth, x0 + depth, y1 - depth), []))
    return lots, depth


def properties(rng):
    usage = rng.choices(["residential", "commercial", "office"], weights=[6, 2, 2])[0]
    height = round(rng.uniform(*{"residential": (6, 18), "commercial": (6, 15), "office": (12, 30)}[usage]), 1)
    roofs = {"residential": [4, 4, 2], "commercial": [1, 2, 7], "office": [1, 1, 8]}[usage]
    return {
        "height": height,
        "floors": max(2, min(10, int(height // 3))),
        "usage": usage,
        "roof": rng.choices(["hipped", "gable", "flat"], weights=roofs)[0],
    }


def metres(cm):
    text = f"{cm / 100:.2f}".rstrip("0").rstrip(".")
    return text if text != "-0" else "0"


def ring_text(ring):
    return "[" + ", ".join(f"[{metres(x)}, {metres(y)}]" for x, y in ring + ring[:1]) + "]"


def generate(seed, count):
    """The lots (id, outer ring, holes, properties) and the blocks (x0, y0, width, height,
    depth, index of the first lot, whether all its lots are there)."""
    rng = random.Random(seed)
    columns = max(1, round(math.sqrt(count / 9)))  # about 9 lots a block: a squarish district
    widths = [rng.randint(5400, 6600) for _ in range(columns)]  # one per column, one height per row
    features, blocks, y0 = [], [], STREET
    while len(features) < count:
        height = rng.randint(3600, 4400)
        x0 = STREET
        for width in widths:
            if len(features) == count:
                break
            lots, depth = block_lots(rng, x0, y0, width, height)
            blocks.append((x0, y0, width, height, depth, len(features), len(features) + len(lots) <= count))
            for outer, holes in lots[: count - len(features)]:
                features.append((f"L{len(features) + 1:04d}", outer, holes, properties(rng)))
            x0 += width + STREET
        y0 += height + STREET
    return features, blocks


def write(features, path):
    lines = []
    for fid, outer, holes, props in features:
        rings = ", ".join(ring_text(r) for r in [outer] + holes)
        lines.append(f'  {{"type": "Feature", "id": "{fid}", "properties": {json.dumps(props)}, '
                     f'"geometry": {{"type": "Polygon", "coordinates": [{rings}]}}}}')
    text = ('{"type": "FeatureCollection",\n'
            ' "crs": {"type": "name", "properties": {"name": "urn:fgsg:local-metres"}},\n'
            ' "features": [\n' + ",\n".join(lines) + "\n]}\n")
    os.makedirs(os.path.dirname(os.path.abspath(path)), exist_ok=True)
    with open(path, "w") as f:
        f.write(text)


# --- --check: everything in integer centimetres, so every test below is exact. ---

def twice_area(ring):
    return sum(ring[i][0] * ring[(i + 1) % len(ring)][1] - ring[(i + 1) % len(ring)][0] * ring[i][1]
               for i in range(len(ring)))


def orient(a, b, c):
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])


def on_segment(p, a, b):
    return orient(a, b, p) == 0 and min(a[0], b[0]) <= p[0] <= max(a[0], b[0]) and \
        min(a[1], b[1]) <= p[1] <= max(a[1], b[1])


def segments_meet(a, b, c, d):
    o1, o2, o3, o4 = orient(a, b, c), orient(a, b, d), orient(c, d, a), orient(c, d, b)
    if o1 * o2 < 0 and o3 * o4 < 0:
        return True
    return on_segment(c, a, b) or on_segment(d, a, b) or on_segment(a, c, d) or on_segment(b, c, d)


def edges(ring):
    return [(ring[i], ring[(i + 1) % len(ring)]) for i in range(len(ring))]


def inside(p, ring):
    """Crossing number; p (possibly at half centimetres) is not on the ring."""
    result = False
    for (ax, ay), (bx, by) in edges(ring):
        if (ay > p[1]) != (by > p[1]) and p[0] < ax + (p[1] - ay) * (bx - ax) / (by - ay):
            result = not result
    return result


def covers(lot, p):
    outer, holes = lot
    return inside(p, outer) and not any(inside(p, h) for h in holes)


def bbox(ring):
    xs, ys = [x for x, _ in ring], [y for _, y in ring]
    return min(xs), min(ys), max(xs), max(ys)


def check_lot(fid, outer, holes):
    assert twice_area(outer) > 0, f"{fid}: outer ring not counter-clockwise"
    rings = [outer] + holes
    for h in holes:
        assert twice_area(h) < 0, f"{fid}: hole not clockwise"
        assert all(inside(p, outer) for p in h), f"{fid}: hole not inside"
    for ring in rings:
        assert len(ring) >= 4 and len(set(ring)) == len(ring), f"{fid}: too few or repeated points"
        for a, b in edges(ring):
            assert a[0] == b[0] or a[1] == b[1], f"{fid}: edge {a}-{b} not along an axis"
    all_edges = [(r, i, e) for r, ring in enumerate(rings) for i, e in enumerate(edges(ring))]
    for j, (r, i, (a, b)) in enumerate(all_edges):
        for s, k, (c, d) in all_edges[j + 1:]:
            n = len(rings[r])
            # Neighbours share a point; two that fold back onto each other leave a point on
            # an edge that is no neighbour (rings here have 4 or more points).
            if r == s and (k == (i + 1) % n or i == (k + 1) % n):
                continue
            assert not segments_meet(a, b, c, d), f"{fid}: edges {a}-{b} and {c}-{d} meet"


def overlap(lot_a, lot_b):
    """Whether two axis-aligned lots share area: test the centre of every cell of the grid
    their coordinates span (inside a cell, neither boundary passes)."""
    xs = sorted({x for lot in (lot_a, lot_b) for ring in [lot[0]] + lot[1] for x, _ in ring})
    ys = sorted({y for lot in (lot_a, lot_b) for ring in [lot[0]] + lot[1] for _, y in ring})
    for x0, x1 in zip(xs, xs[1:]):
        for y0, y1 in zip(ys, ys[1:]):
            centre = ((x0 + x1) / 2, (y0 + y1) / 2)
            if covers(lot_a, centre) and covers(lot_b, centre):
                return True
    return False


def check(path, features):
    with open(path) as f:
        data = json.load(f)
    assert data["crs"]["properties"]["name"] == "urn:fgsg:local-metres"
    lots = []
    for feature in data["features"]:
        rings = feature["geometry"]["coordinates"]
        for ring in rings:
            assert ring[0] == ring[-1], f"{feature['id']}: ring not closed"
        cm = [[(round(x * 100), round(y * 100)) for x, y in ring[:-1]] for ring in rings]
        check_lot(feature["id"], cm[0], cm[1:])
        lots.append((feature["id"], cm[0], cm[1:]))
    assert [f[0] for f in features] == [lot[0] for lot in lots], "ids differ from the generated lots"
    boxes = [bbox(outer) for _, outer, _ in lots]
    order = sorted(range(len(lots)), key=lambda i: boxes[i][0])
    for j, a in enumerate(order):
        for b in order[j + 1:]:
            if boxes[b][0] >= boxes[a][2]:
                break
            if boxes[b][1] < boxes[a][3] and boxes[a][1] < boxes[b][3]:
                assert not overlap(lots[a][1:], lots[b][1:]), f"{lots[a][0]} and {lots[b][0]} overlap"
    return lots


def check_bands(lots, blocks):
    """The outer rings of each whole block's lots cover its band exactly: they do not
    overlap (checked above) and their areas add up to the band's."""
    whole = 0
    for x0, y0, width, height, depth, first, complete in blocks:
        if not complete:
            continue
        band = width * height - (width - 2 * depth) * (height - 2 * depth)
        inside_block = [outer for _, outer, _ in lots[first:]
                        if bbox(outer)[0] >= x0 and bbox(outer)[2] <= x0 + width and
                        bbox(outer)[1] >= y0 and bbox(outer)[3] <= y0 + height]
        area = sum(twice_area(outer) for outer in inside_block) // 2
        assert area == band, f"block at ({metres(x0)}, {metres(y0)}): lots cover {area} of {band} cm2"
        whole += 1
    return whole


def main():
    parser = argparse.ArgumentParser(description="Writes the building lots of a city district as GeoJSON in local metres.")
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--count", type=int, default=200)
    parser.add_argument("-o", "--output", default=os.path.join("examples", "city", "lots.geojson"))
    parser.add_argument("--check", action="store_true", help="read the file back and check the lots")
    args = parser.parse_args()
    if args.count < 1:
        parser.error("--count must be at least 1")
    features, blocks = generate(args.seed, args.count)
    write(features, args.output)
    l_shaped = sum(len(outer) == 6 for _, outer, _, _ in features)
    courtyards = sum(bool(holes) for _, _, holes, _ in features)
    xs = [x for _, outer, _, _ in features for x, _ in outer]
    ys = [y for _, outer, _, _ in features for _, y in outer]
    print(f"{args.output}: {len(features)} lots ({l_shaped} L-shaped, {courtyards} with a courtyard), "
          f"x {metres(min(xs))}..{metres(max(xs))} m, y {metres(min(ys))}..{metres(max(ys))} m, "
          f"{os.path.getsize(args.output)} bytes")
    if args.check:
        lots = check(args.output, features)
        whole = check_bands(lots, blocks)
        print(f"checked: {len(lots)} simple lots, rings oriented, holes inside, no two overlapping; "
              f"{whole} whole blocks tiled exactly")


if __name__ == "__main__":
    main()
