#!/usr/bin/env python3
"""Study (not a test), soliman2021 Fig. 20, written with the Python interface (python/confsurf, docs/python.md):
the same runs, table and pictures as runs/study_fairing_eps.sh, each flow one confsurf.flow call on the arrays of
the input instead of a bin/confsurf process, the displacement computed on the returned arrays. Willmore-regularised
fairing E = 1/2 |f - f0|^2 + eps W (Eq. 21) in the input's conformal class, CGD, -flow_rtol 1e-6.
  python3 runs/study_fairing_eps.py [--eps 0.001 0.01 0.1 1 10] [--maxit 150] [--mesh meshes/bunny_lowres_npm.obj]
                                    [--out runs/results/fairing_eps_py]
Smaller: --eps 0.1 1 --maxit 10 (seconds). Under mpirun -n K every rank runs it, rank 0 writes. Outputs in --out:
eps_<e>.{csv,json,obj} (the files the shell version's bin/confsurf runs write), fairing_eps.md (table),
fairing_eps_shapes.png, fairing_eps_curves.png (by scripts/plots.py, as there)."""
import argparse
import datetime
import json
import os
import subprocess
import sys

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "python"))
import confsurf  # noqa: E402


def write_obj(path, V, F):
    with open(path, "w") as f:
        f.writelines("v %.17g %.17g %.17g\n" % tuple(v) for v in V)
        f.writelines("f %d %d %d\n" % tuple(t + 1) for t in F)


def write_csv(path, history):
    names = list(history)
    rows = np.column_stack([history[k] for k in names]) if names else np.zeros((0, 0))
    with open(path, "w") as f:
        f.write(",".join(names) + "\n")
        f.writelines(",".join("%.17g" % x for x in row) + "\n" for row in rows)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--eps", nargs="+", default=["0.001", "0.01", "0.1", "1", "10"])
    ap.add_argument("--maxit", type=int, default=150)
    ap.add_argument("--mesh", default="meshes/bunny_lowres_npm.obj")
    ap.add_argument("--out", default="runs/results/fairing_eps_py")
    a = ap.parse_args()
    os.chdir(ROOT)
    root = confsurf.rank() == 0
    inp = confsurf.run("info", f"-mesh {a.mesh}")  # the input as the task sees it (validated, oriented)
    if root:
        os.makedirs(a.out, exist_ok=True)
        V0, F = inp.V, inp.F
        write_obj(f"{a.out}/input.obj", V0, F)
        json.dump(inp.summary, open(f"{a.out}/input.json", "w"))
        diag = np.linalg.norm(V0.max(0) - V0.min(0))
    else:
        V0 = F = None
    runs, curves, shapes = [f"input={a.out}/input.json"], [], []
    for e in a.eps:
        r = confsurf.flow(V0, F, f"-flow_energy fairing -flow_fairing_epsilon {e} -flow_max_it {a.maxit} -flow_rtol 1e-6")
        if not root:
            continue
        s, d = r.summary, np.linalg.norm(r.V - V0, axis=1)
        s["disp_rms_rel"], s["disp_max_rel"] = float(np.sqrt(np.mean(d**2)) / diag), float(d.max() / diag)
        stem = f"{a.out}/eps_{e}"
        json.dump(s, open(stem + ".json", "w"))
        write_csv(stem + ".csv", r.history)
        write_obj(stem + ".obj", r.V, r.F)
        print(f"eps {e}: {s['stop_reason']} after {s['iterations']} iterations, W {s['willmore']:.6g}, E {s['energy']:.6g}, {s['seconds']:.1f} s", flush=True)
        runs.append(f"eps {e}={stem}.json"), curves.append(f"eps {e}={stem}.csv"), shapes.append(f"eps {e}={stem}.obj")
    if not root:
        return
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True, text=True).stdout.strip()
    when = datetime.datetime.utcnow().strftime("%Y-%m-%d %H:%M UTC")
    cols = "energy,willmore,disp_rms_rel,disp_max_rel,conformal_violation,el_residual,iterations,q_max,seconds,stop_reason"
    py = subprocess.run(["bash", "scripts/find-python.sh"], capture_output=True, text=True).stdout.strip() or sys.executable
    table = subprocess.run([py, "scripts/plots.py", "table", "-", cols] + runs, capture_output=True, text=True, check=True).stdout
    with open(f"{a.out}/fairing_eps.md", "w") as f:
        f.write(f"Fairing for eps over four decades ({when}, commit {commit}, {a.mesh}, MAXIT={a.maxit}, "
                f"{confsurf.size()} rank(s), runs/study_fairing_eps.py through the Python interface)\n\n" + table)
    print(open(f"{a.out}/fairing_eps.md").read())
    subprocess.run([py, "scripts/plots.py", "panel", f"{a.out}/fairing_eps_shapes.png", "--title",
                    "soliman2021 Fig. 20: E = |f-f0|^2/2 + eps W", "--input", f"{a.out}/input.obj"] + shapes, check=True)
    subprocess.run([py, "scripts/plots.py", "curves", f"{a.out}/fairing_eps_curves.png", "--x", "it", "--title",
                    "fairing, eps over four decades"] + curves, check=True)


if __name__ == "__main__":
    main()
