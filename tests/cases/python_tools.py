"""The checks of the Python interface (tests/cases/python_api.sh, python_errors.sh): run under $MPIEXEC, every rank
makes the same calls; rank 0 compares. Modes:
  equal DIR   each function's result against bin/confsurf's files of the same input in DIR (positions to 1e-12,
              every summary key but the timings and the input's name, the history columns but the timings)
  errors      bad arguments raise ValueError / confsurf.Error with their message, and the next call works
  repeat N    N small calls: PETSc's own memory (run with -malloc_debug) and the global options unchanged, an
              option of one call not seen by the next; RSS quoted"""
import json
import os
import sys

import numpy as np

import confsurf

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts"))
import objio  # noqa: E402  (scripts/objio.py, the project's OBJ reader)

ROOT = confsurf.rank() == 0
TIMING = ("seconds", "time", "_ms", "ms_per")  # keys and columns that measure time, not results


def say(*a):
    if ROOT:
        print(*a, flush=True)


def read_obj(path):
    V, F = objio.read_obj(path)
    return np.array(V), np.array(F, dtype=np.int64)


def read_uv(path):
    """the texture coordinates of an OBJ (vt lines, f v/vt corners): uv, fuv (0-based); the generator's torus has them"""
    uv, fuv = [], []
    for line in open(path):
        t = line.split()
        if t and t[0] == "vt":
            uv.append([float(x) for x in t[1:3]])
        elif t and t[0] == "f" and "/" in t[1]:
            fuv.append([int(x.split("/")[1]) - 1 for x in t[1:4]])
    return np.array(uv), np.array(fuv, dtype=np.int64)


def read_points(path):
    return np.array([[float(x) for x in line.split()[:2]] for line in open(path) if line.strip() and not line.startswith("#")])


def read_csv(path):
    lines = open(path).read().split("\n")
    names = lines[0].split(",")
    rows = np.array([[float(x) for x in l.split(",")] for l in lines[1:] if l])
    return {k: rows[:, j] for j, k in enumerate(names)}


def timing(key):
    return any(t in key for t in TIMING)


# Serially the results agree to the bit (checked as such). On 2 ranks the CGD flow's positions, called twice in one
# process, alternate between two results 1e-12 apart (relative 3e-13; measured: calls 1, 3 equal bin/confsurf's,
# calls 2, 4 differ), so there they are compared to 1e-12 relative: reals in the summary and the history too, the
# integers, strings and booleans exactly.
TOL = 0.0 if confsurf.size() == 1 else 1e-12


def same(a, b):
    if isinstance(a, float) and isinstance(b, float):
        return abs(a - b) <= TOL * max(1.0, abs(b))
    if isinstance(a, list) and isinstance(b, list):
        return len(a) == len(b) and all(same(x, y) for x, y in zip(a, b))
    return a == b and type(a) == type(b)


def close(a, b):
    a, b = np.nan_to_num(a, nan=-7.0), np.nan_to_num(b, nan=-7.0)
    return a.shape == b.shape and np.all(np.abs(a - b) <= TOL * max(1.0, np.abs(b).max(initial=0.0)))  # of the array's size


def compare(name, r, files, skip=()):
    """r (a Result) against the CLI's files: -o (obj or points), -summary, -history_csv; returns the failures"""
    bad = []
    if "obj" in files:
        V, F = read_obj(files["obj"])
        d = np.abs(r.V - V).max()
        if not close(r.V, V) or not np.array_equal(r.F, F):
            bad.append(f"{name}: positions differ by {d:.3e} (or faces differ)")
        say(f"{name}: positions max |python - cli| = {d:.3e} ({len(V)} vertices)")
    if "points" in files:
        P = read_points(files["points"])
        P = P[:-1] if len(P) == len(r.P) + 1 else P  # a closed curve's file repeats its first point
        d = np.abs(r.P - P).max()
        if not close(r.P, P):
            bad.append(f"{name}: points differ by {d:.3e}")
        say(f"{name}: points max |python - cli| = {d:.3e} ({len(P)} points)")
    s = json.load(open(files["summary"]))
    keys = [k for k in s if not timing(k) and k not in skip]
    diff = [k for k in keys if not same(r.summary.get(k), s[k])]
    missing = sorted(set(s) - set(r.summary))
    if diff or missing:
        bad.append(f"{name}: summary keys differ: {[(k, r.summary.get(k), s[k]) for k in diff]} missing {missing}")
    say(f"{name}: {len(keys)} summary keys equal{' to 1e-12' if TOL else ''} (not compared: {sorted(set(s) - set(keys))})")
    if "csv" in files:
        h = read_csv(files["csv"])
        cols = [k for k in h if not timing(k)]
        diff = [k for k in cols if k not in r.history or not close(r.history[k], h[k])]
        if diff or sorted(h) != sorted(r.history):
            bad.append(f"{name}: history columns differ: {diff} (names {sorted(h)} vs {sorted(r.history)})")
        say(f"{name}: history {len(h[cols[0]])} rows x {len(cols)} columns equal{' to 1e-12' if TOL else ''}")
    return bad


