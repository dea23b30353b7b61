#!/usr/bin/env python3
"""n-fold symmetry error about the z axis at every step of a flow's ParaView series (Fig. 17 of soliman2021, issue 39).

  python3 runs/nfold_history.py DIR/series.pvd N [OUT.csv]

Run the flow with -viewer_dir DIR -flow_viewer_every 1. Per step: centre = the vertex centroid's (x, y) (z is free),
the vertex set rotated by 2 pi / N about the vertical line through it, error = the largest distance from a rotated
vertex to the nearest vertex, over the RMS distance from the centroid; also the centroid's distance from the z axis
(a symmetric flow keeps it 0). A symmetric mesh on an N-fold symmetric grid gives round-off; a broken symmetry gives
O(displacement). Unlike runs/nfold_symmetry.py (axis = principal axis, numpy) this fixes the axis to z: the
generator's axis, so a tilt counts as an error. Standard library only (scripts/vtu.py); every rank's piece is read."""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'scripts'))
import vtu  # noqa: E402


def points(pvtu):
    P = []
    for piece in vtu.read_pvtu(pvtu):
        c = piece["arrays"]["Points"]
        (ncomp, vals), = c.values()
        P += [tuple(vals[3 * i:3 * i + 3]) for i in range(len(vals) // 3)]
    # pieces share their interface vertices: drop exact duplicates
    return sorted(set(P))


def nfold_error(P, n):
    """largest distance of a rotated vertex to the nearest vertex / RMS radius; and the centroid's distance from z"""
    m = len(P)
    cx = sum(p[0] for p in P) / m
    cy = sum(p[1] for p in P) / m
    cz = sum(p[2] for p in P) / m
    X = [(p[0] - cx, p[1] - cy, p[2]) for p in P]
    c, s = math.cos(2 * math.pi / n), math.sin(2 * math.pi / n)
    worst = 0.0
    for x, y, z in X:
        rx, ry = c * x - s * y, s * x + c * y
        worst = max(worst, min((rx - a) ** 2 + (ry - b) ** 2 + (z - w) ** 2 for a, b, w in X))
    rms = math.sqrt(sum(x * x + y * y + (z - cz) ** 2 for x, y, z in X) / m)
    return math.sqrt(worst) / rms, math.hypot(cx, cy) / rms


def main():
    pvd, n = sys.argv[1], int(sys.argv[2])
    out = open(sys.argv[3], "w") if len(sys.argv) > 3 else None
    if out:
        out.write("step,time,nfold_error,axis_offset\n")
    top = 0.0
    for k, (t, path) in enumerate(vtu.read_pvd(pvd)):
        e, off = nfold_error(points(path), n)
        top = max(top, e)
        if out:
            out.write("%d,%g,%.6e,%.6e\n" % (k, t, e, off))
        print("step %4d time %-6g %d-fold error %.3e axis offset %.3e" % (k, t, n, e, off))
    print("largest %d-fold error over the series: %.3e" % (n, top))


if __name__ == "__main__":
    main()
