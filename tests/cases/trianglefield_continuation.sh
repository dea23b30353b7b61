# soliman2021 App. C.3 on triangle fields, issue 15: the continuation in the spin weight (-flow_spin_weight w
# -flow_spin_weight_decay f, trianglefield_continuation.c). On the lattice class tau = 1.2i (8 x 8, omega0 = df) with
# w = 1, f = 0.01: two stages end (w 1 -> 0.01 -> 0, each at el_residual < 1e-3), the last stage is W~ alone and
# converges (el < 1e-6, rows < 1e-10, 0 pinch edges) to the critical point the plain flow reaches (W equal to 1e-9:
# the regularised stages leave no bias; with w = 1 kept the 12 x 12 twisted run ends 0.4 above cgd's W).
# Bad input: a decay outside (0, 1].
# nprocs: 1 2
source tests/lib.sh
B="-task flow -gen lattice -gen_tau 0,1.2 -gen_n 8 -gen_m 8 -flow_type trianglefield -flow_max_it 200"
timeout 120 "$CS_BIN" $B -summary "$TMP/plain.json" > "$TMP/plain.log" 2>&1 || { tail "$TMP/plain.log"; exit 1; }
timeout 120 $MPIEXEC "$CS_BIN" $B -flow_spin_weight 1 -flow_spin_weight_decay 0.01 -summary "$TMP/cont.json" > "$TMP/cont.log" 2>&1 || { tail "$TMP/cont.log"; exit 1; }
grep "spin stage" "$TMP/cont.log"
python3 - "$TMP" <<'PY'
import json, re, sys
d = sys.argv[1]; L = lambda n: json.load(open(d + '/' + n + '.json'))
p, c = L('plain'), L('cont')
st = re.findall(r"spin stage (\d+) converged .*w -> (\S+)", open(d + '/cont.log').read())
conv = lambda s: s['converged'] in (True, 1, 'true')
checks = [
  ("two stages ended, the last set w = 0", len(st) == 2 and float(st[-1][1].rstrip('.') or 0) == 0, st),
  ("continuation converged", conv(c), c['converged']),
  ("el_residual of W alone < 1e-6", c['el_residual'] < 1e-6, c['el_residual']),
  ("rows < 1e-10", max(c['conformal_violation'], c['integrability_violation']) < 1e-10, (c['conformal_violation'], c['integrability_violation'])),
  ("0 pinch edges", c['pinch_edges'] == 0, c['pinch_edges']),
  ("W = W of the plain flow to 1e-9", abs(c['energy'] - p['energy']) < 1e-9 * p['energy'], (c['energy'], p['energy'])),
]
bad = 0
for n, ok, v in checks:
  print(("ok  " if ok else "BAD ") + n + ": " + repr(v)); bad += not ok
sys.exit(bad)
PY
EXPECT="spin_weight_decay 1.5: must be in \(0, 1\]" expect_fail $MPIEXEC "$CS_BIN" $B -flow_spin_weight_decay 1.5
