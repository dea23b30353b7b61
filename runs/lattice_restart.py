#!/usr/bin/python3
"""Hand restarts for the tau = i lattice (issue 15, Fig. 16 experiments), for a mesh with the vertex and face order
of `-gen lattice -gen_tau 0,1 -gen_n N -gen_m N` (vertex (i, j) = i m + j):
  lengths N in.obj out.txt        the lattice's flat edge lengths per face of in.obj (opposite corners 0, 1, 2),
                                  for -mesh_lengths: the class c0 of -gen lattice on a mesh read from a file;
  smooth N in.obj out.obj a K s   in.obj displaced by a smooth random field: sum over |k|, |l| <= K of random
                                  vectors times cos/sin(2 pi (k i + l j) / N), scaled to a x the mean edge length;
  revolution N in.obj out.obj R r the torus of revolution with radii R, r on in.obj's faces, vertex (i, j) at the
                                  angles 2 pi i / N (about the axis) and 2 pi j / N (about the tube): a torus of
                                  another class (R / r != sqrt 2) for -mesh out.obj -mesh_lengths (the lattice's)."""
import sys
import numpy as np


def read(path):
    L = open(path).read().splitlines()
    x = np.array([[float(t) for t in l.split()[1:4]] for l in L if l.startswith('v ')])
    f = np.array([[int(t.split('/')[0]) - 1 for t in l.split()[1:4]] for l in L if l.startswith('f ')])
    return x, f


cmd, N = sys.argv[1], int(sys.argv[2])
x, f = read(sys.argv[3])
if cmd == 'lengths':
    step = lambda a, b: (b - a + N + 1) % N - 1
    out = []
    for t in f:
        z = [complex(step(t[0] // N, t[k] // N) / N, step(t[0] % N, t[k] % N) / N) for k in range(3)]
        out.append(' '.join('%.17g' % abs(z[(k + 2) % 3] - z[(k + 1) % 3]) for k in range(3)))
    open(sys.argv[4], 'w').write('\n'.join(out) + '\n')
elif cmd == 'revolution':
    R, r = float(sys.argv[5]), float(sys.argv[6])
    u, v = 2 * np.pi * (np.arange(len(x)) // N) / N, 2 * np.pi * (np.arange(len(x)) % N) / N
    x = np.stack([(R + r * np.cos(v)) * np.cos(u), (R + r * np.cos(v)) * np.sin(u), r * np.sin(v)], axis=1)
    with open(sys.argv[4], 'w') as o:
        o.write(''.join('v %.17g %.17g %.17g\n' % tuple(p) for p in x) + ''.join('f %d %d %d\n' % tuple(t + 1) for t in f))
else:
    a, K, s = float(sys.argv[5]), int(sys.argv[6]), int(sys.argv[7])
    rng = np.random.default_rng(s)
    i, j = np.arange(len(x)) // N, np.arange(len(x)) % N
    d = np.zeros_like(x)
    for k in range(-K, K + 1):
        for l in range(-K, K + 1):
            ph = 2 * np.pi * (k * i + l * j) / N
            d += np.outer(np.cos(ph), rng.normal(size=3)) + np.outer(np.sin(ph), rng.normal(size=3))
    h = np.mean([np.linalg.norm(x[t[0]] - x[t[1]]) for t in f])
    x = x + a * h * d / np.abs(d).max()
    with open(sys.argv[4], 'w') as o:
        o.write(''.join('v %.17g %.17g %.17g\n' % tuple(p) for p in x) + ''.join('f %d %d %d\n' % tuple(t + 1) for t in f))
