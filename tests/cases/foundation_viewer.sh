# ParaView output, in each -viewer_format (binary, the default: appended raw data; zlib; ascii; and zlib with
# -viewer_precision single), read by
# scripts/vtu.py: the series index, the .pvtu and one .vtu piece per rank parse; the pieces' cells add up to the
# mesh's faces, every data array has one tuple per point/cell, the cell-data face areas sum to the summary's area,
# and the formats hold the same values (ascii to its 10 digits, Float32 to its 7).
# nprocs: 1 2
source tests/lib.sh
for fmt in binary zlib ascii; do
  $MPIEXEC "$CS_BIN" -task info -mesh meshes/bunny_lowres_npm.obj -viewer_dir "$TMP/$fmt" -viewer_format $fmt -summary "$TMP/s.json" >/dev/null
done
$MPIEXEC "$CS_BIN" -task info -mesh meshes/bunny_lowres_npm.obj -viewer_dir "$TMP/single" -viewer_format zlib -viewer_precision single >/dev/null
python3 - "$TMP" "${NP:-1}" <<'PY'
import json, sys
sys.path.insert(0, "scripts")
import vtu
d, np = sys.argv[1], int(sys.argv[2])
s = json.load(open(f"{d}/s.json"))
values = {}
for fmt, want in (("binary", {"appended"}), ("zlib", {"appended"}), ("ascii", {"ascii"}), ("single", {"appended"})):
    steps = vtu.read_pvd(f"{d}/{fmt}/series.pvd")
    assert len(steps) == 1, steps
    pieces = vtu.read_pvtu(steps[0][1])
    assert len(pieces) == np, len(pieces)
    cells = 0; area = 0.0
    for piece in pieces:
        assert piece["format"] == want, (fmt, piece["format"])
        npt, nc = piece["points"], piece["cells"]
        cells += nc
        for sect, n in (("Points", npt), ("Cells", None), ("PointData", npt), ("CellData", nc)):
            for name, (k, vals) in piece["arrays"][sect].items():
                if n is not None:
                    assert len(vals) == n * k, (fmt, name, len(vals), n, k)
                values.setdefault((fmt, sect, name), []).extend(vals)
                if name == "face_area": area += sum(vals)
        conn, offs = piece["arrays"]["Cells"]["connectivity"][1], piece["arrays"]["Cells"]["offsets"][1]
        assert len(conn) == 3 * nc and offs == list(range(3, 3 * nc + 1, 3)) and min(conn) >= 0 and max(conn) < npt, fmt
    assert cells == s["faces"], (cells, s["faces"])
    assert abs(area - s["area"]) <= (1e-6 if fmt == "single" else 1e-8) * s["area"], (area, s["area"])
    print(f"ok  {fmt}: {len(pieces)} piece(s), {cells} cells, face areas sum to the area ({area:.10g})")
for (fmt, sect, name), vals in values.items():
    if fmt == "binary": continue
    ref = values[("binary", sect, name)]
    tol = {"zlib": 0, "ascii": 1e-9, "single": 1e-7}[fmt]
    assert len(vals) == len(ref) and all(abs(a - b) <= tol * max(1.0, abs(b)) for a, b in zip(vals, ref)), (fmt, name)
print("ok  zlib, ascii and zlib Float32 hold the binary values (to 0, 1e-9, 1e-7)")
PY
