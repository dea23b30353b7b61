#!/usr/bin/env python3
"""Writes the textured test meshes of issue 38 (tests/cases/texture_io.sh), numbers in %.17g so that a read and a
write (also %.17g) give the same text:
  uv_sphere_seam.obj  a latitude-longitude sphere, 12 segments around and 6 bands (62 vertices, 120 faces, closed,
                      outward), UVs u = longitude / 2 pi, v = 1 - colatitude / pi: the meridian u = 0 = 1 is a seam
                      (its 5 ring vertices carry u = 0 on one side and u = 1 on the other) and each pole carries one
                      UV per face around it (u = (k + 1/2) / 12), so 12 + 5 x 13 + 12 = 89 vt lines.
  tetra_uv_vertex.ply   the tetrahedron of tetra_uv.obj (ascii) with per-vertex UVs s t (float, an extra property
                        between them): vertex i has the UV of vt i of tetra_uv.obj
  tetra_texcoord.ply    the same with per-corner UVs, the face list texcoord (ascii): the UVs of tetra_uv.obj's corners
  tetra_texcoord_binary.ply  the same, binary_little_endian, float texcoord, and a per-vertex texture_u texture_v pair
                        that the per-corner list overrides
  bad_uv_*.obj, bad_uv_*.ply  one defect each, refused with the file and line (tests/cases/texture_io.sh)
Usage: python3 tests/data/make_uv_meshes.py [DIR] (default: the folder of this script)."""
import math, os, struct, sys

def uv_sphere(n=12, m=6):
    v = [(0.0, 0.0, 1.0)]
    for j in range(1, m):
        th = math.pi * j / m
        for k in range(n):
            ph = 2 * math.pi * k / n
            v.append((math.sin(th) * math.cos(ph), math.sin(th) * math.sin(ph), math.cos(th)))
    v.append((0.0, 0.0, -1.0))
    south = len(v) - 1
    ring = lambda j, k: 1 + (j - 1) * n + k % n               # vertex of ring j (1..m-1), segment k
    uv, top, rows, bot = [], [], {}, []
    for k in range(n): top.append(len(uv)); uv.append(((k + 0.5) / n, 1.0))
    for j in range(1, m):
        rows[j] = len(uv)
        for k in range(n + 1): uv.append((k / n, 1.0 - j / m))   # k = n: the seam's second UV
    for k in range(n): bot.append(len(uv)); uv.append(((k + 0.5) / n, 0.0))
    t = lambda j, k: rows[j] + k
    f = []  # (vertex, uv) corners, counter-clockwise seen from outside
    for k in range(n):
        f.append([(0, top[k]), (ring(1, k), t(1, k)), (ring(1, k + 1), t(1, k + 1))])
    for j in range(1, m - 1):
        for k in range(n):
            a, b, c, d = (ring(j, k), t(j, k)), (ring(j, k + 1), t(j, k + 1)), (ring(j + 1, k), t(j + 1, k)), (ring(j + 1, k + 1), t(j + 1, k + 1))
            f.append([a, c, d]); f.append([a, d, b])
    for k in range(n):
        f.append([(south, bot[k]), (ring(m - 1, k + 1), t(m - 1, k + 1)), (ring(m - 1, k), t(m - 1, k))])
    return v, uv, f

def volume(v, f):
    s = 0
    for c in f:
        a, b, d = (v[i] for i, _ in c)
        s += (a[0] * (b[1] * d[2] - b[2] * d[1]) + a[1] * (b[2] * d[0] - b[0] * d[2]) + a[2] * (b[0] * d[1] - b[1] * d[0])) / 6
    return s

def write(path, v, uv, f, what):
    assert volume(v, f) > 0, "not outward"
    with open(path, "w") as o:
        o.write("# %s\n# provenance: tests/data/make_uv_meshes.py (issue 38), %d vertices, %d faces, %d vt\n" % (what, len(v), len(f), len(uv)))
        for p in v: o.write("v %.17g %.17g %.17g\n" % p)
        for p in uv: o.write("vt %.17g %.17g\n" % p)
        for c in f: o.write("f " + " ".join("%d/%d" % (i + 1, t + 1) for i, t in c) + "\n")

