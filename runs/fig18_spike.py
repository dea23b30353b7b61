#!/usr/bin/env python3
"""The spike at the moved point of soliman2021 Fig. 18 (options/flow_fig18_interp.opts; docs/willmore_flow.md,
"Fig. 18"): is it the discrete form of the smooth point-force singularity (then it shrinks under refinement: near a
point constraint the smooth minimiser is C^{1,alpha}, H ~ log r) or an artifact of the discretisation?

  python3 runs/fig18_spike.py INPUT.obj RESULT.obj POINTS.txt [SUMMARY.json]

Prints, for the moved point (the first line of POINTS.txt) and, as a baseline, for a pinned point that was not
moved (the second line):
  height  the vertex's distance from the least-squares sphere through its one-ring neighbours, in units of the
          mean length of its star's edges (a cone of fixed apex angle keeps height/h fixed under refinement; a C^1
          surface has height/h -> 0, like h log h near a point force);
  tilt    the largest angle (degrees) between a star face's normal and that sphere's normal at the vertex (a cone
          keeps it; C^1 sends it to 0);
  area_star  the largest ratio of a star face's area to its input area (the red faces of the picture);
and the mean | |x| - 1 | in bands of angle from the moved point's input direction (the deviation from the sphere),
with W, q_max and the stop reason of the summary."""
import json
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scripts"))
from objio import read_obj  # noqa: E402  (scripts/objio.py, the project's OBJ reader)

sub = lambda a, b: [a[i] - b[i] for i in range(3)]
dot = lambda a, b: sum(a[i] * b[i] for i in range(3))
norm = lambda a: math.sqrt(dot(a, a))
cross = lambda a, b: [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def solve4(A, b):
    """Gaussian elimination with partial pivoting of a small dense system."""
    n = len(b)
    M = [A[i][:] + [b[i]] for i in range(n)]
    for c in range(n):
        p = max(range(c, n), key=lambda r: abs(M[r][c]))
        M[c], M[p] = M[p], M[c]
        for r in range(c + 1, n):
            f = M[r][c] / M[c][c]
            for k in range(c, n + 1):
                M[r][k] -= f * M[c][k]
    x = [0.0] * n
    for r in range(n - 1, -1, -1):
        x[r] = (M[r][n] - sum(M[r][k] * x[k] for k in range(r + 1, n))) / M[r][r]
    return x


def fit_sphere(P):
    """Algebraic least-squares sphere |x|^2 = 2 c.x + d through the points: (centre, radius)."""
    A = [[0.0] * 4 for _ in range(4)]
    b = [0.0] * 4
    for p in P:
        row = [2 * p[0], 2 * p[1], 2 * p[2], 1.0]
        r = dot(p, p)
        for i in range(4):
            b[i] += row[i] * r
            for j in range(4):
                A[i][j] += row[i] * row[j]
    c0, c1, c2, d = solve4(A, b)
    c = [c0, c1, c2]
    return c, math.sqrt(max(d + dot(c, c), 0.0))


def star(F, v):
    faces = [f for f in F if v in f]
    ring = sorted({w for f in faces for w in f if w != v})
    return faces, ring


def face_normal(X, f):
    n = cross(sub(X[f[1]], X[f[0]]), sub(X[f[2]], X[f[0]]))
    return [c / norm(n) for c in n], 0.5 * norm(n)


def spike(X, X0, F, v):
    """(height/h, height, h, tilt in degrees, area_star) of vertex v against the sphere through its one-ring."""
    faces, ring = star(F, v)
    c, r = fit_sphere([X[w] for w in ring])
    d = sub(X[v], c)
    height = abs(norm(d) - r)
    h = sum(norm(sub(X[w], X[v])) for w in ring) / len(ring)
    nu = [x / norm(d) for x in d]
    tilt = max(math.degrees(math.acos(min(1.0, abs(dot(face_normal(X, f)[0], nu))))) for f in faces)
    q = max(face_normal(X, f)[1] / face_normal(X0, f)[1] for f in faces)
    return height / h, height, h, tilt, q


def main():
    X0, F = read_obj(sys.argv[1])
    X, F1 = read_obj(sys.argv[2])
    pts = [l.split() for l in open(sys.argv[3]) if l.strip() and not l.startswith('#')]
    moved, still = int(pts[0][0]), int(pts[1][0])
    s = json.load(open(sys.argv[4])) if len(sys.argv) > 4 else {}
    axis = [c / norm(X0[moved]) for c in X0[moved]]
    bands = ((0, 30), (30, 60), (60, 90), (90, 181))
    ang = [math.degrees(math.acos(max(-1.0, min(1.0, dot(x, axis) / norm(x))))) for x in X0]
    dev = []
    for lo, hi in bands:
        dv = [abs(norm(X[i]) - 1) for i in range(len(X)) if lo <= ang[i] < hi]
        dev.append(sum(dv) / len(dv))
    miss = max(abs(X[int(p[0])][c] - float(p[1 + c])) for p in pts for c in range(3))
    out = {'V': len(X), 'moved': spike(X, X0, F, moved), 'still': spike(X, X0, F, still), 'bands': dev, 'points_miss': miss}
    for k in ('iterations', 'willmore', 'q_max', 'q_mean', 'stop_reason', 'el_residual_scaled', 'conformal_violation'):
        if k in s:
            out[k] = s[k]
    m, st = out['moved'], out['still']
    print("V %d: moved height/h %.4f (height %.4g, h %.4g) tilt %.2f deg area_star %.3f | pinned height/h %.4f tilt %.2f deg"
          % (len(X), m[0], m[1], m[2], m[3], m[4], st[0], st[3]))
    print("  bands 0-30 %.4f 30-60 %.4f 60-90 %.4f 90-180 %.4f; points to %.1e" % (tuple(dev) + (miss,)))
    if s:
        print("  it %s W %.9f q_max %.3f EL %.2e class %.2e %s" % (s.get('iterations'), s.get('willmore', 0), s.get('q_max', 0),
              s.get('el_residual_scaled', 0), s.get('conformal_violation', 0), s.get('stop_reason')))
    print("JSON " + json.dumps(out))


if __name__ == '__main__':
    main()
