#!/usr/bin/python3
"""Is a surface a Moebius image of another with the same vertices (issue 15, Fig. 16: "a Clifford torus up to
Moebius transformations")?  For K random quadruples (a, b, c, d) of vertices the two absolute cross ratios
|a-b||c-d| / (|a-c||b-d|) and |a-d||b-c| / (|a-c||b-d|) are invariant under every Moebius transformation of R^3;
this prints the largest and the rms relative difference of them between the two OBJ files (0 iff Moebius
equivalent, on the sampled quadruples). Usage: clifford_mobius_check.py reference.obj result.obj [K]."""
import sys
import numpy as np


def verts(path):
    return np.array([[float(t) for t in l.split()[1:4]] for l in open(path) if l.startswith('v ')])


def ratios(x, q):
    d = lambda i, j: np.linalg.norm(x[q[:, i]] - x[q[:, j]], axis=1)
    den = d(0, 2) * d(1, 3)
    return np.concatenate([d(0, 1) * d(2, 3) / den, d(0, 3) * d(1, 2) / den])


a, b = verts(sys.argv[1]), verts(sys.argv[2])
assert a.shape == b.shape, "different vertex counts"
K = int(sys.argv[3]) if len(sys.argv) > 3 else 20000
rng = np.random.default_rng(1)
q = np.array([rng.choice(len(a), 4, replace=False) for _ in range(K)])
ra, rb = ratios(a, q), ratios(b, q)
rel = np.abs(rb - ra) / ra
print("vertices %d quadruples %d: cross-ratio relative difference max %.3e rms %.3e" % (len(a), K, rel.max(), np.sqrt(np.mean(rel**2))))
