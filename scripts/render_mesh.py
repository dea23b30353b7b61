#!/usr/bin/env python3
"""Pictures of flow results against their input, for docs and for looking at a run (headless matplotlib).

  /usr/bin/python3 scripts/render_mesh.py OUT.png INPUT.obj RESULT.obj [RESULT2.obj ...] [--views 3] [--title T]
                                          [--labels L1 L2 ...] [--box own|shared]
  /usr/bin/python3 scripts/render_mesh.py pairs OUT.png --pair IN RES LABEL [--pair ...] [--view ELEV AZIM] [--scale area|none]
                                          [--title T]
  /usr/bin/python3 scripts/render_mesh.py pictures DIR --input IN.obj --result OUT.obj [--history H.csv]
                                                  [--summary S.json] [--title T]

The second form (`pairs`, runs/study_real_meshes.sh) draws one row: each input beside its result under one
camera (a raw and a remeshed run of a shape side by side). The third form (`pictures`, used by `make run` and `make demo`; scripts/pictures.py documents it) draws a
finished run's pictures into DIR.

Each RESULT (same connectivity as INPUT, e.g. the -o of a flow) is drawn from a few view directions, its faces
coloured by log10 of (face area / input face area), centred on the median: blue faces have shrunk, red ones have
grown, relative to the rest; a discrete conformal map keeps neighbouring colours close, fins show as isolated red
stars, squeezes as smooth blue regions (docs/real_meshes.md). Shading by the face normal. OBJ only (v and
triangular f lines). Needs Debian's python3-matplotlib and python3-numpy (/usr/bin/python3)."""
import argparse
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import objio  # noqa: E402  (scripts/objio.py, beside this file)
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402

VIEWS = [(20, 30), (70, -60), (-10, 120)]


def read_obj(path):
    verts, faces = objio.read_obj(path, triangles_only=True)
    if not verts or not faces:
        sys.exit("%s: no vertices or faces" % path)
    return np.array(verts), np.array(faces)


def face_geometry(V, F):
    T = V[F]
    n = np.cross(T[:, 1] - T[:, 0], T[:, 2] - T[:, 0])
    a = np.linalg.norm(n, axis=1)
    return T, n / (a[:, None] + 1e-300), a


def box_of(V):
    """The cube around V: centre and half side."""
    lo, hi = V.min(0), V.max(0)
    return (lo + hi) / 2, (hi - lo).max() / 2


def draw(ax, V, F, ratio, view, title, box=None):
    T, n, _ = face_geometry(V, F)
    light = np.array([0.3, 0.3, 1.0]) / np.linalg.norm([0.3, 0.3, 1.0])
    shade = 0.35 + 0.65 * np.abs(n @ light)
    col = plt.cm.coolwarm(np.clip(ratio / 4 + 0.5, 0, 1))
    col[:, :3] *= shade[:, None]
    ax.add_collection3d(Poly3DCollection(T, facecolors=col, edgecolor="k", linewidths=0.03))
    c, r = box if box is not None else box_of(V)
    ax.set_xlim(c[0] - r, c[0] + r)
    ax.set_ylim(c[1] - r, c[1] + r)
    ax.set_zlim(c[2] - r, c[2] + r)
    ax.view_init(*view)
    ax.set_box_aspect((1, 1, 1), zoom=1.35)  # the cube fills the panel (matplotlib's default leaves ~40 % margin)
    ax.set_axis_off()
    ax.set_title(title, fontsize=8)


def area_ratio(V, F, A0):
    """log10 of face area over input face area, centred on its median."""
    _, _, A = face_geometry(V, F)
    r = np.log10(np.maximum(A, 1e-300) / A0)
    return r - np.median(r)


