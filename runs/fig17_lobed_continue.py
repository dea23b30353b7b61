#!/usr/bin/python3
"""Natural continuation in the class b of an n = 2 lobed constrained Willmore torus (soliman2021 Fig. 17, issue 39):
  runs/fig17_lobed_continue.py N M START.obj OUTDIR B1 B2 ... [--homog] [--secant] [--wave A] [--from N0xM0] [--mix H.obj,LAM]
  runs/fig17_lobed_continue.py --check MESH.obj N M      (the amplitude and 2-fold error of one N x M result)
START.obj: a torus on the -gen lattice grid N x M (vertex (i, j) = i M + j, i around the axis), e.g. a result of
options/newton_fig17_lobed_n2.opts; or "gen" with --wave A: the homogeneous torus of the first class B1 with
-gen_deform_nfold 2,A. For each class b = Bk in turn (rectangular lattice tau = i/b): its edge lengths by
runs/fig17_lengths.py, then Newton on the KKT system (-flow_type newton -flow_conformal, Moebius and area rows) from
the previous converged result (--secant: the secant predictor through the last two results instead), serially at nice 10 with a 900 s timeout. One line per class: b, W, iterations,
EL_scaled, class, the 2-lobe amplitude (largest over the rings of |rho_2|/rho_0, rho the distance from the axis),
the 2-fold error by index (vertex (i, j) rotated by pi about the axis against (i + N/2, j), over the RMS radius);
--from N0xM0: START is on an N0 x M0 grid, resampled to N x M by its trigonometric interpolant (runs/fig17_regrid.py). --mix H.obj,LAM:
the start is H + LAM (START - H), both centred and scaled to RMS radius 1 (H a homogeneous torus: a step in the lobe
amplitude at a fixed class, to reach another sheet). "stalled" at EL_scaled < 1e-8 counts as converged.
--homog adds W of the homogeneous torus of the class (Newton from the unperturbed -gen lattice torus,
EL_scaled 1e-6 or 20 iterations: its tail is linear, a saddle above the branch point).
Results: OUTDIR/b<b>.{obj,json,log}. Needs numpy. Numbers: docs/triangle_fields.md "Fig. 17"."""
import json, os, subprocess, sys
import numpy as np
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'scripts'))
import objio  # noqa: E402
from fig17_modes import ring_amplitudes  # noqa: E402
from fig17_regrid import resample  # runs/fig17_regrid.py: the one trigonometric interpolant of a lattice grid

HERE = os.path.dirname(os.path.abspath(__file__))
BIN = os.path.join(HERE, '..', 'bin', 'confsurf')
NEWTON = ['-task', 'flow', '-flow_type', 'newton', '-flow_conformal', '-flow_constraint_mobius',
          '-flow_constraint_area', '-flow_max_it', '40', '-flow_rtol', '1e-9']


def read_obj(path):
    """vertices as an array and faces as 0-based index lists (scripts/objio.py, the project's OBJ reader)"""
    v, f = objio.read_obj(path)
    return np.array(v), f


def write_obj(path, v, faces):
    with open(path, 'w') as f:
        f.write(''.join('v %.17g %.17g %.17g\n' % tuple(p) for p in v))
        f.write(''.join('f %d %d %d\n' % (a + 1, b + 1, c + 1) for a, b, c in faces))


def unit(v):
    x = v - v.mean(0)
    return x / np.sqrt((x * x).sum(1).mean())


def lattice_faces(n, m, start, grid):
    """The faces of START, or with --from those of the -gen lattice grid n x m (written once by the generator)."""
    if not grid:
        return read_obj(start)[1]
    tmp = '/tmp/fig17_faces_%dx%d.obj' % (n, m)
    subprocess.run([BIN, '-task', 'info', '-gen', 'lattice', '-gen_n', str(n), '-gen_m', str(m), '-o', tmp], stdout=subprocess.DEVNULL)
    return read_obj(tmp)[1]


