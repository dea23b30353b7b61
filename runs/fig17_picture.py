#!/usr/bin/python3
"""docs/img/fig17_newton.png: the n-fold starts of options/newton_fig17_n{2,3,4}.opts (top) and the Newton results
(bottom), seen from above, each vertex coloured by its distance from the z axis over its ring's mean minus 1 (the
n-lobe wave; a ring = the vertices of one grid column j = id mod m of -gen lattice). A torus of revolution is 0.
  runs/fig17_picture.py START_n2.obj RESULT_n2.obj START_n3.obj ... out.png   (needs numpy, matplotlib)"""
import sys
import numpy as np
import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt
from matplotlib.collections import PolyCollection


def read(path):
    L = open(path).read().splitlines()
    x = np.array([[float(t) for t in l.split()[1:4]] for l in L if l.startswith('v ')])
    f = np.array([[int(t.split('/')[0]) - 1 for t in l.split()[1:4]] for l in L if l.startswith('f ')])
    return x, f


def wave(x, m):
    rho = np.hypot(x[:, 0] - x[:, 0].mean(), x[:, 1] - x[:, 1].mean())
    ring = np.arange(len(x)) % m
    mean = np.array([rho[ring == j].mean() for j in range(m)])
    return rho / mean[ring] - 1


args, out = sys.argv[1:-1], sys.argv[-1]
ms, ns = [24, 16, 12], [2, 3, 4]
fig, ax = plt.subplots(2, 3, figsize=(12, 8))
for k in range(3):
    for r in range(2):
        x, f = read(args[2 * k + r])
        w = wave(x, ms[k])
        up = (np.cross(x[f[:, 1]] - x[f[:, 0]], x[f[:, 2]] - x[f[:, 0]])[:, 2] > 0)  # faces seen from above
        polys = x[f[up]][:, :, :2]
        pc = PolyCollection(polys, array=w[f[up]].mean(1), cmap='RdBu_r', edgecolors='k', linewidths=0.1)
        pc.set_clim(-0.05, 0.05)
        a = ax[r, k]
        a.add_collection(pc)
        a.set_aspect('equal')
        a.autoscale_view()
        a.axis('off')
        a.set_title('n = %d, %s\nmax |rho/rho_ring - 1| = %.1e' % (ns[k], 'start' if r == 0 else 'Newton result', np.abs(w).max()), fontsize=10)
fig.colorbar(pc, ax=ax, shrink=0.6, label='rho / rho_ring - 1 (clipped at 0.05)')
fig.savefig(out, dpi=90)
