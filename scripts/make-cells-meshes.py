#!/usr/bin/env python3
# Writes the annotated base meshes of feature-based cellular texturing (Legakis et al.
# 2001; runtime/cells/base_mesh_file.h reads them) into examples/assets/, or into the
# folder given as the only argument:
#   python3 scripts/make-cells-meshes.py [OUTDIR]
#
# All three are Wavefront OBJ in metres, Z up, faces counter-clockwise seen from outside
# (normals outward), welded exactly (coordinates rounded to 6 decimals and each written
# once), manifold, open only at the bottom (z = 0: they stand on the ground). OBJ groups
# (`g`) are the labels. Heights of openings are multiples of a brick course, 0.075 m.
#
# brick_building.obj  A block 6.0 (x) x 4.0 (y) x 4.5 (z) on [0,6] x [0,4] x [0,4.5],
#   group "wall" (four walls) and "roof" (flat top). Openings are recessed 0.1 m into the
#   walls: the wall has a hole, four reveal faces run 0.1 m in from its rim, and a back
#   face closes it (so the surface stays a disk: no through holes).
#   - Two windows on the front wall (y = 0, facing -y), x in [0.7, 1.7] and [4.3, 5.3]
#     (centred in the wall on either side of the door), one on the back wall (y = 4),
#     x in [2.5, 3.5]; all 1.0 wide, sill z = 0.975 (13 courses), head z = 2.325 (31
#     courses), so 1.35 high (18 courses). Reveals and glass: group "window".
#   - An arched door in the middle of the front wall, x in [2.4, 3.6]: straight jambs from
#     the ground to the springing line z = 2.025 (27 courses; 2.0 is not on the course
#     grid), then a semicircle of radius 0.6 centred at (3.0, 2.025) up to the crown at
#     z = 2.625 (35 courses), in 12 segments. Jamb reveals and the door's back face
#     (y = 0.1): group "door"; the 12 intrados quads under the arch: group "arch". The
#     door reaches the ground, so its bottom (jambs' and back face's lower edges) is part
#     of the open boundary.
#   - Each wall is a grid of rectangles split at every x and z of its openings; cells in
#     an opening are the hole. The cells of the door's column above the springing line
#     are triangulated between the cell and the arch polyline (fans to the cell's top
#     corners); the window head z = 2.325 crosses the arch exactly at its vertices at 30
#     and 150 degrees. Side walls and the roof join walls of different grids by a strip
#     ("zipper") of triangles, so there are no T-junctions.
#   Features (buildFeatureMesh with the groups): 24 faces (4 walls, roof, 5 per window,
#   door: 2 jambs, back face, intrados), 60 edges, 40 corners; the front wall has 3
#   boundary loops (the outer one, which runs round the door, and one per window).
#
# stepped_column.obj  A square column 0.9 x 0.9 from z = 0.45 to 3.0 on a 1.5 x 1.5 plinth
#   step 0.45 high (6 courses), centred on the z axis: the plinth's 4 sides, its top ring
#   around the column (4 trapezoids), the column's 4 sides ("column") and its top
#   ("cap"). Features: 10 faces, 24 edges (8 vertical), 16 corners.
#
# stone_wall.obj  A free-standing wall on [0,5] x [0,0.6] x [0,2.4] (5.0 long, 0.6 thick,
#   2.4 high) with a window 0.9 x 0.9 through it, x in [2.05, 2.95], z in [0.9, 1.8],
#   and an arched doorway, x in [3.5, 4.4], springing at z = 1.2: the four reveals of
#   the window ("window"), the door's jambs ("door") and intrados ("arch") run through the
#   whole thickness, the rest is "wall".
import math
import os
import sys

COURSE = 0.075
ARCH_SEGMENTS = 12


def r6(x):
    return round(x, 6)


def num(x):
    s = '%.6f' % r6(x)
    s = s.rstrip('0').rstrip('.')
    return '0' if s in ('', '-0') else s


def add(*vs):
    return tuple(sum(c) for c in zip(*vs))


