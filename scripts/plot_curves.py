#!/usr/bin/python3
"""Pictures of the curve flow (crane2013 Sec. 5), headless (Agg), with Debian's python3-matplotlib:

  /usr/bin/python3 scripts/plot_curves.py steps DIR OUT.png [0,1,2,5,...]
      the curves DIR/curve_NNNNN.txt written by -task curveflow -viewer_dir DIR (columns x y kappa) at the
      chosen steps (default: six spread over the run), one panel each, coloured by the curvature kappa (each
      panel its own colour scale), with the step's kappa range, and the edge-length ratio to the first step.
  /usr/bin/python3 scripts/plot_curves.py fig11 CSV OUT.png
      the step-size study of Fig. 11 (runs/curve_fig11.sh): worst edge-length distortion and closure gap
      against tau, log-log, with a dashed line of slope 2 (quadratic convergence).
"""
import glob
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.collections import LineCollection  # noqa: E402


def read_curve(path):
    pts = [list(map(float, l.split())) for l in open(path) if l.strip() and not l.startswith("#")]
    return pts  # closed curves repeat the first point: the polyline closes itself


def lengths(pts):
    return [math.dist(pts[i][:2], pts[i + 1][:2]) for i in range(len(pts) - 1)]


def panel(ax, pts, step, l0):
    segs = [[pts[i][:2], pts[i + 1][:2]] for i in range(len(pts) - 1)]
    kap = [0.5 * (pts[i][2] + pts[i + 1][2]) for i in range(len(pts) - 1)]
    lc = LineCollection(segs, cmap="coolwarm", linewidths=2)
    lc.set_array(kap)
    ax.add_collection(lc)
    xs = [p[0] for p in pts]
    ys = [p[1] for p in pts]
    pad = 0.05 * max(max(xs) - min(xs), max(ys) - min(ys))
    ax.set_xlim(min(xs) - pad, max(xs) + pad)
    ax.set_ylim(min(ys) - pad, max(ys) + pad)
    ax.set_aspect("equal")
    ax.set_xticks([])
    ax.set_yticks([])
    dist = max(abs(a / b - 1) for a, b in zip(lengths(pts), l0))
    ax.set_title(f"step {step}\nkappa {min(kap):.3g} .. {max(kap):.3g}\nmax |l/l0-1| {dist:.1e}", fontsize=8)
    cb = plt.colorbar(lc, ax=ax, fraction=0.046, pad=0.02)
    cb.ax.tick_params(labelsize=6)
    cb.formatter.set_useOffset(False)  # a nearly constant kappa: absolute ticks, not an offset over the title
    cb.update_ticks()


def steps(d, out, which=None):
    files = sorted(glob.glob(os.path.join(d, "curve_*.txt")))
    if not files:
        sys.exit(f"plot_curves.py: no curve_*.txt in {d} (run -task curveflow with -viewer_dir {d})")
    avail = {int(os.path.basename(f)[6:11]): f for f in files}
    keys = sorted(avail)
    if which:
        chosen = [k for k in which if k in avail]
    else:
        chosen = sorted({keys[round(i * (len(keys) - 1) / 5)] for i in range(6)})
    l0 = lengths(read_curve(avail[keys[0]]))
    fig, axes = plt.subplots(1, len(chosen), figsize=(2.6 * len(chosen), 3.2))
    for ax, k in zip(axes if len(chosen) > 1 else [axes], chosen):
        panel(ax, read_curve(avail[k]), k, l0)
    fig.suptitle("isometric curve flow (crane2013 Sec. 5), coloured by curvature", fontsize=10)
    fig.tight_layout()
    fig.savefig(out, dpi=130)
    print(f"wrote {out} (steps {', '.join(map(str, chosen))})")


def fig11(csv, out):
    rows = [l.strip().split(",") for l in open(csv) if l.strip()]
    head, rows = rows[0], [list(map(float, r)) for r in rows[1:]]
    col = {h: i for i, h in enumerate(head)}
    tau = [r[col["tau"]] for r in rows]
    fig, ax = plt.subplots(figsize=(4.5, 3.6))
    ax.loglog(tau, [r[col["distortion"]] for r in rows], "o-", label="max |l~/l - 1| after Poisson")
    ax.loglog(tau, [r[col["gap"]] for r in rows], "s-", ms=4, label="closure gap / length before")
    d0 = rows[-1][col["distortion"]]
    ax.loglog(tau, [d0 * (t / tau[-1]) ** 2 for t in tau], "k--", lw=1, label="slope 2")
    ax.set_xlabel("step size tau")
    ax.set_ylabel("after one step")
    ax.set_title("crane2013 Fig. 11: length distortion vs. step size", fontsize=9)
    ax.legend(fontsize=7)
    ax.grid(True, which="both", lw=0.3)
    fig.tight_layout()
    fig.savefig(out, dpi=130)
    print(f"wrote {out}")


if __name__ == "__main__":
    if len(sys.argv) >= 4 and sys.argv[1] == "steps":
        steps(sys.argv[2], sys.argv[3], [int(s) for s in sys.argv[4].split(",")] if len(sys.argv) > 4 else None)
    elif len(sys.argv) == 4 and sys.argv[1] == "fig11":
        fig11(sys.argv[2], sys.argv[3])
    else:
        sys.exit(__doc__)
