#!/usr/bin/env bash
# soliman2021 Fig. 17 (issue 39): the n = 2 lobed torus continued in the class b from b = 1.6 (48 x 32,
# options/newton_fig17_lobed_n2.opts) to b = 1.98 on 144 x 96, above the smooth branch point sqrt 3, by
# runs/fig17_lobed_continue.py (Newton restarted from the previous result in the next class; a finer grid by the
# trigonometric interpolant of the previous one's result). The branch folds on coarse grids (48 x 32: b ~ 1.655,
# 72 x 48: ~1.77, 96 x 64: ~1.86), so each grid takes over below its fold. Writes runs/results/fig17_lobed_n2_chain/
# (the start of options/newton_fig17_lobed_n2_b198.opts: 144x96/b1.9600.obj). Serially ~20 min under load.
#   bash runs/fig17_lobed_n2_chain.sh      (docs/triangle_fields.md "Fig. 17", "The n = 2 lobed branch in b")
set -euo pipefail
cd "$(dirname "$0")/.."
d=runs/results/fig17_lobed_n2_chain c=runs/fig17_lobed_continue.py
mkdir -p $d
nice -n 10 timeout 600 bin/confsurf -options_file options/newton_fig17_lobed_n2.opts -o $d/48x32_b1.6.obj \
  -summary $d/48x32_b1.6.json -history_csv $d/48x32_b1.6.csv > $d/48x32_b1.6.log 2>&1
/usr/bin/python3 $c 48 32 $d/48x32_b1.6.obj $d/48x32 1.62 1.64
/usr/bin/python3 $c 72 48 $d/48x32/b1.6400.obj $d/72x48 1.71 1.72 1.73 1.74 1.76 --from 48x32 --secant
/usr/bin/python3 $c 96 64 $d/72x48/b1.7600.obj $d/96x64 1.78 1.80 1.82 1.84 --from 72x48
/usr/bin/python3 $c 144 96 $d/96x64/b1.8400.obj $d/144x96 1.84 1.86 1.88 1.90 1.92 1.94 1.96 1.98 --from 96x64
