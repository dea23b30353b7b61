#!/usr/bin/env python3
"""Helpers for willmore_triangulations.sh (pure Python, no numpy).
  triangulation_tools.py flip A.obj OUT.obj   -> OUT: the same vertices (their lines copied verbatim), every quad
        of a triangulated quad grid split by its other diagonal. The diagonals are found geometrically: an
        interior edge is a diagonal when it is the strictly longest edge of both its triangles (true for the
        generator's torus grids, whose cells are near-rectangular). Refused unless every triangle has exactly one
        such edge (so the triangles pair up into quads) and no flipped edge exists already; orientation is kept.
        Prints "V E F flipped".
  triangulation_tools.py hausdorff A.obj B.obj -> "hausdorff diameter bound": the symmetric Hausdorff distance
        between the surfaces of A and B sampled at the points of each mesh (vertices, edge midpoints, face
        centroids) against the exact nearest point on the triangles of the other mesh (exact at the samples, so
        a lower bound of the true distance, which is approached as the mesh is refined); the diameter of A
        (largest pairwise vertex distance); and, when B is A with quads flipped (same vertex order), an upper
        bound of the true distance through the vertex correspondence (flip_bound), else "none".
"""
import math, sys

def load(p):
    lines, V, F = [], [], []
    for l in open(p):
        s = l.split()
        if not s: continue
        if s[0] == 'v':
            V.append([float(t) for t in s[1:4]]); lines.append(l.rstrip('\n'))
        elif s[0] == 'f':
            F.append([int(t.split('/')[0]) - 1 for t in s[1:4]])
    return lines, V, F

def sub(a, b): return (a[0] - b[0], a[1] - b[1], a[2] - b[2])
def dot(a, b): return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
def d2(a, b): return (a[0] - b[0]) ** 2 + (a[1] - b[1]) ** 2 + (a[2] - b[2]) ** 2

