# Issue 15, App. C: random starts of the triangle-field flow are the same on any number of ranks, and the spinor
# diagnostics of the summary. On the 8 x 8 square lattice (tau = i): -flow_init random_spinor (omega = S(l0, psi)
# with the input's face spinors rotated at random, conformal rows met exactly at the start) and -flow_init random
# (df + noise) and -flow_init smooth (d(f + u), u random plane waves), a few iterations serially and on the test's ranks: the energies agree to 1e-9 and the pinch-edge
# counts are equal (the comparison is the 2-rank run's: serially the two runs were the same run, now made once); the start of random_spinor meets the conformal rows (|c|inf of iteration 0 < 1e-10).
# -flow_viewer_iterations writes exactly the listed iterations (and the final state). Bad input: a negative
# -flow_spin_weight, a negative listed iteration.
# nprocs: 1 2
source tests/lib.sh
L="-task flow -flow_type trianglefield -gen lattice -gen_tau 0,1 -gen_n 8 -gen_m 8 -flow_seed 3"
run() { # name, options: serially (reference) and on the test's ranks; serially these are the same run, made once
  local name=$1; shift
  if [ "$NP" != 1 ]; then
    OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 timeout 60 mpirun -n 1 "$CS_BIN" $L "$@" -summary "$TMP/s1_$name.json" > "$TMP/s1_$name.log" 2>&1 || { tail "$TMP/s1_$name.log"; exit 1; }
  fi
  timeout 60 $MPIEXEC "$CS_BIN" $L "$@" -summary "$TMP/sn_$name.json" > "$TMP/sn_$name.log" 2>&1 || { tail "$TMP/sn_$name.log"; exit 1; }
  [ "$NP" != 1 ] || { cp "$TMP/sn_$name.json" "$TMP/s1_$name.json"; cp "$TMP/sn_$name.log" "$TMP/s1_$name.log"; }
  python3 - "$TMP/s1_$name.json" "$TMP/sn_$name.json" "$name" "$TMP/s1_$name.log" "$TMP/sn_$name.log" <<'PY'
import json, sys
a = json.load(open(sys.argv[1])); b = json.load(open(sys.argv[2])); name = sys.argv[3]
def start(log):
  for line in open(log):
    f = line.split()
    if len(f) > 2 and f[0] == '0' and f[1] == 'E': return float(f[2])
e0 = (start(sys.argv[4]), start(sys.argv[5]))
checks = [
  ("start energy (iteration 0) serial = on the test's ranks to 1e-10", abs(e0[0] - e0[1]) <= 1e-10 * abs(e0[0]), e0),
  ("energy after the run to 1e-6 (round-off of the solves grows on a rough field)", abs(a['energy'] - b['energy']) <= 1e-6 * abs(a['energy']), (a['energy'], b['energy'])),
  ("pinch_edges equal", a['pinch_edges'] == b['pinch_edges'] and a['pinch_edges'] >= 0, (a['pinch_edges'], b['pinch_edges'])),
  ("spin_energy reported and equal to 1e-6", abs(a['spin_energy'] - b['spin_energy']) <= 1e-6 * abs(a['spin_energy']), (a['spin_energy'], b['spin_energy'])),
]
bad = 0
for n, ok, v in checks:
  print(("ok  " if ok else "BAD ") + name + ": " + n + ": " + repr(v)); bad += not ok
sys.exit(bad)
PY
}
run spinor -flow_init random_spinor -flow_init_amplitude 0.3 -flow_spin_weight 0.01 -flow_max_it 3 -viewer_dir "$TMP/v" -flow_viewer_iterations 1,2
run df_noise -flow_init random -flow_init_amplitude 0.1 -flow_max_it 1
run smooth -flow_init smooth -flow_init_amplitude 3 -flow_max_it 1
c0=$(awk '$1 == "0" && $2 == "E" { for (i = 1; i <= NF; i++) if ($i == "|c|inf") print $(i + 1) }' "$TMP/sn_spinor.log")
python3 -c "import sys; c = float('$c0'); print(('ok  ' if c < 1e-10 else 'BAD ') + 'random_spinor start meets the conformal rows: |c|inf = %g' % c); sys.exit(c >= 1e-10)"
e_df=$(OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 timeout 60 "$CS_BIN" $L -flow_max_it 0 2>&1 | awk '$1 == "0" && $2 == "E" { print $3 }')
e_sm=$(awk '$1 == "0" && $2 == "E" { print $3 }' "$TMP/s1_smooth.log")
python3 -c "import sys; a, b = float('$e_df'), float('$e_sm'); ok = abs(a - b) > 1e-3 * a; print(('ok  ' if ok else 'BAD ') + 'the smooth start differs from df: W %.10g vs %.10g' % (b, a)); sys.exit(not ok)"
steps=$(grep -c "<DataSet" "$TMP/v/series.pvd")
[ "$steps" = 3 ] && echo "ok   -flow_viewer_iterations 1,2 with 3 iterations: 3 steps written" || { echo "BAD: $steps steps in series.pvd (want 3)"; exit 1; }
EXPECT="spin_weight" expect_fail $MPIEXEC "$CS_BIN" $L -flow_spin_weight -1
EXPECT="viewer_iterations" expect_fail $MPIEXEC "$CS_BIN" $L -viewer_dir "$TMP/v2" -flow_viewer_iterations -2
