# soliman2021 Fig. 17 (issue 39): the cgd flow is equivariant, so an n-fold symmetric start in a rectangular class
# keeps its n-fold symmetry about the z axis to round-off at every iteration (runs/nfold_history.py: rotated vertex
# set against the vertex set, over the RMS radius). Start: -gen lattice tau = 0.4545i (b = 2.2, above the 2-lobed
# branch point sqrt 3) on 24 x 8, -gen_deform_nfold 3,0.05, Moebius rows on, 6 iterations. The checker is shown to
# fail on the same meshes for the wrong n (2), and the flow is shown to move (W falls), so round-off is not trivial.
# nprocs: 1 2
source tests/lib.sh
B="-task flow -flow_type cgd -gen lattice -gen_tau 0,0.4545 -gen_n 24 -gen_m 8 -flow_constraint_mobius -flow_max_it 6 -flow_viewer_every 1"
timeout 60 $MPIEXEC "$CS_BIN" $B -gen_deform_nfold 3,0.05 -viewer_dir "$TMP/v3" -history_csv "$TMP/h3.csv" > "$TMP/f3.log" 2>&1 || { tail "$TMP/f3.log"; exit 1; }
python3 runs/nfold_history.py "$TMP/v3/series.pvd" 3 "$TMP/s3.csv" | tail -1
python3 runs/nfold_history.py "$TMP/v3/series.pvd" 2 "$TMP/s2.csv" | tail -1
python3 - "$TMP" <<'PY'
import csv, sys
d = sys.argv[1]
s3 = list(csv.DictReader(open(d + '/s3.csv'))); s2 = list(csv.DictReader(open(d + '/s2.csv')))
h = list(csv.DictReader(open(d + '/h3.csv')))
e3 = max(float(r['nfold_error']) for r in s3); off = max(float(r['axis_offset']) for r in s3)
e2 = min(float(r['nfold_error']) for r in s2)
W0, W1 = float(h[0]['energy']), float(h[-1]['energy'])
checks = [
  ("a ParaView step per iteration (7)", len(s3) == 7, len(s3)),
  ("3-fold error < 1e-11 at every step", e3 < 1e-11, e3),
  ("centroid on the z axis (< 1e-11)", off < 1e-11, off),
  ("the same steps are not 2-fold symmetric (> 1e-2)", e2 > 1e-2, e2),
  ("the flow moves: W falls by > 1e-3 (W0 = %.6f)" % W0, W1 < W0 - 1e-3, W1),
]
bad = 0
for name, ok, v in checks:
  print(("ok  " if ok else "BAD ") + name + ": " + repr(v)); bad += not ok
sys.exit(bad)
PY
