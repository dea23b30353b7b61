#!/usr/bin/env python3
"""Writes the textured test meshes of issue 38 (tests/cases/texture_io.sh), numbers in %.17g so that a read and a
write (also %.17g) give the same text:
  uv_sphere_seam.obj  a latitude-longitude sphere, 12 segments around and 6 bands (62 vertices, 120 faces, closed,
                      outward), UVs u = longitude / 2 pi, v = 1 - colatitude / pi: the meridian u = 0 = 1 is a seam
                      (its 5 ring vertices carry u = 0 on one side and u = 1 on the other) and each pole carries one
                      UV per face around it (u = (k + 1/2) / 12), so 12 + 5 x 13 + 12 = 89 vt lines.
Usage: python3 tests/data/make_uv_meshes.py [DIR] (default: the folder of this script)."""
import math, os, sys

def uv_sphere(n=12, m=6):
    v = [(0.0, 0.0, 1.0)]
    for j in range(1, m):
        th = math.pi * j / m
        for k in range(n):
            ph = 2 * math.pi * k / n
            v.append((math.sin(th) * math.cos(ph), math.sin(th) * math.sin(ph), math.cos(th)))
    v.append((0.0, 0.0, -1.0))
    south = len(v) - 1
    ring = lambda j, k: 1 + (j - 1) * n + k % n               # vertex of ring j (1..m-1), segment k
    uv, top, rows, bot = [], [], {}, []
    for k in range(n): top.append(len(uv)); uv.append(((k + 0.5) / n, 1.0))
    for j in range(1, m):
        rows[j] = len(uv)
        for k in range(n + 1): uv.append((k / n, 1.0 - j / m))   # k = n: the seam's second UV
    for k in range(n): bot.append(len(uv)); uv.append(((k + 0.5) / n, 0.0))
    t = lambda j, k: rows[j] + k
    f = []  # (vertex, uv) corners, counter-clockwise seen from outside
    for k in range(n):
        f.append([(0, top[k]), (ring(1, k), t(1, k)), (ring(1, k + 1), t(1, k + 1))])
    for j in range(1, m - 1):
        for k in range(n):
            a, b, c, d = (ring(j, k), t(j, k)), (ring(j, k + 1), t(j, k + 1)), (ring(j + 1, k), t(j + 1, k)), (ring(j + 1, k + 1), t(j + 1, k + 1))
            f.append([a, c, d]); f.append([a, d, b])
    for k in range(n):
        f.append([(south, bot[k]), (ring(m - 1, k + 1), t(m - 1, k + 1)), (ring(m - 1, k), t(m - 1, k))])
    return v, uv, f

def volume(v, f):
    s = 0
    for c in f:
        a, b, d = (v[i] for i, _ in c)
        s += (a[0] * (b[1] * d[2] - b[2] * d[1]) + a[1] * (b[2] * d[0] - b[0] * d[2]) + a[2] * (b[0] * d[1] - b[1] * d[0])) / 6
    return s

def write(path, v, uv, f, what):
    assert volume(v, f) > 0, "not outward"
    with open(path, "w") as o:
        o.write("# %s\n# provenance: tests/data/make_uv_meshes.py (issue 38), %d vertices, %d faces, %d vt\n" % (what, len(v), len(f), len(uv)))
        for p in v: o.write("v %.17g %.17g %.17g\n" % p)
        for p in uv: o.write("vt %.17g %.17g\n" % p)
        for c in f: o.write("f " + " ".join("%d/%d" % (i + 1, t + 1) for i, t in c) + "\n")

if __name__ == "__main__":
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))
    write(os.path.join(out, "uv_sphere_seam.obj"), *uv_sphere(), "latitude-longitude sphere with a UV seam on the meridian u = 0 = 1 and per-face UVs at the poles")
