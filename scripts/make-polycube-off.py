#!/usr/bin/env python3
# Writes examples/assets/polycube_l.off: python3 scripts/make-polycube-off.py > examples/assets/polycube_l.off
# A polycube surface (the paper's Fig. 11 shows patterns on polycubes): the boundary of four
# unit cubes in an L with one on top, each unit face split into 4 x 4 squares, two triangles
# each, counter-clockwise seen from outside.
cells = {(0,0,0),(1,0,0),(2,0,0),(0,1,0),(0,0,1)}
n = 4
verts, index, faces = [], {}, []
def vid(p):
    key = tuple(round(c * n) for c in p)
    if key not in index:
        index[key] = len(verts); verts.append(tuple(k / n for k in key))
    return index[key]
for (x, y, z) in sorted(cells):
    for axis in range(3):
        for sign in (-1, 1):
            nb = [x, y, z]; nb[axis] += sign
            if tuple(nb) in cells: continue
            u_axis, v_axis = (axis + 1) % 3, (axis + 2) % 3
            if sign < 0: u_axis, v_axis = v_axis, u_axis
            base = [x, y, z]
            if sign > 0: base[axis] += 1
            for i in range(n):
                for j in range(n):
                    def corner(a, b):
                        p = list(base); p[u_axis] += a / n; p[v_axis] += b / n; return vid(p)
                    c00, c10, c01, c11 = corner(i, j), corner(i+1, j), corner(i, j+1), corner(i+1, j+1)
                    faces.append((c00, c10, c11)); faces.append((c00, c11, c01))
print("OFF")
print("# fgsg examples: an L-shaped polycube of five unit cubes (scripts/make-polycube-off.py)")
print(len(verts), len(faces), 0)
for v in verts: print("%g %g %g" % v)
for f in faces: print("3 %d %d %d" % f)
