#!/usr/bin/env python3
"""Why q_mean grows on the bumpy torus (issue 13, docs/conformal_flow.md "The bumpy torus: why q_mean grows").
Reads a ParaView series written by -flow_type conformal with -viewer_dir DIR -flow_viewer_every 1 -viewer_format
ascii (serial run: the piece files surface_NNNN_0.vtu) of a torus of revolution with axis z and centre radius R, and
prints per step:
  q_mean (area-weighted, against the input; the flow's own measure) and q_mean of the step's own map (against the
  previous step, weighted by its face areas: the history column q_step);
  the conformal class: the cotan Gram matrix G of the harmonic representatives of the two angle forms d(theta)/2pi,
  d(phi)/2pi of the input (Dirichlet energy: a conformal invariant), normalised to det 1, and
  K_min = exp(arccosh(tr(G0^-1 G)/2)), the dilatation of the extremal (affine) map between the input's and this
  step's conformal class: a drift of the class would force q >= K_min;
  u = 1/2 log(A_i / A_i input) (barycentric vertex areas), the mean of h |grad u| per face (h the side of the
  equilateral triangle of the input face's area) and the fit (q - 1) ~ c h |grad u| with its per-face correlation.
The floor: the piecewise-linear interpolant of the exact conformal map z -> exp(z) has c = 0.59-0.61 on equilateral
and 0.67-0.71 on right isosceles triangles, 0.70 and 0.76 for right triangles with legs 1.5:1 and 2:1
(--floor prints it).
  python3 runs/conformal_torus_q.py DIR [R]     (dense linear algebra: ~3 s per step at 2048 vertices)
  python3 runs/conformal_torus_q.py --floor"""
import re, sys, glob, os
import numpy as np

def read_vtu(fn):
    s = open(fn).read()
    m = re.search(r'<Points>\s*<DataArray[^>]*>(.*?)</DataArray>', s, re.S)
    P = np.array(m.group(1).split(), dtype=float).reshape(-1, 3)
    m = re.search(r'<DataArray[^>]*Name="connectivity"[^>]*>(.*?)</DataArray>', s, re.S)
    return P, np.array(m.group(1).split(), dtype=int).reshape(-1, 3)

def frames(P, C):
    """per face: the edge vectors in an orthonormal frame of the face's plane (2x2) and the area"""
    a, b, c = P[C[:, 0]], P[C[:, 1]], P[C[:, 2]]
    e1, e2 = b - a, c - a
    n = np.cross(e1, e2); A = np.linalg.norm(n, axis=1) / 2
    u = e1 / np.linalg.norm(e1, axis=1)[:, None]
    w = np.cross(n / (2 * A)[:, None], u)
    d = lambda x, y: np.einsum('ij,ij->i', x, y)
    return np.stack([np.stack([d(e1, u), d(e2, u)], 1), np.stack([d(e1, w), d(e2, w)], 1)], 1), A

def q_faces(P0, P, C):
    E0, A0 = frames(P0, C); E, _ = frames(P, C)
    s = np.linalg.svd(E @ np.linalg.inv(E0), compute_uv=False)
    return s[:, 0] / s[:, 1], A0

def edges(C):
    e = np.concatenate([C[:, [0, 1]], C[:, [1, 2]], C[:, [2, 0]]]); e.sort(1)
    return np.unique(e, axis=0)

def cotan_weights(P, C, E):
    nv = len(P); key = E[:, 0] * nv + E[:, 1]; W = np.zeros(len(E))
    for k in range(3):
        i, j, o = C[:, k], C[:, (k + 1) % 3], C[:, (k + 2) % 3]
        a, b = P[i] - P[o], P[j] - P[o]
        ct = np.einsum('ij,ij->i', a, b) / np.linalg.norm(np.cross(a, b), axis=1)
        np.add.at(W, np.searchsorted(key, np.minimum(i, j) * nv + np.maximum(i, j)), 0.5 * ct)
    return W

def gram(P, C, E, forms):
    """G_ab = <h_a, h_b> (cotan *1), h the harmonic representative of the closed edge form"""
    W = cotan_weights(P, C, E); nv = len(P); ne = len(E)
    d = np.zeros((ne, nv)); d[np.arange(ne), E[:, 0]] = -1; d[np.arange(ne), E[:, 1]] = 1
    L = d.T @ (W[:, None] * d) + 1e-10 * np.eye(nv)
    H = [o - d @ np.linalg.solve(L, d.T @ (W * o)) for o in forms]
    G = np.array([[np.sum(W * a * b) for b in H] for a in H])
    return G / np.sqrt(np.linalg.det(G))

