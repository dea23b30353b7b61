"""Write a closed OBJ mesh's own log length cross ratios as a -mesh_cross_ratios file (lines "i j c0", 1-based
vertices as in OBJ, c0 = log(l_il l_jk / (l_lj l_ki)) for the faces ijk and jil of the edge ij, soliman2021 Eq. 3),
and variants for the bad-input tests. Plain python (no numpy).
  cross_ratio_tools.py write MESH.obj OUT [--flip]   (--flip: also write MESH with reversed faces to OUT.obj)"""
import math, sys


def read_obj(path):
    V, F = [], []
    for line in open(path):
        t = line.split()
        if t and t[0] == 'v':
            V.append(tuple(map(float, t[1:4])))
        elif t and t[0] == 'f':
            F.append(tuple(int(s.split('/')[0]) - 1 for s in t[1:4]))
    return V, F


def cross_ratios(V, F):
    opp = {}  # directed edge (a, b) of a face -> its third vertex
    for f in F:
        for k in range(3):
            opp[(f[k], f[(k + 1) % 3])] = f[(k + 2) % 3]
    L = lambda a, b: math.dist(V[a], V[b])
    out = []
    for (i, j), k in opp.items():
        if i > j and (j, i) in opp:
            continue  # each interior edge once
        l = opp[(j, i)]
        out.append((i, j, math.log(L(i, l) * L(j, k) / (L(l, j) * L(k, i)))))
    return out


if __name__ == '__main__':
    V, F = read_obj(sys.argv[2])
    if '--flip' in sys.argv:
        F = [(f[0], f[2], f[1]) for f in F]
        with open(sys.argv[3] + '.obj', 'w') as o:
            for v in V:
                o.write('v %.17g %.17g %.17g\n' % v)
            for f in F:
                o.write('f %d %d %d\n' % (f[0] + 1, f[1] + 1, f[2] + 1))
    with open(sys.argv[3], 'w') as o:
        o.write('# i j c0 (1-based vertices), one line per interior edge\n')
        for i, j, c in cross_ratios(V, F):
            o.write('%d %d %.17g\n' % (i + 1, j + 1, c))
