"""OBJ positions and faces, and vertex areas (a third of each face's area to each corner), for tests that compare
a written mesh's vertex-area spread with a summary's (standard library only). Import with
sys.path.insert(0, 'tests/cases')."""
import math


def load(p):
    V, F = [], []
    for l in open(p):
        s = l.split()
        if s and s[0] == 'v': V.append([float(x) for x in s[1:4]])
        elif s and s[0] == 'f': F.append([int(x.split('/')[0]) - 1 for x in s[1:4]])
    return V, F


def vertex_areas(V, F):
    A = [0.0] * len(V)
    for f in F:
        p, q, r = V[f[0]], V[f[1]], V[f[2]]
        u = [q[i] - p[i] for i in range(3)]; v = [r[i] - p[i] for i in range(3)]
        c = (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])
        a = 0.5 * math.sqrt(sum(x * x for x in c))
        for k in f: A[k] += a / 3
    return A


def area_spread(V0, V1, F):
    """largest over smallest ratio of vertex areas, V1 against V0 on the faces F"""
    r = [a / b for a, b in zip(vertex_areas(V1, F), vertex_areas(V0, F))]
    return max(r) / min(r)
