"""An independent reference for fgsg's L-systems: ABOP's context matching on a string of
one-letter modules, ABOP's 2D turtle, and the comparison of its segments and polygons
with those fgsg writes (`turtle segments "lines"`: OBJ `l` lines; polygons: `f`
triangles). Shared by the ABOP checks in this folder."""
import math
import os
import subprocess


def left_context(s, i, skipped):
    """The module ABOP's left context sees before s[i], or None: whole branches ([...])
    are stepped over, a '[' is left into the parent branch, and modules for which
    `skipped` holds (#ignore'd ones; with lpfg's #consider, those not listed) are passed."""
    j = i - 1
    while j >= 0:
        c = s[j]
        if c == "]":  # step over the whole branch
            depth = 0
            while j >= 0:
                if s[j] == "]":
                    depth += 1
                elif s[j] == "[":
                    depth -= 1
                    if depth == 0:
                        break
                j -= 1
            j -= 1
        elif c == "[" or skipped(c):  # out of the branch into its parent; skipped modules
            j -= 1
        else:
            return c
    return None


def right_context(s, i, skipped):
    """The module ABOP's right context sees after s[i], or None: whole branches are stepped
    over, the ']' ending the branch of s[i] ends the search, `skipped` modules are passed."""
    j = i + 1
    while j < len(s):
        c = s[j]
        if c == "[":  # step over the whole branch
            depth = 0
            while j < len(s):
                if s[j] == "[":
                    depth += 1
                elif s[j] == "]":
                    depth -= 1
                    if depth == 0:
                        break
                j += 1
            j += 1
        elif c == "]":  # the end of this branch: no right context
            return None
        elif skipped(c):
            j += 1
        else:
            return c
    return None


def turtle(s, angle):
    """ABOP's 2D turtle, heading +Y, '+' turning left (Y towards -X) about +Z: F draws a
    unit segment (x0, y0, x1, y1) and moves, f moves; { . } collect polygons, which nest
    and are independent of [ ]: per filled polygon its vertices (x, y) in the order '.'
    recorded them. Returns (segments, polygons)."""
    x, y, h = 0.0, 0.0, 90.0
    stack, open_, segs, done = [], [], [], []
    for c in s:
        if c in "Ff":
            nx, ny = x + math.cos(math.radians(h)), y + math.sin(math.radians(h))
            if c == "F":
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
        elif c == "{":
            open_.append([])
        elif c == "." and open_:
            open_[-1].append((x, y))
        elif c == "}" and open_:
            done.append(open_.pop())
    return segs, done


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


def write_grammar(folder, name, text):
    """TEXT written as FOLDER/NAME.fgsg; its path."""
    grammar = os.path.join(folder, name + ".fgsg")
    with open(grammar, "w") as f:
        f.write(text)
    return grammar


def fgsg_obj(fgsg, grammar, n, folder, dims=2, engine=None, extra=()):
    """`fgsg run GRAMMAR --set n=N` written as OBJ (N None: no `--set`; ENGINE: its
    `--engine`; EXTRA: more arguments): its vertices (their first `dims` coordinates) and,
    per element keyword ('f', 'l'), each element as its corners' coordinates joined in one
    tuple."""
    name = os.path.splitext(os.path.basename(grammar))[0]
    out = os.path.join(folder, "%s-%s-%s.obj" % (name, engine or "default", n))
    args = [fgsg, "run", grammar, "-o", out, "--quiet"] + list(extra)
    if n is not None:
        args += ["--set", "n=%d" % n]
    if engine:
        args.append("--engine=" + engine)
    subprocess.run(args, check=True)
    vertices, elements = [], {"f": [], "l": []}
    with open(out) as f:
        for line in f:
            part = line.split()
            if part and part[0] == "v":
                vertices.append(tuple(float(c) for c in part[1:1 + dims]))
            elif part and part[0] in elements:
                corners = [vertices[int(c.split("/")[0]) - 1] for c in part[1:]]
                elements[part[0]].append(sum(corners, ()))
    return elements


def segments_3d(fgsg, folder, name, text, engine):
    """fgsg's segments for grammar TEXT (written as FOLDER/NAME.fgsg) as (x0, y0, z0, x1, y1, z1) tuples."""
    return fgsg_obj(fgsg, write_grammar(folder, name, text), None, folder, dims=3, engine=engine)["l"]


def same_segments(got, want, what, engine, tolerance=1e-9):
    """Exits with FAIL unless the segments GOT (flat tuples) are WANT (pairs of points), in
    any order, each coordinate within TOLERANCE after rounding both to 6 decimals; prints ok."""
    key = lambda flat: tuple(round(c, 6) + 0.0 for c in flat)
    g = sorted(map(key, got))
    w = sorted(key(sum(seg, ())) for seg in want)
    if len(g) != len(w) or any(abs(a - b) > tolerance for s, t in zip(g, w) for a, b in zip(s, t)):
        raise SystemExit("FAIL: %s (%s): segments\n  %s\nexpected\n  %s" % (what, engine, g, w))
    print("ok: %s (%s)" % (what, engine))


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


def check(fgsg, grammar, n, string, angle, folder, polygons=False):
    """Exits with a message unless fgsg draws exactly the segments of `string` (with
    `polygons`: fills exactly its polygons)."""
    segs, filled = turtle(string, angle)
    want = fan_triangles(filled) if polygons else segs
    got = fgsg_obj(fgsg, grammar, n, folder)["f" if polygons else "l"]
    what = "triangles" if polygons else "segments"
    missing = unmatched(want, got)
    if len(want) != len(got) or missing:
        raise SystemExit("FAIL: %s n=%d: fgsg has %d %s, the reference %d (%d of the reference's missing)"
                         % (os.path.basename(grammar), n, len(got), what, len(want), missing))
    print("ok: %s n=%d, %d %s" % (os.path.basename(grammar), n, len(want), what))
