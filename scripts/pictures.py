#!/usr/bin/env python3
"""The pictures of a finished run: the input and the final surface from one camera, coloured by mean curvature
and by the quasi-conformal error Q, and the history plots (headless matplotlib, numpy only).

  /usr/bin/python3 scripts/pictures.py DIR --input IN.obj --result OUT.obj [--history H.csv] [--summary S.json]
                                       [--title T] [--view ELEV,AZIM]
  /usr/bin/python3 scripts/pictures.py DIR --series VTU/series.pvd [...]   (input = first step, result = last;
                                       points at the same input position are merged: a parallel run's pieces
                                       and the seams of texture coordinates repeat vertices)
                                       [--texture_check FILE.png] [--checks N]
  (the same as: /usr/bin/python3 scripts/render_mesh.py pictures DIR ...)

Writes into DIR:
  mean_curvature.png   input | final, faces coloured by the mean curvature H (one colour scale for both, centred
                       on the input's median H, clipped at its 2nd/98th percentiles), shaded by the face normal
  quasi_conformal.png  the final surface from the same camera and from the opposite side, faces coloured by
                       Q = sigma_max/sigma_min of the affine map input triangle -> final triangle (1: conformal)
  history.png          the history CSV against iteration: energy, EL residual, constraint violations, step size
                       (log scales where the values are positive); only the columns the file has
  texture.png          when the input has texture coordinates (OBJ vt with f v/vt, or the series' TCoords): input |
                       final from one camera with a checkerboard painted in UV (--checks squares per unit of u and
                       v), each triangle subdivided in UV so the squares are visible at any mesh size; the title
                       gives texture_q_mean of each (Q of the map UV triangle -> surface triangle, UV-area
                       weighted: src/geometry/texture_quality.c). --texture_check FILE.png writes it there instead.
  spectrum.png         with --summary of -task spectrum (no surfaces): the eigenvalues
  pictures.json        what was drawn: per picture its panels' surface bounding boxes in pixels (for the tests),
                       the mean curvature range, q_mean and q_max (compare with the summary's)
H is the pointwise mean curvature of confsurf (soliman2021 Eq. 27, src/geometry/mean_curvature.c):
h_i = 1/2 |(L f)_i| / A_i with the cotan Laplacian L and the barycentric vertex area A_i, signed by the
area-weighted vertex normal (positive on a sphere with outward normals); a face gets the mean of its vertices.
Q is the quasi-conformal error of src/geometry/quasi_conformal.c (crane2011 Sec. 6.1), q_mean weighted by input
face area. Renders are orthographic, back faces culled, painter's order (2-D polygons, not mplot3d: about 2 s for
75k faces). Needs Debian's python3-matplotlib and python3-numpy: run with /usr/bin/python3."""
import argparse
import csv
import json
import os
import sys
import time

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from render_mesh import face_geometry, read_obj  # noqa: E402

DPI = 100


def mean_curvature(V, F):
    """Signed pointwise mean curvature per vertex, h = 1/2 (L f . n) / A (see the module doc)."""
    T, n, a2 = face_geometry(V, F)
    nv = len(V)
    Lf = np.zeros_like(V)
    for k in range(3):
        i, j, o = F[:, k], F[:, (k + 1) % 3], F[:, (k + 2) % 3]
        u, w = V[i] - V[o], V[j] - V[o]
        cot = np.einsum("ij,ij->i", u, w) / (np.linalg.norm(np.cross(u, w), axis=1) + 1e-300)
        d = 0.5 * cot[:, None] * (V[i] - V[j])
        np.add.at(Lf, i, d)
        np.add.at(Lf, j, -d)
    A = np.zeros(nv)
    N = np.zeros_like(V)
    for k in range(3):
        np.add.at(A, F[:, k], a2 / 6.0)
        np.add.at(N, F[:, k], n * a2[:, None])
    N /= np.linalg.norm(N, axis=1)[:, None] + 1e-300
    h = 0.5 * np.linalg.norm(Lf, axis=1) / np.maximum(A, 1e-300)
    return np.where(np.einsum("ij,ij->i", Lf, N) >= 0, h, -h)


