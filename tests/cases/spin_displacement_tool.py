"""crane2011 Sec. 7.1 check: make g (a bump of amplitude eps on a flat mesh) and the displaced mesh f + g N, and
measure the distance of a spin result to it (after the best similarity fit: the spin transformation fixes
the shape, not its position, rotation or size). Usage:
  make MESH.obj EPS G.txt DISPLACED.obj      distance RESULT.obj DISPLACED.obj  (prints max point-to-surface distance)"""
import sys
import numpy as np
sys.path.insert(0, "scripts")
from objio import read_obj  # noqa: E402


def normal(V, F):
    n = np.cross(V[F[:, 1]] - V[F[:, 0]], V[F[:, 2]] - V[F[:, 0]]).sum(0)
    return n / np.linalg.norm(n)


def make(mesh, eps, gpath, out):
    V, F = (np.array(a, dtype=float) for a in read_obj(mesh))
    F = F.astype(int)
    g = eps * np.exp(-(V[:, 0] ** 2 + V[:, 1] ** 2) / 0.3 ** 2)
    np.savetxt(gpath, g, fmt="%.17g")
    W = V + g[:, None] * normal(V, F)[None, :]
    with open(out, "w") as fp:
        fp.writelines("v %.17g %.17g %.17g\n" % tuple(v) for v in W)
        fp.writelines("f %d %d %d\n" % tuple(f + 1) for f in F)


def point_triangle(P, A, B, C):
    """distance from each point of P (m x 3) to the nearest triangle (A, B, C: n x 3 each): the projection onto the
    plane when it falls inside, else the nearest point on the edges"""
    P = P[:, None, :]
    ab, ac, ap = B - A, C - A, P - A
    n = np.cross(ab, ac)
    n = n / np.linalg.norm(n, axis=1)[:, None]
    h = (ap * n).sum(2)
    q = P - h[:, :, None] * n
    inside = np.ones(h.shape, bool)
    for X, Y in ((A, B), (B, C), (C, A)):
        inside &= (np.cross(Y - X, q - X) * n).sum(2) >= -1e-14
    best = np.where(inside, np.abs(h), np.inf)
    for X, Y in ((A, B), (B, C), (C, A)):
        e = Y - X
        t = np.clip(((P - X) * e).sum(2) / (e * e).sum(1), 0, 1)
        best = np.minimum(best, np.linalg.norm(P - (X + t[:, :, None] * e), axis=2))
    return best.min(1)


def distance(result, target):
    P, F = (np.array(a, dtype=float) for a in read_obj(result))
    T, _ = (np.array(a, dtype=float) for a in read_obj(target))
    F = F.astype(int)
    # best similarity P -> T (Umeyama)
    mp, mt = P.mean(0), T.mean(0)
    X, Y = P - mp, T - mt
    U, S, Vt = np.linalg.svd(Y.T @ X)
    D = np.diag([1, 1, np.sign(np.linalg.det(U @ Vt))])
    R = U @ D @ Vt
    s = (S * np.diag(D)).sum() / (X * X).sum()
    Q = s * X @ R.T + mt
    A, B, C = T[F[:, 0]], T[F[:, 1]], T[F[:, 2]]
    Q = Q[np.lexsort((Q[:, 1], Q[:, 0]))]
    G = (A + B + C) / 3
    r = 2 * np.linalg.norm(B - A, axis=1).max()  # a nearest triangle has its centroid within this of the box
    worst = 0
    for i in range(0, len(Q), 64):
        q = Q[i:i + 64]
        near = np.all((G > q.min(0) - r) & (G < q.max(0) + r), axis=1)
        worst = max(worst, point_triangle(q, A[near], B[near], C[near]).max())
    return worst


if __name__ == "__main__":
    if sys.argv[1] == "make":
        make(sys.argv[2], float(sys.argv[3]), sys.argv[4], sys.argv[5])
    else:
        print("%.6e" % distance(sys.argv[2], sys.argv[3]))
