#!/usr/bin/env python3
"""A torus in a twisted conformal class, for the issue 35 torus sweep (runs/torus_sweep.sh): an elliptic tube
(semi-axes A radial, B vertical) about the circle of radius R in the xy-plane whose ellipse turns once about the
tube's centre line while going once around the axis. The surface has no mirror symmetry in a plane through the
axis (it is chiral), so nothing forces Re tau = 0: its class is twisted (tau not computed; a tube estimate,
runs/knot1_class_estimate.py, gives Im tau ~ 4.3 for the defaults). Written as an N x M grid OBJ, meant to be
remeshed (-mesh_remesh) before a flow.
  usage: runs/chiral_torus.py OUT.obj [R A B N M]   (defaults 2.5 1.0 0.55 200 80)"""
import sys

import numpy as np


def main():
    out = sys.argv[1]
    R, a, b = (float(x) for x in (sys.argv[2:5] if len(sys.argv) > 4 else (2.5, 1.0, 0.55)))
    n, m = (int(x) for x in (sys.argv[5:7] if len(sys.argv) > 6 else (200, 80)))
    with open(out, "w") as f:
        for i in range(n):
            p = 2 * np.pi * i / n
            for j in range(m):
                t = 2 * np.pi * j / m
                u, v = a * np.cos(t), b * np.sin(t)  # the ellipse, turned by p in the (radial, z) plane
                r, z = u * np.cos(p) - v * np.sin(p), u * np.sin(p) + v * np.cos(p)
                f.write("v %.15g %.15g %.15g\n" % ((R + r) * np.cos(p), (R + r) * np.sin(p), z))
        for i in range(n):
            for j in range(m):
                A, B = i * m + j, ((i + 1) % n) * m + j
                C, D = ((i + 1) % n) * m + (j + 1) % m, i * m + (j + 1) % m
                f.write("f %d %d %d\nf %d %d %d\n" % (A + 1, B + 1, C + 1, A + 1, C + 1, D + 1))


if __name__ == "__main__":
    main()