def quasi_conformal(V0, V, F):
    """Per face sigma_max/sigma_min of the affine map from the input triangle to the final one."""
    def frame(X):
        e1, e2 = X[F[:, 1]] - X[F[:, 0]], X[F[:, 2]] - X[F[:, 0]]
        l1 = np.linalg.norm(e1, axis=1)
        u = e1 / l1[:, None]
        nrm = np.cross(e1, e2)
        v = np.cross(nrm / np.linalg.norm(nrm, axis=1)[:, None], u)
        M = np.zeros((len(F), 2, 2))  # columns: the two edges in the triangle's own orthonormal frame
        M[:, 0, 0] = l1
        M[:, 0, 1] = np.einsum("ij,ij->i", e2, u)
        M[:, 1, 1] = np.einsum("ij,ij->i", e2, v)
        return M
    M0, M1 = frame(V0), frame(V)
    J = M1 @ np.linalg.inv(M0)
    s = np.linalg.svd(J, compute_uv=False)
    return s[:, 0] / s[:, 1], np.linalg.norm(np.cross(V0[F[:, 1]] - V0[F[:, 0]], V0[F[:, 2]] - V0[F[:, 0]]), axis=1)


def camera(view):
    el, az = np.radians(view[0]), np.radians(view[1])
    d = np.array([np.cos(el) * np.cos(az), np.cos(el) * np.sin(az), np.sin(el)])  # towards the viewer
    right = np.cross([0.0, 0.0, 1.0], d)
    right = right / np.linalg.norm(right) if np.linalg.norm(right) > 1e-9 else np.array([0.0, 1.0, 0.0])
    up = np.cross(d, right)
    return d, right, up


def draw_surface(ax, V, F, values, cmap, norm, view, frame_box, two_sided=False):
    """Orthographic render into a 2-D axes; frame_box (centre, radius) fixes the camera's extent. two_sided: back
    faces drawn too, shaded by their flipped normal (open surfaces, which a map may turn over)."""
    d, right, up = camera(view)
    T, n, _ = face_geometry(V, F)
    if two_sided:
        n = n * np.where(n @ d < 0, -1.0, 1.0)[:, None]
    vis = (n @ d) > 0 if not two_sided else np.ones(len(F), dtype=bool)
    P = np.stack([T @ right, T @ up], axis=-1)[vis]
    depth = (T @ d).mean(axis=1)[vis]
    order = np.argsort(depth)
    light = np.array(d) * 0.8 + np.array(up) * 0.4 + np.array(right) * 0.2
    light /= np.linalg.norm(light)
    shade = 0.35 + 0.65 * np.clip(n[vis] @ light, 0, 1)
    col = cmap(norm(values[vis]))
    col[:, :3] *= shade[:, None]
    ax.add_collection(PolyCollection(P[order], facecolors=col[order], edgecolors="none", antialiaseds=False, closed=False))
    c, r = frame_box
    cx, cy = c @ right, c @ up
    ax.set_xlim(cx - r, cx + r)
    ax.set_ylim(cy - r, cy + r)
    ax.set_aspect("equal")
    ax.set_axis_off()
    lo, hi = P.reshape(-1, 2).min(0), P.reshape(-1, 2).max(0)
    return lo, hi


def pixel_box(fig, ax, lo, hi):
    """The data box lo..hi of ax in image pixels (x from the left, y from the top)."""
    ax.apply_aspect()
    (x0, y0), (x1, y1) = ax.transData.transform([lo, hi])
    H = fig.get_size_inches()[1] * DPI
    return [int(np.floor(min(x0, x1))), int(np.floor(H - max(y0, y1))), int(np.ceil(max(x0, x1))), int(np.ceil(H - min(y0, y1)))]


def is_open(F):
    """Some edge has one face (a boundary): drawn two-sided, as a map may turn the surface over."""
    e = np.sort(np.concatenate([F[:, [0, 1]], F[:, [1, 2]], F[:, [2, 0]]]), axis=1)
    _, count = np.unique(e, axis=0, return_counts=True)
    return bool((count == 1).any())


