#!/usr/bin/env bash
# ParaView's own reader (pvpython, Debian's paraview + python3-paraview: `make test` installs them through
# scripts/install-deps.sh --test) opens a CGD flow's series.pvd written during the flow (-flow_viewer_every) in the
# default binary format and, for the final step, as zlib: the steps' times, the number of points (after merging
# the pieces' shared vertices) and cells against the summary, the field names, and their ranges against the
# summary: face_area sums to the area, sum vertex_area * mean_curvature^2 is the Willmore energy
# (W = 1/4 <Lf, *0^-1 Lf>, h = 1/2 *0^-1 Lf) at the first and last step, Q is 1 at step 0 and peaks at q_max.
# nprocs: 1 2
source tests/lib.sh
PV=$(command -v pvpython || true)
[ -n "$PV" ] || { echo "BAD: pvpython not found (bash scripts/install-deps.sh --test installs paraview python3-paraview)"; exit 1; }
B="-task flow -gen icosphere -gen_level 2 -gen_deform_bump 0.2 -flow_max_it 12 -flow_viewer_every 5"
timeout 120 $MPIEXEC "$CS_BIN" $B -viewer_dir "$TMP/bin" -summary "$TMP/s.json" > "$TMP/a.log" 2>&1 || { tail "$TMP/a.log"; exit 1; }
timeout 120 $MPIEXEC "$CS_BIN" $B -viewer_dir "$TMP/zlib" -viewer_format zlib > "$TMP/b.log" 2>&1 || { tail "$TMP/b.log"; exit 1; }
grep -q 'format="appended"' "$TMP/bin/surface_0000_0.vtu" || { echo "BAD: default format not appended binary"; exit 1; }
grep -q 'vtkZLibDataCompressor' "$TMP/zlib/surface_0000_0.vtu" || { echo "BAD: -viewer_format zlib not compressed"; exit 1; }
cat > "$TMP/check.py" <<'PY'
import json, sys
from paraview import servermanager as sm
from paraview.simple import PVDReader, CleantoGrid, UpdatePipeline
d, np = sys.argv[1], int(sys.argv[2])
s = json.load(open(f"{d}/s.json"))
bad = 0
def check(ok, msg):
    global bad
    print(("ok  " if ok else "BAD ") + msg); bad += not ok
def close(a, b, tol, msg):
    check(abs(a - b) <= tol * max(1.0, abs(b)), f"{msg}: {a!r} vs {b!r}")
for fmt in ("bin", "zlib"):
    r = PVDReader(FileName=f"{d}/{fmt}/series.pvd")
    times = list(r.TimestepValues)
    check(times == [0.0, 5.0, 10.0, 12.0], f"{fmt}: steps {times}")
    c = CleantoGrid(Input=r)
    for t in (times[0], times[-1]) if fmt == "bin" else (times[-1],):
        c.UpdatePipeline(t)
        g = sm.Fetch(c)
        pd, cd = g.GetPointData(), g.GetCellData()
        names = sorted([pd.GetArrayName(i) for i in range(pd.GetNumberOfArrays())] + [cd.GetArrayName(i) for i in range(cd.GetNumberOfArrays())])
        # a constrained flow also writes its multipliers made visible (issue #21 item 5, docs/multipliers.md)
        check(names == ["Q", "conformal_force", "el_residual", "face_area", "mean_curvature", "stress_direction", "stress_max", "stress_min", "vertex_area"], f"{fmt} t={t}: fields {names}")
        check(g.GetNumberOfPoints() == s["vertices"], f"{fmt} t={t}: {g.GetNumberOfPoints()} points (merged), {s['vertices']} vertices")
        check(g.GetNumberOfCells() == s["faces"], f"{fmt} t={t}: {g.GetNumberOfCells()} cells, {s['faces']} faces")
        fa, Q = cd.GetArray("face_area"), cd.GetArray("Q")
        va, h = pd.GetArray("vertex_area"), pd.GetArray("mean_curvature")
        W = sum(va.GetValue(i) * h.GetValue(i) ** 2 for i in range(g.GetNumberOfPoints()))
        if t == times[-1]:
            close(sum(fa.GetValue(i) for i in range(g.GetNumberOfCells())), s["area"], 1e-9, f"{fmt}: sum face_area = summary area")
            close(W, s["willmore"], 1e-9, f"{fmt}: sum vertex_area h^2 = summary willmore")
            close(Q.GetRange()[1], s["q_max"], 1e-9, f"{fmt}: max Q = summary q_max")
            check(Q.GetRange()[0] >= 1.0, f"{fmt}: min Q {Q.GetRange()[0]} >= 1")
        else:
            close(W, s["energy_initial"], 1e-9, f"{fmt} t=0: sum vertex_area h^2 = summary energy_initial")
            close(Q.GetRange()[0], 1.0, 1e-12, f"{fmt} t=0: Q min = 1")
            close(Q.GetRange()[1], 1.0, 1e-12, f"{fmt} t=0: Q max = 1")
sys.exit(1 if bad else 0)
PY
timeout 120 "$PV" "$TMP/check.py" "$TMP" "$NP" 2>&1 | grep -v "^$"
exit "${PIPESTATUS[0]}"
