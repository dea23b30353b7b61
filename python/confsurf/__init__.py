"""confsurf from Python: the methods of bin/confsurf on numpy arrays (docs/python.md).

    import numpy as np, confsurf
    r = confsurf.flow(V, F, "-flow_type cgd -flow_max_it 50")
    r.V, r.summary["willmore"], r.history["energy"]

Every function runs one task of the command line on the arrays with the command line's options (a string, as
typed after bin/confsurf; -options_file too) and returns a Result: the final positions V (or the curve P), the
faces F, the summary dict (the JSON of -summary) and the history (the columns of -history_csv, as arrays). The
options of one call live in their own PETSc options database: nothing carries over to the next call. A bad
argument raises ValueError, a failed run confsurf.Error with the one-line message of the command line; the
process goes on. Under `mpirun -n K python3 script.py` every rank makes the same calls, the arrays are read on
rank 0, the run is distributed, and the Result comes back on rank 0 (None on the other ranks).
"""
import ctypes
import json

import numpy as np

from . import _lib

__all__ = ["Error", "Result", "run", "info", "flow", "spin", "conformal_flow", "curve_flow", "rank", "size"]


class Error(RuntimeError):
    """A run of confsurf failed; str(e) is its one-line message (as bin/confsurf prints it)."""


class Result:
    """What a run returns on rank 0: V (n x 3; a curve: P, n x 2), F (faces as -o writes them, or None), summary
    (dict), history (dict of column name -> array; empty when the task keeps none)."""

    def __init__(self, V, F, summary, history):
        self.V, self.F, self.summary, self.history = V, F, summary, history

    @property
    def P(self):
        return self.V

    def __repr__(self):
        shape = None if self.V is None else self.V.shape
        return f"confsurf.Result(V{shape}, {len(self.summary)} summary keys, history {sorted(self.history)})"


def rank():
    """This process' rank in PETSC_COMM_WORLD (0 when serial)."""
    return _lib.lib().CSApiRank()


def size():
    """The number of ranks (1 when serial)."""
    return _lib.lib().CSApiSize()


def _array(name, a, cols, dtype, problems):
    """a as a C-contiguous (n, cols) array of dtype; a problem is appended to problems (raised on every rank)."""
    if a is None:
        problems.append(f"{name}: missing (an array of shape (n, {cols}))")
        return None
    try:
        arr = np.asarray(a)
    except Exception as e:  # noqa: BLE001 - anything numpy refuses
        problems.append(f"{name}: not an array ({e})")
        return None
    if arr.ndim != 2 or arr.shape[1] != cols:
        problems.append(f"{name}: shape {arr.shape}, expected (n, {cols})")
        return None
    if dtype is np.float64:
        if not (np.issubdtype(arr.dtype, np.floating) or np.issubdtype(arr.dtype, np.integer)):
            problems.append(f"{name}: dtype {arr.dtype}, expected real numbers")
            return None
        arr = np.ascontiguousarray(arr, dtype=np.float64)
        bad = ~np.isfinite(arr)
        if bad.any():
            i = int(np.argwhere(bad)[0][0])
            problems.append(f"{name}: row {i} is not finite ({arr[i].tolist()})")
            return None
    else:
        if not np.issubdtype(arr.dtype, np.integer):
            problems.append(f"{name}: dtype {arr.dtype}, expected integers (0-based indices)")
            return None
        arr = np.ascontiguousarray(arr, dtype=np.int64)
    return arr


def _faces(F, nv, problems, name="F"):
    F = _array(name, F, 3, np.int64, problems)
    if F is not None and F.size and (F.min() < 0 or F.max() >= nv):
        i = int(np.argwhere((F < 0) | (F >= nv))[0][0])
        problems.append(f"{name}: row {i} {F[i].tolist()} has an index outside [0, {nv}) (0-based vertex indices)")
        return None
    if F is not None and not len(F):
        problems.append(f"{name}: no faces")
        return None
    return F


def _ptr(a, ctype):
    return None if a is None else a.ctypes.data_as(ctypes.POINTER(ctype))


def _results(lib):
    """The results of the last run (rank 0) copied into numpy arrays."""
    dim, n, nf, rows, cols = (ctypes.c_long() for _ in range(5))
    text = lib.CSApiResultSummary()
    summary = json.loads(text.decode()) if text else {}
    px = lib.CSApiResultPositions(ctypes.byref(dim), ctypes.byref(n))
    V = np.ctypeslib.as_array(px, shape=(n.value, dim.value)).copy() if px and n.value else None
    pf = lib.CSApiResultFaces(ctypes.byref(nf))
    F = np.ctypeslib.as_array(pf, shape=(nf.value, 3)).astype(np.int64) if pf and nf.value else None
    header = ctypes.c_char_p()
    ph = lib.CSApiResultHistory(ctypes.byref(header), ctypes.byref(rows), ctypes.byref(cols))
    history = {}
    if header.value:
        names = header.value.decode().split(",")
        table = np.ctypeslib.as_array(ph, shape=(rows.value, cols.value)).copy() if ph and rows.value else np.zeros((0, len(names)))
        history = {k: table[:, j] for j, k in enumerate(names)}
    lib.CSApiRelease()
    return Result(V, F, summary, history)


