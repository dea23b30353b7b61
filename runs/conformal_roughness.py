#!/usr/bin/env python3
"""Where the conformal flow's per-step decrease goes on a scanned mesh (issue 13, docs/conformal_flow.md "The bunny").
Reads a ParaView series written by -flow_type conformal with -viewer_dir DIR -flow_viewer_every 1 (serial run: the
piece files surface_NNNN_0.vtu, fields rho_dot and H) and prints per step:
  |v| (= sqrt(sum A v^2), barycentric A) split into a smooth part (two passes of s <- (s + mean over the 1-ring)/2)
  and the rough (vertex-scale) rest; the relative radial deviation from the least-squares sphere; the Eq. 28 W of
  the vertices projected radially onto that sphere (the floor of the triangulation's round image).
  python3 runs/conformal_roughness.py DIR
With two directories (a state and one small step from it, -flow_keep_area false): the response of the curvature
to the smooth and the rough part of rho = tau v, dH ~ a_s rho_s + a_r rho_r - g (area-weighted least squares):
  python3 runs/conformal_roughness.py --response DIR TAU"""
import re, sys, glob
import numpy as np

def read_vtu(fn):
    b = open(fn, 'rb').read()
    i = b.index(b'<AppendedData encoding="raw">'); j = b.index(b'_', i) + 1
    hdr, out = b[:i].decode(), {}
    for m in re.finditer(r'<DataArray type="(\w+)" Name="(\w+)" NumberOfComponents="(\d+)" format="appended" offset="(\d+)"', hdr):
        t, name, nc, off = m.group(1), m.group(2), int(m.group(3)), int(m.group(4))
        n = int(np.frombuffer(b[j + off:j + off + 8], np.uint64)[0])
        a = np.frombuffer(b[j + off + 8:j + off + 8 + n], {'Float64': np.float64, 'Int32': np.int32, 'UInt8': np.uint8}[t])
        out[name] = a.reshape(-1, nc) if nc > 1 else a
    out['faces'] = out['connectivity'].reshape(-1, 3)
    return out

def vertex_areas(P, F):
    a = 0.5 * np.linalg.norm(np.cross(P[F[:, 1]] - P[F[:, 0]], P[F[:, 2]] - P[F[:, 0]]), axis=1)
    A = np.zeros(len(P))
    for k in range(3): np.add.at(A, F[:, k], a / 3)
    return A

def smooth(v, F, passes=2):
    e = np.r_[F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]]; e = np.r_[e, e[:, ::-1]]
    e = np.unique(e, axis=0); deg = np.bincount(e[:, 0], minlength=len(v))
    s = v.copy()
    for _ in range(passes):
        m = np.zeros_like(s); np.add.at(m, e[:, 0], s[e[:, 1]]); s = 0.5 * s + 0.5 * m / deg
    return s

def willmore_eq28(P, F):  # soliman2021 Eq. 28: sum |L f|^2 / (4 A_i), barycentric A_i, cotan L
    Lf = np.zeros_like(P)
    for k in range(3):
        i, j, l = F[:, k], F[:, (k + 1) % 3], F[:, (k + 2) % 3]
        a, b = P[j] - P[i], P[l] - P[i]
        w = 0.5 * (a * b).sum(1) / np.linalg.norm(np.cross(a, b), axis=1)
        d = P[j] - P[l]; np.add.at(Lf, j, w[:, None] * d); np.add.at(Lf, l, -w[:, None] * d)
    return ((Lf * Lf).sum(1) / (4 * vertex_areas(P, F))).sum()

def sphere(P):
    s = np.linalg.lstsq(np.c_[2 * P, np.ones(len(P))], (P * P).sum(1), rcond=None)[0]
    return s[:3], np.sqrt(s[3] + s[:3] @ s[:3])

def series(d):
    fs = sorted(glob.glob(d + '/surface_*_0.vtu'))
    print('step  |v|  smooth  rough   radial dev (mean, max) / r   W/4pi of the radial projection (Eq. 28)')
    for k, fn in enumerate(fs):
        S = read_vtu(fn); P, F, v = S['positions'], S['faces'], S['rho_dot']
        A = vertex_areas(P, F); n = lambda x: np.sqrt((A * x * x).sum()); s = smooth(v, F)
        c, r = sphere(P); d = np.linalg.norm(P - c, axis=1) - r
        Q = c + (P - c) * (r / np.linalg.norm(P - c, axis=1))[:, None]
        print(f'{k:3d} {n(v):7.3f} {n(s):7.3f} {n(v - s):7.3f}   {np.abs(d).mean() / r:.2e} {np.abs(d).max() / r:.2e}   {willmore_eq28(Q, F) / 4 / np.pi:.4f}')

def response(d, tau):
    S0, S1 = [read_vtu(d + f'/surface_{k:04d}_0.vtu') for k in (0, 1)]
    F = S0['faces']; A = vertex_areas(S0['positions'], F); w = np.sqrt(A)
    rho = tau * S0['rho_dot']; rs = smooth(rho, F); dH = S1['H'] - S0['H']
    a = np.linalg.lstsq(np.c_[rs * w, (rho - rs) * w, -w], dH * w, rcond=None)[0]
    n = lambda x: np.sqrt((A * x * x).sum())
    print(f'rough share of |rho| {n(rho - rs) / n(rho):.3f}; response of H: smooth part {a[0]:.3f}, rough part {a[1]:.3f} (1 = the smooth theory)')

if __name__ == '__main__':
    if sys.argv[1] == '--response': response(sys.argv[2], float(sys.argv[3]))
    else: series(sys.argv[1])
