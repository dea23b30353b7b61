#!/usr/bin/env python3
"""Makes the small meshes of issue 5 (bobenko-schroeder2005 Willmore flow) tests and experiments.
Run from the repository root after building: python3 tests/data/bs_make_meshes.py
  tests/data/bs_cap_flat.obj   icosphere level 3 cap (z > 0.1); the vertices off the boundary strip
                               (boundary + one-ring, the G1 data of Sec. 3.3) are pressed flat onto the
                               plane of the highest strip vertex: hole filling should give back the sphere.
  tests/data/bs_cap_noisy.obj  icosphere level 3 hemisphere (z > 0) with deterministic noise 0.02: a disk
                               for the free boundary (vertex at infinity) runs.
  tests/data/bs_bunny_hole.obj a disk cut from meshes/bunny_lowres_npm.obj around its highest-x vertex, the
                               part inside the boundary strip replaced by a membrane (uniform Laplacian)
                               fill: the "hole" of Fig. 10, filled C0 but not G1.
  tests/data/bs_torus_coarse2.obj  the generator's coarse torus (-gen torus -gen_n 8 -gen_m 4, R 1, r 0.4)
                               subdivided linearly (midpoints, no smoothing) twice: the input of Fig. 8.
  meshes/bs_fig9_pipe.obj      half of bs_torus_coarse2.obj (y >= 0: two boundary loops in the planes u = 0 and
                               u = pi), its boundary strip (boundary + one-ring, the G1 data) moved onto the torus
                               of revolution R 1, r 0.4, so the boundary loops are circles: the pipe of Fig. 9
                               ("in essence half the torus example with fixed boundaries").
  meshes/bs_fig10_hexhole.obj  a six-sided hole of the sphere through the cube's vertices (centre (1/2,1/2,1/2),
                               radius sqrt(3)/2) around the corner (0,0,0): the three faces of the unit cube at that
                               corner, each an n x n grid of squares split by one diagonal (every diamond inside a
                               face is co-circular, beta = 0, as the paper's Fig. 10 start "with many edges having
                               beta = 0"), the boundary strip projected radially onto the sphere (position and
                               tangency data of a smooth surface). An analogue of Fig. 10 (the paper's mesh, a
                               Loop-subdivision outline, is not published); the G1 minimiser is the sphere cap, W = 0.
  runs/results/bs_noisy_man.obj, bs_noisy_bunny.obj  man_cgal.obj / bunny_closed_cgal.obj (meshes/, else
                               ../shared/meshes) with normal noise of 0.3 x mean edge length: the scan-like
                               inputs of Fig. 12.
Deterministic (random.Random with fixed seeds). With arguments, only the named outputs are made
(e.g. python3 tests/data/bs_make_meshes.py bs_fig9_pipe bs_fig10_hexhole)."""
import math
import os
import random
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import objio  # noqa: E402  (the project's OBJ reader)


def read_obj(path):
    return objio.read_obj(path)


def write_obj(path, V, F, comment):
    with open(path, "w") as fp:
        fp.write("# " + comment + "\n")
        for v in V:
            fp.write("v %r %r %r\n" % (v[0], v[1], v[2]))
        for f in F:
            fp.write("f %d %d %d\n" % (f[0] + 1, f[1] + 1, f[2] + 1))


def compact(V, F):
    used = sorted({i for f in F for i in f})
    new = {o: n for n, o in enumerate(used)}
    return [list(V[o]) for o in used], [[new[i] for i in f] for f in F]


def boundary_and_ring(V, F):
    cnt = {}
    for f in F:
        for a in range(3):
            e = tuple(sorted((f[a], f[(a + 1) % 3])))
            cnt[e] = cnt.get(e, 0) + 1
    bd = {i for e, c in cnt.items() if c == 1 for i in e}
    ring = set(bd)
    for e in cnt:
        if e[0] in bd or e[1] in bd:
            ring.update(e)
    return bd, ring


def largest_component(F):
    adj = {}
    for k, f in enumerate(F):
        for i in f:
            adj.setdefault(i, []).append(k)
    seen, best = set(), []
    for s in range(len(F)):
        if s in seen:
            continue
        comp, stack = [], [s]
        seen.add(s)
        while stack:
            k = stack.pop()
            comp.append(k)
            for i in F[k]:
                for q in adj[i]:
                    if q not in seen:
                        seen.add(q)
                        stack.append(q)
        if len(comp) > len(best):
            best = comp
    return [F[k] for k in sorted(best)]


def subdivide(V, F):
    V = [list(v) for v in V]
    mid = {}
    def m(a, b):
        k = (min(a, b), max(a, b))
        if k not in mid:
            mid[k] = len(V)
            V.append([(V[a][t] + V[b][t]) / 2 for t in range(3)])
        return mid[k]
    G = []
    for a, b, c in F:
        ab, bc, ca = m(a, b), m(b, c), m(c, a)
        G += [[a, ab, ca], [ab, b, bc], [ca, bc, c], [ab, bc, ca]]
    return V, G


