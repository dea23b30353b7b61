# Issue 15, Algorithm 2 (soliman2021): -flow_type trianglefield over triangle fields from omega0 = df of a bumpy
# level-2 icosphere reaches Algorithm 1's (cgd's) minimiser: converged with el_residual < 1e-6, W equal to 1e-8,
# the reconstructed positions within 1e-6 of cgd's after the best similarity (scale is a free gauge of both), the
# conformal rows and the integrability rows (d1 omega, face closure) below 1e-10. Bad input: a surface with
# boundary and an energy other than W~ are refused with one line.
# nprocs: 1 2
source tests/lib.sh
P=tests/cases/spin_tools.py
B="-task flow -gen icosphere -gen_level 2 -gen_deform_bump 0.2 -flow_max_it 150"
OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 timeout 60 mpirun -n 1 "$CS_BIN" $B -flow_type cgd -o "$TMP/cgd.obj" -summary "$TMP/cgd.json" > "$TMP/cgd.log" 2>&1 || { tail "$TMP/cgd.log"; exit 1; }
timeout 120 $MPIEXEC "$CS_BIN" $B -flow_type trianglefield -o "$TMP/tf.obj" -summary "$TMP/tf.json" > "$TMP/tf.log" 2>&1 || { tail "$TMP/tf.log"; exit 1; }
python3 - "$TMP/tf.json" "$TMP/cgd.json" "$(python3 $P similarity "$TMP/cgd.obj" "$TMP/tf.obj")" <<'PY'
import json, sys
t = json.load(open(sys.argv[1])); c = json.load(open(sys.argv[2])); d = float(sys.argv[3])
checks = [
  ("converged", t['converged'] in (True, 1, 'true'), t['converged']),
  ("el_residual < 1e-6", t['el_residual'] < 1e-6, t['el_residual']),
  ("conformal_violation < 1e-10", t['conformal_violation'] < 1e-10, t['conformal_violation']),
  ("integrability_violation < 1e-10", t['integrability_violation'] < 1e-10, t['integrability_violation']),
  ("W = cgd's W to 1e-8", abs(t['energy'] - c['energy']) < 1e-8, (t['energy'], c['energy'])),
  ("W of the reconstructed mesh = W~ to 1e-8", abs(t['willmore'] - t['energy']) < 1e-8, (t['willmore'], t['energy'])),
  ("positions = cgd's to 1e-6 (similarity aligned)", d < 1e-6, d),
]
bad = 0
for name, ok, v in checks:
  print(("ok  " if ok else "BAD ") + name + ": " + repr(v)); bad += not ok
sys.exit(bad)
PY
EXPECT="boundary loop" expect_fail $MPIEXEC "$CS_BIN" -task flow -gen cylinder -gen_n 12 -gen_m 6 -flow_type trianglefield
EXPECT="energy area" expect_fail $MPIEXEC "$CS_BIN" $B -flow_type trianglefield -flow_energy area
