#!/usr/bin/env python3
"""Plots of comparison studies (runs/study_*.sh), headless matplotlib on Debian's python3 (/usr/bin/python3).

  /usr/bin/python3 scripts/plots.py curves OUT.png --x it|seconds [--title T] LABEL=HISTORY.csv ...
      one panel per column (energy, conformal_violation, el_residual; those a file has), one line per run,
      log scales for the violation and the residual
  /usr/bin/python3 scripts/plots.py panel OUT.png [--title T] [--view ELEV,AZIM] [--input IN.obj] LABEL=MESH.obj ...
      the final shapes side by side (the input first with --input), each from the same camera direction and
      coloured by its signed mean curvature (scripts/pictures.py), each framed on its own bounding box
  /usr/bin/python3 scripts/plots.py table OUT.md|- COLUMNS [--ref LABEL] LABEL=SUMMARY.json ...
      a markdown table of summary keys (COLUMNS comma separated; a missing key prints as -), and derived columns:
      min_angle (degrees, from the .obj beside the summary), s_per_step (seconds per iteration), step_cost_rel
      (s_per_step relative to the run --ref)
  /usr/bin/python3 scripts/plots.py scaling OUT.png --x COLUMN [--title T] RESULTS.csv
      two panels (iterations, seconds against the column --x, log-log), one line per value of the csv's `series`
      column (runs/study_scaling.sh; columns series, faces, ranks, c, its, seconds)

The studies call these; a new study reuses them."""
import argparse
import csv
import json
import math
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from pictures import draw_surface, mean_curvature  # noqa: E402
from render_mesh import read_obj  # noqa: E402

COLUMNS = [("energy", "energy W", False), ("conformal_violation", "|c|_inf (conformal violation)", True),
           ("el_residual", "EL residual", True)]


def pairs(items):
    out = []
    for s in items:
        label, _, path = s.partition("=")
        if not path:
            sys.exit("expected LABEL=PATH, got %r" % s)
        out.append((label, path))
    return out


def read_history(path):
    with open(path) as f:
        rows = list(csv.DictReader(f))
    return {k: np.array([float(r[k]) for r in rows]) for k in (rows[0].keys() if rows else [])}


def curves(out, x, runs, title):
    hist = [(label, read_history(p)) for label, p in runs]
    cols = [c for c in COLUMNS if any(c[0] in h for _, h in hist)]
    fig, axes = plt.subplots(1, len(cols), figsize=(5 * len(cols), 4), squeeze=False)
    for ax, (key, name, log) in zip(axes[0], cols):
        for i, (label, h) in enumerate(hist):
            if key not in h or x not in h:
                continue
            y = h[key]
            if log:
                y = np.where(y > 0, y, np.nan)
            ax.plot(h[x], y, label=label, color=plt.cm.tab10(i % 10), lw=1.4, ls="-" if i < 10 else "--")
        if log:
            ax.set_yscale("log")
        ax.set_xlabel("iteration" if x == "it" else "seconds")
        ax.set_title(name, fontsize=10)
        ax.grid(alpha=0.3)
    axes[0][0].legend(fontsize=7)
    fig.suptitle(title, fontsize=11)
    fig.tight_layout()
    fig.savefig(out, dpi=100)


def panel(out, meshes, view, title):
    n = len(meshes)
    rows = math.ceil(n / 6)  # at most 6 a row, rows filled evenly (6 shapes: one row, not 5 + 1)
    cols = math.ceil(n / rows)
    fig, axes = plt.subplots(rows, cols, figsize=(3 * cols, 3.2 * rows), squeeze=False)
    hs = [(label, V, F, mean_curvature(V, F)) for label, (V, F) in meshes]
    allh = np.concatenate([h for *_, h in hs])
    lo, hi = np.percentile(allh, [2, 98])
    norm = plt.Normalize(lo, hi)
    for ax in axes.ravel():
        ax.set_axis_off()
    for ax, (label, V, F, h) in zip(axes.ravel(), hs):
        b0, b1 = V.min(0), V.max(0)
        draw_surface(ax, V, F, h[F].mean(axis=1), plt.cm.coolwarm, norm, view, ((b0 + b1) / 2, 0.55 * (b1 - b0).max()))
        ax.set_title(label, fontsize=8)
    fig.suptitle(title + " (colour: mean curvature H, one scale)", fontsize=10)
    fig.tight_layout()
    fig.savefig(out, dpi=100)


