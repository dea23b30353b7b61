# Unconstrained Willmore minimisation (issue #19): the R = 3, r = 1 torus of revolution (48 x 24) reaches W within
# 1 % of 2 pi^2 (the Clifford torus) with -flow_type newton and with gd (no volume constraint), stopping at
# -flow_energy_target (at the first iteration at or below it), without the enclosed volume changing sign; a
# collapsing step size is reported as stalled (exit 0, converged false); newton refuses constraints.
# nprocs: 1 2
source tests/lib.sh
TARGET=$(python3 -c "import math; print(1.01 * 2 * math.pi ** 2)")
TORUS="-gen torus -gen_torus_R 3 -gen_tube_r 1 -gen_n 48 -gen_m 24"
for kind in newton gd; do
  timeout 120 $MPIEXEC "$CS_BIN" -task flow -flow_type $kind $TORUS -flow_max_it 60 -flow_energy_target "$TARGET" \
    -summary "$TMP/$kind.json" -history_csv "$TMP/$kind.csv" > "$TMP/$kind.log" 2>&1 || { tail -20 "$TMP/$kind.log"; exit 1; }
  python3 - "$TMP/$kind" "$kind" "$TARGET" <<'PY'
import json, sys, csv, math
p, kind, target = sys.argv[1], sys.argv[2], float(sys.argv[3])
s = json.load(open(p + ".json"))
rows = list(csv.DictReader(open(p + ".csv")))
W, W2 = s["willmore"], 2 * math.pi ** 2
vols = [float(r["volume"]) for r in rows]
E = [float(r["energy"]) for r in rows]
checks = [
  ("converged (%s), stop_reason %s" % (s["converged"], s["stop_reason"]), s["converged"] and s["stop_reason"] == "energy_target"),
  ("W = %.5f within 1 %% of 2 pi^2 = %.5f (%.2f %%)" % (W, W2, 100 * (W - W2) / W2), abs(W - W2) <= 0.01 * W2),
  ("stopped at the first iteration at or below the target: %s" % E[-2:], E[-1] <= target and all(e > target for e in E[:-1])),
  ("the volume keeps its sign: min %.3f, max %.3f" % (min(vols), max(vols)), min(vols) > 0),
  ("the summary's W is the last history row's", abs(E[-1] - s["energy"]) <= 1e-12 * W),
  ("within 30 iterations (%d)" % s["iterations"], s["iterations"] <= 30),
]
bad = 0
for name, ok in checks:
  print(("ok  " if ok else "BAD ") + kind + ": " + name); bad += not ok
sys.exit(bad)
PY
done
# the scaled tangential relaxation (-flow_newton_relax_scaled): the smallest angle of the result at least 15 degrees
# (the default relaxation leaves the inner cells thin: about 8 degrees at 48 x 24); the discrete W, which depends on
# the vertex distribution, ends below the target (1.6 % below 2 pi^2 at this resolution, docs/bench_evolver.md)
timeout 120 $MPIEXEC "$CS_BIN" -task flow -flow_type newton $TORUS -flow_max_it 60 -flow_energy_target "$TARGET" \
  -flow_newton_relax_scaled -flow_newton_relax 1 -flow_newton_relax_sweeps 3 -o "$TMP/q.obj" -summary "$TMP/q.json" > "$TMP/q.log" 2>&1 || { tail -20 "$TMP/q.log"; exit 1; }
python3 - "$TMP" "$TARGET" <<'PY'
import json, math, sys
d, target = sys.argv[1], float(sys.argv[2])
def min_angle(path):
  V, a = [], 180.0
  for l in open(path):
    s = l.split()
    if s and s[0] == 'v': V.append([float(x) for x in s[1:4]])
    elif s and s[0] == 'f':
      t = [V[int(x.split('/')[0]) - 1] for x in s[1:4]]
      for k in range(3):
        u = [t[(k + 1) % 3][c] - t[k][c] for c in range(3)]; w = [t[(k + 2) % 3][c] - t[k][c] for c in range(3)]
        cs = sum(u[c] * w[c] for c in range(3)) / math.sqrt(sum(x * x for x in u) * sum(x * x for x in w))
        a = min(a, math.degrees(math.acos(max(-1.0, min(1.0, cs)))))
  return a
s, A = json.load(open(d + "/q.json")), min_angle(d + "/q.obj")
checks = [("stopped at the target (%s, W %.5f <= %.5f)" % (s["stop_reason"], s["willmore"], target), s["stop_reason"] == "energy_target" and s["willmore"] <= target),
          ("smallest angle %.1f degrees >= 15" % A, A >= 15), ("volume %.3f > 0" % s["volume"], s["volume"] > 0)]
bad = 0
for name, ok in checks:
  print(("ok  " if ok else "BAD ") + "newton, scaled relaxation: " + name); bad += not ok
sys.exit(bad)
PY
# a step size collapsing below -flow_t_min: stalled, not converged, exit 0 (steps capped at 1e-3 edge lengths)
timeout 60 $MPIEXEC "$CS_BIN" -task flow -flow_type newton $TORUS -flow_max_it 20 -flow_max_step 1e-3 -flow_t_min 1e-2 \
  -summary "$TMP/stall.json" > "$TMP/stall.log" 2>&1 || { tail -20 "$TMP/stall.log"; exit 1; }
[ "$(json stop_reason "$TMP/stall.json")" = stalled ] && [ "$(json converged "$TMP/stall.json")" = False ] || { echo "BAD: not stalled"; grep -E "stop_reason|converged" "$TMP/stall.json"; exit 1; }
echo "ok  a collapsing step size is reported as stalled"
if [ "$NP" = 1 ]; then EXPECT="newton supports no constraints" expect_fail $MPIEXEC "$CS_BIN" -task flow -flow_type newton $TORUS -flow_constraint_volume; fi
