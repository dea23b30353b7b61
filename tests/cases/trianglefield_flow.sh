# Issue 15, Algorithm 2 (soliman2021): -flow_type trianglefield over triangle fields from omega0 = df of a bumpy
# level-2 icosphere reaches Algorithm 1's (cgd's) minimiser: converged with el_residual_scaled < -flow_rtol 5e-7, W equal to 1e-8,
# the reconstructed positions within 1e-6 of cgd's after the best similarity (scale is a free gauge of both), the
# conformal rows and the integrability rows (d1 omega, face closure) below 1e-10. The same on a 12 x 6 torus of
# revolution (genus 1: the six rows <<Y_i|omega>> active, in integrability_violation). Bad input: a surface with
# boundary, an energy other than W~ and a non-positive -flow_integrability_weight are refused with one line.
# nprocs: 1 2
source tests/lib.sh
P=tests/cases/spin_tools.py
compare() { # name, generator options: cgd serially, trianglefield on the test's ranks, then the checks
  local name=$1; shift
  local B="-task flow $* -flow_max_it 150"
  OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 timeout 60 mpirun -n 1 "$CS_BIN" $B -flow_type cgd -o "$TMP/cgd_$name.obj" -summary "$TMP/cgd_$name.json" > "$TMP/cgd_$name.log" 2>&1 || { tail "$TMP/cgd_$name.log"; exit 1; }
  timeout 120 $MPIEXEC "$CS_BIN" $B -flow_type trianglefield -o "$TMP/tf_$name.obj" -summary "$TMP/tf_$name.json" > "$TMP/tf_$name.log" 2>&1 || { tail "$TMP/tf_$name.log"; exit 1; }
  python3 - "$TMP/tf_$name.json" "$TMP/cgd_$name.json" "$(python3 $P similarity "$TMP/cgd_$name.obj" "$TMP/tf_$name.obj")" "$name" <<'PY'
import json, sys
t = json.load(open(sys.argv[1])); c = json.load(open(sys.argv[2])); d = float(sys.argv[3]); name = sys.argv[4]
checks = [
  ("converged", t['converged'] in (True, 1, 'true'), t['converged']),
  ("el_residual_scaled < -flow_rtol 5e-7", t['el_residual_scaled'] < 5e-7, t['el_residual']),
  ("conformal_violation < 1e-10", t['conformal_violation'] < 1e-10, t['conformal_violation']),
  ("integrability_violation < 1e-10", t['integrability_violation'] < 1e-10, t['integrability_violation']),
  ("W = cgd's W to 1e-8", abs(t['energy'] - c['energy']) < 1e-8, (t['energy'], c['energy'])),
  ("W of the reconstructed mesh = W~ to 1e-8", abs(t['willmore'] - t['energy']) < 1e-8, (t['willmore'], t['energy'])),
  ("positions = cgd's to 1e-6 (similarity aligned)", d < 1e-6, d),
  ("no pinch edges (App. C.1 spinor test)", t.get('pinch_edges') == 0, t.get('pinch_edges')),
]
if name == 'torus': checks.append(("six <<Y_i|omega>> rows", len(t.get('constraint_values', [])) == 6, t.get('constraint_values')))
bad = 0
for n, ok, v in checks:
  print(("ok  " if ok else "BAD ") + name + ": " + n + ": " + repr(v)); bad += not ok
sys.exit(bad)
PY
}
compare sphere -gen icosphere -gen_level 2 -gen_deform_bump 0.2
compare torus -gen torus -gen_torus_R 3 -gen_tube_r 1 -gen_n 12 -gen_m 6
B="-task flow -gen icosphere -gen_level 1"
EXPECT="boundary loop" expect_fail $MPIEXEC "$CS_BIN" -task flow -gen cylinder -gen_n 12 -gen_m 6 -flow_type trianglefield
EXPECT="energy area" expect_fail $MPIEXEC "$CS_BIN" $B -flow_type trianglefield -flow_energy area
EXPECT="integrability_weight" expect_fail $MPIEXEC "$CS_BIN" $B -flow_type trianglefield -flow_integrability_weight 0
