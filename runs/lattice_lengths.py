#!/usr/bin/env python3
"""An irregular mesh of a twisted conformal class (issue 35 torus sweep, docs/real_meshes.md "Issue 35").
-gen lattice gives a twisted class tau only on its structured n x m grid. This script takes any triangulation of
the stereographic flat torus of class i*IM (-gen flattorus -gen_tau_im IM, e.g. remeshed: its vertices lie on
the image of {(r1 e^{ia}, r2 e^{ib})} c S^3, r2/r1 = IM, src/mesh/meshdata_generate.c FlatTorusPositions),
recovers each vertex's angles (a, b), places it at z = a/2pi + (b/2pi) tau in C/(Z + tau Z) and writes the flat
lengths of every face's edges (per face the edges opposite corners 0, 1, 2: the -mesh_lengths format). The flow
then starts from the mesh's positions (class i*IM) and targets the lattice tau on the same irregular
connectivity, as -gen lattice does on its grid.
  usage: runs/lattice_lengths.py mesh.obj IM RE,IMtau out.len"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'scripts'))
import objio  # noqa: E402  (scripts/objio.py, the project's OBJ reader)


def main():
    path, im, tau, out = sys.argv[1], float(sys.argv[2]), sys.argv[3], sys.argv[4]
    tre, tim = (float(s) for s in tau.split(','))
    V, F = objio.read_obj(path)
    X, F = np.array(V), np.array(F)
    r1 = 1 / np.sqrt(1 + im * im)
    r2 = im * r1
    rho = np.hypot(X[:, 0], X[:, 1])
    s = rho / r1                                  # s = 1 / (1 - r2 sin b)
    a = np.arctan2(X[:, 1], X[:, 0]) / (2 * np.pi)
    b = np.arctan2((1 - 1 / s) / r2, X[:, 2] / (s * r2)) / (2 * np.pi)
    resid = np.abs(np.hypot((1 - 1 / s) / r2, X[:, 2] / (s * r2)) - 1).max()
    print("largest |(sin b, cos b)| - 1 over the vertices: %.2e (the mesh must lie on the flat torus of class %g i)" % (resid, im))
    with open(out, 'w') as f:
        for t in F:
            du = a[t] - a[t[0]]
            dv = b[t] - b[t[0]]
            du -= np.round(du)
            dv -= np.round(dv)
            z = du + tre * dv + 1j * tim * dv
            for k in range(3):
                f.write("%.17g\n" % abs(z[(k + 2) % 3] - z[(k + 1) % 3]))


if __name__ == "__main__":
    main()
