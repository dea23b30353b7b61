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
  runs/results/bs_noisy_man.obj, bs_noisy_bunny.obj  man_cgal.obj / bunny_closed_cgal.obj (meshes/, else
                               ../shared/meshes) with normal noise of 0.3 x mean edge length: the scan-like
                               inputs of Fig. 12.
Deterministic (random.Random with fixed seeds)."""
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


def main():
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
    Vt, Ft = generated(["-gen", "torus", "-gen_n", "8", "-gen_m", "4", "-gen_torus_R", "1", "-gen_tube_r", "0.4"])
    for _ in range(2):
        Vt, Ft = subdivide(Vt, Ft)
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
