#!/usr/bin/env bash
# Study (not a test): why the vesicle of options/flow_vesicle.opts (soliman2021 Fig. 3: area + volume + conformal
# constraints with Moebius balancing, reduced volume 0.84, icosphere level 4) does not reach EL < 1e-6. One CGD
# run of MAXIT iterations with a ParaView step every EVERY iterations; then scripts/vesicle_drift.py measures,
# between the last two steps, where the surface still moves and where the EL residual points: the normal and the
# tangential parts (against area-weighted vertex normals), the slope of W and of the vertex-area spread.
# Outputs in runs/results/vesicle/ (history.csv, summary.json, vtu/, drift.txt). Knobs: MAXIT=400 EVERY=50.
set -u
cd "$(dirname "$0")/.."
MAXIT=${MAXIT:-400}; EVERY=${EVERY:-50}
PY=$(bash scripts/find-python.sh 2>/dev/null || echo /usr/bin/python3)
out=runs/results/vesicle; mkdir -p "$out"
bin/confsurf -task flow -options_file options/flow_vesicle.opts -flow_max_it "$MAXIT" -flow_viewer_every "$EVERY" \
  -viewer_dir "$out/vtu" -history_csv "$out/history.csv" -summary "$out/summary.json" > "$out/log" 2>&1
tail -6 "$out/log" | head -2
"$PY" runs/vesicle_drift.py "$out/vtu/series.pvd" "$out/history.csv" | tee "$out/drift.txt"