def scale(k, v):
    return tuple(k * c for c in v)


def sub(a, b):
    return tuple(x - y for x, y in zip(a, b))


def dot(a, b):
    return sum(x * y for x, y in zip(a, b))


def cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def norm(a):
    return math.sqrt(dot(a, a))


class Mesh:
    """Vertices welded by their written form; polygons oriented by an expected normal."""

    def __init__(self, header):
        self.header = header
        self.verts, self.index, self.faces = [], {}, []  # faces: (group, vertex ids)

    def vid(self, p):
        key = tuple(num(c) for c in p)
        if key not in self.index:
            self.index[key] = len(self.verts)
            self.verts.append(tuple(float(k) for k in key))
        return self.index[key]

    def poly(self, group, pts, normal):
        # Convex and planar by construction; turned (keeping the first corner, where the
        # reader's fan starts) so that it faces `normal`.
        ids = [self.vid(p) for p in pts]
        ps = [self.verts[i] for i in ids]
        n = (0.0, 0.0, 0.0)
        for a, b in zip(ps, ps[1:] + ps[:1]):
            n = add(n, cross(a, b))
        d = dot(n, normal) / (norm(n) * norm(normal))
        assert abs(d) > 0.9999, (group, ps, normal)
        if d < 0:
            ids = ids[:1] + ids[:0:-1]
        self.faces.append((group, ids))

    def zipper(self, group, a, b, normal):
        # Triangles between two parallel rows of points (each sorted along the rows, the
        # rows' ends paired): every point of both rows is used, none is skipped.
        i = j = 0
        t = lambda p, q: dot(sub(q, p[0]), sub(p[-1], p[0]))
        while i < len(a) - 1 or j < len(b) - 1:
            if j == len(b) - 1 or (i < len(a) - 1 and t(a, a[i + 1]) <= t(b, b[j + 1])):
                self.poly(group, [a[i], a[i + 1], b[j]], normal)
                i += 1
            else:
                self.poly(group, [a[i], b[j + 1], b[j]], normal)
                j += 1

    def check(self):
        """Manifold, consistently oriented, no degenerate fan triangle; the open boundary
        lies on the ground. Returns the number of boundary edges."""
        directed = set()
        for group, ids in self.faces:
            for k in range(1, len(ids) - 1):
                p, q, r = (self.verts[ids[0]], self.verts[ids[k]], self.verts[ids[k + 1]])
                longest = max(dot(sub(q, p), sub(q, p)), dot(sub(r, q), sub(r, q)), dot(sub(p, r), sub(p, r)))
                assert norm(cross(sub(q, p), sub(r, p))) > 1e-9 * longest, (group, ids)
            for e in zip(ids, ids[1:] + ids[:1]):
                assert e not in directed, ('edge used twice the same way', e)
                directed.add(e)
        boundary = [e for e in directed if (e[1], e[0]) not in directed]
        for a, b in boundary:
            assert self.verts[a][2] == 0 and self.verts[b][2] == 0, ('open edge off the ground', a, b)
        starts = [a for a, _ in boundary]
        assert len(starts) == len(set(starts)), 'the boundary touches itself'
        return len(boundary)

    def write(self, path):
        self.check()
        with open(path, 'w') as f:
            f.write(self.header)
            for v in self.verts:
                f.write('v %s %s %s\n' % tuple(num(c) for c in v))
            groups = []
            for g, _ in self.faces:
                if g not in groups:
                    groups.append(g)
            for g in groups:
                f.write('g %s\n' % g)
                for h, ids in self.faces:
                    if h == g:
                        f.write('f %s\n' % ' '.join(str(i + 1) for i in ids))


class Frame:
    """A wall's plane: P(u, z, d) = origin + u * U + z * Z - d * n (d: depth into it)."""

    def __init__(self, origin, U, Z, n):
        self.o, self.U, self.Z, self.n = origin, U, Z, n

    def p(self, u, z, d=0.0):
        return add(self.o, scale(u, self.U), scale(z, self.Z), scale(-d, self.n))

    def dir(self, du, dz):
        return add(scale(du, self.U), scale(dz, self.Z))


