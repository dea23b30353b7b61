#!/usr/bin/env python3
"""Projects the vertices of an OBJ to the unit sphere and bumps the northern hemisphere only:
r = 1 + A max(z, 0) sin(k x) sin(k y) sin(k z) (A = 0.25, k = 7): rounding it takes area from the north, an
imbalance a Moebius map can undo (crane2013 App. E). Used by tests/cases/conformal_mobius.sh."""
import math, sys
src, dst = sys.argv[1], sys.argv[2]
out = []
for l in open(src).read().splitlines():
    if l.startswith('v '):
        x, y, z = map(float, l.split()[1:4]); r = math.sqrt(x * x + y * y + z * z); x, y, z = x / r, y / r, z / r
        f = 1 + 0.25 * max(z, 0) * math.sin(7 * x) * math.sin(7 * y) * math.sin(7 * z)
        out.append('v %.17g %.17g %.17g' % (x * f, y * f, z * f))
    else:
        out.append(l)
open(dst, 'w').write('\n'.join(out) + '\n')
