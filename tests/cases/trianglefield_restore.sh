# Issue 15 (soliman2021 Fig. 15): the triangle-field flow's restoration (src/methods/willmore/impls/trianglefield/trianglefield_restore.c).
# Input: the perturbed Morin surface on 24 x 12 with the conformal rows. Its first accepted step uses ~83 % of the
# step filter's violation ceiling -flow_vmax 1e-2; without a restoration every later trial step's violation tends to
# the current one from above and all are rejected (docs/triangle_fields.md, "Fig. 15").
# (off) -flow_restore_near_ceiling 0 -flow_restore_stalled false: stalls (t < -flow_t_min 1e-4) with the violation
#       near the ceiling (> 5e-3) and W still > 172 (measured: stalled at iteration 4, violation 9.995e-3, W 172.98).
# (on)  the default: each accepted omega near the ceiling is projected back onto its rows by Gauss-Newton steps
#       (restoration lines with the violation after < 1e-10), and the run moves: 7 iterations done (max_it),
#       W < 160 (measured 150.73), the violation at the end below half the ceiling (measured 3.4e-3).
# Serially both; on 2 ranks (on) only (29 s wall serially, 27 s on 2 ranks, under load ~4: ~4 s of CPU per rank).
# nprocs: 1 2
source tests/lib.sh
G="-task flow -flow_type trianglefield -gen morin -gen_n 24 -gen_m 12 -gen_morin_perturb 0.02 -flow_t_min 1e-4"
if [ "$NP" = 1 ]; then
  timeout 120 "$CS_BIN" $G -flow_max_it 8 -flow_restore_near_ceiling 0 -flow_restore_stalled false -summary "$TMP/off.json" > "$TMP/off.log" 2>&1 || { tail "$TMP/off.log"; exit 1; }
fi
timeout 120 $MPIEXEC "$CS_BIN" $G -flow_max_it 7 -summary "$TMP/on.json" > "$TMP/on.log" 2>&1 || { tail "$TMP/on.log"; exit 1; }
python3 - "$TMP" <<'PY'
import json, re, sys
d = sys.argv[1]
checks = []
try: off = json.load(open(d + '/off.json'))
except OSError: off = None  # 2 ranks: (on) only
if off:
  checks += [
  ("(off) stalled", off['stop_reason'] == 'stalled', (off['stop_reason'], off['iterations'])),
  ("(off) the violation near the ceiling 1e-2 (> 5e-3)", max(off['conformal_violation'], off['constraint_violation']) > 5e-3, off['conformal_violation']),
  ("(off) W still > 172", off['energy'] > 172, off['energy'])]
on = json.load(open(d + '/on.json'))
log = open(d + '/on.log').read()
rest = [float(v) for v in re.findall(r'restoration after iteration \d+ \(\S+\): violation \S+ -> (\S+) in', log)]
checks += [
  ("(on) restorations made, each to a violation < 1e-10", len(rest) > 0 and max(rest) < 1e-10 and 'restored' in log, rest),
  ("(on) moves: 7 iterations (max_it)", on["stop_reason"] == "max_it" and on["iterations"] == 7, (on['stop_reason'], on['iterations'])),
  ("(on) W < 160", on["energy"] < 160, on['energy']),
  ("(on) violation at the end < 5e-3", max(on['conformal_violation'], on['constraint_violation']) < 5e-3, on['conformal_violation'])]
bad = 0
for name, ok, val in checks:
  print("%s: %s %s" % ("ok" if ok else "BAD", name, val)); bad += not ok
sys.exit(1 if bad else 0)
PY
