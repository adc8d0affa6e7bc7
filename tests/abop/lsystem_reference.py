"""An independent reference for fgsg's L-systems: ABOP's 2D turtle, and the
comparison of its segments with those fgsg writes (`turtle segments "lines"`, OBJ `l`
lines). Shared by the ABOP checks in this folder."""
import math
import os
import subprocess


def polygons(s, angle):
    """ABOP's { . }: per filled polygon its vertices (x, y), in the order '.' recorded them;
    polygons nest and are independent of [ ]."""
    x, y, h = 0.0, 0.0, 90.0
    stack, open_, done = [], [], []
    for c in s:
        if c in "Ff":
            x, y = x + math.cos(math.radians(h)), y + math.sin(math.radians(h))
        elif c == "+":
            h += angle
        elif c == "-":
            h -= angle
        elif c == "[":
            stack.append((x, y, h))
        elif c == "]":
            x, y, h = stack.pop()
        elif c == "{":
            open_.append([])
        elif c == "." and open_:
            open_[-1].append((x, y))
        elif c == "}" and open_:
            done.append(open_.pop())
    return done


def fan_triangles(polygon_list, min_area=1e-12):
    """The triangles fgsg fills a polygon with (a fan from its first vertex), without those
    whose area is below the assembler's threshold, as (x0, y0, x1, y1, x2, y2)."""
    out = []
    for p in polygon_list:
        for k in range(1, len(p) - 1):
            a, b, c = p[0], p[k], p[k + 1]
            area = 0.5 * abs((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]))
            if area >= min_area:
                out.append(a + b + c)
    return out


def fgsg_triangles(fgsg, grammar, n, folder):
    """The triangles of `fgsg run GRAMMAR --set n=N` as (x0, y0, x1, y1, x2, y2), from its OBJ."""
    out = os.path.join(folder, "tri%d.obj" % n)
    subprocess.run([fgsg, "run", grammar, "-o", out, "--set", "n=%d" % n, "--quiet"], check=True)
    vertices, tris = [], []
    with open(out) as f:
        for line in f:
            part = line.split()
            if part and part[0] == "v":
                vertices.append((float(part[1]), float(part[2])))
            elif part and part[0] == "f":
                corners = [vertices[int(c.split("/")[0]) - 1] for c in part[1:4]]
                tris.append(corners[0] + corners[1] + corners[2])
    return tris


def segments(s, angle):
    """F as unit segments; heading +Y; '+' turns left (Y towards -X) about +Z."""
    x, y, h = 0.0, 0.0, 90.0
    stack, segs = [], []
    for c in s:
        if c == "F":
            nx, ny = x + math.cos(math.radians(h)), y + math.sin(math.radians(h))
            segs.append((x, y, nx, ny))
            x, y = nx, ny
        elif c == "+":
            h += angle
        elif c == "-":
            h -= angle
        elif c == "[":
            stack.append((x, y, h))
        elif c == "]":
            x, y, h = stack.pop()
    return segs


def unmatched(want, got, tolerance=1e-3):
    """The segments (or triangles) of `want` with no one of `got` within `tolerance` (each used once);
    fgsg writes 32-bit floats, so coordinates agree to about 1e-6 of the plant's size."""
    cells = {}
    cell = lambda v: tuple(int(math.floor(c / 0.01)) for c in v[:2])
    for g in got:
        cells.setdefault(cell(g), []).append(g)
    missing = 0
    for w in want:
        cx, cy = cell(w)
        found = None
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                for g in cells.get((cx + dx, cy + dy), []):
                    if all(abs(a - b) <= tolerance for a, b in zip(w, g)):
                        found = (cx + dx, cy + dy), g
                        break
                if found:
                    break
            if found:
                break
        if found:
            cells[found[0]].remove(found[1])
        else:
            missing += 1
    return missing


def fgsg_segments(fgsg, grammar, n, folder):
    """The segments of `fgsg run GRAMMAR --set n=N` as (x0, y0, x1, y1), from its OBJ."""
    out = os.path.join(folder, "plant%d.obj" % n)
    subprocess.run([fgsg, "run", grammar, "-o", out, "--set", "n=%d" % n, "--quiet"], check=True)
    vertices, segs = [], []
    with open(out) as f:
        for line in f:
            part = line.split()
            if part and part[0] == "v":
                vertices.append((float(part[1]), float(part[2])))
            elif part and part[0] == "l":
                a, b = vertices[int(part[1]) - 1], vertices[int(part[2]) - 1]
                segs.append((a[0], a[1], b[0], b[1]))
    return segs


def check(fgsg, grammar, n, string, angle, folder):
    """Exits with a message unless fgsg draws exactly the segments of `string`."""
    want = segments(string, angle)
    got = fgsg_segments(fgsg, grammar, n, folder)
    missing = unmatched(want, got)
    if len(want) != len(got) or missing:
        raise SystemExit("FAIL: %s n=%d: fgsg drew %d segments, the reference %d (%d of the reference's missing)"
                         % (os.path.basename(grammar), n, len(got), len(want), missing))
    print("ok: %s n=%d, %d segments" % (os.path.basename(grammar), n, len(want)))


def check_polygons(fgsg, grammar, n, string, angle, folder):
    """Exits with a message unless fgsg fills exactly the polygons of `string`."""
    want = fan_triangles(polygons(string, angle))
    got = fgsg_triangles(fgsg, grammar, n, folder)
    missing = unmatched(want, got)
    if len(want) != len(got) or missing:
        raise SystemExit("FAIL: %s n=%d: fgsg filled %d triangles, the reference %d (%d of the reference's missing)"
                         % (os.path.basename(grammar), n, len(got), len(want), missing))
    print("ok: %s n=%d, %d triangles" % (os.path.basename(grammar), n, len(want)))
