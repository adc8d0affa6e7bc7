#!/usr/bin/env python3
"""A canonical, readable digest of a mesh file (the OBJ `fgsg run -o x.obj` writes), for
golden tests that compare geometry, not only counts (#51), and a diff of two digests.

  mesh_digest.py digest MESH.obj [--precision P] [--full-limit N] > expected_geometry.txt
  mesh_digest.py diff EXPECTED.txt ACTUAL.txt     exit 1 and a readable report if they differ
  mesh_digest.py check EXPECTED.txt MESH.obj      digest MESH.obj as EXPECTED.txt says, then diff

Canonical form: every position is rounded to a multiple of P (default 1e-4; -0 is 0), each
triangle is written as its three rounded corners starting at its least one (its winding,
and so its facing, kept), each line segment as its two corners in order, and both lists are
sorted. Vertex and triangle order do not matter; positions, facing and connectivity do.
The digest's summary (counts, bounding box, centroid of the corners, total area of the
rounded triangles) is always written; the triangles and segments themselves when there
are at most --full-limit of them (default 2000), else their sha256 alone (16 hex digits) —
the summary still says what changed.
"""
import argparse
import hashlib
import math
import sys

FORMAT = "fgsg-mesh-digest 1"


def read_obj(path):
    vertices, triangles, segments = [], [], []
    with open(path) as f:
        for line in f:
            w = line.split()
            if not w:
                continue
            if w[0] == "v":
                vertices.append(tuple(float(x) for x in w[1:4]))
            elif w[0] == "f":
                corners = [int(c.split("/")[0]) for c in w[1:]]
                corners = [c - 1 if c > 0 else len(vertices) + c for c in corners]
                for k in range(1, len(corners) - 1):  # a polygon as a fan (fgsg writes triangles)
                    triangles.append((corners[0], corners[k], corners[k + 1]))
            elif w[0] == "l":
                corners = [int(c.split("/")[0]) - 1 for c in w[1:]]
                segments += list(zip(corners, corners[1:]))
    return vertices, triangles, segments


def decimals(precision):
    return max(0, -int(math.floor(math.log10(precision) + 1e-9)))


def digest(path, precision=1e-4, full_limit=2000):
    vertices, triangles, segments = read_obj(path)
    places = decimals(precision)

    def text(p):
        out = []
        for x in p:
            r = round(x / precision) * precision
            s = f"{r:.{places}f}"
            out.append("0" + s[2:] if s.startswith("-0") and float(s) == 0 else s)
        return " ".join(out)

    rounded = [text(p) for p in vertices]
    keys = [tuple(round(x / precision) for x in p) for p in vertices]

    def canonical_triangle(t):
        k = min(range(3), key=lambda i: keys[t[i]])
        t = t[k:] + t[:k]
        return " | ".join(rounded[i] for i in t)

    tri_lines = sorted(canonical_triangle(t) for t in triangles)
    seg_lines = sorted(" | ".join(rounded[i] for i in s) for s in segments)
    lines = [f"# {FORMAT}: positions rounded to {precision:g}; written by scripts/mesh_digest.py",
             f"precision {precision:g}",
             f"vertices {len(vertices)}",
             f"triangles {len(triangles)}",
             f"segments {len(segments)}"]
    if vertices:
        lo = [min(p[a] for p in vertices) for a in range(3)]
        hi = [max(p[a] for p in vertices) for a in range(3)]
        used = [vertices[i] for t in triangles for i in t] + [vertices[i] for s in segments for i in s]
        centroid = [sum(p[a] for p in used) / len(used) for a in range(3)] if used else [0, 0, 0]
        lines += [f"bbox.min {text(lo)}", f"bbox.max {text(hi)}", f"centroid {text(centroid)}"]
    # The area of the rounded triangles: a move below the precision cannot change it.
    snapped = [tuple(k * precision for k in key) for key in keys]
    area = 0.0
    for a, b, c in triangles:
        u = [snapped[b][k] - snapped[a][k] for k in range(3)]
        v = [snapped[c][k] - snapped[a][k] for k in range(3)]
        n = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
        area += 0.5 * math.sqrt(sum(x * x for x in n))
    # The area to 6 significant digits: exact enough to see a change, not float noise.
    lines.append(f"area {area:.6g}")
    if len(tri_lines) + len(seg_lines) <= full_limit:
        lines += [f"t {t}" for t in tri_lines] + [f"l {s}" for s in seg_lines]
    else:
        h = hashlib.sha256("\n".join(tri_lines + ["--"] + seg_lines).encode()).hexdigest()[:16]
        lines.append(f"geometry.sha256 {h}")
    return "\n".join(lines) + "\n"


def parse(text):
    summary, items = {}, []
    for line in text.splitlines():
        if not line or line.startswith("#"):
            continue
        key, _, value = line.partition(" ")
        if key in ("t", "l"):
            items.append(line)
        else:
            summary[key] = value
    return summary, items


def diff(expected_text, actual_text, limit=10):
    """A readable report of what differs, empty when nothing does."""
    (es, ei), (as_, ai) = parse(expected_text), parse(actual_text)
    report = []
    for key in list(es) + [k for k in as_ if k not in es]:
        if es.get(key) != as_.get(key):
            report.append(f"  {key}: expected {es.get(key, '(none)')}, got {as_.get(key, '(none)')}")
    if ei != ai:
        only_e = sorted(set(ei) - set(ai))
        only_a = sorted(set(ai) - set(ei))
        report.append(f"  {len(only_e)} expected triangles/segments missing, {len(only_a)} unexpected ones; the first:")
        report += [f"    - {x}" for x in only_e[:limit]] + [f"    + {x}" for x in only_a[:limit]]
    return "\n".join(report)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="command", required=True)
    d = sub.add_parser("digest")
    d.add_argument("mesh")
    d.add_argument("--precision", type=float, default=1e-4)
    d.add_argument("--full-limit", type=int, default=2000)
    f = sub.add_parser("diff")
    f.add_argument("expected")
    f.add_argument("actual")
    c = sub.add_parser("check")
    c.add_argument("expected")
    c.add_argument("mesh")
    a = ap.parse_args()
    if a.command == "digest":
        sys.stdout.write(digest(a.mesh, a.precision, a.full_limit))
        return 0
    expected = open(a.expected).read()
    if a.command == "diff":
        actual = open(a.actual).read()
    else:  # as the expected digest was made: its precision, listed in full or hashed
        summary, items = parse(expected)
        listed = len(items) > 0 or int(summary.get("triangles", 0)) + int(summary.get("segments", 0)) == 0
        actual = digest(a.mesh, float(summary.get("precision", 1e-4)), 10**12 if listed else -1)
    report = diff(expected, actual)
    if report:
        print(f"geometry differs from {a.expected}:\n{report}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