def equal(d):
    f = lambda n: os.path.join(d, n)
    V, F = read_obj(f("torus.obj"))
    T = dict(zip(("uv", "fuv"), read_uv(f("torus.obj"))))  # -gen torus gives its angles as UVs, -mesh reads them
    S, G = read_obj(f("sphere.obj"))
    rho = np.loadtxt(f("rho.txt"))
    P = read_points(f("star.txt"))[:-1]
    runs = [
        ("flow cgd", lambda: confsurf.flow(V, F, "-flow_type cgd -flow_max_it 3", **T), dict(obj=f("flow.obj"), summary=f("flow.json"), csv=f("flow.csv"))),
        ("info", lambda: confsurf.info(V, F, **T), dict(obj=f("info.obj"), summary=f("info.json"))),
        ("flow bs", lambda: confsurf.flow(V, F, "-flow_type bs -bs_max_it 3", **T), dict(obj=f("bs.obj"), summary=f("bs.json"), csv=f("bs.csv"))),
        ("conformal_flow", lambda: confsurf.conformal_flow(S, G, "-flow_max_it 2"), dict(obj=f("conformal.obj"), summary=f("conformal.json"), csv=f("conformal.csv"))),
        ("spin", lambda: confsurf.spin(S, G, rho), dict(obj=f("spin.obj"), summary=f("spin.json"))),
        ("curve_flow", lambda: confsurf.curve_flow(P, "-curve_max_it 5"), dict(points=f("curve.txt"), summary=f("curve.json"), csv=f("curve.csv"))),
        # the same cgd call again, after five other meshes were distributed in this process: the same partition
        # (PT-Scotch's generator is reset before each one, src/mesh/mesh_create.c), so the same bits as the binary
        ("flow cgd again", lambda: confsurf.flow(V, F, "-flow_type cgd -flow_max_it 3", **T), dict(obj=f("flow.obj"), summary=f("flow.json"), csv=f("flow.csv"))),
    ]
    bad = []
    for name, call, files in runs:
        r = call()
        if ROOT:
            bad += compare(name, r, files, skip=("mesh", "curve"))
    for b in bad:
        say("BAD", b)
    return not bad


def expect(exc, text, call):
    try:
        call()
    except exc as e:
        ok = text.lower() in str(e).lower()
        say(("ok  " if ok else "BAD ") + f"{exc.__name__}: {e}" + ("" if ok else f" (expected /{text}/)"))
        return ok
    say(f"BAD: no {exc.__name__} (expected /{text}/)")
    return False