def pairs(argv):
    """OUT.png --pair INPUT RESULT LABEL ... [--view ELEV AZIM]: one row, each pair's input (grey) beside its result,
    the two under one camera (a cube around both; the result scaled to the input's area unless --scale none); pairs may have different connectivities (a raw and a remeshed
    input of one shape)."""
    ap = argparse.ArgumentParser(prog="render_mesh.py pairs", description=pairs.__doc__)
    ap.add_argument("out")
    ap.add_argument("--pair", nargs=3, action="append", required=True, metavar=("INPUT", "RESULT", "LABEL"))
    ap.add_argument("--view", nargs=2, type=float, default=list(VIEWS[0]), metavar=("ELEV", "AZIM"))
    ap.add_argument("--scale", choices=["area", "none"], default="area",
                    help="area: the result scaled to the input's area about its centroid (default); none: as it is")
    ap.add_argument("--title", default="")
    a = ap.parse_args(argv)
    n = 2 * len(a.pair)
    fig = plt.figure(figsize=(3.2 * n, 3.6))
    for k, (inp, res, label) in enumerate(a.pair):
        V0, F = read_obj(inp)
        V, F1 = read_obj(res)
        if F1.shape != F.shape or (F1 != F).any():
            sys.exit("%s: not the connectivity of %s" % (res, inp))
        _, _, A0 = face_geometry(V0, F)
        if a.scale == "area":  # W and the conformal class do not see a similarity: show the shape, not its size
            _, _, A = face_geometry(V, F)
            V = V0.mean(0) + np.sqrt(A0.sum() / A.sum()) * (V - V.mean(0))
        box = box_of(np.vstack([V0, V]))
        for j, (X, name) in enumerate(((V0, "input"), (V, "result"))):
            ax = fig.add_subplot(1, n, 2 * k + j + 1, projection="3d")
            draw(ax, X, F, area_ratio(X, F, A0), tuple(a.view), "%s: %s" % (label, name) if name == "input" else name, box)
    fig.suptitle((a.title + "   " if a.title else "") + "colour: log10 face area / input face area (blue -2 ... red +2, median 0)",
                 fontsize=9)
    plt.tight_layout()
    plt.savefig(a.out, dpi=85)
    print("wrote %s" % a.out)
    return 0


def main():
    if len(sys.argv) > 1 and sys.argv[1] == "pairs":
        sys.exit(pairs(sys.argv[2:]))
    if len(sys.argv) > 1 and sys.argv[1] == "pictures":
        import pictures  # scripts/pictures.py, next to this file
        sys.exit(pictures.main(sys.argv[2:]))
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("out")
    ap.add_argument("input")
    ap.add_argument("results", nargs="+")
    ap.add_argument("--views", type=int, default=3, choices=[1, 2, 3])
    ap.add_argument("--title", default="")
    ap.add_argument("--labels", nargs="+", help="one panel title per RESULT (default: its file name)")
    ap.add_argument("--box", choices=["own", "shared"], default="own",
                    help="own: each mesh fills its panel; shared: one cube around all meshes, the same camera for all")
    a = ap.parse_args()
    if a.labels and len(a.labels) != len(a.results):
        sys.exit("--labels: %d labels for %d results" % (len(a.labels), len(a.results)))
    V0, F = read_obj(a.input)
    _, _, A0 = face_geometry(V0, F)
    views = VIEWS[: a.views]
    meshes = []
    for path in a.results:
        V, F1 = read_obj(path)
        if F1.shape != F.shape or (F1 != F).any():
            sys.exit("%s: not the connectivity of %s" % (path, a.input))
        meshes.append(V)
    box = box_of(np.vstack(meshes)) if a.box == "shared" else None
    fig = plt.figure(figsize=(4.5 * len(a.results), 4.5 * len(views)))
    for col, (path, V) in enumerate(zip(a.results, meshes)):
        ratio = area_ratio(V, F, A0)
        for row, view in enumerate(views):
            ax = fig.add_subplot(len(views), len(a.results), row * len(a.results) + col + 1, projection="3d")
            label = a.labels[col] if a.labels else path.split("/")[-1]
            draw(ax, V, F, ratio, view, (a.title + " " if a.title else "") + label, box)
    fig.suptitle("face area / input face area, log10 (blue -2 ... red +2, median 0)", fontsize=9)
    plt.tight_layout()
    plt.savefig(a.out, dpi=70)
    print("wrote %s" % a.out)


if __name__ == "__main__":
    main()
