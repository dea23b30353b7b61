#!/usr/bin/env python3
"""Helpers for the spin_*.sh cases (pure Python, no numpy).
  spin_tools.py q A.obj B.obj            -> "q_mean q_max" of the map A -> B, with a cancellation-free formula
  spin_tools.py rigid A.obj B.obj        -> max distance after the best rigid motion (Horn), relative to size
  spin_tools.py similarity A.obj B.obj   -> same with the best similarity (rotation, scale, translation)
  spin_tools.py transform A.obj OUT s    -> OUT = s * R A + t (fixed rotation R, translation t)
  spin_tools.py rho_bump A.obj OUT       -> per-vertex file of a smooth bump rho (one value per line)
  spin_tools.py rho_bump_face A.obj OUT  -> the same bump per face (at the centroids)
  spin_tools.py tangents A.obj OUT a     -> per-vertex target tangents: boundary tangents tilted out of plane by a*sin(2 phi)
  spin_tools.py tangent_error A.obj TAN  -> mean and max angle (deg) between outgoing boundary edges of A and TAN
"""
import math, sys

def load(p):
    V, F = [], []
    for l in open(p):
        s = l.split()
        if not s: continue
        if s[0] == 'v': V.append([float(t) for t in s[1:4]])
        elif s[0] == 'f': F.append([int(t.split('/')[0]) - 1 for t in s[1:4]])
    return V, F

def save(p, V, F):
    with open(p, 'w') as f:
        for v in V: f.write('v %.17g %.17g %.17g\n' % tuple(v))
        for t in F: f.write('f %d %d %d\n' % (t[0] + 1, t[1] + 1, t[2] + 1))

