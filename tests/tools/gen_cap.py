#!/usr/bin/env python3
"""Writes a spherical cap (a hemisphere by default) as an OBJ: the pole, then rings i = 1..n of 6i vertices at polar
angle i/n * cap (radians), zipped into triangles counter-clockwise seen from outside (6 n^2 faces, one boundary
loop). Options: --n N, --cap ANGLE_DEG (90: hemisphere), --bump A (radial factor 1 + A sin(pi phi/cap) cos(3t)
sin(2 pi phi/cap), zero at pole and boundary), --wave A (z += A cos(2t) (phi/cap)^4: moves the boundary, for a
fixed-boundary target). Used by tests/cases/conformal_boundary.sh."""
import argparse, math
p = argparse.ArgumentParser()
p.add_argument('out'); p.add_argument('--n', type=int, default=12); p.add_argument('--cap', type=float, default=90)
p.add_argument('--bump', type=float, default=0); p.add_argument('--wave', type=float, default=0)
a = p.parse_args()
cap = math.radians(a.cap)
V, F, rings = [], [], []
for i in range(a.n + 1):
    m = 1 if i == 0 else 6 * i
    ring = []
    for k in range(m):
        phi, t = cap * i / a.n, 2 * math.pi * k / m
        r = 1 + a.bump * math.sin(math.pi * phi / cap) * math.sin(2 * math.pi * phi / cap) * math.cos(3 * t)
        x, y, z = r * math.sin(phi) * math.cos(t), r * math.sin(phi) * math.sin(t), r * math.cos(phi)
        z += a.wave * math.cos(2 * t) * (phi / cap) ** 4
        ring.append(len(V)); V.append((x, y, z))
    rings.append(ring)
for i in range(1, a.n + 1):
    A, B = rings[i - 1], rings[i]
    m0, m1, ia, ib = len(A), len(B), 0, 0
    while ia < m0 or ib < m1:
        if ib < m1 and (ia >= m0 or (ib + 1) / m1 <= (ia + 1) / m0 + 1e-12):
            F.append((A[ia % m0], B[ib % m1], B[(ib + 1) % m1])); ib += 1
        else:
            if m0 > 1: F.append((A[ia % m0], B[ib % m1], A[(ia + 1) % m0]))
            ia += 1
with open(a.out, 'w') as f:
    f.write(f'# spherical cap {a.cap} deg, {a.n} rings, bump {a.bump}, wave {a.wave} (tests/tools/gen_cap.py)\n')
    for v in V: f.write('v %.17g %.17g %.17g\n' % v)
    for t in F: f.write('f %d %d %d\n' % tuple(i + 1 for i in t))
