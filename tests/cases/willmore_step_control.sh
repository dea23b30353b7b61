# Issue 35 item 2: the step size control rarely rejects (-flow_step_model predictive, the default; willmore_step_model.c,
# docs/willmore_flow.md "The step size model"). The bumped torus of the issue (R 3, r 1, 88 x 44 = 7744 faces, bump
# 0.2), default CGD, 20 iterations: at most 3 rejected trials and W <= 60 at iteration 20 (the issue's acceptance;
# with the halving rule: 20 rejections, W 106.3). Serially also -flow_step_model halving for one iteration: the old
# rule halves t from 1 nine times at iteration 0 (the issue's "1 -> 0.0039"), the predictive one needs at most 3
# trials there; and a bad -flow_step_model value is refused by name. The halving run keeps the issue's dual step
# t_mu = 1e3 t (cgd's default before issue 39): with today's 1e5 t the first step restores the class ~100x harder and
# even the halving rule halves only twice here (docs/studies.md "The default dual step").
# nprocs: 1 2
source tests/lib.sh
T="-gen torus -gen_torus_R 3 -gen_tube_r 1 -gen_n 88 -gen_m 44 -gen_deform_bump 0.2"
timeout 300 $MPIEXEC "$CS_BIN" -task flow $T -flow_max_it 20 -summary "$TMP/p.json" -history_csv "$TMP/p.csv" > "$TMP/p.log" 2>&1 || { tail "$TMP/p.log"; exit 1; }
if [ "$NP" = 1 ]; then
  timeout 120 "$CS_BIN" -task flow $T -flow_max_it 1 -flow_step_model halving -flow_t_mu 1e3 -summary "$TMP/h.json" > "$TMP/h.log" 2>&1 || { tail "$TMP/h.log"; exit 1; }
  EXPECT="step_model" expect_fail "$CS_BIN" -task flow -gen torus -flow_step_model bisect -flow_max_it 1
fi
python3 - "$TMP" <<'PY'
import csv, json, os, sys
d = sys.argv[1]
s = json.load(open(d + '/p.json'))
h = list(csv.DictReader(open(d + '/p.csv')))
last = h[-1]
checks = [
  ("20 iterations run", s['iterations'] == 20 and int(float(last['it'])) == 20, (s['iterations'], last['it'])),
  ("at most 3 rejected trials in 20 iterations", s['rejections'] <= 3, s['rejections']),
  ("the history's rejection count agrees", int(float(last['rejections'])) == s['rejections'], (last['rejections'], s['rejections'])),
  ("W <= 60 at iteration 20", s['energy'] <= 60 and float(last['energy']) <= 60, (s['energy'], last['energy'])),
  ("W fell from the input's", s['energy'] < s['energy_initial'], (s['energy_initial'], s['energy'])),
]
if os.path.exists(d + '/h.json'):
  hs = json.load(open(d + '/h.json'))
  rej0 = int(float(h[1]['rejections']))  # the predictive run's rejections at iteration 0
  checks += [
    ("halving: t halved at least 5 times at iteration 0", hs['rejections'] >= 5 and 'halving t' in open(d + '/h.log').read(), hs['rejections']),
    ("predictive: at most 3 trials rejected at iteration 0, fewer than halving", rej0 <= 3 and rej0 < hs['rejections'], (rej0, hs['rejections'])),
  ]
bad = 0
for name, ok, val in checks:
  print(("ok   " if ok else "FAIL ") + name + ": " + str(val))
  bad += not ok
sys.exit(1 if bad else 0)
PY