def sub(a, b): return [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
def dot(a, b): return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
def cross(a, b): return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
def norm(a): return math.sqrt(dot(a, a))

def frame(a, b, c):
    u, v = sub(b, a), sub(c, a)
    lu = norm(u); t1 = [x / lu for x in u]
    n = cross(u, v); t2 = cross(n, t1); l2 = norm(t2); t2 = [x / l2 for x in t2]
    return [[lu, dot(v, t1)], [0.0, dot(v, t2)]], norm(n) / 2

def q(A, B):
    (V0, F), (V1, _) = load(A), load(B)
    s = w = 0.0; mx = 1.0
    for f in F:
        E0, area = frame(*[V0[i] for i in f]); E1, _ = frame(*[V1[i] for i in f])
        d = E0[0][0] * E0[1][1] - E0[0][1] * E0[1][0]
        inv = [[E0[1][1] / d, -E0[0][1] / d], [-E0[1][0] / d, E0[0][0] / d]]
        M = [[sum(E1[i][k] * inv[k][j] for k in range(2)) for j in range(2)] for i in range(2)]
        # conformal and anti-conformal parts: sigma = c +- a, no cancellation near Q = 1
        c = math.hypot(M[0][0] + M[1][1], M[1][0] - M[0][1]) / 2
        a = math.hypot(M[0][0] - M[1][1], M[1][0] + M[0][1]) / 2
        Q = (c + a) / abs(c - a)
        s += area * Q; w += area; mx = max(mx, Q)
    return s / w, mx

def horn(P, Qp, scale):
    n = len(P)
    cp = [sum(p[k] for p in P) / n for k in range(3)]; cq = [sum(p[k] for p in Qp) / n for k in range(3)]
    X = [sub(p, cp) for p in P]; Y = [sub(p, cq) for p in Qp]
    S = [[sum(x[i] * y[j] for x, y in zip(X, Y)) for j in range(3)] for i in range(3)]
    Sxx, Sxy, Sxz = S[0]; Syx, Syy, Syz = S[1]; Szx, Szy, Szz = S[2]
    N = [[Sxx + Syy + Szz, Syz - Szy, Szx - Sxz, Sxy - Syx],
         [Syz - Szy, Sxx - Syy - Szz, Sxy + Syx, Szx + Sxz],
         [Szx - Sxz, Sxy + Syx, -Sxx + Syy - Szz, Syz + Szy],
         [Sxy - Syx, Szx + Sxz, Syz + Szy, -Sxx - Syy + Szz]]
    shift = sum(abs(N[i][j]) for i in range(4) for j in range(4)) + 1
    qv = [1.0, 0.0, 0.0, 0.0]
    for _ in range(2000):  # power iteration on N + shift I: the largest eigenvector is the rotation
        nq = [sum(N[i][j] * qv[j] for j in range(4)) + shift * qv[i] for i in range(4)]
        l = math.sqrt(sum(t * t for t in nq)); nq = [t / l for t in nq]
        if sum((a - b) ** 2 for a, b in zip(nq, qv)) < 1e-30: qv = nq; break
        qv = nq
    w, x, y, z = qv
    R = [[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
         [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
         [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]]
    RX = [[dot(R[i], x) for i in range(3)] for x in X]
    s = sum(dot(a, b) for a, b in zip(RX, Y)) / sum(dot(a, a) for a in RX) if scale else 1.0
    size = math.sqrt(sum(dot(y, y) for y in Y) / n)
    return max(norm(sub([s * t for t in a], b)) for a, b in zip(RX, Y)) / size

def boundary_tangents(V, F):
    cnt = {}
    for f in F:
        for a in range(3):
            e = tuple(sorted((f[a], f[(a + 1) % 3]))); cnt[e] = cnt.get(e, 0) + 1
    T = {}
    for f in F:
        for a in range(3):
            i, j = f[a], f[(a + 1) % 3]
            if cnt[tuple(sorted((i, j)))] == 1:
                d = sub(V[j], V[i]); l = norm(d); T[i] = [t / l for t in d]
    return T

cmd = sys.argv[1]
if cmd == 'q':
    print('%.17g %.17g' % q(sys.argv[2], sys.argv[3]))
elif cmd in ('rigid', 'similarity'):
    print('%.6g' % horn(load(sys.argv[2])[0], load(sys.argv[3])[0], cmd == 'similarity'))
elif cmd == 'transform':
    V, F = load(sys.argv[2]); s = float(sys.argv[4])
    c, sn = math.cos(0.7), math.sin(0.7)
    V = [[s * (c * v[0] - sn * v[1]) + 0.3, s * (sn * v[0] + c * v[1]) - 0.2, s * v[2] + 0.1] for v in V]
    save(sys.argv[3], V, F)
elif cmd == 'rho_bump':
    V, F = load(sys.argv[2])
    with open(sys.argv[3], 'w') as f:
        for v in V: f.write('%.17g\n' % (3 * math.exp(-((v[0] - 0.3) ** 2 + (v[1] + 0.2) ** 2 + (v[2] - 0.9) ** 2) / 0.25)))
elif cmd == 'rho_bump_face':
    V, F = load(sys.argv[2])
    with open(sys.argv[3], 'w') as f:
        for t in F:
            c = [sum(V[i][k] for i in t) / 3 for k in range(3)]
            f.write('%.17g\n' % (3 * math.exp(-((c[0] - 0.3) ** 2 + (c[1] + 0.2) ** 2 + (c[2] - 0.9) ** 2) / 0.25)))
elif cmd == 'tangents':
    V, F = load(sys.argv[2]); a = float(sys.argv[4]); T = boundary_tangents(V, F)
    with open(sys.argv[3], 'w') as f:
        for i, v in enumerate(V):
            if i in T:
                t = T[i]; phi = math.atan2(v[1], v[0]); th = a * math.sin(2 * phi)
                # tilt the tangent toward +z by the angle th
                f.write('%.17g %.17g %.17g\n' % (math.cos(th) * t[0], math.cos(th) * t[1], math.sin(th)))
            else:
                f.write('0 0 0\n')
elif cmd == 'tangent_error':
    V, F = load(sys.argv[2]); T = boundary_tangents(V, F)
    G = [[float(t) for t in l.split()] for l in open(sys.argv[3]) if l.strip()]
    errs = []
    for i, t in T.items():
        g = G[i]; l = norm(g); c = max(-1.0, min(1.0, dot(t, g) / l)); errs.append(math.degrees(math.acos(c)))
    print('%.6g %.6g' % (sum(errs) / len(errs), max(errs)))