def generated(args):
    with tempfile.TemporaryDirectory() as d:
        out = os.path.join(d, "s.obj")
        subprocess.run([os.path.join(ROOT, "bin", "confsurf")] + args + ["-o", out], check=True, stdout=subprocess.DEVNULL)
        return read_obj(out)


def icosphere(level):
    with tempfile.TemporaryDirectory() as d:
        out = os.path.join(d, "s.obj")
        subprocess.run([os.path.join(ROOT, "bin", "confsurf"), "-gen", "icosphere", "-gen_level", str(level), "-o", out], check=True, stdout=subprocess.DEVNULL)
        return read_obj(out)


def torus_coarse2():
    Vt, Ft = generated(["-gen", "torus", "-gen_n", "8", "-gen_m", "4", "-gen_torus_R", "1", "-gen_tube_r", "0.4"])
    for _ in range(2):
        Vt, Ft = subdivide(Vt, Ft)
    return Vt, Ft


def fig9_pipe():
    Vt, Ft = torus_coarse2()
    Fp = [f for f in Ft if all(Vt[i][1] >= -1e-12 for i in f)]
    Vp, Fp = compact(Vt, Fp)
    bd, ring = boundary_and_ring(Vp, Fp)
    R, r = 1.0, 0.4
    for i in ring:  # onto the torus of revolution: keep the angles u (around z) and v (around the tube)
        x, y, z = Vp[i]
        u, rho = math.atan2(y, x), math.hypot(x, y)
        v = math.atan2(z, rho - R)
        Vp[i] = [(R + r * math.cos(v)) * math.cos(u), (R + r * math.cos(v)) * math.sin(u), r * math.sin(v)]
        if abs(y) < 1e-12:
            Vp[i][1] = 0.0
    out = os.path.join(ROOT, "meshes", "bs_fig9_pipe.obj")
    write_obj(out, Vp, Fp, "half (y >= 0) of bs_torus_coarse2.obj, boundary strip moved onto the torus R 1 r 0.4: circular boundary loops (tests/data/bs_make_meshes.py)")
    print("bs_fig9_pipe: V=%d F=%d boundary=%d fixed=%d" % (len(Vp), len(Fp), len(bd), len(ring)))


def fig10_hexhole(n=10):
    V, F, key = [], [], {}
    def vid(p):
        k = tuple(round(c * n) for c in p)
        if k not in key:
            key[k] = len(V)
            V.append([c / n for c in k])
        return key[k]
    # the faces z = 0, y = 0, x = 0 of the unit cube, (a, b) the in-face coordinates; orientation: outward normal
    # of the cube (-z, -y, -x), so the three faces are consistently oriented as part of its closed surface
    planes = [lambda a, b: (b, a, 0.0), lambda a, b: (a, 0.0, b), lambda a, b: (0.0, b, a)]
    for P in planes:
        for i in range(n):
            for j in range(n):
                q = [vid(P((i + di) / n, (j + dj) / n)) for di, dj in ((0, 0), (1, 0), (1, 1), (0, 1))]
                F += [[q[0], q[1], q[2]], [q[0], q[2], q[3]]]
    bd, ring = boundary_and_ring(V, F)
    c, rad = 0.5, math.sqrt(3) / 2
    for i in ring:
        d = [x - c for x in V[i]]
        s = rad / math.sqrt(sum(x * x for x in d))
        V[i] = [c + s * x for x in d]
    out = os.path.join(ROOT, "meshes", "bs_fig10_hexhole.obj")
    write_obj(out, V, F, "six-sided hole of the sphere through the cube's vertices, filled with the cube corner at the origin (%d x %d squares per face, one diagonal each), boundary strip on the sphere (tests/data/bs_make_meshes.py)" % (n, n))
    print("bs_fig10_hexhole: V=%d F=%d boundary=%d fixed=%d" % (len(V), len(F), len(bd), len(ring)))


