#!/usr/bin/env python3
"""Pictures of soliman2021 Fig. 15 (the Morin surface flowing to a round sphere) from a run's ParaView series.

  /usr/bin/python3 runs/trianglefield_morin_pictures.py SERIES.pvd[,SERIES2.pvd] HISTORY.csv[,HISTORY2.csv] OUT.png
                                                       [--panels 7] [--view ELEV,AZIM]

Several series / histories (the stages of a run resumed from a checkpoint) are joined by iteration, a later one
replacing an earlier one's rows from its first iteration on.

OUT.png: a row of iterations (the first, the last and the steps between them nearest to evenly spaced values of
W, so the fast and the slow parts of the flow both show) and below it W and the EL residual against the iteration
with the levels 4 pi k (an immersed sphere with a k-fold point has W >= 4 pi k: the start is Kusner's Morin
surface, 16 pi, with its quadruple point). Each surface is the Poisson reconstruction of the triangle field (the
field is integrable to the flow's tolerance along the way, so its triangles glue); the two sides of the surface
have two colours (orange outside, blue inside as the faces are oriented), which shows the eversion: the halfway
model has as much of one colour as of the other, the round sphere shows one. Orthographic, painter's order, a
fixed camera; each panel scaled to its own bounding box. Needs Debian's python3-matplotlib and python3-numpy."""
import argparse
import csv
import math
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scripts"))
import vtu  # noqa: E402


def surface(pvtu):
    """Points and triangles of a serial step (one piece)."""
    piece = vtu.read_pvtu(pvtu)[0]
    P = np.array(piece["arrays"]["Points"][next(iter(piece["arrays"]["Points"]))][1]).reshape(-1, 3)
    cells = piece["arrays"]["Cells"]
    F = np.array(cells["connectivity"][1]).reshape(-1, 3)
    return P, F


def camera(elev, azim):
    e, a = math.radians(elev), math.radians(azim)
    d = np.array([math.cos(e) * math.cos(a), math.cos(e) * math.sin(a), math.sin(e)])  # towards the viewer
    right = np.cross([0, 0, 1], d)
    right /= np.linalg.norm(right)
    return d, right, np.cross(d, right)


def draw(ax, P, F, view, title):
    d, right, up = camera(*view)
    T = P[F]
    n = np.cross(T[:, 1] - T[:, 0], T[:, 2] - T[:, 0])
    n /= np.linalg.norm(n, axis=1)[:, None] + 1e-300
    facing = n @ d
    light = 0.35 + 0.65 * np.abs(facing)
    col = np.where((facing > 0)[:, None], [[0.95, 0.6, 0.25]], [[0.3, 0.5, 0.9]]) * light[:, None]
    order = np.argsort(T.mean(1) @ d)  # far to near
    xy = np.stack([T @ right, T @ up], axis=2)
    ax.add_collection(PolyCollection(xy[order], facecolors=col[order], edgecolors="k", linewidths=0.05))
    lo, hi = xy.reshape(-1, 2).min(0), xy.reshape(-1, 2).max(0)
    c, r = (lo + hi) / 2, (hi - lo).max() / 2 * 1.05
    ax.set_xlim(c[0] - r, c[0] + r)
    ax.set_ylim(c[1] - r, c[1] + r)
    ax.set_aspect("equal")
    ax.set_axis_off()
    ax.set_title(title, fontsize=8)


def history(paths):
    rows = []
    for path in paths.split(","):
        more = list(csv.DictReader(open(path)))
        first = float(more[0]["it"]) if more else math.inf
        rows = [r for r in rows if float(r["it"]) < first] + more
    it = np.array([float(r["it"]) for r in rows])
    W = np.array([float(r["energy"]) for r in rows])
    el = np.array([float(r["el_residual"]) for r in rows])
    return it, W, el


def pick(steps, it, W, k):
    """The first and last step and k - 2 between them nearest to evenly spaced W."""
    Ws = [np.interp(t, it, W) for t, _ in steps]
    chosen = {0, len(steps) - 1}
    for w in np.linspace(Ws[0], Ws[-1], k)[1:-1]:
        chosen.add(int(np.argmin([abs(x - w) + (1e9 if i in chosen else 0) for i, x in enumerate(Ws)])))
    return sorted(chosen), Ws


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("series")
    ap.add_argument("history")
    ap.add_argument("out")
    ap.add_argument("--panels", type=int, default=7)
    ap.add_argument("--view", default="25,-50")
    a = ap.parse_args()
    steps = []
    for path in a.series.split(","):
        more = vtu.read_pvd(path)
        first = more[0][0] if more else math.inf
        steps = [st for st in steps if st[0] < first] + more
    it, W, el = history(a.history)
    chosen, Ws = pick(steps, it, W, min(a.panels, len(steps)))
    view = tuple(float(x) for x in a.view.split(","))
    fig = plt.figure(figsize=(2.2 * len(chosen), 5.6))
    for k, i in enumerate(chosen):
        P, F = surface(steps[i][1])
        ax = fig.add_axes([k / len(chosen), 0.42, 1 / len(chosen), 0.55])
        draw(ax, P, F, view, "iteration %d, W = %.2f" % (steps[i][0], Ws[i]))
    ax = fig.add_axes([0.07, 0.08, 0.38, 0.28])
    ax.plot(it, W, "k-", lw=1)
    for k in range(1, 5):
        ax.axhline(4 * math.pi * k, color="gray", lw=0.5, ls=":")
        ax.text(it[-1], 4 * math.pi * k, " %dπ" % (4 * k), fontsize=7, va="center")
    ax.set_xlabel("iteration", fontsize=8)
    ax.set_ylabel("W", fontsize=8)
    ax.tick_params(labelsize=7)
    ax = fig.add_axes([0.56, 0.08, 0.38, 0.28])
    ax.semilogy(it, el, "k-", lw=1)
    ax.axhline(1e-6, color="gray", lw=0.5, ls=":")
    ax.set_xlabel("iteration", fontsize=8)
    ax.set_ylabel("EL residual", fontsize=8)
    ax.tick_params(labelsize=7)
    fig.savefig(a.out, dpi=110)
    print("wrote %s (iterations %s)" % (a.out, ", ".join("%d" % steps[i][0] for i in chosen)))


if __name__ == "__main__":
    main()