TV = [(0, 0, 0), (1.25, 0, 0), (0, 1.5, 0), (0, 0, 0.75)]
TF = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]
TUV = [(0, 0), (1, 0), (0, 1), (0.5, 0.25)]
TFUV = [(0, 2, 1), (0, 1, 3), (0, 3, 1), (1, 2, 3)]

def ply_files(out):
    head = "ply\nformat %s 1.0\ncomment tetrahedron of tetra_uv.obj (tests/data/make_uv_meshes.py, issue 38)\n"
    with open(os.path.join(out, "tetra_uv_vertex.ply"), "w") as o:
        o.write(head % "ascii" + "element vertex 4\nproperty float x\nproperty float y\nproperty float z\nproperty float s\n"
                "property uchar red\nproperty float t\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n")
        for p, t in zip(TV, TUV): o.write("%g %g %g %g 7 %g\n" % (p + (t[0], t[1])))
        for f in TF: o.write("3 %d %d %d\n" % f)
    with open(os.path.join(out, "tetra_texcoord.ply"), "w") as o:
        o.write(head % "ascii" + "element vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                "element face 4\nproperty list uchar int vertex_indices\nproperty list uchar float texcoord\nend_header\n")
        for p in TV: o.write("%g %g %g\n" % p)
        for f, t in zip(TF, TFUV): o.write("3 %d %d %d 6 " % f + " ".join("%g %g" % TUV[k] for k in t) + "\n")
    with open(os.path.join(out, "tetra_texcoord_binary.ply"), "wb") as o:
        o.write((head % "binary_little_endian" + "element vertex 4\nproperty double x\nproperty double y\nproperty double z\n"
                 "property float texture_u\nproperty float texture_v\nelement face 4\nproperty list uchar int vertex_indices\n"
                 "property list uchar float texcoord\nend_header\n").encode())
        for p in TV: o.write(struct.pack("<3d2f", *p, 9, 9))
        for f, t in zip(TF, TFUV): o.write(struct.pack("<B3iB6f", 3, *f, 6, *[c for k in t for c in TUV[k]]))

BAD = {  # file: (text, the line the reader names)
    "bad_uv_mixed_faces.obj": "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvt 0 0\nvt 1 0\nvt 0 1\nf 1/1 3/3 2/2\nf 1 2 4\n",
    "bad_uv_mixed_corners.obj": "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nf 1/1 2/2 3\n",
    "bad_uv_out_of_range.obj": "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nf 1/1 2/2 3/3\n",
    "bad_uv_relative.obj": "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nf 1/-1 2/-2 3/-3\nvt 0 1\n",
    "bad_uv_nan.obj": "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt nan 0\nvt 0 1\nf 1/1 2/2 3/3\n",
    "bad_uv_short.obj": "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 0.5\nvt 0 1\nf 1/1 2/2 3/3\n",
    "bad_uv_texcoord_count.ply": "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
        "element face 1\nproperty list uchar int vertex_indices\nproperty list uchar float texcoord\nend_header\n"
        "0 0 0\n1 0 0\n0 1 0\n3 0 1 2 4 0 0 1 0\n",
    "bad_uv_inf.ply": "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
        "property float u\nproperty float v\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
        "0 0 0 0 0\n1 0 0 inf 0\n0 1 0 0 1\n3 0 1 2\n",
}

if __name__ == "__main__":
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.dirname(os.path.abspath(__file__))
    write(os.path.join(out, "uv_sphere_seam.obj"), *uv_sphere(), "latitude-longitude sphere with a UV seam on the meridian u = 0 = 1 and per-face UVs at the poles")
    ply_files(out)
    for name, text in BAD.items():
        open(os.path.join(out, name), "w").write(text)
