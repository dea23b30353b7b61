#!/usr/bin/env python3
"""Writes the binary PLY test files (committed; rerun only to change them):
tetra_binary.ply      the tetrahedron of tetra.obj, binary_little_endian, with extra properties of several
                      types and an extra element that the reader must skip
truncated_binary.ply  the same file cut inside the face data
bigendian.ply         a binary_big_endian file (unsupported: must be refused)"""
import struct

V = [(0, 0, 0), (1.25, 0, 0), (0, 1.5, 0), (0, 0, 0.75)]
F = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]


def tetra(endian, fmt):
    head = ("ply\nformat %s 1.0\ncomment tetrahedron of tetra.obj\n"
            "element vertex 4\nproperty short id\nproperty float x\nproperty double y\nproperty float z\n"
            "property list uchar ushort tags\nproperty uchar alpha\n"
            "element face 4\nproperty int8 flags\nproperty list uchar int vertex_indices\nproperty double quality\n"
            "element material 2\nproperty list int uchar name\nproperty float shininess\n"
            "end_header\n") % fmt
    e = endian
    data = b""
    for i, (x, y, z) in enumerate(V):
        data += struct.pack(e + "hfdf", i, x, y, z) + struct.pack(e + "B", i) + struct.pack(e + "%dH" % i, *range(i)) + struct.pack(e + "B", 200)
    for i, f in enumerate(F):
        data += struct.pack(e + "bB3id", -i, 3, *f, 0.5 * i)
    for name in (b"red", b"plastic"):
        data += struct.pack(e + "i", len(name)) + name + struct.pack(e + "f", 1.5)
    return head.encode() + data


full = tetra("<", "binary_little_endian")
open("tetra_binary.ply", "wb").write(full)
open("truncated_binary.ply", "wb").write(full[:len(full) - 2 * 22 - 30])  # cut inside face 2
open("bigendian.ply", "wb").write(tetra(">", "binary_big_endian"))
