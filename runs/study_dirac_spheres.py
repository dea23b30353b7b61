#!/usr/bin/python3
"""crane2011 Fig. 9 and 11 (issue 39): confsurf's Dirac spheres against their closed forms under refinement.

For each unit icosphere level: `-task spectrum -spectrum_signed -spectrum_reconstruct 0,4,...,51` (every eigenvector
of n = 0, 1, -2, 2, -3, 3, with -spectrum_nev 64: at 52 Krylov-Schur returned 14 of the 16 of n = 3 on level 4 and
two of n = -4; n read back from the computed eigenvalues, the cluster sizes checked), then tests/cases/dirac_sphere_tool.py (the
closed forms, derived in its docstring and docs/spin_applications.md) on each surface:
  gamma    |gamma_h - n| / |n|, the eigenvalue rho = n of Eq. 3 (crane2011 Sec. 6.2), largest over the cluster
  dist     max over vertices of |f~_h(x_i) - f~(x_i)| / size, f~ the nearest closed form (any element of the
           eigenspace, any similarity and translation), size = sqrt(area / 4 pi) of the result; largest over the
           cluster (dist_min: smallest); the rest the median over the cluster (_max: largest; these derivatives
           depend on the element: near a zero of lam, a near branch point, they are poor, the positions are not):
  rho_rms  rho as a potential, H~|df~| / |df| - H per vertex (cotan H), its area-weighted rms deviation from n
  W        the cotan Willmore energy against the closed form 4 pi (1 + n)^2, relative
  q_mean   crane2011 Sec. 6.1 quasi-conformal error of the result against the input (confsurf's summary)
Writes runs/results/study_dirac_spheres.csv and _table.md, docs/img/dirac_spheres_convergence.png and (with
level 4 among the levels) docs/img/dirac_spheres_closed_form.png (computed beside the closed form).
  /usr/bin/python3 runs/study_dirac_spheres.py [LEVELS]      (default "2 3 4 5"; levels 2-5: 6.5 min wall, 85 s CPU under load)"""
import csv
import json
import math
import os
import subprocess
import sys
import time

import numpy as np

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
sys.path.insert(0, os.path.join(ROOT, "tests", "cases"))
sys.path.insert(0, os.path.join(ROOT, "scripts"))
import dirac_sphere_tool as tool  # noqa: E402

BIN = os.path.join(ROOT, "bin", "confsurf")
OUT = os.path.join(ROOT, "runs", "results", "dirac_spheres")
VECS = [0] + list(range(4, 52))
COLS = ["level", "vertices", "h", "k", "n", "vectors", "gamma", "gamma_err", "dist_max", "dist_min", "dist_rms",
        "rho_rms_err", "rho_rms_err_max", "W", "W_closed", "W_err", "W_err_max", "area_ratio_min", "q_mean", "q_mean_max",
        "seconds"]


