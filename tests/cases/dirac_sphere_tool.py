"""Closed-form Dirac spheres (crane2011 Sec. 6.2, Fig. 9 and 11; Richter 1997) and the distance of a computed one to
them. Usage:
  distance INPUT.obj RESULT.obj N [CLOSED.obj]
                                    fit the closed-form Dirac spheres of eigenvalue N to RESULT (vertices in the
                                    order of INPUT, the unit icosphere); prints one JSON line with the errors (and
                                    writes the nearest closed form at INPUT's vertices to CLOSED.obj)
  check INPUT.obj N                 the closed forms against the discrete D (Eq. 5) on INPUT and their closedness

The closed form (derived here; the paper only cites [Richter 1997]). On the unit sphere f(x) = x (outward normal, the
orientation of Eq. 5) with a function lam extended homogeneously of degree d to R^3, Eq. 2 in an oriented orthonormal
frame (X, Y, N = x), XY = N, YN = X, NX = Y, gives
    D lam = -(X d_Y lam - Y d_X lam) = N (X d_X + Y d_Y) lam = x (del lam) + d lam,   del = i d_x + j d_y + k d_z.
So, with P_k the left-monogenic polynomials (del P_k = 0) homogeneous of degree k, an H-right-module of rank k + 1:
    lam = P_k        : D lam = k lam,                    n = k >= 0,
    lam = x P_k      : del(x P_k) = -(2k + 3) P_k,  D lam = -(k + 2) lam,    n = -(k + 2),
the spectrum Z minus {-1} with quaternionic multiplicity |n + 1| of Sec. 6.2 (real 4|n + 1|, as the code measures).
The Dirac sphere of lam is f~ = int conj(lam) dx lam (Eq. 1; closed because rho = n is real, Eq. 3), integrated
here along great circles by Gauss-Legendre (the integrand is a trigonometric polynomial of degree <= 2|n| + 1).
Its mean curvature half-density is H~|df~| = (1 + n)|df| (Sec. 4.1 with H = 1, rho = n), so
    W(f~) = int H~^2 dA~ = 4 pi (1 + n)^2         (n = -2: the round sphere again, f~ = -conj(q) x q).
A computed eigenvector is some element of the eigenspace: the distance is to the nearest closed form, over all
lam = sum_a c_a phi_a (c real, phi_a a real basis; this includes every similarity: lam q gives conj(q) f~ q) and
translations, with the vertex x_i of the input matched to the point x_i of the sphere."""
import json
import os
import sys
import numpy as np
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
from objio import read_obj  # noqa: E402


def qmul(a, b):
    """Hamilton product of quaternion arrays (..., 4)"""
    a0, a1, a2, a3 = np.moveaxis(a, -1, 0)
    b0, b1, b2, b3 = np.moveaxis(b, -1, 0)
    return np.stack([a0 * b0 - a1 * b1 - a2 * b2 - a3 * b3, a0 * b1 + a1 * b0 + a2 * b3 - a3 * b2,
                     a0 * b2 - a1 * b3 + a2 * b0 + a3 * b1, a0 * b3 + a1 * b2 - a2 * b1 + a3 * b0], -1)


def conj(a):
    return a * np.array([1, -1, -1, -1])


def imag(x):
    return np.concatenate([np.zeros(x.shape[:-1] + (1,)), x], -1)


def monomials(k):
    return [(a, b, k - a - b) for a in range(k + 1) for b in range(k + 1 - a)]


def monogenic_basis(k):
    """real basis (4(k+1) x len(monomials) x 4) of the quaternion coefficients c_alpha of P = sum x^alpha c_alpha with
    del P = sum_l e_l d_l P = 0 (e_l = i, j, k multiplying from the left)"""
    mon = monomials(k)
    if k == 0:
        return np.eye(4).reshape(4, 1, 4)
    low = {m: i for i, m in enumerate(monomials(k - 1))}
    E = np.eye(4)[1:]
    A = np.zeros((4 * len(low), 4 * len(mon)))
    for j, m in enumerate(mon):
        for l in range(3):
            if m[l] == 0:
                continue
            mm = list(m); mm[l] -= 1
            r = low[tuple(mm)]
            for c in range(4):  # e_l * (unit c) * m[l]
                A[4 * r:4 * r + 4, 4 * j + c] += m[l] * qmul(E[l], np.eye(4)[c])
    _, s, vt = np.linalg.svd(A)
    rank = int((s > 1e-10 * s[0]).sum())
    N = vt[rank:]
    assert len(N) == 4 * (k + 1), "monogenic polynomials of degree %d: dimension %d, want %d" % (k, len(N), 4 * (k + 1))
    return N.reshape(len(N), len(mon), 4)


