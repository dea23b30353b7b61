#!/usr/bin/python3
"""Estimate the conformal class of a tube-shaped torus mesh (issue 21, Fig. 5; docs/real_meshes.md 0c).

A tube of radius r around a closed curve of length l is, up to O(r kappa), the flat cylinder of circumference
2 pi r and length l glued with a twist: tau = s + i l / (2 pi r) for some twist s, whose reduction to the modular
fundamental domain keeps Im tau when Im tau >> 1. r and l are read off the mesh by area A = 2 pi r l and enclosed
volume V = pi r^2 l (r = 2 V / A). The homogeneous torus of the rectangular class b = Im tau (a torus of revolution
with circular profile, R/r = sqrt(1 + b^2)) is a constrained Willmore surface with W = pi^2 (b + 1/b)
(Bohle-Peters-Pinkall 2008; W = 2 pi^2 at b = 1, the Clifford torus).

Usage: runs/knot1_class_estimate.py [mesh.obj ...]   (default: meshes/knot1_cgal.obj)"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'scripts'))
import objio  # noqa: E402  (scripts/objio.py, the project's OBJ reader)


def main(paths):
    print('| mesh | area A | volume V | tube radius r = 2V/A | length l = A/(2 pi r) | Im tau = l/(2 pi r) | W of the homogeneous torus pi^2 (b + 1/b) |')
    print('|---|---|---|---|---|---|---|')
    for path in paths:
        v, t = objio.read_obj(path, triangles_only=True)
        x, f = np.array(v), np.array(t)
        a, b, c = x[f[:, 0]], x[f[:, 1]], x[f[:, 2]]
        area = 0.5 * np.linalg.norm(np.cross(b - a, c - a), axis=1).sum()
        vol = np.einsum('ij,ij->i', a, np.cross(b, c)).sum() / 6.0
        r = 2.0 * vol / area
        length = area / (2.0 * math.pi * r)
        im_tau = length / (2.0 * math.pi * r)
        w_hom = math.pi ** 2 * (im_tau + 1.0 / im_tau)
        print(f'| {path} | {area:.4f} | {vol:.5f} | {r:.4f} | {length:.3f} | {im_tau:.2f} | {w_hom:.2f} |')


if __name__ == '__main__':
    main(sys.argv[1:] or ['meshes/knot1_cgal.obj'])
