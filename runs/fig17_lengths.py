#!/usr/bin/python3
"""The class of `-gen lattice -gen_tau RE,IM -gen_n N -gen_m M` as a -mesh_lengths file, for a mesh read back with
that vertex and face order (an OBJ written by a run on -gen lattice): per face, the flat lattice lengths of the
edges opposite corners 0, 1, 2 (vertex (i, j) = i M + j at i/N + j tau/M, src/mesh/meshdata_generate.c
CSMeshDataLattice). Used by runs/fig17_nfold.sh to restart the Fig. 17 tori in their exact class.
  usage: runs/fig17_lengths.py N M RE,IM in.obj out.txt"""
import sys


def main():
    n, m = int(sys.argv[1]), int(sys.argv[2])
    tre, tim = (float(s) for s in sys.argv[3].split(','))
    faces = [[int(t.split('/')[0]) - 1 for t in l.split()[1:4]] for l in open(sys.argv[4]) if l.startswith('f ')]
    step = lambda a, b, k: (b - a + k + 1) % k - 1  # the grid step from a to b, in {-1, 0, 1}
    out = []
    for t in faces:
        z = [complex(step(t[0] // m, v // m, n) / n + step(t[0] % m, v % m, m) * tre / m,
                     step(t[0] % m, v % m, m) * tim / m) for v in t]
        out.append(' '.join('%.17g' % abs(z[(k + 2) % 3] - z[(k + 1) % 3]) for k in range(3)))
    open(sys.argv[5], 'w').write('\n'.join(out) + '\n')


main()
