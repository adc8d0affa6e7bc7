#!/usr/bin/python3
"""Independent checker for continuous model synthesis output (Merrell 2009, ch. 4).

Usage: check_continuous.py EXAMPLE.obj OUTPUT.obj [--samples N] [--seed N] [--max-points N]

Checks that OUTPUT is a closed, consistently (outward) oriented 2-manifold and
that it satisfies the continuous adjacency constraint with respect to EXAMPLE:
the neighbourhood ("figure", the cone {d : x + eps*d is inside}) of every
checked output point equals the figure of some example point, up to translation.

A figure is represented by its signature: the bits inside(x + eps*d_i) for a
fixed set of random unit directions d_i, with inside decided by the generalized
winding number. Equal cones give equal signatures; the converse holds up to the
resolution of the direction sample (a cone differing only in a region containing
no sample direction is missed), so a pass is strong evidence, not a proof.

Deliberately imports nothing from the repository: it is a second implementation.
Exit status: 0 all checks pass, 1 a violation was found, 2 unreadable input.
"""

import argparse
import sys
import time

import numpy as np

MAX_PRINT = 20
# Largest accepted distance between unit normals of an output triangle and of an
# example face: loose enough for 32-bit coordinates of small triangles (a face fanned
# around its centre, 1.3e-5 seen), far below any real tilt (a slope off by one lattice
# step in 12 is 0.08).
NORMAL_TOL = 1e-4


class InputError(Exception):
    pass


# --------------------------------------------------------------------------- OBJ


def read_obj(path):
    """Returns (vertices (n,3) float64, polygons list of lists of 0-based indices)."""
    try:
        with open(path, "r") as fh:
            lines = fh.readlines()
    except (OSError, UnicodeDecodeError) as e:
        raise InputError(f"{path}: cannot read: {e}")
    verts, polys = [], []
    for lineno, line in enumerate(lines, 1):
        parts = line.split("#", 1)[0].split()
        if not parts:
            continue
        try:
            if parts[0] == "v":
                verts.append([float(t) for t in parts[1:4]])
                if len(verts[-1]) != 3:
                    raise ValueError("vertex needs 3 coordinates")
            elif parts[0] == "f":
                poly = []
                for tok in parts[1:]:
                    i = int(tok.split("/")[0])
                    # OBJ indices are 1-based; negative ones count back from the end.
                    i = i - 1 if i > 0 else len(verts) + i
                    if i < 0 or i >= len(verts):
                        raise ValueError(f"index {tok} out of range")
                    poly.append(i)
                if len(poly) < 3:
                    raise ValueError("face with fewer than 3 corners")
                polys.append(poly)
        except ValueError as e:
            raise InputError(f"{path}:{lineno}: {e}")
    if not polys:
        raise InputError(f"{path}: no faces")
    v = np.array(verts, dtype=np.float64).reshape(-1, 3)
    if not np.all(np.isfinite(v)):
        raise InputError(f"{path}: non-finite vertex coordinate")
    return v, polys


def weld(verts, polys):
    """Merges vertices at bit-identical positions. Returns (verts, polys, obj_index):
    obj_index[i] is the 1-based OBJ index of the first vertex welded into i."""
    uniq, first, inverse = np.unique(verts, axis=0, return_index=True, return_inverse=True)
    inverse = inverse.reshape(-1)
    return uniq, [[int(inverse[i]) for i in p] for p in polys], first + 1


def fan(polys):
    """Fan triangulation. Correct for the winding number even for non-convex planar
    polygons: the signed fan triangles cancel exactly outside the polygon.
    Returns (triangles, 1-based OBJ face number of each triangle)."""
    tris = [(p[0], p[k], p[k + 1]) for p in polys for k in range(1, len(p) - 1)]
    face = [f + 1 for f, p in enumerate(polys) for k in range(1, len(p) - 1)]
    return np.array(tris, dtype=np.int64).reshape(-1, 3), np.array(face, dtype=np.int64)


# --------------------------------------------------------------- manifold check