def fmt(v):
    if isinstance(v, float):
        return "%.4g" % v if abs(v) >= 1e-3 or v == 0 else "%.2e" % v
    return str(v)


def min_angle(path):
    """Smallest interior angle (degrees) of the triangles of an OBJ file."""
    V, F = read_obj(path)
    T = V[F]
    best = 180.0
    for k in range(3):
        u, w = T[:, (k + 1) % 3] - T[:, k], T[:, (k + 2) % 3] - T[:, k]
        c = np.einsum("ij,ij->i", u, w) / (np.linalg.norm(u, axis=1) * np.linalg.norm(w, axis=1) + 1e-300)
        best = min(best, float(np.degrees(np.arccos(np.clip(c, -1, 1))).min()))
    return best


def derived(s, path):
    """Columns computed from a summary and the mesh beside it (same name, .obj): min_angle, s_per_step."""
    obj = os.path.splitext(path)[0] + ".obj"
    if os.path.exists(obj):
        s["min_angle"] = min_angle(obj)
    spi = s.get("seconds_per_iteration", s.get("seconds_per_step"))
    if spi is None and s.get("iterations"):
        spi = s["seconds"] / s["iterations"]
    if spi is not None:
        s["s_per_step"] = spi
    return s


def table(out, columns, runs, ref=None):
    cols = columns.split(",")
    rows = []
    for label, p in runs:
        try:
            with open(p) as f:
                s = derived(json.load(f), p)
        except (OSError, ValueError):
            s = {}
        rows.append((label, s))
    base = dict(rows).get(ref, {}).get("s_per_step") if ref else None
    lines = ["| run | " + " | ".join(cols) + " |", "|---" * (len(cols) + 1) + "|"]
    for label, s in rows:
        if base and "s_per_step" in s:
            s["step_cost_rel"] = s["s_per_step"] / base
        lines.append("| %s | " % label + " | ".join(fmt(s[c]) if c in s else "-" for c in cols) + " |")
    text = "\n".join(lines) + "\n"
    if out == "-":
        sys.stdout.write(text)
    else:
        with open(out, "w") as f:
            f.write(text)


def scaling(out, x, path, title):
    rows = list(csv.DictReader(open(path)))
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    for ax, col, lab in zip(axes, ("its", "seconds"), ("Krylov iterations per solve", "seconds per step (under load)")):
        for name in sorted({r["series"] for r in rows}):
            pts = sorted((float(r[x]), float(r[col])) for r in rows if r["series"] == name and r[col] not in ("", "nan"))
            if pts:
                ax.plot([p[0] for p in pts], [p[1] for p in pts], "o-", label=name)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel(x)
        ax.set_ylabel(lab)
        ax.grid(True, which="both", alpha=0.3)
    axes[0].legend(fontsize=7)
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(out, dpi=110)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    sub = ap.add_subparsers(dest="cmd", required=True)
    c = sub.add_parser("curves")
    c.add_argument("out")
    c.add_argument("--x", default="it", choices=["it", "seconds"])
    c.add_argument("--title", default="")
    c.add_argument("runs", nargs="+")
    p = sub.add_parser("panel")
    p.add_argument("out")
    p.add_argument("--title", default="")
    p.add_argument("--view", default="20,30")
    p.add_argument("--input")
    p.add_argument("runs", nargs="+")
    t = sub.add_parser("table")
    t.add_argument("out")
    t.add_argument("columns")
    t.add_argument("--ref", help="label of the run whose s_per_step is 1 in the column step_cost_rel")
    t.add_argument("runs", nargs="+")
    g = sub.add_parser("scaling")
    g.add_argument("out")
    g.add_argument("--x", default="faces")
    g.add_argument("--title", default="")
    g.add_argument("csv")
    a = ap.parse_args(argv)
    if a.cmd == "curves":
        curves(a.out, a.x, pairs(a.runs), a.title)
    elif a.cmd == "panel":
        meshes = ([("input", read_obj(a.input))] if a.input else []) + [(lb, read_obj(pth)) for lb, pth in pairs(a.runs)]
        panel(a.out, meshes, tuple(float(v) for v in a.view.split(",")), a.title)
    elif a.cmd == "scaling":
        scaling(a.out, a.x, a.csv, a.title)
    else:
        table(a.out, a.columns, pairs(a.runs), a.ref)


if __name__ == "__main__":
    main()
