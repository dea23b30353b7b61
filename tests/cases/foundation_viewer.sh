# ParaView output: the series index, the .pvtu and one .vtu piece per rank parse as XML; the pieces' cells add
# up to the mesh's faces, every data array has one tuple per point/cell, and the cell-data face areas sum to
# the summary's area.
# nprocs: 1 2
source tests/lib.sh
$MPIEXEC "$CS_BIN" -task info -mesh meshes/bunny_lowres_npm.obj -viewer_dir "$TMP/vtu" -summary "$TMP/s.json" >/dev/null
python3 - "$TMP" "${NP:-1}" <<'PY'
import json, sys, xml.etree.ElementTree as ET
d, np = sys.argv[1], int(sys.argv[2])
s = json.load(open(f"{d}/s.json"))
ET.parse(f"{d}/vtu/series.pvd")
pv = ET.parse(f"{d}/vtu/surface_0000.pvtu")
pieces = [p.attrib["Source"] for p in pv.iter("Piece")]
assert len(pieces) == np, pieces
cells = 0; area = 0.0
for src in pieces:
    piece = ET.parse(f"{d}/vtu/{src}").find(".//Piece")
    npt, nc = int(piece.attrib["NumberOfPoints"]), int(piece.attrib["NumberOfCells"])
    cells += nc
    for sect, n in (("Points", npt), ("PointData", npt), ("CellData", nc)):
        for a in piece.find(sect).iter("DataArray"):
            k = int(a.attrib.get("NumberOfComponents", 1))
            vals = a.text.split()
            assert len(vals) == n * k, (src, a.attrib["Name"], len(vals), n, k)
            if a.attrib["Name"] == "face_area": area += sum(map(float, vals))
assert cells == s["faces"], (cells, s["faces"])
assert abs(area - s["area"]) <= 1e-8 * s["area"], (area, s["area"])
print(f"ok  {len(pieces)} piece(s), {cells} cells, face areas sum to the area ({area:.10g})")
PY
