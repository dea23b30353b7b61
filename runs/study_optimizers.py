#!/usr/bin/env python3
"""Study (not a test), soliman2021 Fig. 7, written with the Python interface (python/confsurf, docs/python.md): the
runs, tables, ranking and pictures of runs/study_optimizers.sh (read its header for the methods and why), each flow
one confsurf.flow call on the arrays of the generated input instead of a bin/confsurf process.
  python3 runs/study_optimizers.py [--its 30] [--secs 6] [--cap 60] [--alm-rho 0.1] [--hold 1e-5]
                                   [--shapes sphere torus] [--methods cgd cgdf cgdv pgd alm gd] [--metrics h2 l2]
                                   [--out runs/results/optimizers_py]
Small: --its 2 --secs 1 --shapes sphere (a minute). mpirun -n K python3 runs/study_optimizers.py: distributed runs,
rank 0 writes. Outputs in --out: <shape>_<method>_<metric>_{its,time}.{csv,json,obj}, optimizers.md,
<shape>_{its,time}_vs_{it,seconds}.png, <shape>_shapes.png (by scripts/plots.py, as there)."""
import argparse
import datetime
import json
import os
import subprocess
import sys

import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(ROOT, "python"))
sys.path.insert(0, os.path.join(ROOT, "runs"))
import confsurf  # noqa: E402
from study_fairing_eps import write_csv, write_obj  # noqa: E402  (runs/: the same file writers)

SHAPES = {"sphere": "-gen icosphere -gen_level 3 -gen_deform_bump 0.2 -gen_deform_stretch 1.5,1,0.8",
          "torus": "-gen torus -gen_torus_R 3 -gen_tube_r 1 -gen_n 32 -gen_m 16 -gen_deform_bump 0.1"}


def method_options(m, metric, alm_rho):
    opts = {"alm": f"-flow_type alm -flow_alm_metric plain -flow_alm_rho {alm_rho} -flow_alm_rho_grow 1",
            "gd": "-flow_type gd", "cgdv": "-flow_type cgd -flow_vmax 1",
            "cgdf": "-flow_type cgd -flow_t_mu 1e5 -flow_t_mu_grow 1 -flow_t_mu_max 1e5"}.get(m, f"-flow_type {m}")
    return f"{opts} -flow_metric {metric}"


def ranking(hold, runs):
    rows = [(s["willmore"], name) for name, s in runs if s and not name.startswith("gd ") and s["conformal_violation"] < hold]
    return (f"Ranking (runs holding the class, conformal_violation < {hold:g}; GD excluded): "
            + " < ".join(f"{n} {w:.4f}" for w, n in sorted(rows)))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--its", type=int, default=30)
    ap.add_argument("--secs", type=float, default=6)
    ap.add_argument("--cap", type=float, default=60)
    ap.add_argument("--alm-rho", default="0.1")
    ap.add_argument("--hold", type=float, default=1e-5)
    ap.add_argument("--shapes", nargs="+", default=["sphere", "torus"], choices=sorted(SHAPES))
    ap.add_argument("--methods", nargs="+", default=["cgd", "cgdf", "cgdv", "pgd", "alm", "gd"])
    ap.add_argument("--metrics", nargs="+", default=["h2", "l2"])
    ap.add_argument("--out", default="runs/results/optimizers_py")
    a = ap.parse_args()
    os.chdir(ROOT)
    root = confsurf.rank() == 0
    py = subprocess.run(["bash", "scripts/find-python.sh"], capture_output=True, text=True).stdout.strip() or sys.executable
    plots = lambda *args: subprocess.run([py, "scripts/plots.py", *args], check=True, capture_output=True, text=True).stdout
    if root:
        os.makedirs(a.out, exist_ok=True)
    summaries = {}
    for shape in a.shapes:
        inp = confsurf.run("info", SHAPES[shape])  # the deformed input, as -gen ... -gen_deform_* makes it
        V0, F = (inp.V, inp.F) if root else (None, None)
        if root:
            write_obj(f"{a.out}/{shape}_input.obj", V0, F)
        for budget in ("its", "time"):
            lim = f"-flow_max_it {a.its} -flow_max_seconds {a.cap}" if budget == "its" else f"-flow_max_it 100000 -flow_max_seconds {a.secs}"
            for metric in a.metrics:
                for m in a.methods:
                    name = f"{shape}_{m}_{metric}_{budget}"
                    try:
                        r = confsurf.flow(V0, F, f"{method_options(m, metric, a.alm_rho)} {lim} -flow_max_area_ratio 0")
                    except confsurf.Error as e:
                        if root:
                            print(f"{name}: failed: {e}", flush=True)
                        continue
                    if not root:
                        continue
                    summaries[name] = r.summary
                    json.dump(r.summary, open(f"{a.out}/{name}.json", "w"))
                    write_csv(f"{a.out}/{name}.csv", r.history)
                    write_obj(f"{a.out}/{name}.obj", r.V, r.F)
                    s = r.summary
                    print(f"{name}: {s['stop_reason']} after {s['iterations']} iterations, W {s['willmore']:.6g}, violation {s['conformal_violation']:.2e}, {s['seconds']:.1f} s", flush=True)
            if root:
                runs = [f"{m} {mt}={a.out}/{shape}_{m}_{mt}_{budget}.csv" for mt in a.metrics for m in a.methods]
                title = f"{shape}, equal " + (f"iterations ({a.its})" if budget == "its" else f"wall time ({a.secs:g} s)")
                for x in ("it", "seconds"):
                    plots("curves", f"{a.out}/{shape}_{budget}_vs_{x}.png", "--x", x, "--title", title, *runs)
        if root:
            shapes = [f"{m} {mt}={a.out}/{shape}_{m}_{mt}_its.obj" for mt in a.metrics for m in a.methods]
            plots("panel", f"{a.out}/{shape}_shapes.png", "--title", f"{shape} after {a.its} iterations", "--input", f"{a.out}/{shape}_input.obj", *shapes)
    if not root:
        return
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True, text=True).stdout.strip()
    when = datetime.datetime.utcnow().strftime("%Y-%m-%d %H:%M")
    text = [f"# Optimiser study (soliman2021 Fig. 7), {when} UTC, commit {commit}, ITS={a.its} SECS={a.secs:g} ALM_RHO={a.alm_rho} NP={confsurf.size()} (shared machine: seconds are noisy; runs/study_optimizers.py through the Python interface)", ""]
    cols = "willmore,energy_initial,conformal_violation,el_residual,iterations,rejections,seconds,q_mean,q_max,stop_reason"
    for shape in a.shapes:
        for budget in ("its", "time"):
            text += [f"## {shape}, equal " + (f"iterations ({a.its})" if budget == "its" else f"wall time ({a.secs:g} s)"), ""]
            names = [(f"{m} {mt}", f"{shape}_{m}_{mt}_{budget}") for mt in a.metrics for m in a.methods]
            text += [plots("table", "-", cols, *[f"{n}={a.out}/{f}.json" for n, f in names]), ranking(a.hold, [(n, summaries.get(f)) for n, f in names]), ""]
    open(f"{a.out}/optimizers.md", "w").write("\n".join(text) + "\n")
    print("\n".join(text))


if __name__ == "__main__":
    main()