def check_manifold(verts, tris, face, diag, idx):
    """Returns (violation messages, signed volume) for a closed, oriented, outward
    2-manifold. face and idx give OBJ face and vertex numbers for the messages."""
    errs = []
    a, b, c = verts[tris[:, 0]], verts[tris[:, 1]], verts[tris[:, 2]]
    area2 = np.linalg.norm(np.cross(b - a, c - a), axis=1)
    for t in np.nonzero(area2 <= 1e-12 * diag * diag)[0]:
        errs.append(f"degenerate triangle of face f{face[t]} (v{idx[tris[t]].tolist()}) at {fmt(a[t])}")

    # Every directed edge exactly once and its reverse exactly once.
    directed = {}
    for t, (i, j, k) in enumerate(tris.tolist()):
        for e in ((i, j), (j, k), (k, i)):
            directed.setdefault(e, []).append(t)
    for (i, j), ts in directed.items():
        if len(ts) != 1:
            errs.append(f"directed edge v{idx[i]}->v{idx[j]} ({fmt(verts[i])} -> {fmt(verts[j])}) "
                        f"used by {len(ts)} triangles, of faces f{face[ts[:4]].tolist()}")
        nrev = len(directed.get((j, i), []))
        # Report a bad pair once: from its smaller end, or from the only side present.
        if nrev != 1 and (i < j or (j, i) not in directed):
            errs.append(f"edge v{idx[i]}->v{idx[j]} ({fmt(verts[i])} -> {fmt(verts[j])}) has "
                        f"{nrev} reverse edges (expected 1)")

    # Every vertex's triangles form one fan: rotating each triangle to start at v,
    # the links a->b must make a single cycle through all of them.
    links = {}
    for i, j, k in tris.tolist():
        for v, x, y in ((i, j, k), (j, k, i), (k, i, j)):
            links.setdefault(v, []).append((x, y))
    for v, lk in links.items():
        nxt = {}
        for x, y in lk:
            if x in nxt:
                break  # already reported as a repeated directed edge
            nxt[x] = y
        else:
            start, cur, n = lk[0][0], lk[0][0], 0
            while True:
                cur = nxt.get(cur)
                n += 1
                if cur is None or cur == start or n > len(lk):
                    break
            if cur != start or n != len(lk):
                errs.append(f"vertex v{idx[v]} at {fmt(verts[v])}: its {len(lk)} triangles "
                            f"do not form a single fan")
    unused = len(verts) - len(links)
    if unused:
        print(f"note: {unused} output vertices are not used by any face")

    vol = float(np.einsum("ij,ij->i", a, np.cross(b, c)).sum() / 6.0)
    if not vol > 0:
        errs.append(f"signed volume {vol:.6g} is not positive (inward or open mesh)")
    return errs, vol


# ------------------------------------------------------------- winding numbers


def solid_angles(q, a, b, c):
    """Signed solid angle of triangles (a,b,c) seen from points q (Van Oosterom &
    Strackee). q and the corners are tuples of x, y, z component arrays that
    broadcast against each other (components, not (...,3) arrays: avoiding
    3-vector temporaries makes the dense points-by-triangles case ~2.5x faster).
    Positive for a point inside an outward-oriented closed mesh."""
    ax, ay, az = a[0] - q[0], a[1] - q[1], a[2] - q[2]
    bx, by, bz = b[0] - q[0], b[1] - q[1], b[2] - q[2]
    cx, cy, cz = c[0] - q[0], c[1] - q[1], c[2] - q[2]
    la = np.sqrt(ax * ax + ay * ay + az * az)
    lb = np.sqrt(bx * bx + by * by + bz * bz)
    lc = np.sqrt(cx * cx + cy * cy + cz * cz)
    num = ax * (by * cz - bz * cy) + ay * (bz * cx - bx * cz) + az * (bx * cy - by * cx)
    den = (la * lb * lc + (ax * bx + ay * by + az * bz) * lc
           + (bx * cx + by * cy + bz * cz) * la + (cx * ax + cy * ay + cz * az) * lb)
    return 2.0 * np.arctan2(num, den)


def comps(p):
    """(..., 3) array -> tuple of contiguous component arrays."""
    return tuple(np.ascontiguousarray(p[..., k]) for k in range(3))