def run(task, options="", V=None, F=None, *, uv=None, fuv=None, rho=None, P=None, closed=True, verbose=False):
    """One task (info|flow|spin|spectrum|curveflow) of bin/confsurf with the options string; the input as arrays
    V (n x 3) and F (m x 3, 0-based), or P (n x 2, a closed curve unless closed=False), or none (the options name
    it: -mesh, -gen, -curve, -gen_curve). uv (k x 2) with fuv (m x 3; default F when k == n): texture coordinates
    carried with the mesh. rho: spin's change of mean curvature half-density (one value per vertex, or per face with
    -rho_location face), in place of -rho FILE. verbose: the task's progress lines on stdout. Returns a Result on
    rank 0, None on the other ranks; raises ValueError (a bad array) or Error (a failed run)."""
    lib = _lib.lib()
    problems = []
    args = dict(nv=0, V=None, nf=0, F=None, nuv=0, uv=None, fuv=None, nrho=0, rho=None, np_=0, P=None)
    root = lib.CSApiRank() == 0
    if root:  # the arrays of rank 0 are the input; the other ranks' are not read
        if not isinstance(options, str):
            problems.append(f"options: {type(options).__name__}, expected a string of command-line options")
        if V is not None or F is not None:
            Va = _array("V", V, 3, np.float64, problems)
            Fa = _faces(F, len(Va) if Va is not None else 0, problems) if Va is not None else None
            if Va is not None and Fa is not None:
                args.update(nv=len(Va), V=Va, nf=len(Fa), F=Fa)
                if uv is not None:
                    uva = _array("uv", uv, 2, np.float64, problems)
                    if fuv is None and uva is not None and len(uva) == len(Va):
                        fuv = Fa
                    fa = _faces(fuv, len(uva) if uva is not None else 0, problems, "fuv") if uva is not None else None
                    if fa is not None and len(fa) != len(Fa):
                        problems.append(f"fuv: {len(fa)} rows, expected one per face ({len(Fa)})")
                    elif uva is not None and fa is not None:
                        args.update(nuv=len(uva), uv=uva, fuv=fa)
        if P is not None:
            Pa = _array("P", P, 2, np.float64, problems)
            if Pa is not None:
                args.update(np_=len(Pa), P=Pa)
        if rho is not None:
            ra = _array("rho", np.asarray(rho).reshape(-1, 1) if np.ndim(rho) == 1 else rho, 1, np.float64, problems)
            if ra is not None:
                args.update(nrho=len(ra), rho=ra)
    refuse = "; ".join(problems).encode() if problems else None
    rc = lib.CSApiRun(task.encode(), (options if isinstance(options, str) else "").encode(), 0 if verbose else 1,
                      args["nv"], _ptr(args["V"], ctypes.c_double), args["nf"], _ptr(args["F"], ctypes.c_long),
                      args["nuv"], _ptr(args["uv"], ctypes.c_double), _ptr(args["fuv"], ctypes.c_long),
                      args["nrho"], _ptr(args["rho"], ctypes.c_double),
                      args["np_"], _ptr(args["P"], ctypes.c_double), 1 if closed else 0, refuse)
    if rc:
        message = lib.CSApiLastError().decode(errors="replace")
        raise (ValueError if lib.CSApiLastErrorIsInput() else Error)(message)
    return _results(lib) if root else None


def info(V, F, options="", **kw):
    """-task info: counts, topology, area, volume, Willmore energies (summary); V, F as validated."""
    return run("info", options, V, F, **kw)


def flow(V, F, options="-flow_type cgd", uv=None, **kw):
    """-task flow: the conformally constrained Willmore flow (soliman2021; -flow_type cgd|pgd|gd|newton|alm|...),
    the Bobenko-Schroeder flow (-flow_type bs) or the conformal curvature flow (-flow_type conformal)."""
    return run("flow", options, V, F, uv=uv, **kw)


def conformal_flow(V, F, options="", **kw):
    """-task flow -flow_type conformal: the conformal curvature flow of crane2013 Sec. 6."""
    return run("flow", "-flow_type conformal " + options, V, F, **kw)


def spin(V, F, rho=None, options="", **kw):
    """-task spin: the spin transformation of crane2011 for rho (one value per vertex; per face with
    -rho_location face), or with the options' rho (-rho_bump_*, -rho_mean_curvature, -spin_target_mesh ...)."""
    return run("spin", options, V, F, rho=rho, **kw)


def curve_flow(P, options="", closed=True, **kw):
    """-task curveflow: the isometric curvature flow of a planar polygon P (n x 2, crane2013 Sec. 5)."""
    return run("curveflow", options, P=P, closed=closed, **kw)