def flip(src, dst):
    lines, V, F = load(src)
    opp = {}  # directed edge (a, b) -> (face, third vertex)
    for fi, (a, b, c) in enumerate(F):
        for e, o in (((a, b), c), ((b, c), a), ((c, a), b)):
            if e in opp: sys.exit('flip: directed edge %s twice (inconsistent orientation or non-manifold)' % (e,))
            opp[e] = (fi, o)
    edges = {frozenset(e) for e in opp}
    def longest(fi):
        a, b, c = F[fi]
        L = sorted(((d2(V[a], V[b]), (a, b)), (d2(V[b], V[c]), (b, c)), (d2(V[c], V[a]), (c, a))))
        return frozenset(L[2][1]) if L[2][0] > L[1][0] * (1 + 1e-12) else None
    per_face = [0] * len(F)
    newF, used = [], set()
    for (a, b), (f1, c) in opp.items():
        if (b, a) not in opp or a > b: continue  # each undirected edge once
        f2, d = opp[(b, a)]
        e = frozenset((a, b))
        if longest(f1) != e or longest(f2) != e: continue
        if frozenset((c, d)) in edges: sys.exit('flip: the other diagonal %d-%d of quad %d %d %d %d is already an edge' % (c, d, a, d, b, c))
        per_face[f1] += 1; per_face[f2] += 1
        # quad a -> d -> b -> c (triangles a b c and b a d); split by c-d, same orientation
        newF += [(a, d, c), (d, b, c)]
        used.add(frozenset((c, d)))
    bad = [i for i, k in enumerate(per_face) if k != 1]
    if bad: sys.exit('flip: %d triangles are not in exactly one quad (first: face %d, %d diagonals): not a quad grid' % (len(bad), bad[0], per_face[bad[0]]))
    with open(dst, 'w') as f:
        f.write('# %s with every quad diagonal flipped (tests/cases/triangulation_tools.py)\n' % src)
        for l in lines: f.write(l + '\n')
        for t in newF: f.write('f %d %d %d\n' % (t[0] + 1, t[1] + 1, t[2] + 1))
    print(len(V), len(edges), len(newF), len(newF) // 2)

def closest_d2(p, a, b, c):
    """Squared distance from p to triangle abc (Ericson, Real-Time Collision Detection 5.1.5)."""
    ab, ac, ap = sub(b, a), sub(c, a), sub(p, a)
    d1, d2_ = dot(ab, ap), dot(ac, ap)
    if d1 <= 0 and d2_ <= 0: return d2(p, a)
    bp = sub(p, b); d3, d4 = dot(ab, bp), dot(ac, bp)
    if d3 >= 0 and d4 <= d3: return d2(p, b)
    vc = d1 * d4 - d3 * d2_
    if vc <= 0 and d1 >= 0 and d3 <= 0:
        v = d1 / (d1 - d3); return d2(p, (a[0] + v * ab[0], a[1] + v * ab[1], a[2] + v * ab[2]))
    cp = sub(p, c); d5, d6 = dot(ab, cp), dot(ac, cp)
    if d6 >= 0 and d5 <= d6: return d2(p, c)
    vb = d5 * d2_ - d1 * d6
    if vb <= 0 and d2_ >= 0 and d6 <= 0:
        w = d2_ / (d2_ - d6); return d2(p, (a[0] + w * ac[0], a[1] + w * ac[1], a[2] + w * ac[2]))
    va = d3 * d6 - d5 * d4
    if va <= 0 and (d4 - d3) >= 0 and (d5 - d6) >= 0:
        w = (d4 - d3) / ((d4 - d3) + (d5 - d6))
        return d2(p, (b[0] + w * (c[0] - b[0]), b[1] + w * (c[1] - b[1]), b[2] + w * (c[2] - b[2])))
    den = 1.0 / (va + vb + vc); v, w = vb * den, vc * den
    return d2(p, (a[0] + ab[0] * v + ac[0] * w, a[1] + ab[1] * v + ac[1] * w, a[2] + ab[2] * v + ac[2] * w))

def samples(V, F):
    P = [tuple(v) for v in V]
    E = set()
    for a, b, c in F:
        P.append(tuple((V[a][k] + V[b][k] + V[c][k]) / 3 for k in range(3)))
        for e in ((a, b), (b, c), (c, a)): E.add((min(e), max(e)))
    P += [tuple((V[a][k] + V[b][k]) / 2 for k in range(3)) for a, b in E]
    return P

def one_sided(P, V, F):
    """max over the points P of the exact distance to the triangles F (vertices V). The triangles are binned by
    their bounding boxes into a uniform grid of cells of the longest edge; each query visits rings of cells
    around its own and stops once every triangle not yet seen is farther than the best distance found."""
    h = math.sqrt(max(max(d2(V[a], V[b]), d2(V[b], V[c]), d2(V[c], V[a])) for a, b, c in F))
    grid = {}
    for i, (a, b, c) in enumerate(F):
        lo = [int(math.floor(min(V[a][k], V[b][k], V[c][k]) / h)) for k in range(3)]
        hi = [int(math.floor(max(V[a][k], V[b][k], V[c][k]) / h)) for k in range(3)]
        for x in range(lo[0], hi[0] + 1):
            for y in range(lo[1], hi[1] + 1):
                for z in range(lo[2], hi[2] + 1): grid.setdefault((x, y, z), []).append(i)
    worst = 0.0
    for p in P:
        c = [int(math.floor(p[k] / h)) for k in range(3)]
        best, seen, r = math.inf, set(), 0
        while True:
            for x in range(c[0] - r, c[0] + r + 1):
                for y in range(c[1] - r, c[1] + r + 1):
                    for z in range(c[2] - r, c[2] + r + 1):
                        if max(abs(x - c[0]), abs(y - c[1]), abs(z - c[2])) != r: continue
                        for i in grid.get((x, y, z), ()):
                            if i in seen: continue
                            seen.add(i)
                            a, b, cc = F[i]
                            best = min(best, closest_d2(p, V[a], V[b], V[cc]))
            # a triangle not seen has its box outside the cube of cells within ring r
            gap = min(min(p[k] - (c[k] - r) * h, (c[k] + r + 1) * h - p[k]) for k in range(3))
            if best <= gap * gap or len(seen) == len(F): break
            r += 1
        worst = max(worst, best)
    return math.sqrt(worst)

def flip_bound(VA, FA, VB, FB):
    """Upper bound of the symmetric Hausdorff distance when B has A's vertices (same order) and A's triangulation
    with some quad diagonals flipped: over the parameter domain of each quad the two piecewise-linear surfaces
    differ by at most max_i |a_i - b_i| over its four vertices + |(p0 + p2)/2 - (p1 + p3)/2| (the difference of the two splittings of the
    quad p0 p1 p2 p3 is linear on the four triangles around its centre, zero at the corners, and the difference
    of the diagonals' midpoints at the centre). None when B is not such a flip of A."""
    if len(VA) != len(VB) or len(FA) != len(FB): return None
    key = lambda t: frozenset(t)
    fb = {key(t) for t in FB}
    ea = {}
    for t in FA:
        if key(t) in fb: continue
        for e, o in (((t[0], t[1]), t[2]), ((t[1], t[2]), t[0]), ((t[2], t[0]), t[1])): ea.setdefault(frozenset(e), []).append(o)
    flipped = [(tuple(e), o) for e, o in ea.items() if len(o) == 2 and key((o[0], o[1], tuple(e)[0])) in fb and key((o[0], o[1], tuple(e)[1])) in fb]
    if 2 * len(flipped) != sum(1 for t in FA if key(t) not in fb): return None
    disp = [math.sqrt(d2(a, b)) for a, b in zip(VA, VB)]
    bound = max(max(disp[i] for i in t) for t in FA if key(t) in fb) if len(flipped) * 2 < len(FA) else 0.0
    for (i, j), (k, l) in flipped:
        g = min(math.sqrt(d2([(W[i][q] + W[j][q]) / 2 for q in range(3)], [(W[k][q] + W[l][q]) / 2 for q in range(3)])) for W in (VA, VB))
        bound = max(bound, max(disp[i], disp[j], disp[k], disp[l]) + g)
    return bound

def hausdorff(pa, pb):
    _, VA, FA = load(pa); _, VB, FB = load(pb)
    h = max(one_sided(samples(VA, FA), VB, FB), one_sided(samples(VB, FB), VA, FA))
    diam = math.sqrt(max(d2(p, q) for i, p in enumerate(VA) for q in VA[i + 1:]))
    ub = flip_bound(VA, FA, VB, FB)
    print('%.6e %.6e %s' % (h, diam, 'none' if ub is None else '%.6e' % ub))

if __name__ == '__main__':
    cmd = sys.argv[1] if len(sys.argv) > 1 else ''
    if cmd == 'flip' and len(sys.argv) == 4: flip(sys.argv[2], sys.argv[3])
    elif cmd == 'hausdorff' and len(sys.argv) == 4: hausdorff(sys.argv[2], sys.argv[3])
    else: sys.exit(__doc__)
