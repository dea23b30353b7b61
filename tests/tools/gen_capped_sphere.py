#!/usr/bin/env python3
"""Writes the unit sphere with six caps cut off (soliman2021 Fig. 21, right) as an OBJ: the caps are centred on
+-x, +-y, +-z with angular radius --cap (degrees). Built on the cube sphere: each cube face [-1,1]^2 keeps the ring
between the circle of radius tan(cap) (the gnomonic image of the cap's rim, a circle) and the square, meshed by
--n segments per square side (4 n around) and --m rows from the rim to the square, radial lines through the face
centre; the points are projected to the sphere, the shared cube edges merged, every face turned outward. The mesh
has the cube's symmetry; its six boundary loops lie exactly on the cap circles (|x_axis| = cos(cap))."""
import argparse, math
p = argparse.ArgumentParser()
p.add_argument('out'); p.add_argument('--n', type=int, default=4); p.add_argument('--m', type=int, default=4)
p.add_argument('--cap', type=float, default=30)
a = p.parse_args()
rho = math.tan(math.radians(a.cap))
if not 0 < rho < 0.9: raise SystemExit('gen_capped_sphere: --cap must lie in (0, 41) degrees')

def square(k):  # the k-th of 4 n points on the square's boundary, counter-clockwise from the corner (1, -1)
    side, j = divmod(k % (4 * a.n), a.n); s = -1 + 2 * j / a.n
    return [(1, s), (-s, 1), (-1, -s), (s, -1)][side]

def frame(axis, sign):  # (u, v, w) with u x v = w = sign e_axis: the face seen from outside
    w = [0, 0, 0]; w[axis] = sign
    u = [0, 0, 0]; u[(axis + 1) % 3] = 1
    v = [w[1] * u[2] - w[2] * u[1], w[2] * u[0] - w[0] * u[2], w[0] * u[1] - w[1] * u[0]]
    return u, v, w

V, F, index = [], [], {}
def vertex(x):
    r = math.sqrt(sum(c * c for c in x)); x = tuple(c / r for c in x)
    key = tuple(round(c, 12) for c in x)
    if key not in index: index[key] = len(V); V.append(x)
    return index[key]

N = 4 * a.n
for axis in range(3):
    for sign in (1, -1):
        u, v, w = frame(axis, sign)
        grid = []
        for i in range(a.m + 1):
            row = []
            for k in range(N):
                qx, qy = square(k); th = math.atan2(qy, qx); t = i / a.m
                px, py = (1 - t) * rho * math.cos(th) + t * qx, (1 - t) * rho * math.sin(th) + t * qy
                row.append(vertex([px * u[c] + py * v[c] + w[c] for c in range(3)]))
            grid.append(row)
        for i in range(a.m):
            for k in range(N):
                a0, a1, b0, b1 = grid[i][k], grid[i][(k + 1) % N], grid[i + 1][k], grid[i + 1][(k + 1) % N]
                F += [(a0, b0, b1), (a0, b1, a1)] if (k // a.n) % 2 == 0 else [(a0, b0, a1), (a1, b0, b1)]

def outward(t):  # the face normal against its centroid (the sphere's outward direction)
    A, B, C = (V[i] for i in t)
    e1, e2 = [B[c] - A[c] for c in range(3)], [C[c] - A[c] for c in range(3)]
    nrm = [e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]]
    return sum(nrm[c] * (A[c] + B[c] + C[c]) for c in range(3)) > 0
F = [t if outward(t) else (t[0], t[2], t[1]) for t in F]
with open(a.out, 'w') as f:
    f.write(f'# unit sphere with six caps of {a.cap} deg cut off, n {a.n}, m {a.m} (tests/tools/gen_capped_sphere.py)\n')
    for x in V: f.write('v %.17g %.17g %.17g\n' % x)
    for t in F: f.write('f %d %d %d\n' % tuple(i + 1 for i in t))
