#!/usr/bin/env python3
"""Independent dense analysis of the conformal constraint on an open mesh (issue 21, docs/boundary_twist.md,
"Why CGD stalls on open surfaces"). From the class's mesh (the flow's input, written with -flow_max_it 0) and a
state of the flow (two OBJ files, same connectivity) it builds, in numpy and independently of src/:
  C       the cross-ratio map on interior edges (soliman2021 Eq. 24, as src/operators/cross_ratio.c),
  Dlambda the derivative of the log lengths at the state (Sec. 3.1),
  X_free  = C Dlambda restricted to the free (non-boundary) vertices: the Jacobian a Dirichlet run sees,
and prints its rank (against C Dlambda with the boundary free), its smallest nonzero singular values, the
violation c = C (lambda(state) - lambda(input)) split along the left singular vectors, and, for the generator's
cylinders (optional third argument: vertices per ring), the mean of the smallest left singular vector on ring,
vertical and diagonal edges.
  usage: runs/constraint_jacobian_svd.py input.obj state.obj [ring_size]
Dense SVD: meant for small generated meshes (24 x 12: 840 x 792, a second)."""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'scripts'))
import objio  # noqa: E402  (scripts/objio.py, the project's OBJ reader)


def read_obj(path):
    """(vertices, faces) as numpy arrays, read by the project's OBJ reader"""
    v, f = objio.read_obj(path)
    return np.array(v), np.array(f)



def main():
    X0, F = read_obj(sys.argv[1])
    X1, F1 = read_obj(sys.argv[2])
    assert (F == F1).all() and X0.shape == X1.shape, "the two meshes must share the connectivity"
    nv = len(X0)
    eid, E, cnt = {}, [], []
    for f in F:
        for k in range(3):
            a, b = f[(k + 1) % 3], f[(k + 2) % 3]
            key = (min(a, b), max(a, b))
            if key not in eid:
                eid[key] = len(E)
                E.append(key)
                cnt.append(0)
            cnt[eid[key]] += 1
    E, cnt = np.array(E), np.array(cnt)
    ne = len(E)
    bnd = cnt == 1
    bv = np.zeros(nv, bool)
    bv[E[bnd].ravel()] = True
    inter = np.where(~bnd)[0]
    row = {e: i for i, e in enumerate(inter)}
    C = np.zeros((len(inter), ne))
    for f in F:  # face ijk adds +lambda_next - lambda_prev to the row of each of its interior edges
        fe = [eid[(min(f[(k + 1) % 3], f[(k + 2) % 3]), max(f[(k + 1) % 3], f[(k + 2) % 3]))] for k in range(3)]
        for k in range(3):
            if fe[k] in row:
                C[row[fe[k]], fe[(k + 1) % 3]] += 1
                C[row[fe[k]], fe[(k + 2) % 3]] -= 1

    def loglen(X):
        return np.log(np.linalg.norm(X[E[:, 0]] - X[E[:, 1]], axis=1))

    d = X1[E[:, 0]] - X1[E[:, 1]]
    l2 = (d * d).sum(1)
    D = np.zeros((ne, 3 * nv))
    for e in range(ne):
        i, j = E[e]
        D[e, 3 * i:3 * i + 3] = d[e] / l2[e]
        D[e, 3 * j:3 * j + 3] = -d[e] / l2[e]
    free = np.repeat(~bv, 3)
    c = C @ (loglen(X1) - loglen(X0))
    U, s, _ = np.linalg.svd((C @ D)[:, free])
    r = int((s > 1e-10 * s[0]).sum())
    sa = np.linalg.svd(C @ D, compute_uv=False)
    ra = int((sa > 1e-10 * sa[0]).sum())
    print("interior edges %d, free coordinates %d, interior vertices %d" % (len(inter), free.sum(), (~bv).sum()))
    print("rank of X_free %d (boundary free: %d; bound: interior edges - interior vertices = %d)" % (r, ra, len(inter) - (~bv).sum()))
    print("largest singular value %.3e; smallest 8 nonzero: %s" % (s[0], " ".join("%.2e" % x for x in s[r - 8:r])))
    p = U.T @ c
    print("violation |c|_inf %.3e |c|_2 %.3e; along the smallest singular vector %.3e, along the other %d %.3e, outside the range %.3e"
          % (abs(c).max(), np.linalg.norm(c), abs(p[r - 1]), r - 1, np.linalg.norm(p[:r - 1]), np.linalg.norm(p[r:])))
    print("violation along the 8 smallest singular vectors: %s" % " ".join("%.1e" % abs(x) for x in p[r - 8:r]))
    if len(sys.argv) > 3:
        n = int(sys.argv[3])
        u = U[:, r - 1] * np.sign(U[:, r - 1].sum() or 1)
        kinds = []
        for e in inter:
            i, j = E[e]
            kinds.append('ring' if i // n == j // n else ('vertical' if (i - j) % n == 0 else 'diagonal'))
        kinds = np.array(kinds)
        for k in ('ring', 'vertical', 'diagonal'):
            m = kinds == k
            print("smallest left singular vector on %s edges (%d): mean %+.3f, mean |.| %.3f" % (k, m.sum(), u[m].mean(), abs(u[m]).mean()))


if __name__ == '__main__':
    main()
