# issue 35 (a stopping rule that means something): -flow_rtol tests el_residual_scaled = el_residual sqrt(A) / |W|,
# which is invariant under x -> s x (W is; el_residual ~ 1/s: docs/willmore_flow.md "Stopping"). The R = 3 torus
# and its copy scaled by 10 (-gen_deform_stretch) stop at the same iteration with the same W, their
# el_residual 1/s times the unit one; with -flow_el_norm absolute (the old test of el_residual itself) they do not
# stop at the same iteration (the same shape at another size meant another accuracy).
# nprocs: 1 2
source tests/lib.sh
G="-task flow -gen torus -gen_torus_R 3 -gen_tube_r 1 -gen_n 24 -gen_m 12 -flow_max_it 40"
for s in 1 10; do
  timeout 60 $MPIEXEC "$CS_BIN" $G -gen_deform_stretch $s,$s,$s -summary "$TMP/s$s.json" > "$TMP/s$s.log" 2>&1 || { tail "$TMP/s$s.log"; exit 1; }
  timeout 60 $MPIEXEC "$CS_BIN" $G -gen_deform_stretch $s,$s,$s -flow_el_norm absolute -summary "$TMP/a$s.json" > "$TMP/a$s.log" 2>&1 || { tail "$TMP/a$s.log"; exit 1; }
done
python3 - "$TMP" <<'PY'
import json, sys
d = sys.argv[1]
S = {s: json.load(open(d + '/s%s.json' % s)) for s in ('1', '10')}
A = {s: json.load(open(d + '/a%s.json' % s)) for s in ('1', '10')}
u = S['1']
checks = [("unit torus: converged by -flow_rtol", u['stop_reason'] == 'converged', (u['stop_reason'], u['iterations']))]
for s in ('10',):
  t = S[s]
  checks += [
    ("x%s: stops at the same iteration (%d)" % (s, u['iterations']), t['stop_reason'] == 'converged' and t['iterations'] == u['iterations'], (t['stop_reason'], t['iterations'])),
    ("x%s: the same W (1e-10)" % s, abs(t['energy'] - u['energy']) <= 1e-10 * u['energy'], (t['energy'], u['energy'])),
    ("x%s: the same el_residual_scaled (1e-6)" % s, abs(t['el_residual_scaled'] - u['el_residual_scaled']) <= 1e-6 * u['el_residual_scaled'], (t['el_residual_scaled'], u['el_residual_scaled'])),
    ("x%s: el_residual = unit / %s (1e-6)" % (s, s), abs(t['el_residual'] * float(s) - u['el_residual']) <= 1e-6 * u['el_residual'], (t['el_residual'], u['el_residual'])),
  ]
checks.append(("-flow_el_norm absolute: the two sizes stop at different iterations", A['1']['iterations'] != A['10']['iterations'], (A['1']['iterations'], A['10']['iterations'])))
bad = 0
for name, ok, v in checks:
  print(("ok  " if ok else "BAD ") + name + ": " + repr(v)); bad += not ok
sys.exit(bad)
PY
