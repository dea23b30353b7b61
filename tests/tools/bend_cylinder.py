#!/usr/bin/env python3
"""Bend a cylinder about the y axis: its axis (z, from zmin to zmax) becomes a circular arc turning by ANGLE degrees,
so the top end's cross-section is tilted by ANGLE and the bottom end is unchanged (its neighbourhood too, to first
order). The target of options/conformal_fig14_bend.opts (crane2013 Fig. 14 top): its top binormals are the input's
rotated by ANGLE about y. Same vertices and faces, in the same order.
  bend_cylinder.py IN.obj OUT.obj ANGLE"""
import math
import sys

src, dst, angle = sys.argv[1], sys.argv[2], math.radians(float(sys.argv[3]))
lines = open(src).read().splitlines()
zs = [float(l.split()[3]) for l in lines if l.startswith("v ")]
z0, h = min(zs), max(zs) - min(zs)
R = h / angle  # the arc's radius: the axis keeps its length
with open(dst, "w") as out:
    for l in lines:
        if l.startswith("v "):
            x, y, z = (float(t) for t in l.split()[1:4])
            phi = (z - z0) / R
            l = "v %.17g %.17g %.17g" % (R - (R - x) * math.cos(phi), y, z0 + (R - x) * math.sin(phi))
        out.write(l + "\n")
