#!/usr/bin/env python3
"""An irregular bumpy sphere from an icosphere OBJ: every vertex moved by a seeded uniform random vector of up to
J h per coordinate (h = 0.06, the edge length at level 5; J = 0.2), projected to the unit sphere, then bumped
radially by 1 + A sin(k x) sin(k y) sin(k z) (A = 0.01, k = 6). Used by tests/cases/conformal_stability_fine.sh.
Optional third and fourth arguments: h and k (conformal_stability.sh: h = 0.03, the level-6 edge, and k = 9)."""
import math, random, sys
src, dst = sys.argv[1], sys.argv[2]
random.seed(1)
J, h, A, k = 0.2, 0.06, 0.01, 6
if len(sys.argv) > 3: h, k = float(sys.argv[3]), float(sys.argv[4])
out = []
for l in open(src).read().splitlines():
    if l.startswith('v '):
        x, y, z = (float(c) + random.uniform(-J, J) * h for c in l.split()[1:4])
        r = math.sqrt(x * x + y * y + z * z); x, y, z = x / r, y / r, z / r
        f = 1 + A * math.sin(k * x) * math.sin(k * y) * math.sin(k * z)
        out.append('v %.17g %.17g %.17g' % (x * f, y * f, z * f))
    else:
        out.append(l)
open(dst, 'w').write('\n'.join(out) + '\n')