def lobes(v, n, m):
    """(largest |rho_2|/rho_0 over the rings, 2-fold error by index over the RMS radius) about the principal axis."""
    amps, x = ring_amplitudes(v, m, 2)  # runs/fig17_modes.py
    amp = amps[2]
    g = x.reshape(n, m, 3)
    rot = g * np.array([-1.0, -1.0, 1.0])  # rotation by pi about z
    err = np.sqrt(((rot - np.roll(g, -n // 2, axis=0)) ** 2).sum(2)).max() / np.sqrt((x * x).sum(1).mean())
    return amp, err


def newton(args, out, log):
    cmd = ['nice', '-n', '10', 'timeout', '900', BIN] + NEWTON + args + ['-summary', out + '.json', '-o', out + '.obj']
    with open(log, 'w') as f:
        subprocess.run(cmd, stdout=f, stderr=subprocess.STDOUT)
    return json.load(open(out + '.json')) if os.path.exists(out + '.json') else None


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    if sys.argv[1] == '--check':  # --check MESH.obj N M: the lobe amplitude and the 2-fold error by index only
        amp, err = lobes(read_obj(sys.argv[2])[0], int(sys.argv[3]), int(sys.argv[4]))
        print('%s: 2-lobe amplitude |rho_2|/rho_0 %.4e, 2-fold error by index %.1e (of the RMS radius)' % (sys.argv[2], amp, err))
        return
    argv = [a for a in sys.argv[1:] if not a.startswith('--')]
    flags = sys.argv[1:]
    opt = lambda k: flags[flags.index(k) + 1] if k in flags else None
    wave, mix, grid = opt('--wave'), opt('--mix'), opt('--from')
    for o in (wave, mix, grid):
        if o: argv.remove(o)
    n, m, start, outdir, bs = int(argv[0]), int(argv[1]), argv[2], argv[3], [float(b) for b in argv[4:]]
    os.makedirs(outdir, exist_ok=True)
    hist = []  # (b, vertices) of the converged results, for the secant predictor
    if start != 'gen':
        x0 = read_obj(start)[0]
        if grid:  # a start on another N0 x M0 grid: its trigonometric interpolant on N x M
            n0, m0 = (int(k) for k in grid.split('x'))
            x0 = resample(resample(x0.reshape(n0, m0, 3), n, 0), m, 1).reshape(-1, 3)
        if mix:  # the homogeneous torus H plus LAM times (start - H), both centred and scaled to RMS radius 1
            h, lam = mix.split(',')
            h, x0 = unit(read_obj(h)[0]), unit(x0)
            x0 = h + float(lam) * (x0 - h)
        hist.append((None, x0))
        faces = lattice_faces(n, m, start, grid)
    print('# %d x %d from %s%s' % (n, m, start, ' wave ' + wave if wave else ''))
    print('# b          W               its  EL_scaled class     |rho2|/rho0  2-fold err  stop%s' % ('  W homogeneous' if '--homog' in flags else ''))
    for b in bs:
        tau = '0,%.17g' % (1 / b)
        out = os.path.join(outdir, 'b%.4f' % b)
        if start == 'gen' and not hist:
            s = newton(['-gen', 'lattice', '-gen_tau', tau, '-gen_n', str(n), '-gen_m', str(m), '-gen_deform_nfold', '2,' + wave], out, out + '.log')
            faces = read_obj(out + '.obj')[1] if s else None
        else:
            x0 = hist[-1][1]
            if '--secant' in flags and len(hist) >= 2 and None not in (hist[-1][0], hist[-2][0]) and hist[-1][0] != hist[-2][0]:
                x0 = x0 + (b - hist[-1][0]) / (hist[-1][0] - hist[-2][0]) * (x0 - hist[-2][1])
            write_obj(out + '.start.obj', x0, faces)
            subprocess.run(['/usr/bin/python3', os.path.join(HERE, 'fig17_lengths.py'), str(n), str(m), tau, out + '.start.obj', out + '.len'], check=True)
            s = newton(['-mesh', out + '.start.obj', '-mesh_lengths', out + '.len'], out, out + '.log')
        if not s:
            print('%.4f  no summary (see %s.log)' % (b, out)); break
        v = read_obj(out + '.obj')[0]
        amp, err = lobes(v, n, m)
        line = '%.4f  %.10f  %3d  %.1e  %.1e  %.4e   %.1e     %s' % (b, s['willmore'], s['iterations'], s['el_residual_scaled'], s['conformal_violation'], amp, err, s['stop_reason'])
        if '--homog' in flags:
            h = newton(['-gen', 'lattice', '-gen_tau', tau, '-gen_n', str(n), '-gen_m', str(m), '-flow_rtol', '1e-6', '-flow_max_it', '20'], out + '.homog', out + '.homog.log')
            line += '  %.10f' % h['willmore'] if h else '  -'
        print(line, flush=True)
        if not s['converged'] and s['el_residual_scaled'] > 1e-8:  # 'stalled' at round-off counts as converged
            break
        hist.append((b, v))


main()
