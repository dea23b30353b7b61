#!/usr/bin/env python3
"""Where a stalled flow still moves (runs/study_vesicle.sh): between the last two steps of a serial ParaView
series, the displacement and the EL residual split into normal and tangential parts (area-weighted vertex
normals), the part of the displacement that is a rigid motion, and the per-iteration slopes of W, the EL
residual and the vertex-area spread from the history.
  /usr/bin/python3 runs/vesicle_drift.py SERIES.pvd HISTORY.csv"""
import csv
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "scripts"))
import vtu  # noqa: E402


def step(path):
    p = vtu.read_pvtu(path)[0]  # one piece: a serial run
    X = np.array(p["arrays"]["Points"]["positions"][1]).reshape(-1, 3)
    C = np.array(p["arrays"]["Cells"]["connectivity"][1]).reshape(-1, 3)
    r = np.array(p["arrays"]["PointData"]["el_residual"][1]).reshape(-1, 3)
    return X, C, r


def normals(X, C):
    n = np.cross(X[C[:, 1]] - X[C[:, 0]], X[C[:, 2]] - X[C[:, 0]])
    N = np.zeros_like(X)
    for k in range(3):
        np.add.at(N, C[:, k], n)
    return N / np.linalg.norm(N, axis=1)[:, None]


def split(v, N):
    vn = np.einsum("ij,ij->i", v, N)[:, None] * N
    return np.linalg.norm(vn), np.linalg.norm(v - vn)


def rigid_part(X0, X1):
    """|X1 - (R X0 + t)| for the best rotation R and translation t (Kabsch), and the angle of R in degrees."""
    c0, c1 = X0.mean(0), X1.mean(0)
    U, _, Vt = np.linalg.svd((X0 - c0).T @ (X1 - c1))
    d = np.sign(np.linalg.det(Vt.T @ U.T))
    R = Vt.T @ np.diag([1, 1, d]) @ U.T
    ang = np.degrees(np.arccos(np.clip((np.trace(R) - 1) / 2, -1, 1)))
    return np.linalg.norm(X1 - ((X0 - c0) @ R.T + c1)), ang


def main():
    steps = vtu.read_pvd(sys.argv[1])
    (t0, p0), (t1, p1) = steps[-2], steps[-1]
    X0, C, _ = step(p0)
    X1, _, r = step(p1)
    N = normals(X1, C)
    dn, dt = split(X1 - X0, N)
    rn, rt = split(r, N)
    print("steps %g -> %g: displacement normal %.3e tangential %.3e (tangential share %.0f %%)" % (t0, t1, dn, dt, 100 * dt ** 2 / (dn ** 2 + dt ** 2)))
    print("EL residual at %g: |r| %.3e, normal %.3e, tangential %.3e (tangential share %.0f %%)" % (t1, np.linalg.norm(r), rn, rt, 100 * rt ** 2 / (rn ** 2 + rt ** 2)))
    rigid, ang = rigid_part(X0, X1)
    print("displacement after the best rigid motion (Kabsch): %.3e of %.3e (rigid share %.0f %%), rotation %.4f deg" % (rigid, np.linalg.norm(X1 - X0), 100 * (1 - rigid ** 2 / np.linalg.norm(X1 - X0) ** 2), ang))
    print("inertia eigenvalues (nearly equal pairs: a nearly axisymmetric shape):", np.linalg.eigvalsh(np.cov((X1 - X1.mean(0)).T)))
    rows = list(csv.DictReader(open(sys.argv[2])))
    a, b = rows[int(t0)], rows[-1]
    n = int(b["it"]) - int(a["it"])
    for k in ("energy", "el_residual", "area_spread", "q_max"):
        print("%-12s %.10g -> %.10g over %d iterations (%+.3e per iteration)" % (k, float(a[k]), float(b[k]), n, (float(b[k]) - float(a[k])) / n))


if __name__ == "__main__":
    main()
