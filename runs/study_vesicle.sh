#!/usr/bin/env bash
# Study (not a test): the vesicle of options/flow_vesicle.opts (soliman2021 Fig. 3: area + volume + conformal
# constraints, reduced volume 0.84, icosphere level 4) with and without the rotation gauge of the domain.
#   gauge:    the options file as it is (Moebius balancing + -flow_constraint_rotation): converges
#   balance:  -flow_constraint_rotation false, MAXIT iterations with a ParaView step every EVERY iterations; then
#             runs/vesicle_drift.py measures between the last two steps where the surface still moves (normal and
#             tangential parts, the rigid part, the slopes of W, EL residual and vertex-area spread)
# Outputs in runs/results/vesicle/{gauge,balance}/ (history.csv, summary.json, log; balance: vtu/, drift.txt).
# Knobs: MAXIT=200 EVERY=25. One rank; the machine is shared (seconds are noisy). docs/vesicle.md.
set -u
cd "$(dirname "$0")/.."
MAXIT=${MAXIT:-200}; EVERY=${EVERY:-25}
PY=$(bash scripts/find-python.sh 2>/dev/null || echo /usr/bin/python3)
out=runs/results/vesicle; mkdir -p "$out/gauge" "$out/balance"
bin/confsurf -task flow -options_file options/flow_vesicle.opts -history_csv "$out/gauge/history.csv" \
  -summary "$out/gauge/summary.json" -o "$out/gauge/vesicle.obj" > "$out/gauge/log" 2>&1
grep -E "converged" "$out/gauge/log"
python3 -c "import json; s=json.load(open('$out/gauge/summary.json')); print('gauge: ' + ', '.join('%s %s' % (k, s[k]) for k in ('converged', 'iterations', 'willmore', 'el_residual', 'conformal_violation', 'constraint_violation', 'q_max', 'seconds')))"
bin/confsurf -task flow -options_file options/flow_vesicle.opts -flow_constraint_rotation false -flow_max_it "$MAXIT" \
  -flow_viewer_every "$EVERY" -viewer_dir "$out/balance/vtu" -history_csv "$out/balance/history.csv" \
  -summary "$out/balance/summary.json" > "$out/balance/log" 2>&1
grep -E "converged" "$out/balance/log"
"$PY" runs/vesicle_drift.py "$out/balance/vtu/series.pvd" "$out/balance/history.csv" | tee "$out/balance/drift.txt"