def vertex_areas(P, C):
    _, A = frames(P, C); a = np.zeros(len(P))
    for k in range(3): np.add.at(a, C[:, k], A / 3)
    return a

def scale_gradient(P0, P, C):
    E0, A0 = frames(P0, C)
    u = 0.5 * np.log(vertex_areas(P, C) / vertex_areas(P0, C))
    du = np.stack([u[C[:, 1]] - u[C[:, 0]], u[C[:, 2]] - u[C[:, 0]]], 1)
    g = np.linalg.solve(np.transpose(E0, (0, 2, 1)), du[:, :, None])[:, :, 0]
    return np.linalg.norm(g, axis=1) * np.sqrt(A0 * 4 / np.sqrt(3))

def floor():
    for name, tri in [("equilateral", np.array([0, 1, 0.5 + 0.5j * np.sqrt(3)])), ("right isosceles", np.array([0, 1, 1j])),
                      ("right, legs 1.5:1", np.array([0, 1.5, 1j])), ("right, legs 2:1", np.array([0, 2, 1j]))]:
        for h in [0.05, 0.1, 0.2]:
            r = []
            for th in np.linspace(0, 2 * np.pi, 24, endpoint=False):
                z = tri * h; w = np.exp(np.exp(1j * th) * z)  # |grad u| = 1
                M = lambda p: np.array([[(p[1] - p[0]).real, (p[2] - p[0]).real], [(p[1] - p[0]).imag, (p[2] - p[0]).imag]])
                s = np.linalg.svd(M(w) @ np.linalg.inv(M(z)), compute_uv=False); r.append(s[0] / s[1] - 1)
            heq = np.sqrt(abs(np.linalg.det(M(z))) / 2 * 4 / np.sqrt(3))
            print(f"{name}, h {h}: (q - 1) / (h |grad u|) = {np.mean(r) / heq:.3f}")

def main(dirn, R):
    fs = sorted(glob.glob(dirn + '/surface_*_0.vtu'), key=lambda f: int(re.findall(r'(\d+)', os.path.basename(f))[0]))
    P0, C = read_vtu(fs[0]); E = edges(C)
    th = np.arctan2(P0[:, 1], P0[:, 0]); ph = np.arctan2(P0[:, 2], np.hypot(P0[:, 0], P0[:, 1]) - R)
    wrap = lambda x: (x + np.pi) % (2 * np.pi) - np.pi
    forms = [wrap(t[E[:, 1]] - t[E[:, 0]]) / (2 * np.pi) for t in (th, ph)]
    G0 = gram(P0, C, E, forms); Pp = P0
    print("step  q_mean  q_step | G11 G22 G12 (det 1)   K_min | mean h|grad u|  c=(q-1)/(h|grad u|)  corr")
    for k, f in enumerate(fs):
        P, _ = read_vtu(f)
        Q, A0 = q_faces(P0, P, C); w = A0 / A0.sum(); Qs, Ap = q_faces(Pp, P, C); wp = Ap / Ap.sum()
        G = gram(P, C, E, forms); K = np.exp(np.arccosh(max(1.0, 0.5 * np.trace(np.linalg.inv(G0) @ G))))
        x = scale_gradient(P0, P, C)
        c = np.sum(w * (Q - 1) * x) / max(np.sum(w * x * x), 1e-300)
        cr = np.corrcoef(Q - 1, x)[0, 1] if k else 0
        print(f"{k:4d}  {np.sum(w * Q):.4f}  {np.sum(wp * Qs):.4f} | {G[0, 0]:.4f} {G[1, 1]:.4f} {G[0, 1]:+.4f}  {K:.4f} | {np.sum(w * x):.4f}  {c:.2f}  {cr:.2f}")
        Pp = P

if __name__ == '__main__':
    if len(sys.argv) > 1 and sys.argv[1] == '--floor': floor()
    elif len(sys.argv) > 1: main(sys.argv[1], float(sys.argv[2]) if len(sys.argv) > 2 else 3.0)
    else: print(__doc__)
