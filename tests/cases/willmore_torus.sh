# soliman2021 Fig. 13 on a torus of revolution R=3, r=1: cgd keeps the conformal class (q_mean < 1.01 against
# the input) while unconstrained Sobolev gd degrades the mesh (q_mean much larger) and lowers W towards 2 pi^2.
# nprocs: 1 2
source tests/lib.sh
B="-task flow -gen torus -gen_torus_R 3 -gen_tube_r 1 -gen_n 24 -gen_m 12"
timeout 60 $MPIEXEC "$CS_BIN" $B -flow_type cgd -flow_max_it 100 -summary "$TMP/cgd.json" -history_csv "$TMP/cgd.csv" > "$TMP/cgd.log" 2>&1 || { tail "$TMP/cgd.log"; exit 1; }
timeout 60 $MPIEXEC "$CS_BIN" $B -flow_type gd -flow_max_it 60 -summary "$TMP/gd.json" -history_csv "$TMP/gd.csv" > "$TMP/gd.log" 2>&1 || { tail "$TMP/gd.log"; exit 1; }
python3 - "$TMP" <<'PY'
import json, sys, csv, math
d = sys.argv[1]
c = json.load(open(d + '/cgd.json')); g = json.load(open(d + '/gd.json'))
W0 = float(list(csv.DictReader(open(d + '/gd.csv')))[0]['energy']); w2 = 2 * math.pi ** 2
checks = [
  ("cgd converged", c['converged'] in (True, 1, 'true'), c['iterations']),
  ("cgd conformal_violation < 1e-10", c['conformal_violation'] < 1e-10, c['conformal_violation']),
  ("cgd q_mean < 1.01", c['q_mean'] < 1.01, c['q_mean']),
  ("gd q_mean > 1.5 (mesh degrades)", g['q_mean'] > 1.5, g['q_mean']),
  ("gd lowers W (W0 = %.3f)" % W0, g['willmore'] < W0 - 5, g['willmore']),
  ("gd W moves towards 2pi^2 = %.3f" % w2, abs(g['willmore'] - w2) < 0.5 * abs(W0 - w2), g['willmore']),
]
bad = 0
for name, ok, v in checks:
  print(("ok  " if ok else "BAD ") + name + ": " + repr(v)); bad += not ok
sys.exit(bad)
PY