def arch_points(u0, u1, springing):
    """The intrados polyline at the wall surface, from the right springer (angle 0) over
    the crown to the left one, in wall coordinates (u, z)."""
    uc, r = (u0 + u1) / 2, (u1 - u0) / 2
    pts = []
    for k in range(ARCH_SEGMENTS + 1):
        a = math.pi * k / ARCH_SEGMENTS
        pts.append((r6(uc + r * math.cos(a)), r6(springing + r * math.sin(a))))
    pts[0], pts[-1] = (u1, springing), (u0, springing)  # exactly the jambs' tops
    return pts


def wall(mesh, frame, U, Z, openings, depth, reveals=True, back=True):
    """A wall rectangle gridded at levels U x Z with openings, each a dict(u0, u1, z0, z1,
    group) and for an arched door arch=True (z1 is then the springing line; the arch
    rises (u1 - u0) / 2 above it). Reveals `depth` deep with a back face, or with
    back=False going through (another wall closes their far rim); reveals=False: only the
    wall with its holes."""
    U, Z = [r6(u) for u in U], [r6(z) for z in Z]
    openings = [dict(o, u0=r6(o['u0']), u1=r6(o['u1']), z0=r6(o['z0']), z1=r6(o['z1'])) for o in openings]
    kind = {}  # cell (i, j) -> 'wall', 'arch' or the opening it lies in
    arch = None
    for i in range(len(U) - 1):
        for j in range(len(Z) - 1):
            kind[i, j] = 'wall'
            for o in openings:
                if o['u0'] <= U[i] and U[i + 1] <= o['u1'] and o['z0'] <= Z[j] and Z[j + 1] <= o['z1']:
                    kind[i, j] = id(o)
                if o.get('arch') and U[i] == o['u0'] and U[i + 1] == o['u1'] and o['z1'] <= Z[j] < o['z1'] + (o['u1'] - o['u0']) / 2:
                    kind[i, j] = 'arch'
                    arch = o
    by_id = {id(o): o for o in openings}
    wall_area = 0.0

    def tri(pts2):
        nonlocal wall_area
        (a, b, c) = pts2
        wall_area += abs((b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1])) / 2
        mesh.poly('wall', [frame.p(*q) for q in pts2], frame.n)

    apts = arch_points(arch['u0'], arch['u1'], arch['z1']) if arch else []
    crown = apts[ARCH_SEGMENTS // 2][1] if arch else None
    for (i, j), k in sorted(kind.items()):
        u0, u1, z0, z1 = U[i], U[i + 1], Z[j], Z[j + 1]
        if k == 'wall':
            mesh.poly('wall', [frame.p(u0, z0), frame.p(u1, z0), frame.p(u1, z1), frame.p(u0, z1)], frame.n)
            wall_area += (u1 - u0) * (z1 - z0)
        elif k == 'arch':
            # Between the cell and the arch: each half of the arch that lies in the cell
            # fans to the cell's top corner on its side; a crown inside the cell closes
            # the gap with one triangle between the top corners. Grid lines crossing the
            # arch must meet it at its vertices.
            assert z1 != crown, 'a grid line touching the crown would be a T-junction'
            inside = lambda p: z0 <= p[1] <= z1
            right = [p for p in apts[:ARCH_SEGMENTS // 2 + 1] if inside(p)]
            left = [p for p in apts[ARCH_SEGMENTS // 2:] if inside(p)][::-1]
            for half, corner_b, corner_t in ((left, (u0, z0), (u0, z1)), (right, (u1, z0), (u1, z1))):
                assert half[0][1] == z0, 'the grid line z=%g cuts the arch between vertices' % z0
                if half[0] != corner_b:
                    tri([corner_b, half[0], corner_t])
                for p, q in zip(half, half[1:]):
                    tri([p, q, corner_t])
                assert half[-1][1] == z1 or half[-1][1] == crown, 'the grid line z=%g cuts the arch' % z1
            if crown < z1:
                tri([(u0, z1), apts[ARCH_SEGMENTS // 2], (u1, z1)])
    # Whatever is not wall is the openings: the wall's area says no triangle overlaps.
    holes = sum((U[i + 1] - U[i]) * (Z[j + 1] - Z[j]) for (i, j), k in kind.items() if k != 'wall')
    if arch:
        r = (arch['u1'] - arch['u0']) / 2
        inner = ARCH_SEGMENTS * r * r * math.sin(math.pi / ARCH_SEGMENTS) / 2  # the half 24-gon
        holes -= sum((U[i + 1] - U[i]) * (Z[j + 1] - Z[j]) for (i, j), k in kind.items() if k == 'arch') - inner
    assert abs(wall_area - ((U[-1] - U[0]) * (Z[-1] - Z[0]) - holes)) < 1e-6, (wall_area, holes)

    if not reveals:
        return
    for (i, j), k in sorted(kind.items()):
        if k in ('wall', 'arch'):
            continue
        o = by_id[k]
        for di, dj in ((-1, 0), (1, 0), (0, -1), (0, 1)):
            nb = kind.get((i + di, j + dj))
            if nb is None:  # the wall's edge: only a door may reach it, at the ground
                assert o.get('arch') and dj == -1 and Z[j] == 0, 'an opening touches the wall edge'
                continue
            if nb == k or nb == 'arch':  # inside the opening (a door's rectangle meets its arch)
                continue
            assert nb == 'wall', 'openings touch'
            # The rim side shared with the neighbour, from the wall to the back.
            if di:
                uu = U[i] if di < 0 else U[i + 1]
                a, b = (uu, Z[j]), (uu, Z[j + 1])
            else:
                zz = Z[j] if dj < 0 else Z[j + 1]
                a, b = (U[i], zz), (U[i + 1], zz)
            mesh.poly(o['group'], [frame.p(*a), frame.p(*b), frame.p(*b, depth), frame.p(*a, depth)],
                      frame.dir(-di, -dj))
        if back:
            mesh.poly(o['group'], [frame.p(U[i], Z[j], depth), frame.p(U[i + 1], Z[j], depth),
                                   frame.p(U[i + 1], Z[j + 1], depth), frame.p(U[i], Z[j + 1], depth)], frame.n)
    if arch:
        uc, zs = (arch['u0'] + arch['u1']) / 2, arch['z1']
        for p, q in zip(apts, apts[1:]):
            mid = ((p[0] + q[0]) / 2 - uc, (p[1] + q[1]) / 2 - zs)  # the intrados faces the centre
            mesh.poly('arch', [frame.p(*p), frame.p(*q), frame.p(*q, depth), frame.p(*p, depth)],
                      frame.dir(-mid[0], -mid[1]))
        if back:  # the half-disk under the arch, closing the door's back face
            mesh.poly(arch['group'], [frame.p(*p, depth) for p in apts], frame.n)


def brick_building():
    m = Mesh(header_for('brick_building', 'a brick building with two windows and an arched door in front, one window at the back'))
    W, D, H, reveal = 6.0, 4.0, 60 * COURSE, 0.1
    sill, head, spring = 13 * COURSE, 31 * COURSE, 27 * COURSE
    front_openings = [dict(u0=0.7, u1=1.7, z0=sill, z1=head, group='window'),
                      dict(u0=4.3, u1=5.3, z0=sill, z1=head, group='window'),
                      dict(u0=2.4, u1=3.6, z0=0.0, z1=spring, group='door', arch=True)]
    back_openings = [dict(u0=2.5, u1=3.5, z0=sill, z1=head, group='window')]
    Uf = [0.0, 0.7, 1.7, 2.4, 3.6, 4.3, 5.3, W]
    Zf = [0.0, sill, spring, head, H]
    Ub = [0.0, 2.5, 3.5, W]
    Zb = [0.0, sill, head, H]
    wall(m, Frame((0, 0, 0), (1, 0, 0), (0, 0, 1), (0, -1, 0)), Uf, Zf, front_openings, reveal)
    wall(m, Frame((0, D, 0), (1, 0, 0), (0, 0, 1), (0, 1, 0)), Ub, Zb, back_openings, reveal)
    # Side walls: strips between the front wall's corner column and the back wall's.
    for x, n in ((0.0, (-1, 0, 0)), (W, (1, 0, 0))):
        m.zipper('wall', [(x, 0, r6(z)) for z in Zf], [(x, D, r6(z)) for z in Zb], n)
    m.zipper('roof', [(u, 0, H) for u in Uf], [(u, D, H) for u in Ub], (0, 0, 1))
    return m


def stepped_column():
    m = Mesh(header_for('stepped_column', 'a square column on a plinth step'))
    P, C = 0.75, 0.45                      # half widths of the plinth and the column
    step, top = 6 * COURSE, 40 * COURSE    # 0.45 and 3.0
    sq = [(-1, -1), (1, -1), (1, 1), (-1, 1)]  # counter-clockwise seen from above
    for k in range(4):
        (ax, ay), (bx, by) = sq[k], sq[(k + 1) % 4]
        out = ((ax + bx) / 2, (ay + by) / 2, 0)  # the side's outward normal
        m.poly('column', [(P * ax, P * ay, 0), (P * bx, P * by, 0), (P * bx, P * by, step), (P * ax, P * ay, step)], out)
        m.poly('column', [(P * ax, P * ay, step), (P * bx, P * by, step), (C * bx, C * by, step), (C * ax, C * ay, step)], (0, 0, 1))
        m.poly('column', [(C * ax, C * ay, step), (C * bx, C * by, step), (C * bx, C * by, top), (C * ax, C * ay, top)], out)
    m.poly('cap', [(C * x, C * y, top) for x, y in sq], (0, 0, 1))
    return m


def stone_wall():
    m = Mesh(header_for('stone_wall', 'a free-standing wall with a window and an arched doorway through it'))
    L, T, H = 5.0, 0.6, 32 * COURSE        # 2.4 high
    win = dict(u0=2.05, u1=2.95, z0=12 * COURSE, z1=24 * COURSE, group='window')
    door = dict(u0=3.5, u1=4.4, z0=0.0, z1=16 * COURSE, group='door', arch=True)
    spring = door['z1']
    U = [0.0, win['u0'], win['u1'], door['u0'], door['u1'], L]
    Z = [0.0, win['z0'], spring, win['z1'], H]
    # The front wall's reveals run through to the back wall's hole.
    wall(m, Frame((0, 0, 0), (1, 0, 0), (0, 0, 1), (0, -1, 0)), U, Z, [win, door], T, back=False)
    wall(m, Frame((0, T, 0), (1, 0, 0), (0, 0, 1), (0, 1, 0)), U, Z, [win, door], T, reveals=False)
    for x, n in ((0.0, (-1, 0, 0)), (L, (1, 0, 0))):
        m.zipper('wall', [(x, 0, r6(z)) for z in Z], [(x, T, r6(z)) for z in Z], n)
    m.zipper('wall', [(u, 0, H) for u in U], [(u, T, H) for u in U], (0, 0, 1))
    return m


def header_for(name, what):
    return ('# fgsg examples: %s.obj, %s (scripts/make-cells-meshes.py).\n'
            '# A base mesh for feature-based cellular texturing: metres, Z up, open at the\n'
            '# bottom; groups label the features.\n' % (name, what))


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'examples', 'assets')
    for name, make in (('brick_building', brick_building), ('stepped_column', stepped_column), ('stone_wall', stone_wall)):
        mesh = make()
        path = os.path.normpath(os.path.join(out, name + '.obj'))
        mesh.write(path)
        print('%s: %d vertices, %d polygons, %d boundary edges' % (path, len(mesh.verts), len(mesh.faces), mesh.check()))


if __name__ == '__main__':
    main()
