"""n-fold symmetry error of a surface mesh about its axis (Fig. 17 of soliman2021, issue 15):
   nfold_symmetry.py MESH.obj N
centre = vertex centroid, axis = the principal axis of the largest moment of inertia (z for a torus about z);
error = max over vertices of the distance from the rotated vertex (by 2 pi / N about the axis) to the nearest vertex,
relative to the RMS distance from the centre. Vertices of an N-fold symmetric grid map onto vertices, so a symmetric
mesh gives round-off; a broken symmetry gives O(displacement). Needs numpy (/usr/bin/python3)."""
import sys
import numpy as np

V = np.array([list(map(float, l.split()[1:4])) for l in open(sys.argv[1]) if l.startswith('v ')])
n = int(sys.argv[2])
X = V - V.mean(0)
I = (X * X).sum() * np.eye(3) - X.T @ X
w, U = np.linalg.eigh(I)
a = U[:, 2]  # largest moment: the symmetry axis
th = 2 * np.pi / n
K = np.array([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
R = np.eye(3) + np.sin(th) * K + (1 - np.cos(th)) * K @ K
Y = X @ R.T
d = np.sqrt(((Y[:, None, :] - X[None, :, :]) ** 2).sum(2)).min(1)
rms = np.sqrt((X * X).sum(1).mean())
print("%s: %d-fold symmetry error max %.3e, mean %.3e (relative to the RMS radius %.4g)" % (sys.argv[1], n, d.max() / rms, d.mean() / rms, rms))
