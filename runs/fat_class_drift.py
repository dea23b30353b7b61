#!/usr/bin/env python3
"""Where does the remeshed fat-class torus drift? (issue 35 finding 4, docs/real_meshes.md "Issue 35").
From the flow's input (the class) and states of the flow (OBJ files, same connectivity; a torus of revolution
about the z axis) it prints, for each state:
  - the vertex-area spread max/min of A/A0 (barycentric areas, as src/energy/willmore.c);
  - the pattern of log(A/A0): the share of its variance (about its mean) explained by a linear function of the
    input positions (what an infinitesimal Moebius boost does: log conformal factor -2 b.x) and by the torus's
    low Fourier modes cos/sin(j phi + k theta), |j|,|k| <= 3 (phi around z, theta around the tube), and the
    three largest modes;
  - the displacement from the previous state split along the ten Moebius fields at the previous state
    (translations, rotations, scaling, boosts 2(b.x)x - |x|^2 b): the share of |dx|^2 each group explains.
  usage: runs/fat_class_drift.py [--png OUT.png] class.obj state1.obj [state2.obj ...]
A state given as CLASS2=STATE is measured against its own class mesh CLASS2 (another torus; no displacement).
With --png it also draws each state's log(A/A0) over the torus's angles (phi, theta) (Debian matplotlib)."""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'scripts'))
import objio  # noqa: E402  (scripts/objio.py, the project's OBJ reader)


def read_obj(path):
    """(vertices, faces) as numpy arrays, read by the project's OBJ reader"""
    v, f = objio.read_obj(path)
    return np.array(v), np.array(f)



def vertex_areas(X, F):
    a = 0.5 * np.linalg.norm(np.cross(X[F[:, 1]] - X[F[:, 0]], X[F[:, 2]] - X[F[:, 0]]), axis=1)
    A = np.zeros(len(X))
    for k in range(3):
        np.add.at(A, F[:, k], a / 3)
    return A


def share(y, B):
    """share of the variance of y (about its mean) explained by the columns of B (plus a constant)"""
    B = np.column_stack([np.ones(len(y)), B])
    c, *_ = np.linalg.lstsq(B, y, rcond=None)
    r = y - B @ c
    return 1 - (r @ r) / ((y - y.mean()) @ (y - y.mean())), c


def mobius_fields(X):
    n = len(X)
    G = {'translations': [], 'rotations': [], 'scaling': [], 'boosts': []}
    for k in range(3):
        e = np.zeros(3); e[k] = 1
        G['translations'].append(np.tile(e, (n, 1)))
        G['rotations'].append(np.cross(e, X))
        G['boosts'].append(2 * (X @ e)[:, None] * X - (X * X).sum(1)[:, None] * e)
    G['scaling'].append(X.copy())
    return {k: np.column_stack([v.ravel() for v in vs]) for k, vs in G.items()}


def main():
    args, png = sys.argv[1:], None
    if args[0] == "--png":
        png, args = args[1], args[2:]
    X0, F = read_obj(args[0])
    A0 = vertex_areas(X0, F)
    phi = np.arctan2(X0[:, 1], X0[:, 0])
    R = np.hypot(X0[:, 0], X0[:, 1]).mean()
    theta = np.arctan2(X0[:, 2], np.hypot(X0[:, 0], X0[:, 1]) - R)
    modes, names = [], []
    for j in range(0, 4):
        for k in range(-3, 4):
            if j == 0 and k <= 0:
                continue
            modes += [np.cos(j * phi + k * theta), np.sin(j * phi + k * theta)]
            names += ["cos(%d phi %+d theta)" % (j, k), "sin(%d phi %+d theta)" % (j, k)]
    modes = np.column_stack(modes)
    prev = X0
    pats = []
    for path in args[1:]:
        if "=" in path:  # another class: its own angles and areas
            c2, path = path.split("=")
            Xc, Fc = read_obj(c2)
            X, F1 = read_obj(path)
            g = np.log(vertex_areas(X, F1) / vertex_areas(Xc, Fc))
            p2 = np.arctan2(Xc[:, 1], Xc[:, 0])
            t2 = np.arctan2(Xc[:, 2], np.hypot(Xc[:, 0], Xc[:, 1]) - np.hypot(Xc[:, 0], Xc[:, 1]).mean())
            print("%s (class %s): area spread %.4f, variance of log(A/A0) linear in x (Moebius boost) %.3f"
                  % (path, c2, np.exp(g.max() - g.min()), share(g, Xc)[0]))
            pats.append((path, g, p2, t2))
            continue
        X, F1 = read_obj(path)
        assert (F1 == F).all(), "the states must share the class's connectivity"
        g = np.log(vertex_areas(X, F) / A0)
        pats.append((path, g, phi, theta))
        sl, _ = share(g, X0)
        sf, c = share(g, modes)
        top = np.argsort(-np.abs(c[1:]))[:3]
        print("%s: area spread %.4f, std log(A/A0) %.3e; variance explained: linear in x (Moebius boost) %.3f, "
              "Fourier |j|,|k|<=3 %.3f; largest modes %s"
              % (path, np.exp(g.max() - g.min()), g.std(), sl, sf,
                 ", ".join("%s %.2e" % (names[i], c[1 + i]) for i in top)))
        d = (X - prev).ravel()
        if d @ d > 0:
            Gs = mobius_fields(prev)
            allG = np.column_stack(list(Gs.values()))
            c, *_ = np.linalg.lstsq(allG, d, rcond=None)
            tot = 1 - np.sum((d - allG @ c) ** 2) / (d @ d)
            parts = []
            for name, Gk in Gs.items():
                ck, *_ = np.linalg.lstsq(Gk, d, rcond=None)
                parts.append("%s %.3f" % (name, 1 - np.sum((d - Gk @ ck) ** 2) / (d @ d)))
            print("   displacement from the previous state |dx|_2 %.3e: Moebius share %.3f (%s)"
                  % (np.sqrt(d @ d), tot, ", ".join(parts)))
        prev = X
    if png:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, axs = plt.subplots(1, len(pats), figsize=(4.6 * len(pats), 3.8), squeeze=False)
        lim = max(np.abs(p[1] - p[1].mean()).max() for p in pats)
        for ax, (path, g, ph, th) in zip(axs[0], pats):
            sc = ax.scatter(ph, th, c=g - g.mean(), s=6, cmap="coolwarm", vmin=-lim, vmax=lim)
            ax.set_xlabel("phi (around the z axis)")
            if ax is axs[0][0]:
                ax.set_ylabel("theta (around the tube; 0 = outer equator)")
            ax.set_title("%s\nlog(A/A0) - mean, spread %.3f" % (path.split("/")[-1], np.exp(g.max() - g.min())), fontsize=8)
        fig.colorbar(sc, ax=axs[0].tolist(), shrink=0.8)
        fig.savefig(png, dpi=90)
        print("wrote", png)


if __name__ == "__main__":
    main()