def main():
    only = set(sys.argv[1:])
    if only:
        for name in sorted(only):
            {"bs_fig9_pipe": fig9_pipe, "bs_fig10_hexhole": fig10_hexhole}[name]()
        return
    fig9_pipe()
    fig10_hexhole()
    data = os.path.join(ROOT, "tests", "data")
    V, F = icosphere(3)
    # flat-filled cap
    Fc = [f for f in F if all(V[i][2] > 0.1 for i in f)]
    Vc, Fc = compact(V, Fc)
    bd, ring = boundary_and_ring(Vc, Fc)
    z0 = max(Vc[i][2] for i in ring)
    for i in range(len(Vc)):
        if i not in ring:
            Vc[i][2] = z0
    write_obj(os.path.join(data, "bs_cap_flat.obj"), Vc, Fc, "icosphere level 3 cap z>0.1, inside of the boundary strip flattened to z=%r (tests/data/bs_make_meshes.py)" % z0)
    # noisy hemisphere
    rnd = random.Random(5)
    Fh = [f for f in F if all(V[i][2] > 0.0 for i in f)]
    Vh, Fh = compact(V, Fh)
    Vh = [[c + rnd.uniform(-0.02, 0.02) for c in v] for v in Vh]
    write_obj(os.path.join(data, "bs_cap_noisy.obj"), Vh, Fh, "icosphere level 3 hemisphere z>0 with uniform noise 0.02 (tests/data/bs_make_meshes.py)")
    # bunny with a flattened hole
    Vb, Fb = read_obj(os.path.join(ROOT, "meshes", "bunny_lowres_npm.obj"))
    c = max(range(len(Vb)), key=lambda i: Vb[i][0])
    lo = [min(v[k] for v in Vb) for k in range(3)]
    hi = [max(v[k] for v in Vb) for k in range(3)]
    diag = math.dist(lo, hi)
    r = 0.25 * diag
    Fp = [f for f in Fb if all(math.dist(Vb[i], Vb[c]) < r for i in f)]
    Fp = largest_component(Fp)
    Vp, Fp = compact(Vb, Fp)
    bd, ring = boundary_and_ring(Vp, Fp)
    inner = [i for i in range(len(Vp)) if i not in ring]
    # fill: the membrane (uniform-Laplacian) interpolation of the strip, i.e. a surface that is C0 but not G1
    # across the strip; flattening onto a plane folded 17 edges, this does not
    nb = {i: set() for i in range(len(Vp))}
    for f in Fp:
        for a in range(3):
            nb[f[a]].update((f[(a + 1) % 3], f[(a + 2) % 3]))
    for _ in range(2000):
        for i in inner:
            Vp[i] = [sum(Vp[j][k] for j in nb[i]) / len(nb[i]) for k in range(3)]
    write_obj(os.path.join(data, "bs_bunny_hole.obj"), Vp, Fp, "disk cut from bunny_lowres_npm.obj (radius 0.25 bbox diagonal around its highest-x vertex), inside of the boundary strip replaced by the membrane (uniform Laplacian) fill (tests/data/bs_make_meshes.py)")
    print("bs_bunny_hole: V=%d F=%d boundary=%d fixed=%d" % (len(Vp), len(Fp), len(bd), len(ring)))
    # coarse torus subdivided linearly twice (Fig. 8)
    Vt, Ft = torus_coarse2()
    write_obj(os.path.join(data, "bs_torus_coarse2.obj"), Vt, Ft, "coarse torus (confsurf -gen torus -gen_n 8 -gen_m 4 -gen_torus_R 1 -gen_tube_r 0.4) subdivided linearly twice (tests/data/bs_make_meshes.py)")
    # noisy scan-like meshes (Fig. 12): man_cgal.obj (very irregular) and bunny_closed_cgal.obj (regular)
    for name in ("man_cgal", "bunny_closed_cgal"):
        src = os.path.join(ROOT, "meshes", name + ".obj")
        if not os.path.exists(src):
            src = os.path.join(os.path.dirname(ROOT), "shared", "meshes", name + ".obj")
        if not os.path.exists(src):
            print(name + ".obj not found: its noisy copy is not made", file=sys.stderr)
            continue
        Vm, Fm = read_obj(src)
        el, ne = 0.0, 0
        N = [[0.0, 0.0, 0.0] for _ in Vm]
        for f in Fm:
            a, b, cc = (Vm[i] for i in f)
            u = [b[k] - a[k] for k in range(3)]
            w = [cc[k] - a[k] for k in range(3)]
            an = [u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]]
            for i in f:
                for k in range(3):
                    N[i][k] += an[k]
            el += math.dist(a, b)
            ne += 1
        h = el / ne
        rnd = random.Random(12)
        for i, v in enumerate(Vm):
            nl = math.sqrt(sum(x * x for x in N[i])) or 1.0
            s = rnd.uniform(-0.3, 0.3) * h
            Vm[i] = [v[k] + s * N[i][k] / nl for k in range(3)]
        short = name.split("_")[0]
        os.makedirs(os.path.join(ROOT, "runs", "results"), exist_ok=True)
        write_obj(os.path.join(ROOT, "runs", "results", "bs_noisy_%s.obj" % short), Vm, Fm, "%s.obj (libcgal-demo, CC0) with normal noise uniform in +-0.3 mean edge length (tests/data/bs_make_meshes.py)" % name)


if __name__ == "__main__":
    main()
