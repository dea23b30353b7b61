#!/usr/bin/python3
"""A torus on the N x M lattice grid moved to an N2 x M2 grid of the same class by trigonometric interpolation
(soliman2021 Fig. 17, issue 39: the refinement check of the lobed tori, a start for Newton on the finer or coarser grid).
  runs/fig17_regrid.py N M in.obj N2 M2 template.obj out.obj
in.obj: vertex (i, j) = i M + j (an OBJ written by a run on -gen lattice -gen_n N -gen_m M, or restarted from one);
template.obj: any OBJ of -gen lattice -gen_n N2 -gen_m M2 (its faces and texture lines are kept, its v lines replaced).
The positions are periodic in (i, j); their discrete Fourier series is truncated or zero-padded to N2 x M2 (an even
size's Nyquist term split in two), so a smooth surface moves to the new grid with a spectrally small error. The class
is then that of the new grid's lattice: restart with runs/fig17_lengths.py N2 M2 ... and -mesh_lengths. Needs numpy."""
import sys
import numpy as np


def resample(a, n2, axis):
    """Trigonometric interpolation of the periodic samples a along axis to n2 samples."""
    n = a.shape[axis]
    A = np.moveaxis(np.fft.fft(a, axis=axis), axis, 0)
    B = np.zeros((n2,) + A.shape[1:], complex)
    k = min(n, n2)
    h = (k - 1) // 2  # the frequencies -h..h both grids hold
    B[:h + 1], B[n2 - h:] = A[:h + 1], A[n - h:]
    if k % 2 == 0:  # the Nyquist term of the smaller grid: split (up) or folded (down)
        nyq = A[n // 2] if n == k else A[k // 2] + A[n - k // 2]
        B[k // 2] += nyq / 2 if n2 > k else nyq
        if n2 > k:
            B[n2 - k // 2] += nyq / 2
    return np.moveaxis(np.fft.ifft(B, axis=0), 0, axis).real * n2 / n


def main():
    n, m, src, n2, m2, tmpl, out = sys.argv[1:8]
    n, m, n2, m2 = int(n), int(m), int(n2), int(m2)
    x = np.array([[float(t) for t in l.split()[1:4]] for l in open(src) if l.startswith('v ')])
    assert len(x) == n * m, "%s has %d vertices, not N M = %d" % (src, len(x), n * m)
    y = resample(resample(x.reshape(n, m, 3), n2, 0), m2, 1).reshape(-1, 3)
    lines = open(tmpl).read().splitlines()
    assert sum(l.startswith('v ') for l in lines) == n2 * m2, "%s is not an N2 x M2 grid" % tmpl
    it = iter(y)
    with open(out, 'w') as f:
        for l in lines:
            f.write(('v %.17g %.17g %.17g' % tuple(next(it))) if l.startswith('v ') else l)
            f.write('\n')


if __name__ == '__main__':
    main()
