#!/usr/bin/python3
"""The n-lobe amplitude at every step of a flow's ParaView series (soliman2021 Fig. 17, issue 39): where a small n-wave
on a homogeneous torus grows (the class is above the discrete branch point of the n-lobed tori) or decays (below).
  runs/fig17_mode_history.py DIR/series.pvd N
Per step: |rho_N| / rho_0 of the whole vertex set about the vertical line through the centroid (the generator's axis;
rho the distance from it, summed over the vertices: on an N-fold grid the rings of a torus of revolution give 0),
and the growth factor per step against the previous one. Serial series (one piece). Needs numpy (/usr/bin/python3)."""
import os
import sys
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'scripts'))
import vtu  # noqa: E402


def amplitude(P, n):
    P = np.unique(P, axis=0)  # the pieces repeat seam vertices
    X = P - P.mean(0)
    rho, phi = np.hypot(X[:, 0], X[:, 1]), np.arctan2(X[:, 1], X[:, 0])
    return abs((rho * np.exp(-1j * n * phi)).sum()) / rho.sum()


def main():
    pvd, n = sys.argv[1], int(sys.argv[2])
    prev = None
    for k, (t, path) in enumerate(vtu.read_pvd(pvd)):
        pieces = vtu.read_pvtu(path)
        assert len(pieces) == 1, "serial series only"
        (_, vals), = pieces[0]["arrays"]["Points"].values()
        a = amplitude(np.array(vals).reshape(-1, 3), n)
        print("step %4d |rho_%d|/rho_0 %.4e%s" % (k, n, a, "" if prev is None else "  x%.4f" % (a / prev)))
        prev = a


if __name__ == "__main__":
    main()
