#!/usr/bin/env bash
# crane2013 Fig. 11: one step of the isometric curve flow of size tau = 0.8, 0.4, ..., 0.0125 on the 200-edge
# wobbly curve (options/curve_fig11.opts); the worst edge-length distortion after the Poisson step and the closure
# gap before it, into runs/results/curve_fig11.csv, and the log-log plot runs/results/curve_fig11.png.
set -euo pipefail
cd "$(dirname "$0")/.."
mkdir -p runs/results out
csv=runs/results/curve_fig11.csv
echo "tau,distortion,gap" > $csv
for tau in 0.8 0.4 0.2 0.1 0.05 0.025 0.0125; do
  bin/confsurf -options_file options/curve_fig11.opts -curve_tau $tau -summary out/curve_fig11.json > /dev/null
  python3 -c "import json,sys; s=json.load(open('out/curve_fig11.json')); print('%s,%.6e,%.6e' % (sys.argv[1], s['max_length_distortion'], s['closure_gap_max']))" $tau >> $csv
done
cat $csv
python3 - $csv <<'PY'
import math, sys
r = [l.split(',') for l in open(sys.argv[1]).read().split()[1:]]
t = [math.log(float(a[0])) for a in r]; d = [math.log(float(a[1])) for a in r]
for i in range(len(r) - 1): print(f"slope {r[i][0]} -> {r[i+1][0]}: {(d[i] - d[i+1]) / (t[i] - t[i+1]):.3f}")
PY
/usr/bin/python3 scripts/plot_curves.py fig11 $csv runs/results/curve_fig11.png
