#!/usr/bin/python3
"""The n-lobe content of a torus about its axis (soliman2021 Fig. 17, issue 39):
  runs/fig17_modes.py MESH.obj M
axis = the principal axis of the largest moment of inertia; per ring of the -gen lattice grid (vertex id mod M) the
Fourier coefficients |rho_k| / rho_0 of the distance from the axis along the ring, k = 0..8, the largest over the
rings; also the extent along the axis. A torus of revolution has rho_k = 0 for k > 0; an n-lobed one rho_n (and its
multiples) of the lobes' size. Needs numpy (/usr/bin/python3)."""
import sys, numpy as np


def axis_frame(x):
    """x centred, rotated so that the principal axis of the largest moment of inertia is z"""
    X = x - x.mean(0)
    w, U = np.linalg.eigh((X * X).sum() * np.eye(3) - X.T @ X)
    return X @ U[:, ::-1][:, [1, 2, 0]]


def ring_amplitudes(x, m, kmax=8):
    """per k = 0..kmax the largest over the grid's rings (vertex id mod m) of |rho_k| / rho_0 about the axis"""
    X = axis_frame(x)
    rho, phi, ring = np.hypot(X[:, 0], X[:, 1]), np.arctan2(X[:, 1], X[:, 0]), np.arange(len(x)) % m
    amps = np.zeros(kmax + 1)
    for j in range(m):
        r, p = rho[ring == j], phi[ring == j]
        for k in range(kmax + 1):
            amps[k] = max(amps[k], abs((r * np.exp(-1j * k * p)).mean()) / r.mean())
    return amps, X


if __name__ == '__main__':
    x = np.array([list(map(float, l.split()[1:4])) for l in open(sys.argv[1]) if l.startswith('v ')])
    amps, X = ring_amplitudes(x, int(sys.argv[2]))
    print(sys.argv[1], 'max over rings of |rho_k|/rho_0, k=0..8:', ' '.join('%.1e' % a for a in amps), ' z-extent %.3f' % (X[:, 2].max() - X[:, 2].min()))
