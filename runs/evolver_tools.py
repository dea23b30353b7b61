#!/usr/bin/env python3
"""Helpers of runs/bench_evolver.sh (numpy; run with /usr/bin/python3).
  fe  IN.obj OUT.fe           Surface Evolver datafile of a triangle mesh: vertices, oriented edges, faces with
                              tension 0 and the energy star_perp_sq_mean_curvature (int H^2, H the mean of the
                              principal curvatures: 4 pi on a round sphere, 2 pi^2 on the Clifford torus)
  dump IN.dmp OUT.obj         the vertices and faces of an Evolver dump as an OBJ (vertex ids kept: Evolver only
                              flips edges here, so vertex i is still input vertex i)
  stats INPUT.obj RESULT.obj  q_mean/q_max of RESULT against INPUT on the input's faces (crane2011 Sec. 6.1,
                              weighted by input face area, as confsurf's -reference), the smallest angle of RESULT's
                              own faces, as JSON"""
import json
import os
import sys
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'scripts'))
import objio  # noqa: E402  (scripts/objio.py, the project's OBJ reader)


def read_obj(p):
    V, F = objio.read_obj(p)
    return np.array(V), np.array(F)


def write_fe(obj, fe):
    V, F = read_obj(obj)
    E, el = {}, []

    def edge(a, b):
        if (b, a) in E:
            return -E[(b, a)]
        if (a, b) not in E:
            el.append((a, b))
            E[(a, b)] = len(el)
        return E[(a, b)]
    faces = [[edge(f[0], f[1]), edge(f[1], f[2]), edge(f[2], f[0])] for f in F]
    with open(fe, 'w') as o:
        o.write(f"// {obj}: written by runs/evolver_tools.py\n")
        o.write("quantity willmore energy method star_perp_sq_mean_curvature global\n\nvertices\n")
        for i, v in enumerate(V):
            o.write(f"{i + 1} {v[0]!r} {v[1]!r} {v[2]!r}\n")
        o.write("\nedges\n")
        for i, (a, b) in enumerate(el):
            o.write(f"{i + 1} {a + 1} {b + 1}\n")
        o.write("\nfaces\n")
        for i, f in enumerate(faces):
            o.write(f"{i + 1} {f[0]} {f[1]} {f[2]} tension 0\n")
        o.write("\nread\n")


def read_dump(dmp, obj):
    sec, V, E, F = None, {}, {}, []
    for l in open(dmp):
        s = l.split("//")[0].split()
        if not s:
            continue
        key = s[0].lower()
        if key in ("vertices", "edges", "faces", "facets", "bodies"):
            sec = key
            continue
        if key == "read":
            break
        if not s[0].lstrip('-').isdigit():
            continue
        if sec == "vertices":
            V[int(s[0])] = [float(t) for t in s[1:4]]
        elif sec == "edges":
            E[int(s[0])] = (int(s[1]), int(s[2]))
        elif sec in ("faces", "facets"):
            ids = [int(t) for t in s[1:4]]
            F.append([E[e][0] if e > 0 else E[-e][1] for e in ids])
    ids = sorted(V)
    index = {v: i for i, v in enumerate(ids)}
    with open(obj, 'w') as o:
        for v in ids:
            o.write("v %r %r %r\n" % tuple(V[v]))
        for f in F:
            o.write("f %d %d %d\n" % tuple(index[v] + 1 for v in f))


def frame(P):
    e1, e2 = P[:, 1] - P[:, 0], P[:, 2] - P[:, 0]
    n = np.cross(e1, e2)
    u = e1 / np.linalg.norm(e1, axis=1)[:, None]
    w = np.cross(n / np.linalg.norm(n, axis=1)[:, None], u)
    return np.stack([np.stack([(e1 * u).sum(1), (e1 * w).sum(1)], 1), np.stack([(e2 * u).sum(1), (e2 * w).sum(1)], 1)], 2)


def stats(inp, res):
    V0, F0 = read_obj(inp)
    V, F = read_obj(res)
    A = np.linalg.solve(frame(V0[F0]).transpose(0, 1, 2), np.eye(2)[None].repeat(len(F0), 0))  # E0^-1
    M = frame(V[F0]) @ A
    s = np.linalg.svd(M, compute_uv=False)
    q = s[:, 0] / s[:, 1]
    a0 = 0.5 * np.linalg.norm(np.cross(V0[F0][:, 1] - V0[F0][:, 0], V0[F0][:, 2] - V0[F0][:, 0]), axis=1)
    P = V[F]
    ang = []
    for k in range(3):
        u, w = P[:, (k + 1) % 3] - P[:, k], P[:, (k + 2) % 3] - P[:, k]
        c = (u * w).sum(1) / np.linalg.norm(u, axis=1) / np.linalg.norm(w, axis=1)
        ang.append(np.degrees(np.arccos(np.clip(c, -1, 1))))
    return {"q_mean": float((q * a0).sum() / a0.sum()), "q_max": float(q.max()), "min_angle": float(np.min(ang))}


if __name__ == "__main__":
    if sys.argv[1] == "fe":
        write_fe(sys.argv[2], sys.argv[3])
    elif sys.argv[1] == "dump":
        read_dump(sys.argv[2], sys.argv[3])
    elif sys.argv[1] == "stats":
        print(json.dumps(stats(sys.argv[2], sys.argv[3])))
