#!/usr/bin/python3
"""docs/img/fig17_lobed.png: n-lobed critical tori of options/newton_fig17_lobed_n*.opts beside the homogeneous torus
of the same class, in perspective, faces coloured by the distance from the axis over the ring's mean minus 1.
  runs/fig17_lobed_picture.py [--clim C] [--elev E] M1 LOBED1.obj HOMOGENEOUS1.obj TITLE1 [M2 ...] out.png
(--clim: the colour range +-C, default 0.3; --elev: the view's elevation in degrees, default 55; fine grids (> 5000
faces) are drawn without edges)
(M: the -gen_m of the grid; needs numpy, matplotlib)"""
import sys
import numpy as np
import matplotlib
matplotlib.use('Agg')
import matplotlib.pyplot as plt
from mpl_toolkits.mplot3d.art3d import Poly3DCollection


def read(path):
    L = open(path).read().splitlines()
    x = np.array([[float(t) for t in l.split()[1:4]] for l in L if l.startswith('v ')])
    f = np.array([[int(t.split('/')[0]) - 1 for t in l.split()[1:4]] for l in L if l.startswith('f ')])
    X = x - x.mean(0)
    I = (X * X).sum() * np.eye(3) - X.T @ X
    w, U = np.linalg.eigh(I)
    X = X @ U[:, ::-1][:, [1, 2, 0]]  # the largest moment's axis to z
    return X / np.sqrt((X * X).sum(1).mean()), f


args, out = sys.argv[1:-1], sys.argv[-1]
opt = {'--clim': 0.3, '--elev': 55.0}
while args and args[0] in opt:
    opt[args[0]] = float(args[1]); args = args[2:]
rows = [args[i:i + 4] for i in range(0, len(args), 4)]
fig = plt.figure(figsize=(10, 4.5 * len(rows)))
for r, (m, lob, hom, title) in enumerate(rows):
    for c, (path, what) in enumerate([(lob, 'n-lobed critical torus'), (hom, 'homogeneous torus')]):
        x, f = read(path)
        rho = np.hypot(x[:, 0], x[:, 1])
        ring = np.arange(len(x)) % int(m)
        w = rho / np.array([rho[ring == j].mean() for j in range(int(m))])[ring] - 1
        a = fig.add_subplot(len(rows), 2, 2 * r + c + 1, projection='3d')
        pc = Poly3DCollection(x[f], array=w[f].mean(1), cmap='RdBu_r', edgecolors='k', linewidths=0.05 if len(f) < 5000 else 0)
        pc.set_clim(-opt['--clim'], opt['--clim'])
        if len(f) >= 5000:  # no edges to show the shape: shade by the face normal against a light
            nrm = np.cross(x[f[:, 1]] - x[f[:, 0]], x[f[:, 2]] - x[f[:, 0]])
            lit = np.abs(nrm @ np.array([0.3, -0.5, 0.8]) / np.linalg.norm(nrm, axis=1) / np.linalg.norm([0.3, -0.5, 0.8]))
            col = plt.get_cmap('RdBu_r')(np.clip(w[f].mean(1) / (2 * opt['--clim']) + 0.5, 0, 1))
            col[:, :3] *= (0.35 + 0.65 * lit)[:, None]
            pc.set_array(None); pc.set_facecolor(col)
        a.add_collection3d(pc)
        lim = np.abs(x).max()
        a.set_xlim(-lim, lim); a.set_ylim(-lim, lim); a.set_zlim(-lim, lim)
        a.view_init(elev=opt['--elev'], azim=30)
        a.set_box_aspect((1, 1, 1))
        a.axis('off')
        a.set_title('%s: %s' % (title, what), fontsize=10)
fig.colorbar(matplotlib.cm.ScalarMappable(matplotlib.colors.Normalize(-opt['--clim'], opt['--clim']), 'RdBu_r'), ax=fig.axes, shrink=0.5, label='rho / rho_ring - 1')
fig.savefig(out, dpi=90)