def eigenbasis(n, X):
    """values (npts x m x 4) of a real basis of the eigenspace D lam = n lam on the unit sphere at the points X"""
    assert n != -1, "n = -1 is not an eigenvalue of D on the round sphere"
    k = n if n >= 0 else -n - 2
    C = monogenic_basis(k)
    mon = np.stack([X[:, 0] ** a * X[:, 1] ** b * X[:, 2] ** c for a, b, c in monomials(k)], 1)  # npts x nmon
    P = np.einsum("pm,amc->pac", mon, C)
    return P if n >= 0 else qmul(imag(X)[:, None, :], P)


def path_pieces(n, X, p0, nodes=32):
    """F[p, r, a, b] = int_gamma sym(conj(phi_a) dx phi_b)_r along the great circle from p0 to X[p]: the closed-form
    Dirac sphere of lam = sum c_a phi_a is sum_ab c_a c_b F[:, :, a, b] (up to a translation)"""
    cth = np.clip(X @ p0, -1, 1)
    th = np.arccos(cth)
    u = X - cth[:, None] * p0
    nu = np.linalg.norm(u, axis=1)
    assert nu.min() > 1e-8 or th.max() < np.pi - 1e-6, "base point antipodal to a vertex"
    u = np.where(nu[:, None] > 0, u / np.maximum(nu, 1e-300)[:, None], 0)
    t, w = np.polynomial.legendre.leggauss(nodes)
    m = eigenbasis(n, X[:1]).shape[1]
    F = np.zeros((len(X), 3, m, m))
    for tn, wn in zip(t, w):
        s = (tn + 1) / 2 * th
        g = np.cos(s)[:, None] * p0 + np.sin(s)[:, None] * u
        dg = (-np.sin(s)[:, None] * p0 + np.cos(s)[:, None] * u) * (th / 2 * wn)[:, None]
        phi = eigenbasis(n, g)
        psi = qmul(conj(phi), imag(dg)[:, None, :])  # conj(phi_a) dx, p x m x 4
        for r in range(3):
            # (psi_a phi_b)_r as a bilinear form: the row r + 1 of the left-multiplication matrix of psi_a
            L = np.stack([qmul(psi, np.broadcast_to(np.eye(4)[c], psi.shape))[..., r + 1] for c in range(4)], -1)
            F[:, r] += np.einsum("pac,pbc->pab", L, phi)
    return (F + F.transpose(0, 1, 3, 2)) / 2


def surface(F, c):
    return np.einsum("prab,a,b->pr", F, c, c)


def fit(F, Y):
    """the closed form nearest to Y (npts x 3): a linear fit of Z = c c^T and a translation, its rank-one part,
    then Gauss-Newton on (c, t)"""
    p, _, m, _ = F.shape
    iu = np.triu_indices(m)
    G = (F + F.transpose(0, 1, 3, 2) * (1 - np.eye(m)))[:, :, iu[0], iu[1]]  # Z_ab for a <= b
    A = np.concatenate([G.reshape(3 * p, -1), np.tile(np.eye(3), (p, 1))], 1)
    z = np.linalg.lstsq(A, Y.reshape(-1), rcond=None)[0]
    Z = np.zeros((m, m)); Z[iu] = z[:-3]; Z = (Z + Z.T) / 2
    ev, V = np.linalg.eigh(Z)
    c = V[:, -1] * np.sqrt(max(ev[-1], 0.0))
    t = z[-3:]
    for _ in range(50):
        r = (surface(F, c) + t - Y).reshape(-1)
        J = np.concatenate([2 * np.einsum("prab,b->pra", F, c).reshape(3 * p, m), np.tile(np.eye(3), (p, 1))], 1)
        dx = np.linalg.lstsq(J, -r, rcond=None)[0]
        c, t = c + dx[:m], t + dx[m:]
        if np.linalg.norm(dx) < 1e-13 * (1 + np.linalg.norm(c)):
            break
    return c, t


def area(V, F):
    return 0.5 * np.linalg.norm(np.cross(V[F[:, 1]] - V[F[:, 0]], V[F[:, 2]] - V[F[:, 0]]), axis=1).sum()


def half_density(V, F):
    """H|df| per vertex divided by the vertex area's square root: H_i sqrt(A_i), H_i = (L V)_i . N_i / (2 A_i) (L the
    positive cotan Laplacian, (L V)_i = sum_j (cot a + cot b)/2 (V_i - V_j) = 2 H N A_i; A_i a third of the incident
    areas, N_i the area-weighted face normal: H = 1 on the unit sphere with the outward orientation)"""
    nv = len(V)
    LV = np.zeros_like(V)
    N = np.zeros_like(V)
    A = np.zeros(nv)
    for a, b, c in ((0, 1, 2), (1, 2, 0), (2, 0, 1)):
        i, j, k = F[:, a], F[:, b], F[:, c]
        u, w = V[j] - V[i], V[k] - V[i]
        cr = np.cross(u, w)
        cot = (u * w).sum(1) / np.linalg.norm(cr, axis=1)  # angle at i, opposite edge jk
        d = (cot / 2)[:, None] * (V[k] - V[j])
        np.add.at(LV, j, -d)
        np.add.at(LV, k, d)
        np.add.at(N, i, cr / 2)
        np.add.at(A, i, np.linalg.norm(cr, axis=1) / 6)
    N /= np.linalg.norm(N, axis=1)[:, None]
    H = (LV * N).sum(1) / (2 * A)
    return H * np.sqrt(A), A


