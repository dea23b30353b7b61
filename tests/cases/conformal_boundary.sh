# Boundary conditions of the conformal flow (crane2013 Sec. 6.3, -flow_boundary vector|fixed) on spherical caps
# written by tests/tools/gen_cap.py:
# 1. V~ = V (the current binormals kept, -flow_boundary vector) with rho ~ 0 (tau = 1e-12) is the identity:
#    q_max - 1 < 1e-8, W unchanged to 1e-10;
# 2. the V = B flow (Sec. 6.3.1: binormals kept) on a bumpy hemisphere (1536 faces) makes H nearly constant (a CMC
#    surface): std(H)/|mean H| over the interior falls below 0.1 and by 10x in 10 steps at tau = 0.95;
# 3. fixed boundary (Sec. 6.3.2) to the boundary of another mesh (-flow_target_mesh, the hemisphere with a wavy rim):
#    the target positions are met to 1e-12 after every step, and without a target the input's rim is kept.
# nprocs: 1 2
source tests/lib.sh
run() { timeout 120 $MPIEXEC "$CS_BIN" -task flow -flow_type conformal "$@"; }
python3 tests/tools/gen_cap.py "$TMP/h12.obj" --n 12
python3 tests/tools/gen_cap.py "$TMP/h16.obj" --n 16
python3 tests/tools/gen_cap.py "$TMP/bump.obj" --n 16 --bump 0.15
python3 tests/tools/gen_cap.py "$TMP/wave.obj" --n 16 --wave 0.15
run -mesh "$TMP/h12.obj" -flow_boundary vector -flow_tau 1e-12 -flow_max_it 3 -flow_rtol 0 -summary "$TMP/id.json" > "$TMP/log1"
run -mesh "$TMP/bump.obj" -flow_boundary vector -flow_max_it 10 -flow_rtol 0 -history_csv "$TMP/cmc.csv" > "$TMP/log2"
run -mesh "$TMP/h16.obj" -flow_boundary fixed -flow_target_mesh "$TMP/wave.obj" -flow_max_it 3 -flow_rtol 0 -history_csv "$TMP/fix.csv" > "$TMP/log3"
run -mesh "$TMP/bump.obj" -flow_boundary fixed -flow_max_it 3 -flow_rtol 0 -history_csv "$TMP/keep.csv" > "$TMP/log4"
python3 - "$TMP" <<'PY'
import sys, csv, json
t = sys.argv[1]
ok = True
def report(c, msg):
    print(("ok   " if c else "FAIL ") + msg); return c
i = json.load(open(t + '/id.json'))
ok &= report(i['q_max'] - 1 < 1e-8, f"V~ = V, tau 1e-12: q_max - 1 = {i['q_max'] - 1:.2e} (< 1e-8)")
dw = abs(i['willmore'] / i['willmore_initial'] - 1)
ok &= report(dw < 1e-10, f"V~ = V, tau 1e-12: W change {dw:.2e} (< 1e-10)")
c = list(csv.DictReader(open(t + '/cmc.csv')))
h0, h1 = float(c[0]['H_spread']), float(c[-1]['H_spread'])
ok &= report(len(c) == 11 and h1 < 0.1 and h1 < h0 / 10, f"V = B flow, bumpy hemisphere: std(H)/|mean H| {h0:.3f} -> {h1:.4f} in {len(c) - 1} steps (< 0.1, 10x less); q_mean {float(c[-1]['q_mean']):.4f}")
for name, what in (('fix', 'to the wavy target rim'), ('keep', 'to the input rim')):
    r = list(csv.DictReader(open(t + f'/{name}.csv')))
    e = max(float(x['boundary_error']) for x in r[1:])
    ok &= report(len(r) == 4 and e < 1e-12, f"fixed boundary {what}: max |f - f~| / sqrt(area) over steps 1-3 = {e:.1e} (< 1e-12; input {float(r[0]['boundary_error']):.3f})")
sys.exit(0 if ok else 1)
PY