def surfaces(outdir, V0, V, F, view, title, info):
    two = is_open(F)
    both = np.vstack([V0, V])
    lo, hi = both.min(0), both.max(0)
    box = ((lo + hi) / 2, 0.55 * np.linalg.norm(hi - lo) / np.sqrt(3) * 1.05)
    # mean curvature, one scale centred on the input's median
    h0 = mean_curvature(V0, F)[F].mean(axis=1)
    h1 = mean_curvature(V, F)[F].mean(axis=1)
    med = np.median(h0)
    half = max(np.percentile(np.abs(np.concatenate([h0, h1]) - med), 96), 1e-12)
    norm = matplotlib.colors.Normalize(med - half, med + half)
    cmap = plt.cm.coolwarm
    fig, axs = plt.subplots(1, 2, figsize=(9, 4.6))
    boxes = []
    for ax, X, h, lab in ((axs[0], V0, h0, "input"), (axs[1], V, h1, "final")):
        lo2, hi2 = draw_surface(ax, X, F, h, cmap, norm, view, box, two)
        ax.set_title(lab, fontsize=10)
        boxes.append((ax, lo2, hi2))
    fig.colorbar(matplotlib.cm.ScalarMappable(norm=norm, cmap=cmap), ax=list(axs), shrink=0.8, label="mean curvature H")
    fig.suptitle((title + ": " if title else "") + "mean curvature, input and final (same camera)", fontsize=10)
    info["mean_curvature.png"] = {"panels": [pixel_box(fig, ax, a, b) for ax, a, b in boxes]}
    fig.savefig(os.path.join(outdir, "mean_curvature.png"), dpi=DPI)
    plt.close(fig)
    info["h_input"] = [float(h0.min()), float(h0.max())]
    info["h_final"] = [float(h1.min()), float(h1.max())]
    # quasi-conformal error of the final surface against the input
    q, a0 = quasi_conformal(V0, V, F)
    info["q_mean"] = float((q * a0).sum() / a0.sum())
    info["q_max"] = float(q.max())
    qhi = max(float(np.percentile(q, 99.5)), 1.0 + 1e-6)
    qnorm = matplotlib.colors.Normalize(1.0, qhi)
    qcmap = plt.cm.viridis
    fig, axs = plt.subplots(1, 2, figsize=(9, 4.6))
    boxes = []
    for ax, vw, lab in ((axs[0], view, "final"), (axs[1], (-view[0], view[1] + 180), "final, from the other side")):
        lo2, hi2 = draw_surface(ax, V, F, q, qcmap, qnorm, vw, box, two)
        ax.set_title(lab, fontsize=10)
        boxes.append((ax, lo2, hi2))
    fig.colorbar(matplotlib.cm.ScalarMappable(norm=qnorm, cmap=qcmap), ax=list(axs), shrink=0.8,
                 label="Q = sigma_max / sigma_min (1: conformal)")
    fig.suptitle("%squasi-conformal error against the input: q_mean %.4g, q_max %.4g" %
                 (title + ": " if title else "", info["q_mean"], info["q_max"]), fontsize=10)
    info["quasi_conformal.png"] = {"panels": [pixel_box(fig, ax, a, b) for ax, a, b in boxes]}
    fig.savefig(os.path.join(outdir, "quasi_conformal.png"), dpi=DPI)
    plt.close(fig)


# (column, label, log scale) per panel; the first columns a history has are drawn
PANELS = [
    ([("energy", "energy", False), ("willmore_bs", "W (Bobenko-Schroeder)", False), ("willmore", "W", False)], "energy"),
    ([("el_residual", "EL residual", True)], "Euler-Lagrange residual"),
    ([("conformal_violation", "conformal |c|inf", True), ("constraint_violation", "other constraints", True)], "constraint violation"),
    ([("t", "t", True), ("dt", "dt", True)], "step size"),
]


def history(outdir, path, title, info):
    with open(path) as fh:
        rows = list(csv.DictReader(fh))
    if not rows:
        return
    it = np.array([float(r["it"]) for r in rows])
    panels = [(cols, name) for cols, name in PANELS if any(c in rows[0] for c, _, _ in cols)]
    fig, axs = plt.subplots(1, len(panels), figsize=(3.2 * len(panels), 3.2), squeeze=False)
    for ax, (cols, name) in zip(axs[0], panels):
        logy = False
        for c, lab, log in cols:
            if c not in rows[0]:
                continue
            y = np.array([float(r[c]) for r in rows])
            if name != "energy" and not (y != 0).any():
                continue  # e.g. no constraint besides the conformal one
            if log and (y > 0).any():
                m = y > 0
                ax.semilogy(it[m], y[m], ".-", ms=3, lw=1, label=lab)
                logy = True
            else:
                ax.plot(it, y, ".-", ms=3, lw=1, label=lab)
            if name == "energy":
                break  # the flow's own energy only
        ax.set_title(name, fontsize=9)
        ax.set_xlabel("iteration", fontsize=8)
        ax.tick_params(labelsize=7)
        ax.grid(True, which="major" if not logy else "both", alpha=0.3)
        if len(ax.get_lines()) > 1:
            ax.legend(fontsize=7)
    fig.suptitle((title + ": " if title else "") + "history", fontsize=10)
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, "history.png"), dpi=DPI)
    plt.close(fig)
    info["history.png"] = {"rows": len(rows)}


