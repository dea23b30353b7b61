# man_cgal (17k vertices, needles, edge ratio 1654): the conformal map of its limbs toward a round sphere shrinks
# them exponentially (shortest edge 2.6e-10 of the diameter after step 1 at tau = 0.95, 6.7e-17 after step 2; the
# next curvature is rounding noise and step 3 used to give NaN). The step whose shortest edge falls below
# -flow_min_edge (1e-12) of the diameter is rejected: the flow stops with stop_reason "resolution", the last good
# state is written, and nothing in the summary, history or mesh is NaN (docs/conformal_flow.md "man_cgal").
# nprocs: 1 2
source tests/lib.sh
timeout 120 $MPIEXEC "$CS_BIN" -task flow -flow_type conformal -mesh "$CS_SHARED/meshes/man_cgal.obj" -flow_max_it 5 \
  -flow_rtol 0 -history_csv "$TMP/h.csv" -summary "$TMP/s.json" -o "$TMP/out.obj" > "$TMP/run.log"
grep "rejected" "$TMP/run.log"
python3 - "$TMP" <<'PY'
import sys, csv, json, math
t = sys.argv[1]
s = json.load(open(t + '/s.json'))
rows = list(csv.DictReader(open(t + '/h.csv')))
ok = True
def report(c, msg):
    print(("ok   " if c else "FAIL ") + msg); return c
ok &= report(s['stop_reason'] == 'resolution', f"stop_reason {s['stop_reason']} (resolution)")
ok &= report(1 <= s['iterations'] < 5, f"iterations {s['iterations']} (steps kept before the rejected one)")
ok &= report(len(rows) == s['iterations'] + 1, f"history rows {len(rows)} = iterations + 1 (no row for the rejected step)")
num = [v for k, v in s.items() if isinstance(v, float)]
ok &= report(all(math.isfinite(v) for v in num), f"all {len(num)} numbers of the summary finite")
ok &= report(all(math.isfinite(float(v)) for r in rows for v in r.values()), "all history values finite")
ok &= report(s['willmore'] < 0.5 * s['willmore_initial'], f"W/4pi {s['willmore_initial'] / 4 / math.pi:.1f} -> {s['willmore'] / 4 / math.pi:.1f} (the kept state is the last step's)")
ok &= report(abs(s['willmore'] - float(rows[-1]['willmore'])) <= 1e-12 * s['willmore'], "summary W = the last history row's W")
xs = [float(c) for l in open(t + '/out.obj') if l.startswith('v ') for c in l.split()[1:4]]
ok &= report(len(xs) == 3 * 17495 and all(math.isfinite(x) for x in xs), f"written mesh: {len(xs) // 3} finite vertices")
sys.exit(0 if ok else 1)
PY