def run_level(L):
    ico = os.path.join(OUT, "ico%d.obj" % L)
    subprocess.run([BIN, "-task", "info", "-gen", "icosphere", "-gen_level", str(L), "-o", ico], check=True,
                   stdout=subprocess.DEVNULL)
    summ = os.path.join(OUT, "L%d.json" % L)
    t0 = time.time()
    subprocess.run([BIN, "-task", "spectrum", "-gen", "icosphere", "-gen_level", str(L), "-spectrum_signed",
                    "-spectrum_nev", "64", "-spectrum_reconstruct", ",".join(map(str, VECS)),
                    "-spectrum_reconstruct_prefix", os.path.join(OUT, "L%d" % L), "-summary", summ], check=True,
                   stdout=subprocess.DEVNULL)
    sec = time.time() - t0
    s = json.load(open(summ))
    V, F = (np.array(a, dtype=float) for a in tool.read_obj(ico))
    F = F.astype(int)
    h = np.mean([np.linalg.norm(V[F[:, a]] - V[F[:, (a + 1) % 3]], axis=1).mean() for a in range(3)])
    rows = []
    eig = s["eigenvalues_by_magnitude"]
    X0 = V / np.linalg.norm(V, axis=1)[:, None]
    h0, A0 = tool.half_density(X0, F)
    clusters = {}
    for i, k in enumerate(VECS):
        clusters.setdefault(int(round(eig[k])), []).append((i, k))
    for n, members in clusters.items():
        if n not in (0, 1, -2, 2, -3, 3):
            continue
        if n and len(members) != 4 * abs(n + 1):  # Krylov-Schur can miss copies of a multiple eigenvalue (docs)
            print("level %d n = %d: %d eigenvectors, not %d" % (L, n, len(members), 4 * abs(n + 1)))
        i, k = members[0]
        d = tool.distance(ico, os.path.join(OUT, "L%d_%d.obj" % (L, k)), n, os.path.join(OUT, "C%d_%d.obj" % (L, k)))
        dall = tool.cluster_distances(ico, [os.path.join(OUT, "L%d_%d.obj" % (L, kk)) for _, kk in members], n)
        gerr = max(abs(eig[kk] - n) for _, kk in members) / max(abs(n), 1)
        inv = [invariants(X0, F, h0, A0, os.path.join(OUT, "L%d_%d.obj" % (L, kk)), n) for _, kk in members]
        qs = [s["reconstruct_q_mean"][ii] for ii, _ in members]
        rows.append({"level": L, "vertices": len(V), "h": h, "k": k, "n": n, "vectors": len(members), "gamma": eig[k],
                     "gamma_err": gerr, "dist_max": max(dall), "dist_min": min(dall), "dist_rms": d["dist_rms"],
                     "rho_rms_err": float(np.median([r for r, _, _ in inv])) / max(abs(n), 1),
                     "rho_rms_err_max": max(r for r, _, _ in inv) / max(abs(n), 1), "W": d["willmore"],
                     "W_closed": d["willmore_closed_form"], "W_err": float(np.median([w for _, w, _ in inv])),
                     "W_err_max": max(w for _, w, _ in inv), "area_ratio_min": min(a for _, _, a in inv),
                     "q_mean": float(np.median(qs)), "q_mean_max": max(qs), "seconds": sec})
        r = rows[-1]
        print("level %d n=%+d (%d eigenvectors): gamma err %.3e, distance %.3e .. %.3e; median (max): rho rms %.3e "
              "(%.3e), W err %.3e (%.3e), q_mean %.4f (%.4f); smallest face area ratio %.1e" % (
                  L, n, len(members), r["gamma_err"], r["dist_min"], r["dist_max"], r["rho_rms_err"],
                  r["rho_rms_err_max"], r["W_err"], r["W_err_max"], r["q_mean"], r["q_mean_max"], r["area_ratio_min"]))
    return rows


def invariants(X0, F, h0, A0, path, n):
    """rho as a potential (area rms of H~|df~| / |df| - H - n, cotan H), abs(W / 4 pi (1 + n)^2 - 1) and the smallest
    face area ratio (|lam|^4 there: near 0 at a near-zero of lam, a near branch point of the Dirac sphere) of one result"""
    Y = np.array(tool.read_obj(path)[0], dtype=float)
    R = np.sqrt(tool.area(Y, F) / (4 * np.pi))
    h1, _ = tool.half_density(Y / R, F)
    rho = (h1 - h0) / np.sqrt(A0)
    fa = lambda P: np.linalg.norm(np.cross(P[F[:, 1]] - P[F[:, 0]], P[F[:, 2]] - P[F[:, 0]]), axis=1)  # noqa: E731
    return (float(np.sqrt((A0 * (rho - n) ** 2).sum() / A0.sum())),
            abs((h1 ** 2).sum() / (4 * np.pi * (1 + n) ** 2) - 1), float((fa(Y / R) / fa(X0)).min()))


def orders(rows, key):
    """observed order between consecutive levels, per n: log(e1/e2) / log(h1/h2)"""
    out = {}
    for n in sorted({r["n"] for r in rows if r["n"]}, key=lambda n: (abs(n + 0.5), n)):
        rs = sorted([r for r in rows if r["n"] == n], key=lambda r: r["level"])
        out[n] = [math.log(a[key] / b[key]) / math.log(a["h"] / b["h"]) if a[key] > 0 and b[key] > 0 else float("nan")
                  for a, b in zip(rs, rs[1:])]
    return out


def table(rows):
    ns = sorted({r["n"] for r in rows if r["n"]}, key=lambda n: (abs(n + 0.5), n))
    levels = sorted({r["level"] for r in rows})
    lines = []
    for key, name in (("gamma_err", "abs(gamma - n) / abs(n), cluster max"), ("dist_max", "max vertex distance / size, cluster max"),
                      ("dist_min", "max vertex distance / size, cluster min"),
                      ("rho_rms_err", "rms (rho - n) / abs(n) (cotan H), cluster median"), ("W_err", "abs(W / (4 pi (1+n)^2) - 1), cluster median"),
                      ("q_mean", "q_mean, cluster median"), ("q_mean_max", "q_mean, cluster max")):
        lines.append("| %s | %s |" % (name, " | ".join("n = %d" % n for n in ns)))
        lines.append("|---|%s" % ("---|" * len(ns)))
        for L in levels:
            by = {r["n"]: r for r in rows if r["level"] == L}
            lines.append("| level %d (%d vertices) | %s |" % (L, by[ns[0]]["vertices"], " | ".join(
                "%.3f" % by[n][key] if key.startswith("q_mean") else "%.2e" % by[n][key] for n in ns)))
        if not key.startswith("q_mean"):
            od = orders(rows, key)
            for j in range(len(levels) - 1):
                lines.append("| order, level %d -> %d | %s |" % (levels[j], levels[j + 1],
                                                               " | ".join("%.2f" % od[n][j] for n in ns)))
        lines.append("")
    return "\n".join(lines)