def read_series(path):
    """(input positions, final positions, faces, per-corner UVs or None) from the first and last step of a ParaView
    series; the points of the first step at the same position are merged (pieces of a parallel run, texture seams)."""
    import vtu  # scripts/vtu.py
    steps = vtu.read_pvd(path)
    out = []
    for _, pvtu in (steps[0], steps[-1]):
        V, F, T, off = [], [], [], 0
        for piece in vtu.read_pvtu(pvtu):
            V.extend(piece["arrays"]["Points"]["positions"][1])
            F.extend(c + off for c in piece["arrays"]["Cells"]["connectivity"][1])
            if "TCoords" in piece["arrays"].get("PointData", {}):
                T.extend(piece["arrays"]["PointData"]["TCoords"][1])
            off += piece["points"]
        out.append((np.array(V).reshape(-1, 3), np.array(F).reshape(-1, 3), np.array(T).reshape(-1, 2) if T else None))
    if out[0][1].shape != out[1][1].shape or (out[0][1] != out[1][1]).any():
        sys.exit("pictures: %s: the first and last steps differ in connectivity" % path)
    (V0, F, T), V = out[0], out[1][0]
    UV = T[F] if T is not None and len(T) == len(V0) else None
    _, first, inv = np.unique(V0, axis=0, return_index=True, return_inverse=True)
    return V0[first], V[first], inv.reshape(-1)[F], UV


def read_obj_uv(path):
    """Per-corner texture coordinates of an OBJ (vt lines, faces f v/vt or v/vt/vn), or None."""
    vt, fuv = [], []
    with open(path) as fh:
        for line in fh:
            w = line.split()
            if not w:
                continue
            if w[0] == "vt":
                vt.append((float(w[1]), float(w[2])))
            elif w[0] == "f":
                c = [x.split("/") for x in w[1:4]]
                if len(c[0]) < 2 or not c[0][1]:
                    return None
                fuv.append([int(x[1]) - 1 if int(x[1]) > 0 else len(vt) + int(x[1]) for x in c])
    if not vt or not fuv:
        return None
    return np.array(vt)[np.array(fuv)]


def texture_q(V, F, UV):
    """Per face Q of the affine map UV triangle -> surface triangle; the UV-area weights (texture_quality.c)."""
    e1, e2 = V[F[:, 1]] - V[F[:, 0]], V[F[:, 2]] - V[F[:, 0]]
    l1 = np.linalg.norm(e1, axis=1)
    u = e1 / l1[:, None]
    nrm = np.cross(e1, e2)
    w = np.cross(nrm / np.linalg.norm(nrm, axis=1)[:, None], u)
    M = np.zeros((len(F), 2, 2))
    M[:, 0, 0], M[:, 0, 1], M[:, 1, 1] = l1, np.einsum("ij,ij->i", e2, u), np.einsum("ij,ij->i", e2, w)
    M0 = np.stack([UV[:, 1] - UV[:, 0], UV[:, 2] - UV[:, 0]], axis=-1)  # columns: the UV edges
    s = np.linalg.svd(M @ np.linalg.inv(M0), compute_uv=False)
    return s[:, 0] / s[:, 1], 0.5 * np.abs(np.linalg.det(M0))


def checker_subdivide(V, F, UV, checks, budget=400000):
    """Each triangle cut into L^2 in UV (L from the largest UV edge: 16 pieces across a square, at least 3 a face, within budget
    sub-triangles): the sub-triangles' positions and their checker colour (0/1) at the UV centroid."""
    emax = max(np.linalg.norm(UV[:, (k + 1) % 3] - UV[:, k], axis=1).max() for k in range(3))
    L = int(max(1, min(max(3, np.ceil(emax * checks * 16)), np.floor(np.sqrt(budget / len(F))))))
    tris = []
    for i in range(L):
        for j in range(L - i):
            tris.append([(i, j), (i + 1, j), (i, j + 1)])
            if i + j + 1 < L:
                tris.append([(i + 1, j), (i + 1, j + 1), (i, j + 1)])
    B = np.array([[[1 - (a + b) / L, a / L, b / L] for a, b in t] for t in tris])  # (ns, 3 corners, 3 weights)
    P = np.einsum("sck,fkd->fscd", B, V[F]).reshape(-1, 3, 3)
    W = np.einsum("sck,fkd->fscd", B, UV).reshape(-1, 3, 2).mean(axis=1)
    colour = (np.floor(W[:, 0] * checks) + np.floor(W[:, 1] * checks)) % 2
    return P.reshape(-1, 3), np.arange(3 * len(P)).reshape(-1, 3), colour, L


