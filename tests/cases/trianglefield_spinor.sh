# Issue 15, App. C.2/C.3: the triangle-field flow in the spinor variables (-flow_variables spinor, x = (u, psi),
# omega = S_c(u, psi); src/methods/willmore/impls/trianglefield/trianglefield_spinor.c). tests/unit/test_trianglefield_spinor.c: the
# gradient of W~(S_c(u, psi)) + w E_tau(psi) against central differences (<= 1e-6) along u, psi and both. Then the
# flow on the 4 x 4 square lattice (tau = i) from psi(df) (u uniform), serially and on the test's ranks: it converges
# (el_residual < 1e-6), the class is met by construction (|C~ lambda - c0|inf < 1e-10), integrability < 1e-10, no
# pinch edges, and the two runs reach the same W to 1e-8 (on 2 ranks; serially they are one run). Bad input: a negative -flow_scale_gauge_weight.
# nprocs: 1 2
source tests/lib.sh
timeout 60 $MPIEXEC "$CS_TESTS/test_trianglefield_spinor" -malloc_dump || exit 1
L="-task flow -flow_type trianglefield -flow_variables spinor -gen lattice -gen_tau 0,1 -gen_n 4 -gen_m 4 -flow_max_it 100"
# the serial reference (serially it is the test's run itself, made once)
if [ "$NP" != 1 ]; then
  OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 timeout 60 mpirun -n 1 "$CS_BIN" $L -summary "$TMP/s1.json" > "$TMP/s1.log" 2>&1 || { tail "$TMP/s1.log"; exit 1; }
fi
timeout 120 $MPIEXEC "$CS_BIN" $L -summary "$TMP/sn.json" > "$TMP/sn.log" 2>&1 || { tail "$TMP/sn.log"; exit 1; }
[ "$NP" != 1 ] || cp "$TMP/sn.json" "$TMP/s1.json"
python3 - "$TMP/s1.json" "$TMP/sn.json" <<'PY'
import json, sys
a = json.load(open(sys.argv[1])); b = json.load(open(sys.argv[2]))
checks = []
for tag, s in (("serial", a), ("ranks", b)):
  checks += [
    (tag + ": converged, el_residual < 1e-6", s['converged'] and s['el_residual'] < 1e-6, (s['converged'], s['el_residual'], s['iterations'])),
    (tag + ": conformal class |C~ lambda - c0|inf < 1e-10 (S_c is conformal by construction)", s['conformal_violation'] < 1e-10, s['conformal_violation']),
    (tag + ": integrability (d1 omega, periods) and |psi| = 1 rows < 1e-10", s['constraint_violation'] < 1e-10, s['constraint_violation']),
    (tag + ": no pinch edges", s['pinch_edges'] == 0, s['pinch_edges']),
  ]
checks.append(("W serial = W on the test's ranks to 1e-8", abs(a['energy'] - b['energy']) <= 1e-8 * abs(a['energy']), (a['energy'], b['energy'])))
bad = 0
for n, ok, v in checks:
  print(("ok   " if ok else "BAD  ") + n + ": " + repr(v)); bad += not ok
print("%d passed, %d failed" % (len(checks) - bad, bad))
sys.exit(bad)
PY
[ $? = 0 ] || exit 1
if "$CS_BIN" $L -flow_scale_gauge_weight -1 > "$TMP/bad.log" 2>&1; then echo "BAD: -flow_scale_gauge_weight -1 accepted"; exit 1; fi
grep -q "scale_gauge_weight" "$TMP/bad.log" && echo "ok   -flow_scale_gauge_weight -1 refused by name" || { cat "$TMP/bad.log"; exit 1; }