def write_obj(path, V, F):
    with open(path, "w") as fp:
        fp.writelines("v %.17g %.17g %.17g\n" % tuple(v) for v in V)
        fp.writelines("f %d %d %d\n" % tuple(f + 1) for f in F)


def distance(inp, res, n, closed=None):
    X, Fc = (np.array(a, dtype=float) for a in read_obj(inp))
    Y, _ = (np.array(a, dtype=float) for a in read_obj(res))
    X /= np.linalg.norm(X, axis=1)[:, None]
    p0 = np.array([0.3, 0.5, 0.8]) / np.linalg.norm([0.3, 0.5, 0.8])
    F = path_pieces(n, X, p0)
    c, t = fit(F, Y)
    E = surface(F, c) + t
    R = np.sqrt(area(Y, Fc.astype(int)) / (4 * np.pi))  # the result's size (its area is restored to the input's)
    d = np.linalg.norm(E - Y, axis=1) / R
    # rho as a potential (Sec. 4.1): H~|df~| = H|df| + rho |df| with rho = n, per vertex against the input
    h0, A0 = half_density(X, Fc.astype(int))
    h1, _ = half_density(Y / R, Fc.astype(int))
    rho = (h1 - h0) / np.sqrt(A0)
    if closed:
        write_obj(closed, E, Fc.astype(int))
    return {"n": n, "vertices": len(X), "dist_max": float(d.max()), "dist_rms": float(np.sqrt((d ** 2).mean())),
            "rho_max_err": float(np.abs(rho - n).max()), "rho_rms_err": float(np.sqrt((A0 * (rho - n) ** 2).sum() / A0.sum())),
            "willmore": float((h1 ** 2).sum()), "willmore_closed_form": 4 * np.pi * (1 + n) ** 2,
            "size": float(R), "coefficient_norm": float(np.linalg.norm(c))}


def cluster_distances(inp, results, n):
    """dist_max of each of several results of one eigenvalue n on one input (the closed forms integrated once)"""
    X, Fc = (np.array(a, dtype=float) for a in read_obj(inp))
    X /= np.linalg.norm(X, axis=1)[:, None]
    F = path_pieces(n, X, np.array([0.3, 0.5, 0.8]) / np.linalg.norm([0.3, 0.5, 0.8]))
    out = []
    for res in results:
        Y = np.array(read_obj(res)[0], dtype=float)
        c, t = fit(F, Y)
        R = np.sqrt(area(Y, Fc.astype(int)) / (4 * np.pi))
        out.append(float((np.linalg.norm(surface(F, c) + t - Y, axis=1) / R).max()))
    return out


def check(inp, n):
    """the closed forms satisfy the discrete Eq. 5 to O(h) (||D lam - n B lam|| / ||B lam|| on the faces) and the
    1-form conj(lam) dx lam is closed (two base points give the same surface up to a translation)"""
    X, Fc = (np.array(a, dtype=float) for a in read_obj(inp))
    Fc = Fc.astype(int)
    X /= np.linalg.norm(X, axis=1)[:, None]
    phi = eigenbasis(n, X)
    rng = np.random.default_rng(1)
    lam = np.einsum("pac,a->pc", phi, rng.standard_normal(phi.shape[1]))
    i, j, k = Fc.T
    A2 = np.linalg.norm(np.cross(X[j] - X[i], X[k] - X[i]), axis=1)  # 2 A
    Dl = -sum(qmul(imag(X[c] - X[b]), lam[a]) for a, b, c in ((i, j, k), (j, k, i), (k, i, j))) / A2[:, None]
    Bl = (lam[i] + lam[j] + lam[k]) / 3
    res = np.sqrt((A2 * ((Dl - n * Bl) ** 2).sum(1)).sum() / (A2 * (Bl ** 2).sum(1)).sum())
    c = rng.standard_normal(phi.shape[1])
    S1 = surface(path_pieces(n, X, np.array([0.3, 0.5, 0.8]) / np.linalg.norm([0.3, 0.5, 0.8])), c)
    S2 = surface(path_pieces(n, X, np.array([-0.7, 0.1, 0.2]) / np.linalg.norm([-0.7, 0.1, 0.2])), c)
    dS = S1 - S2
    return {"n": n, "eq5_residual": float(res), "closedness": float(np.abs(dS - dS.mean(0)).max() / np.abs(S1).max())}


if __name__ == "__main__":
    if sys.argv[1] == "distance":
        print(json.dumps(distance(sys.argv[2], sys.argv[3], int(sys.argv[4]), sys.argv[5] if len(sys.argv) > 5 else None)))
    elif sys.argv[1] == "check":
        print(json.dumps(check(sys.argv[2], int(sys.argv[3]))))
    else:
        sys.exit(__doc__)
