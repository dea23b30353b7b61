# The time-step threshold of the conformal flow near tau = 1 (crane2013 Sec. 4, Fig. 18) on level-5 spheres
# (20480 faces) bumped with sin(6x) sin(6y) sin(6z) (amplitude 0.01), a regular icosphere and an irregular one
# (tests/tools/jitter_sphere.py): 6 steps at tau = 0.95 remove more than half of W - 4 pi, at tau = 1.05 less than
# a tenth (the curvature deviation flips sign each step without decaying: the step responds to rho with c ~ 0.95 on
# these features, and |1 - 2 tau c| ~ 1 at tau = 1.05).
# Level 6 (81920 faces), sin(9x) sin(9y) sin(9z) (amplitude 0.01; c = 0.976, the largest response measured at this
# level, so the threshold 1/c is 1.025): regular and irregular (jitter_sphere.py with the level-6 edge 0.03), 3 steps:
# W falls at every step at tau = 0.95 and grows at every step at tau = 1.05 (docs/conformal_flow.md "Stability").
# nprocs: 1
source tests/lib.sh
run() { timeout 120 $MPIEXEC "$CS_BIN" -task flow -flow_type conformal "$@"; }
run -gen icosphere -gen_level 5 -flow_max_it 0 -o "$TMP/ico.obj" > "$TMP/log0"
python3 tests/tools/jitter_sphere.py "$TMP/ico.obj" "$TMP/irr.obj"
for tau in 0.95 1.05; do
  run -gen icosphere -gen_level 5 -gen_deform_bump 0.01 -gen_deform_bump_freq 6 -flow_max_it 6 -flow_rtol 0 -flow_tau $tau -history_csv "$TMP/reg$tau.csv" > "$TMP/logr$tau"
  run -mesh "$TMP/irr.obj" -flow_max_it 6 -flow_rtol 0 -flow_tau $tau -history_csv "$TMP/irr$tau.csv" > "$TMP/logi$tau"
done
run -gen icosphere -gen_level 6 -flow_max_it 0 -o "$TMP/ico6.obj" > "$TMP/log6"
python3 tests/tools/jitter_sphere.py "$TMP/ico6.obj" "$TMP/irr6.obj" 0.03 9
for tau in 0.95 1.05; do
  run -gen icosphere -gen_level 6 -gen_deform_bump 0.01 -gen_deform_bump_freq 9 -flow_max_it 3 -flow_rtol 0 -flow_tau $tau -history_csv "$TMP/reg6_$tau.csv" > "$TMP/logr6$tau"
  run -mesh "$TMP/irr6.obj" -flow_max_it 3 -flow_rtol 0 -flow_tau $tau -history_csv "$TMP/irr6_$tau.csv" > "$TMP/logi6$tau"
done
python3 - "$TMP" <<'PY'
import sys, csv, math
t = sys.argv[1]
ok = True
def report(c, msg):
    print(("ok   " if c else "FAIL ") + msg); return c
for mesh in ('reg', 'irr'):
    for tau, lo, hi in (('0.95', 0.5, 1.01), ('1.05', -1, 0.1)):
        r = list(csv.DictReader(open(t + f'/{mesh}{tau}.csv')))
        w = [float(x['willmore']) / (4 * math.pi) - 1 for x in r]
        removed = 1 - w[-1] / w[0]
        ok &= report(len(r) == 7 and lo < removed < hi, f"{mesh} tau {tau}: W/4pi - 1 {w[0]:.5f} -> {w[-1]:.5f} in 6 steps: removed {removed:.3f} (in ({lo}, {hi}))")
for mesh in ('reg6', 'irr6'):
    for tau, sign, word in (('0.95', -1, 'falls'), ('1.05', 1, 'grows')):
        r = list(csv.DictReader(open(t + f'/{mesh}_{tau}.csv')))
        w = [float(x['willmore']) / (4 * math.pi) for x in r]
        q = [float(y['vnorm']) / float(x['vnorm']) for x, y in zip(r, r[1:])]
        d = len(w) == 4 and all(sign * (y - x) > 0 for x, y in zip(w, w[1:]))
        ok &= report(d, f"{mesh} tau {tau}: W {word} at every step: W/4pi " + " ".join(f"{x:.5f}" for x in w) + "; |v| ratios " + " ".join(f"{x:.3f}" for x in q))
sys.exit(0 if ok else 1)
PY
