# Surfaces with boundary (soliman2021 App. D, Fig. 6): conformally constrained minimal surface of a cylinder with
# fixed (Dirichlet) boundary keeps its boundary, its class (C0 on interior edges) and does not neck, while the
# unconstrained area flow shrinks it; with fixed positions and boundary-face normals (App. D) the Willmore flow
# converges with every constraint (interior cross ratios and normals) met to 1e-10.
# nprocs: 1 2
source tests/lib.sh
B="-task flow -gen cylinder -gen_n 24 -gen_m 12 -gen_height 2 -flow_energy area -flow_max_it 40"
"$CS_BIN" -task info -gen cylinder -gen_n 24 -gen_m 12 -gen_height 2 -o "$TMP/in.obj" > /dev/null
timeout 60 $MPIEXEC "$CS_BIN" $B -flow_type cgd -o "$TMP/cgd.obj" -summary "$TMP/cgd.json" > "$TMP/cgd.log" 2>&1 || { tail "$TMP/cgd.log"; exit 1; }
timeout 60 $MPIEXEC "$CS_BIN" $B -flow_type gd -flow_max_it 20 -o "$TMP/gd.obj" -summary "$TMP/gd.json" > "$TMP/gd.log" 2>&1 || { tail "$TMP/gd.log"; exit 1; }
timeout 60 $MPIEXEC "$CS_BIN" -task flow -gen cylinder -gen_n 24 -gen_m 12 -gen_height 2 -flow_boundary normals -flow_max_it 100 -o "$TMP/nrm.obj" -summary "$TMP/nrm.json" > "$TMP/nrm.log" 2>&1 || { tail "$TMP/nrm.log"; exit 1; }
python3 - "$TMP" <<'PY'
import json, sys
d = sys.argv[1]
load = lambda p: [[float(t) for t in l.split()[1:4]] for l in open(p) if l.startswith('v ')]
I, C, G = load(d + '/in.obj'), load(d + '/cgd.obj'), load(d + '/gd.obj')
zs = [v[2] for v in I]; lo, hi = min(zs), max(zs)
bnd = [i for i, v in enumerate(I) if abs(v[2] - lo) < 1e-12 or abs(v[2] - hi) < 1e-12]
bmove = max(abs(C[i][k] - I[i][k]) for i in bnd for k in range(3))
gmove = max(abs(G[i][k] - I[i][k]) for i in bnd for k in range(3))
c = json.load(open(d + '/cgd.json')); g = json.load(open(d + '/gd.json')); n = json.load(open(d + '/nrm.json'))
N = load(d + '/nrm.obj'); nmove = max(abs(N[i][k] - I[i][k]) for i in bnd for k in range(3))
checks = [
  ("cgd boundary vertices fixed", bmove == 0.0, bmove),
  ("gd boundary vertices fixed", gmove == 0.0, gmove),
  ("cgd class kept (interior cross ratios) < 1e-8", c['conformal_violation'] < 1e-8, c['conformal_violation']),
  ("cgd q_mean < 1.001", c['q_mean'] < 1.001, c['q_mean']),
  ("cgd el_residual < 1e-3", c['el_residual'] < 1e-3, c['el_residual']),
  ("gd shrinks the area by > 20%", g['area'] < 0.8 * c['area'], g['area']),
  ("normals: converged", n['converged'] in (True, 1, 'true'), n['iterations']),
  ("normals: cross ratios + normals met to 1e-10", n['conformal_violation'] < 1e-10, n['conformal_violation']),
  ("normals: boundary vertices fixed", nmove == 0.0, nmove),
]
bad = 0
for name, ok, v in checks:
  print(("ok  " if ok else "BAD ") + name + ": " + repr(v)); bad += not ok
sys.exit(bad)
PY