def errors():
    r0 = confsurf.run("info", "-gen icosphere -gen_level 1")
    V, F = (r0.V, r0.F) if ROOT else (None, None)
    Vnan = V.copy() if ROOT else None
    if ROOT:
        Vnan[3, 1] = np.nan
    ok = [
        expect(ValueError, "V: shape (", lambda: confsurf.info(V[:, :2] if ROOT else None, F)),
        expect(ValueError, "F: shape (", lambda: confsurf.info(V, F.ravel() if ROOT else None)),
        expect(ValueError, "V: row 3 is not finite", lambda: confsurf.info(Vnan, F)),
        expect(ValueError, "expected integers", lambda: confsurf.info(V, F.astype(float) if ROOT else None)),
        expect(ValueError, "index outside [0, 42)", lambda: confsurf.info(V, F + 1 if ROOT else None)),
        expect(ValueError, "P: shape (", lambda: confsurf.curve_flow(V)),
        expect(confsurf.Error, "unknown option -flow_nosuch 3", lambda: confsurf.flow(V, F, "-flow_type cgd -flow_nosuch 3 -flow_max_it 1")),
        expect(confsurf.Error, "-flow_type nosuch: unknown flow", lambda: confsurf.flow(V, F, "-flow_type nosuch")),
        # a solver option no solver of the run reads: found after the run (bin/confsurf: exit 2 then), an error here
        expect(confsurf.Error, "unknown or unused option -flow_saddle_ksp_nosuch 1 (1 option(s) not used", lambda: confsurf.flow(V, F, "-flow_type cgd -flow_max_it 1 -flow_saddle_ksp_nosuch 1")),
        expect(confsurf.Error, "rho (array): value 0 is 1e+13, beyond 1e12", lambda: confsurf.spin(V, F, np.full(42, 1e13))),
        expect(confsurf.Error, "rho (array): 5 values, expected 42", lambda: confsurf.spin(V, F, np.ones(5))),
        expect(confsurf.Error, "Unable to open options file /nonexistent/x.opts", lambda: confsurf.info(V, F, "-options_file /nonexistent/x.opts")),
        expect(confsurf.Error, "duplicate faces", lambda: confsurf.info(V, np.vstack([F, F[:1]]) if ROOT else None)),
        expect(confsurf.Error, "the mesh is given as arrays", lambda: confsurf.info(V, F, "-gen icosphere")),
    ]
    r1 = confsurf.info(V, F)  # the library goes on: the same result as before the errors
    if ROOT:
        same = np.array_equal(r1.V, r0.V) and r1.summary["willmore"] == r0.summary["willmore"]
        say(("ok  " if same else "BAD ") + "a call after the errors gives the result of the first call")
        ok.append(same)
    return all(ok)


def rss_kb():
    for line in open("/proc/self/status"):
        if line.startswith("VmRSS:"):
            return int(line.split()[1])


def repeat(n):
    lib = confsurf._lib.lib()
    r = confsurf.run("info", "-gen icosphere -gen_level 1")
    V, F = (r.V, r.F) if ROOT else (None, None)
    first = confsurf.flow(V, F, "-flow_type cgd -flow_max_it 2")
    opts0 = lib.CSApiGlobalOptionsCount()
    warm = max(6, n // 10)  # each kind of call twice: what PETSc allocates once per process (a registration) is done
    for i in range(n):
        if i == warm:
            mem0, rss0 = lib.CSApiPetscMemory(), rss_kb()
        which = i % 3
        try:
            if which == 0:
                confsurf.flow(V, F, "-flow_type cgd -flow_max_it 0")  # an option of this call only
            elif which == 1:
                confsurf.info(V, F, "-flow_max_it 0")  # a failing call: an option this task does not read
            else:
                confsurf.curve_flow(None, "-gen_curve star -gen_curve_n 40 -curve_max_it 2")
        except confsurf.Error:
            assert which == 1
    mem1, rss1 = lib.CSApiPetscMemory(), rss_kb()
    last = confsurf.flow(V, F, "-flow_type cgd -flow_max_it 2")  # sees none of the -flow_max_it 0 before
    opts1 = lib.CSApiGlobalOptionsCount()
    ok = True
    if ROOT:
        d = np.abs(first.V - last.V).max()
        agree = close(first.V, last.V) and first.summary["iterations"] == last.summary["iterations"] == 2
        say(("ok  " if agree else "BAD ") + f"the first and the last flow agree after {n} calls (max difference {d:.1e}, iterations {last.summary['iterations']})")
        ok = agree
    say(("ok  " if opts0 == opts1 else "BAD ") + f"global options database: {opts0} options before, {opts1} after")
    say(("ok  " if mem0 == mem1 else "BAD ") + f"PETSc memory (-malloc_debug) after call {warm}: {mem0:.0f} B, after call {n}: {mem1:.0f} B")
    say(f"RSS after call {warm}: {rss0} kB, after call {n}: {rss1} kB ({(rss1 - rss0) / max(1, n - warm):.2f} kB per call)")
    return ok and opts0 == opts1 and mem0 == mem1


if __name__ == "__main__":
    mode = sys.argv[1]
    ok = {"equal": lambda: equal(sys.argv[2]), "errors": errors, "repeat": lambda: repeat(int(sys.argv[2]))}[mode]()
    sys.exit(0 if ok else 1)
