#!/usr/bin/env python3
"""Reads confsurf's ParaView output without ParaView (standard library only: any python3): the .pvd series, the
.pvtu of a step and its .vtu pieces, in each -viewer_format (ascii; binary = appended raw data with UInt64
headers; zlib = the same, compressed in blocks). Used by the tests (tests/cases/foundation_viewer.sh).

  python3 scripts/vtu.py DIR/series.pvd     # prints per step: points, cells, each array's name, size and range

  import vtu; steps = vtu.read_pvd(path)    # [(time, pvtu path)]
  pieces = vtu.read_pvtu(path)              # [piece]; piece = vtu.read_vtu(path)
  piece["points"], piece["cells"]           # counts; piece["arrays"][section][name] = (ncomp, [values])
                                            # section: Points, Cells, PointData, CellData
"""
import os
import struct
import sys
import xml.etree.ElementTree as ET
import zlib

FMT = {"Float64": "d", "Float32": "f", "Int64": "q", "Int32": "i", "UInt8": "B", "UInt64": "Q"}


def read_pvd(path):
    root = ET.parse(path).getroot()
    d = os.path.dirname(path)
    return [(float(e.attrib["timestep"]), os.path.join(d, e.attrib["file"])) for e in root.iter("DataSet")]


def read_pvtu(path):
    root = ET.parse(path).getroot()
    d = os.path.dirname(path)
    return [read_vtu(os.path.join(d, p.attrib["Source"])) for p in root.iter("Piece")]


def _decode(blob, pos, typ, hdr, compressed):
    hs = struct.calcsize("<" + hdr)
    if not compressed:
        (n,) = struct.unpack_from("<" + hdr, blob, pos)
        raw = blob[pos + hs:pos + hs + n]
    else:
        nb, _, _ = struct.unpack_from("<3" + hdr, blob, pos)
        sizes = struct.unpack_from("<%d%s" % (nb, hdr), blob, pos + 3 * hs)
        p = pos + (3 + nb) * hs
        raw = b""
        for s in sizes:
            raw += zlib.decompress(blob[p:p + s])
            p += s
    k = struct.calcsize(FMT[typ])
    return list(struct.unpack("<%d%s" % (len(raw) // k, FMT[typ]), raw))


def read_vtu(path):
    data = open(path, "rb").read()
    cut = data.find(b"<AppendedData")
    if cut >= 0:
        head = data[:cut] + b"</VTKFile>"
        start = data.index(b"_", cut) + 1
        blob = data[start:]
    else:
        head, blob = data, b""
    root = ET.fromstring(head)
    if root.attrib.get("byte_order", "LittleEndian") != "LittleEndian":
        raise ValueError("%s: big-endian data not supported" % path)
    hdr = {"UInt64": "Q", "UInt32": "I"}[root.attrib.get("header_type", "UInt32")]
    compressed = "compressor" in root.attrib
    piece = root.find(".//Piece")
    out = {"points": int(piece.attrib["NumberOfPoints"]), "cells": int(piece.attrib["NumberOfCells"]),
           "format": set(), "arrays": {}}
    for sect in ("Points", "Cells", "PointData", "CellData"):
        out["arrays"][sect] = {}
        node = piece.find(sect)
        if node is None:
            continue
        for a in node.iter("DataArray"):
            typ, fmt = a.attrib["type"], a.attrib["format"]
            out["format"].add(fmt)
            if fmt == "ascii":
                conv = float if typ.startswith("Float") else int
                vals = [conv(t) for t in a.text.split()]
            elif fmt == "appended":
                vals = _decode(blob, int(a.attrib["offset"]), typ, hdr, compressed)
            else:
                raise ValueError("%s: format %s not supported" % (path, fmt))
            out["arrays"][sect][a.attrib["Name"]] = (int(a.attrib.get("NumberOfComponents", 1)), vals)
    return out


def main():
    for t, pvtu in read_pvd(sys.argv[1]):
        pieces = read_pvtu(pvtu)
        print("step %g: %s, %d piece(s), %d points, %d cells" % (t, os.path.basename(pvtu), len(pieces),
              sum(p["points"] for p in pieces), sum(p["cells"] for p in pieces)))
        for sect in ("PointData", "CellData"):
            for name in pieces[0]["arrays"][sect]:
                vals = [v for p in pieces for v in p["arrays"][sect][name][1]]
                print("  %s %s: %d values, range %.6g .. %.6g" % (sect, name, len(vals), min(vals), max(vals)))


if __name__ == "__main__":
    main()