def texture(path, V0, V, F, UV, view, checks, title, info):
    both = np.vstack([V0, V])
    lo, hi = both.min(0), both.max(0)
    box = ((lo + hi) / 2, 0.55 * np.linalg.norm(hi - lo) / np.sqrt(3) * 1.2)  # room for a flat disk seen at an angle
    cmap = matplotlib.colors.ListedColormap(["#1d3557", "#f1faee"])
    norm = matplotlib.colors.Normalize(0, 1)
    fig, axs = plt.subplots(1, 2, figsize=(9, 4.8))
    boxes, qs = [], []
    for ax, X, lab in ((axs[0], V0, "input"), (axs[1], V, "final")):
        q, a = texture_q(X, F, UV)
        qs.append((float((q * a).sum() / a.sum()), float(q.max())))
        P, T, colour, L = checker_subdivide(X, F, UV, checks)
        lo2, hi2 = draw_surface(ax, P, T, colour, cmap, norm, view, box, two_sided=True)
        ax.set_title("%s: texture_q_mean %.4f, max %.4f" % (lab, qs[-1][0], qs[-1][1]), fontsize=9)
        boxes.append((ax, lo2, hi2))
    fig.suptitle((title + ": " if title else "") + "checkerboard in UV (%d squares per unit), input and final (same camera)" % checks, fontsize=10)
    fig.tight_layout()
    name = os.path.basename(path)
    info[name] = {"panels": [pixel_box(fig, ax, a, b) for ax, a, b in boxes], "subdivision": L}
    info["texture_q_mean_input"], info["texture_q_max_input"] = qs[0]
    info["texture_q_mean"], info["texture_q_max"] = qs[1]
    fig.savefig(path, dpi=DPI)
    plt.close(fig)


def spectrum(outdir, summary, title, info):
    ev = np.array(summary["eigenvalues"])
    fig, ax = plt.subplots(figsize=(5, 3.2))
    ax.plot(np.arange(len(ev)), ev, "o-")
    ax.set_xlabel("k", fontsize=8)
    ax.set_ylabel("eigenvalue", fontsize=8)
    ax.grid(True, alpha=0.3)
    ax.set_title((title + ": " if title else "") + "smallest eigenvalues of the Dirac problem (rho = 0)", fontsize=9)
    fig.tight_layout()
    fig.savefig(os.path.join(outdir, "spectrum.png"), dpi=DPI)
    plt.close(fig)
    info["spectrum.png"] = {"eigenvalues": len(ev)}


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("dir")
    ap.add_argument("--input")
    ap.add_argument("--result")
    ap.add_argument("--series")
    ap.add_argument("--history")
    ap.add_argument("--summary")
    ap.add_argument("--title", default="")
    ap.add_argument("--view", default="20,-60", help="camera elevation,azimuth in degrees")
    ap.add_argument("--texture_check", help="the checkerboard picture's file (default DIR/texture.png)")
    ap.add_argument("--checks", type=int, default=8, help="checkerboard squares per unit of u and v")
    a = ap.parse_args(argv)
    t0 = time.time()
    os.makedirs(a.dir, exist_ok=True)
    info = {}
    UV = None
    if a.series:
        V0, V, F, UV = read_series(a.series)
    elif a.input and a.result:
        V0, F = read_obj(a.input)
        UV = read_obj_uv(a.input)
        V, F1 = read_obj(a.result)
        if F1.shape != F.shape or (F1 != F).any():
            sys.exit("pictures: --result %s: not the connectivity of --input %s" % (a.result, a.input))
    elif a.summary and "eigenvalues" in json.load(open(a.summary)):
        V = None
    else:
        sys.exit("pictures: give --input and --result, or --series (or --summary of -task spectrum)")
    if V is not None:
        view = tuple(float(x) for x in a.view.split(","))
        info.update({"faces": len(F), "vertices": len(V)})
        surfaces(a.dir, V0, V, F, view, a.title, info)
        if UV is not None:
            texture(a.texture_check or os.path.join(a.dir, "texture.png"), V0, V, F, UV, view, a.checks, a.title, info)
    if a.history:
        history(a.dir, a.history, a.title, info)
    if a.summary:
        s = json.load(open(a.summary))
        info["summary"] = {k: s[k] for k in ("energy_initial", "energy", "willmore", "q_mean", "q_max", "texture_q_mean", "texture_q_mean_input") if k in s}
        if "eigenvalues" in s:
            spectrum(a.dir, s, a.title, info)
    info["seconds"] = time.time() - t0
    with open(os.path.join(a.dir, "pictures.json"), "w") as fh:
        json.dump(info, fh, indent=1)
    print("pictures: wrote %s in %.1f s" % (", ".join(k if k == os.path.basename(a.texture_check or "") else os.path.join(a.dir, k) for k in info if k.endswith(".png")), info["seconds"]))
    return 0


if __name__ == "__main__":
    sys.exit(main())