def point_triangle_distance(p, a, b, c):
    """Distance from one point p (3,) to triangles (k,3) each (Ericson, RTCD 5.1.5)."""
    ab, ac, ap = b - a, c - a, p - a
    d1, d2 = np.einsum("ij,ij->i", ab, ap), np.einsum("ij,ij->i", ac, ap)
    bp = p - b
    d3, d4 = np.einsum("ij,ij->i", ab, bp), np.einsum("ij,ij->i", ac, bp)
    cp = p - c
    d5, d6 = np.einsum("ij,ij->i", ab, cp), np.einsum("ij,ij->i", ac, cp)
    va, vb, vc = d3 * d6 - d5 * d4, d5 * d2 - d1 * d6, d1 * d4 - d3 * d2
    with np.errstate(divide="ignore", invalid="ignore"):
        denom = va + vb + vc
        v = np.where(denom != 0, vb / denom, 0.0)
        w = np.where(denom != 0, vc / denom, 0.0)
        closest = a + ab * v[:, None] + ac * w[:, None]  # face region
        # Edge regions (bc first so vertex regions below override it).
        t_bc = (d4 - d3) / ((d4 - d3) + (d5 - d6))
        m = (va <= 0) & (d4 - d3 >= 0) & (d5 - d6 >= 0)
        closest = np.where(m[:, None], b + (c - b) * np.nan_to_num(t_bc)[:, None], closest)
        t_ac = d2 / (d2 - d6)
        m = (vb <= 0) & (d2 >= 0) & (d6 <= 0)
        closest = np.where(m[:, None], a + ac * np.nan_to_num(t_ac)[:, None], closest)
        t_ab = d1 / (d1 - d3)
        m = (vc <= 0) & (d1 >= 0) & (d3 <= 0)
        closest = np.where(m[:, None], a + ab * np.nan_to_num(t_ab)[:, None], closest)
    closest = np.where(((d6 >= 0) & (d5 <= d6))[:, None], c, closest)
    closest = np.where(((d3 >= 0) & (d4 <= d3))[:, None], b, closest)
    closest = np.where(((d1 <= 0) & (d2 <= 0))[:, None], a, closest)
    return np.linalg.norm(p - closest, axis=1)


