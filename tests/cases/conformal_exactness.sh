# The exactness constraint of crane2013 App. C, C.1 (genus >= 1; CSHarmonicBasis from src/operators/harmonic_basis.c):
# on a bumpy torus (R = 3, r = 1, 48 x 24) 4 steps with -flow_exactness (default) against the same run without it:
# the direction is orthogonal to the Z_i^x,y,z to 1e-12, W falls at every step, and the closing error (the harmonic
# part of conj(lambda) df lambda) and q_mean are smaller with the constraint (measured 0.018 vs 0.13, 1.09 vs 1.67 since Z linearises the shifted inverse step).
# And the constraint is the exact linearisation of the closing condition: one step's closing error falls by more
# than 3x when tau is halved (second order; measured 4.2e-3 -> 1.1e-3; the paper's Im Z_i form, -flow_exactness_paper,
# is first order: 2.0e-2 -> 1.1e-2). Under 2 ranks only the run with the constraint (orthogonality, W falling, q_step).
# Per step (history column q_step: q_mean of the step's own map, previous surface -> new one) every step with the
# constraint is conformal to q_step <= 1.05 (measured 1.049, 1.020, 1.015, 1.022), every step without it is not
# (measured 1.128-1.140): q_mean against the input compounds these plus the piecewise-linear floor
# ~0.6 h |grad u| of any conformal map with scale factor e^u (docs/conformal_flow.md "The bumpy torus: why q_mean grows").
# nprocs: 1 2
source tests/lib.sh
run() { timeout 120 $MPIEXEC "$CS_BIN" -task flow -flow_type conformal -gen torus -gen_torus_R 3 -gen_tube_r 1 -gen_n 48 -gen_m 24 -gen_deform_bump 0.1 -flow_max_it 4 -flow_rtol 0 -flow_curvature_factor 1 "$@"; }
run -history_csv "$TMP/a.csv" -summary "$TMP/a.json" > "$TMP/log1"
if [ "$NP" = 1 ]; then
  run -flow_exactness false -history_csv "$TMP/b.csv" -summary "$TMP/b.json" > "$TMP/log2"
  for t in 0.2 0.1; do run -flow_curvature_factor 2 -flow_max_it 1 -flow_tau $t -summary "$TMP/t$t.json" > "$TMP/logt$t"; done
fi
python3 - "$TMP" <<'PY'
import sys, csv, json
t = sys.argv[1]
import os
a = list(csv.DictReader(open(t + '/a.csv'))); sa = json.load(open(t + '/a.json'))
def report(c, msg):
    print(("ok   " if c else "FAIL ") + msg); return c
ok = report(sa['genus'] == 1 and sa['exactness'], f"genus {sa['genus']}, exactness on")
res = max(float(r['res_exact']) for r in a)
ok &= report(res < 1e-12, f"<<v, Z_i>> / |v| = {res:.1e} (< 1e-12)")
W = [float(r['willmore']) for r in a]
ok &= report(all(y < x for x, y in zip(W, W[1:])), "W falls at every step: " + " ".join(f"{w:.3f}" for w in W))
qa = [float(r['q_step']) for r in a[1:]]
ok &= report(len(qa) == 4 and max(qa) <= 1.05 and abs(sa['q_step_max'] - max(qa)) < 1e-12, "every step's own q_mean with the constraint <= 1.05: " + " ".join(f"{q:.4f}" for q in qa))
if not os.path.exists(t + '/b.json'): sys.exit(0 if ok else 1)
sb = json.load(open(t + '/b.json'))
ok &= report(not sb['exactness'], "exactness off in the second run")
ca, cb = sa['closing_error_max'], sb['closing_error_max']
ok &= report(ca < 0.5 * cb, f"closing error with {ca:.3e} < half of without {cb:.3e}")
ok &= report(sa['q_mean'] < sb['q_mean'], f"q_mean with {sa['q_mean']:.4f} < without {sb['q_mean']:.4f}")
b = list(csv.DictReader(open(t + '/b.csv')))
qb = [float(r['q_step']) for r in b[1:]]
ok &= report(len(qb) == 4 and min(qb) - 1 > 2 * (max(qa) - 1), "without it every step's q - 1 is > 2x the largest with it: " + " ".join(f"{q:.4f}" for q in qb))
c2, c1 = [json.load(open(t + f'/t{x}.json'))['closing_error_max'] for x in ('0.2', '0.1')]
ok &= report(c2 / c1 > 3, f"one step's closing error {c2:.2e} (tau 0.2) -> {c1:.2e} (tau 0.1): ratio {c2 / c1:.2f} (> 3, second order)")
sys.exit(0 if ok else 1)
PY