def plot(rows, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    ns = sorted({r["n"] for r in rows if r["n"]}, key=lambda n: (abs(n + 0.5), n))
    fig, axs = plt.subplots(1, 4, figsize=(16, 4))
    for ax, (key, title) in zip(axs, (("gamma_err", "eigenvalue |gamma - n| / |n| (cluster max)"),
                                      ("dist_max", "surface: max vertex distance / size (cluster max)"),
                                      ("rho_rms_err", "rho - n, area rms / |n| (cotan H, cluster median)"),
                                      ("W_err", "|W / 4 pi (1+n)^2 - 1| (cluster median)"))):
        for n in ns:
            rs = sorted([r for r in rows if r["n"] == n], key=lambda r: r["level"])
            ax.loglog([r["h"] for r in rs], [r[key] for r in rs], "o-", label="n = %d" % n)
        hs = np.array(sorted({r["h"] for r in rows}))
        ref = max(r[key] for r in rows if r["h"] == hs[-1])
        for p, ls in ((1, ":"), (2, "--")):
            ax.loglog(hs, ref * (hs / hs[-1]) ** p, "k" + ls, lw=0.8, label="order %d" % p)
        ax.set_xlabel("mean edge length h")
        ax.set_title(title, fontsize=9)
        ax.grid(True, which="both", alpha=0.3)
    axs[0].legend(fontsize=7)
    fig.suptitle("crane2011 Fig. 9/11: confsurf's Dirac spheres (unit icosphere levels %s) against the closed forms" %
                 ", ".join(str(L) for L in sorted({r["level"] for r in rows})), fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=90)


def main():
    levels = [int(x) for x in (sys.argv[1] if len(sys.argv) > 1 else "2 3 4 5").split()]
    os.makedirs(OUT, exist_ok=True)
    rows = []
    for L in levels:
        rows += run_level(L)
    with open(os.path.join(ROOT, "runs", "results", "study_dirac_spheres.csv"), "w", newline="") as fp:
        w = csv.DictWriter(fp, COLS)
        w.writeheader()
        w.writerows(rows)
    md = table(rows)
    open(os.path.join(ROOT, "runs", "results", "study_dirac_spheres_table.md"), "w").write(md + "\n")
    print(md)
    if len(levels) > 1:
        plot(rows, os.path.join(ROOT, "docs", "img", "dirac_spheres_convergence.png"))
    if 4 in levels:
        pictures(os.path.join(ROOT, "docs", "img", "dirac_spheres_closed_form.png"))


def pictures(path):
    """level 4: each computed Dirac sphere (top) above the nearest closed form (bottom), one camera per column"""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import render_mesh as rm
    V0, F = rm.read_obj(os.path.join(OUT, "ico4.obj"))
    _, _, A0 = rm.face_geometry(V0, F)
    cases = ((4, 1), (28, -3), (16, 2), (36, 3))
    fig = plt.figure(figsize=(3.6 * len(cases), 7.4))
    for col, (k, n) in enumerate(cases):
        Vh, _ = rm.read_obj(os.path.join(OUT, "L4_%d.obj" % k))
        Vc, _ = rm.read_obj(os.path.join(OUT, "C4_%d.obj" % k))
        box = rm.box_of(np.vstack([Vh, Vc]))
        d = np.linalg.norm(Vh - Vc, axis=1).max() / np.sqrt(rm.face_geometry(Vh, F)[2].sum() / 2 / (4 * np.pi))
        for row, (V, name) in enumerate(((Vh, "confsurf, level 4: max distance %.1e" % d), (Vc, "closed form"))):
            ax = fig.add_subplot(2, len(cases), row * len(cases) + col + 1, projection="3d")
            rm.draw(ax, V, F, rm.area_ratio(V, F, A0), (20, 30), "n = %d, W = 4 pi (1+n)^2 = %g pi\n%s" % (
                n, 4 * (1 + n) ** 2, name), box)
    fig.suptitle("Dirac spheres (crane2011 Fig. 9, 11): eigenvectors of Eq. 6 on the unit sphere through Eq. 8 (top), "
                 "the nearest closed form int conj(lam) dx lam (bottom)\ncolour: log10 face area / input face area",
                 fontsize=9)
    plt.tight_layout()
    plt.savefig(path, dpi=80)
    print("wrote %s" % path)

if __name__ == "__main__":
    main()