class Solid:
    """A closed triangle mesh that answers figure signatures at points.

    The winding number at q = x + eps*d is split into the triangles near x
    (evaluated exactly at every q) and the far ones (evaluated once, at x).
    Far triangles are at least K*eps away, where their summed winding function is
    harmonic, so moving by eps changes it by O(1/K) -- far below the 0.5 margin.
    """

    K = 200.0          # far triangles are at least K*eps from x
    EPS_REL = 1e-4     # eps cap, relative to the bounding-box diagonal
    CHUNK = 128        # at most this many points per vectorized block

    def __init__(self, verts, tris):
        self.v, self.t = verts, tris
        self.a, self.b, self.c = verts[tris[:, 0]], verts[tris[:, 1]], verts[tris[:, 2]]
        self.ca, self.cb, self.cc = comps(self.a), comps(self.b), comps(self.c)
        self.diag = float(np.linalg.norm(verts.max(0) - verts.min(0)))
        self.r0 = self.K * self.EPS_REL * self.diag  # candidate search radius
        # Bounding spheres for cheap culling of far triangles.
        self.cen = (self.a + self.b + self.c) / 3.0
        self.rad = np.max(np.stack([np.linalg.norm(x - self.cen, axis=1)
                                    for x in (self.a, self.b, self.c)]), axis=0)
        self.ccen = comps(self.cen)
        self.worst = 0.0  # largest |w - round(w)| seen, a numerical health check

    def signatures(self, pts, dirs):
        """Returns a (len(pts), len(dirs)) bool array: inside(x + eps*d)."""
        out = np.zeros((len(pts), len(dirs)), dtype=bool)
        # Bound the dense points-by-triangles block to ~1M entries (memory).
        chunk = int(np.clip(1_000_000 // max(len(self.t), 1), 1, self.CHUNK))
        for s in range(0, len(pts), chunk):
            blk = pts[s:s + chunk]
            om = solid_angles(comps(blk[:, None, :]), self.ca, self.cb, self.cc)
            total = om.sum(axis=1)
            qx, qy, qz = comps(blk[:, None, :])
            cx, cy, cz = self.ccen
            dc = np.sqrt((cx - qx) ** 2 + (cy - qy) ** 2 + (cz - qz) ** 2) - self.rad
            for j, x in enumerate(blk):
                cand = np.nonzero(dc[j] < self.r0)[0]
                dist = point_triangle_distance(x, self.a[cand], self.b[cand], self.c[cand])
                tol = 1e-9 * self.diag
                non_incident = dist[dist >= tol]
                d_non = non_incident.min() if len(non_incident) else self.r0
                eps = min(self.EPS_REL * self.diag, d_non / self.K)
                near = cand[dist < self.K * eps]
                far = total[j] - om[j, near].sum()
                q = x + eps * dirs  # (n,3)
                local = solid_angles(comps(q[:, None, :]), comps(self.a[near]),
                                     comps(self.b[near]), comps(self.c[near])).sum(axis=1)
                w = (far + local) / (4.0 * np.pi)
                self.worst = max(self.worst, float(np.abs(w - np.round(w)).max()))
                out[s + j] = w > 0.5
        return out


# ------------------------------------------------------------------ directions


def directions(n, seed, normals):
    """n seeded random unit directions, each kept at least a small angle away from
    every example face plane, so that rounding can never flip a half-space bit."""
    rng = np.random.default_rng(seed)
    got = []
    while len(got) < n:
        d = rng.normal(size=(4 * n, 3))
        d /= np.linalg.norm(d, axis=1, keepdims=True)
        ok = np.all(np.abs(d @ normals.T) > 0.02, axis=1) if len(normals) else np.ones(len(d), bool)
        got.extend(d[ok])
    return np.array(got[:n])


# ---------------------------------------------------------------------- helpers


def fmt(p):
    return "(" + ", ".join(f"{x:.6g}" for x in p) + ")"


def polygon_normal(verts, poly):
    """Newell normal (unit), valid for non-convex planar polygons."""
    p = verts[poly]
    n = np.cross(p, np.roll(p, -1, axis=0)).sum(axis=0)
    ln = np.linalg.norm(n)
    return n / ln if ln > 0 else None


def interior_point(verts, poly, normal):
    """A point strictly inside a planar polygon: the first fan-triangle centroid
    that passes an even-odd test in the polygon's plane (None if none does)."""
    p = verts[poly]
    drop = int(np.argmax(np.abs(normal)))
    q2 = np.delete(p, drop, axis=1)
    for k in range(1, len(poly) - 1):
        c3 = (p[0] + p[k] + p[k + 1]) / 3.0
        c = np.delete(c3, drop)
        inside = False
        for i in range(len(q2)):
            (x1, y1), (x2, y2) = q2[i], q2[i - 1]
            if (y1 > c[1]) != (y2 > c[1]) and c[0] < x1 + (c[1] - y1) * (x2 - x1) / (y2 - y1):
                inside = not inside
        area = np.linalg.norm(np.cross(p[k] - p[0], p[k + 1] - p[0]))
        if inside and area > 0:
            return c3
    return None


def describe(sig, dirs):
    """Short description of a figure: fraction inside and the mean inside direction."""
    frac = sig.mean()
    mean = dirs[sig].mean(axis=0) if sig.any() else np.zeros(3)
    return f"{frac:.0%} inside, mean inside dir {fmt(mean)}"


# ------------------------------------------------------------------------- main


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("example")
    ap.add_argument("output")
    ap.add_argument("--samples", type=int, default=400, help="directions per figure")
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--max-points", type=int, default=3000,
                    help="check at most this many output points (random, seeded)")
    args = ap.parse_args(argv)
    t0 = time.time()

    try:
        ev, epolys = read_obj(args.example)
        ov, opolys = read_obj(args.output)
    except InputError as e:
        print(f"error: {e}")
        return 2

    ev, epolys, _ = weld(ev, epolys)
    # Welding the output too turns geometric touching (two parts sharing an edge or
    # a vertex through duplicated vertices) into topological non-manifoldness.
    n_read = len(ov)
    ov, opolys, oidx = weld(ov, opolys)
    merged = n_read - len(ov)
    if merged:
        print(f"note: welded {merged} duplicate output vertices")
    (etris, _), (otris, oface) = fan(epolys), fan(opolys)
    ex, out = Solid(ev, etris), Solid(ov, otris)

    # ---- 2. manifold check
    merrs, vol = check_manifold(ov, otris, oface, out.diag, oidx)
    for m in merrs[:MAX_PRINT]:
        print("manifold:", m)
    print(f"output: {len(ov)} vertices, {len(otris)} triangles, volume {vol:.6g}, "
          f"{len(merrs)} manifold violations")

    # ---- 3a. example figures
    normals = []
    for p in epolys:
        n = polygon_normal(ev, p)
        if n is not None and not any(np.allclose(n, m, atol=1e-12) for m in normals):
            normals.append(n)
    normals = np.array(normals).reshape(-1, 3)
    if not len(normals):
        print(f"error: {args.example}: every face is degenerate")
        return 2
    dirs = directions(args.samples, args.seed, normals)

    kinds, pts = [], []
    for p in ev:
        kinds.append(f"example vertex {fmt(p)}")
        pts.append(p)
    edges = {tuple(sorted((p[k], p[k - 1]))) for p in epolys for k in range(len(p))}
    for i, j in sorted(edges):
        m = (ev[i] + ev[j]) / 2.0
        kinds.append(f"example edge midpoint {fmt(m)}")
        pts.append(m)
    for f, p in enumerate(epolys):
        n = polygon_normal(ev, p)
        c = interior_point(ev, p, n) if n is not None else None
        if c is None:
            print(f"note: no interior point found for example face f{f + 1}")
            continue
        kinds.append(f"example face f{f + 1} interior {fmt(c)}")
        pts.append(c)
    esig = ex.signatures(np.array(pts), dirs)
    known = {}
    for s, k in zip(esig, kinds):
        known.setdefault(s.tobytes(), k)
    # Interior and exterior, and (analytically) the half-space of every face normal:
    # the latter guards against a face whose interior point could not be found.
    extra = [(np.ones(len(dirs), bool), "example interior"),
             (np.zeros(len(dirs), bool), "example exterior")]
    extra += [(dirs @ n < 0, f"example face plane, normal {fmt(n)}") for n in normals]
    for s, k in extra:
        known.setdefault(s.tobytes(), k)
    known_sigs = np.array([np.frombuffer(b, dtype=bool) for b in known])
    known_names = list(known.values())
    print(f"example: {len(ev)} vertices, {len(epolys)} faces, {len(normals)} face normals, "
          f"{len(known)} distinct figures")

    # ---- 3b. output figures
    opts, okinds = [], []
    for i, p in enumerate(ov):
        opts.append(p)
        okinds.append(f"vertex v{oidx[i]}")
    oedges = {tuple(sorted(e)) for t in otris.tolist() for e in ((t[0], t[1]), (t[1], t[2]), (t[2], t[0]))}
    for i, j in sorted(oedges):
        opts.append((ov[i] + ov[j]) / 2.0)
        okinds.append(f"edge midpoint v{oidx[i]}-v{oidx[j]}")
    for t in range(len(otris)):
        opts.append(out.cen[t])
        okinds.append(f"centroid of a triangle of face f{oface[t]}")
    opts = np.array(opts)
    total_pts = len(opts)
    if total_pts > args.max_points:
        pick = np.sort(np.random.default_rng(args.seed).choice(total_pts, args.max_points, replace=False))
        opts = opts[pick]
        okinds = [okinds[i] for i in pick]
    osig = out.signatures(opts, dirs)

    misses = 0
    for s, p, k in zip(osig, opts, okinds):
        if s.tobytes() in known:
            continue
        misses += 1
        if misses <= MAX_PRINT:
            ham = (known_sigs != s[None]).sum(axis=1)
            best = int(np.argmin(ham))
            print(f"adjacency: output {k} at {fmt(p)}: figure ({describe(s, dirs)}) not in "
                  f"example; closest is {known_names[best]} ({describe(known_sigs[best], dirs)}), "
                  f"differing in {ham[best]}/{len(dirs)} directions")
    print(f"adjacency: {len(opts)} of {total_pts} output points checked "
          f"(vertices, edge midpoints, triangle centroids), {misses} misses")

    # Exact check of every face plane. A slightly tilted face changes the figures
    # only in a sliver that few (or, given the margin in directions(), no) sample
    # directions hit, so the signatures alone would let it through.
    tn = np.cross(out.b - out.a, out.c - out.a)
    ln = np.linalg.norm(tn, axis=1)
    good = ln > 0  # degenerate triangles are already manifold violations
    tn = tn[good] / ln[good, None]
    dev = np.linalg.norm(tn[:, None, :] - normals[None], axis=2).min(axis=1)
    bad = np.nonzero(dev > NORMAL_TOL)[0]
    tri_face = oface[good]
    for i in bad[:MAX_PRINT]:
        n = tn[i]
        print(f"normal: output face f{tri_face[i]} has normal {fmt(n)}, "
              f"{dev[i]:.3g} from the nearest example face normal")
    print(f"normals: {len(tn)} output triangles, {len(bad)} with a normal that is not an "
          f"example face normal (largest deviation {dev.max() if len(dev) else 0:.3g})")
    worst = max(ex.worst, out.worst)
    if worst > 0.25:
        print(f"warning: winding numbers up to {worst:.3f} from an integer; "
              f"the mesh may be open or self-intersecting, signatures are unreliable")
    print(f"time: {time.time() - t0:.1f} s")

    if merrs or misses or len(bad):
        print(f"FAIL: {len(merrs)} manifold violations, {misses} of {len(opts)} points "
              f"with figures not in the example ({len(known)} example figures), "
              f"{len(bad)} triangles off the example's face normals")
        return 1
    print(f"ok: {len(opts)} points checked, {len(known)} example figures")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
