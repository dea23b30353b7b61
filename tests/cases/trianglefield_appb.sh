# Issue 15, App. B of soliman2021 for triangle fields (tests/unit/test_trianglefield_appb.c): the enclosed volume
# (B.2) and relative point positions (B.1) extended through the frozen-metric Poisson reconstruction are extensions
# (V~(df) = V(f), P~(df) = f_v - f_v0 to 1e-12, also for a random f) and their rows match central differences to
# 1e-6 at df and at a non-integrable field, on a bumpy icosphere and a bumpy torus. Then the flow: -flow_type
# trianglefield -flow_constraint_volume V from a bumpy level-1 icosphere converges with the volume met to 1e-10 and
# the same W as cgd with the same constraint (the volume is a scale gauge of W there, so both equal the
# unconstrained minimum); a one-point file is refused (a triangle field has no absolute position). The Moebius
# balancing M~(omega) = m(R omega) (-flow_constraint_mobius): extension and rows in the unit test; in the flow, the
# df start of the 6 x 6 Clifford lattice (balanced by symmetry) converges with the rows met to 1e-10 and the same W
# as without them (1e-8).
# nprocs: 1 2
source tests/lib.sh
printf '0 -0.6 0.97 0.04\n50 0.78 -0.93 -0.53\n' > "$TMP/pts.txt"
timeout 60 $MPIEXEC "$CS_TESTS/test_trianglefield_appb" -points "$TMP/pts.txt" -malloc_dump || exit 1
B="-task flow -gen icosphere -gen_level 1 -gen_deform_bump 0.2 -flow_constraint_volume 3 -flow_max_it 150"
OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 timeout 60 mpirun -n 1 "$CS_BIN" $B -flow_type cgd -summary "$TMP/cgd.json" > "$TMP/cgd.log" 2>&1 || { tail "$TMP/cgd.log"; exit 1; }
timeout 120 $MPIEXEC "$CS_BIN" $B -flow_type trianglefield -summary "$TMP/tf.json" > "$TMP/tf.log" 2>&1 || { tail "$TMP/tf.log"; exit 1; }
python3 - "$TMP/tf.json" "$TMP/cgd.json" <<'PY' || exit 1
import json, sys
t = json.load(open(sys.argv[1])); c = json.load(open(sys.argv[2]))
checks = [
  ("converged", t['converged'] in (True, 1, 'true'), t['converged']),
  ("el_residual_scaled < -flow_rtol 5e-7", t['el_residual_scaled'] < 5e-7, t['el_residual']),
  ("volume row below 1e-10", abs(t['constraint_values'][-1]) < 1e-10, t['constraint_values']),
  ("reconstructed volume = 3 to 1e-9", abs(t['volume'] - 3) < 1e-9, t['volume']),
  ("integrability_violation < 1e-10", t['integrability_violation'] < 1e-10, t['integrability_violation']),
  ("W = cgd's W to 1e-8", abs(t['energy'] - c['energy']) < 1e-8, (t['energy'], c['energy'])),
]
bad = 0
for n, ok, v in checks:
  print(("ok  " if ok else "BAD ") + n + ": " + repr(v)); bad += not ok
sys.exit(bad)
PY
L="-task flow -flow_type trianglefield -gen lattice -gen_tau 0,1 -gen_n 6 -gen_m 6 -flow_max_it 100"
timeout 60 $MPIEXEC "$CS_BIN" $L -summary "$TMP/l0.json" > "$TMP/l0.log" 2>&1 || { tail "$TMP/l0.log"; exit 1; }
timeout 60 $MPIEXEC "$CS_BIN" $L -flow_constraint_mobius -summary "$TMP/lm.json" > "$TMP/lm.log" 2>&1 || { tail "$TMP/lm.log"; exit 1; }
python3 - "$TMP/lm.json" "$TMP/l0.json" <<'PY' || exit 1
import json, sys
t = json.load(open(sys.argv[1])); c = json.load(open(sys.argv[2]))
mob = t['constraint_values'][-3:]
checks = [
  ("Moebius gauge: converged", t['converged'] in (True, 1, 'true'), t['converged']),
  ("Moebius gauge: el_residual_scaled < -flow_rtol 5e-7", t['el_residual_scaled'] < 5e-7, t['el_residual']),
  ("Moebius gauge: 3 balancing rows below 1e-10", len(t['constraint_values']) == 9 and max(abs(v) for v in mob) < 1e-10, mob),
  ("Moebius gauge: W = W without it to 1e-8", abs(t['energy'] - c['energy']) < 1e-8, (t['energy'], c['energy'])),
]
bad = 0
for n, ok, v in checks:
  print(("ok  " if ok else "BAD ") + n + ": " + repr(v)); bad += not ok
sys.exit(bad)
PY
printf '0 0 0 1\n' > "$TMP/one.txt"
EXPECT="at least 2 points" expect_fail $MPIEXEC "$CS_BIN" -task flow -gen icosphere -gen_level 1 -flow_type trianglefield -flow_constraint_points "$TMP/one.txt"
