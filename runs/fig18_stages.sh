#!/usr/bin/env bash
# soliman2021 Fig. 18 (issue 39): the continuation of the point targets (-flow_points_stages K) against the direct
# start, on the icosphere of levels 4 and 5 through the six points of options/flow_fig18_points.txt with the +x one at
# (1.075, 0.1, 0) and at the file's (1.15, 0.15, 0). Without the continuation the start is off the points by 0.1 / 0.15
# (2-3 edges at level 5) and CGD stalls at the first iterations (docs/willmore_flow.md "Fig. 18"). Each run from the
# sphere, measured by runs/fig18_spike.py. Writes runs/fig18_stages.md. About 20 min serial under load.
#   bash runs/fig18_stages.sh            (after make; LEVELS="4" for a quicker look, K=20 the stages, BIG=1 the
#                                         point at (1.3, 0.4, 0) on level 5 with K = 80 too)
set -uo pipefail
cd "$(dirname "$0")/.."
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
out=runs/fig18_stages.md
K=${K:-20}
run() { # NAME LEVEL X Y STAGES
  local n=$1 L=$2 x=$3 y=$4 k=$5
  bin/confsurf -task info -gen icosphere -gen_level "$L" -o "$tmp/ico$L.obj" > /dev/null
  sed "s/^41 .*/41 $x $y 0/" options/flow_fig18_points.txt > "$tmp/$n.pts"
  nice -n 10 timeout 2400 bin/confsurf -task flow -gen icosphere -gen_level "$L" -flow_type cgd -flow_max_it 1000 \
    -flow_constraint_points "$tmp/$n.pts" -flow_points_stages "$k" -o "$tmp/$n.obj" -summary "$tmp/$n.json" > "$tmp/$n.log" 2>&1
  python3 runs/fig18_spike.py "$tmp/ico$L.obj" "$tmp/$n.obj" "$tmp/$n.pts" "$tmp/$n.json" | sed -n 's/^JSON //p' |
    python3 -c "
import json, sys
d = json.load(sys.stdin); s = json.load(open('$tmp/$n.json')); m = d['moved']
print('| %d | (%s, %s) | %s | %d | %s | %d | %d | %.9f | %.1e | %.1e | %.3f | %.2f / %.1f | %s | %.0f |' % ($L, '$x', '$y', '$k', s['iterations'],
      s['stop_reason'], s['rejections'], s['linear_solves'], s['willmore'], s['constraint_violation'], s['conformal_violation'],
      s['q_max'], m[0], m[3], ' '.join('%.3f' % b for b in d['bands']), s['seconds']))" | tee -a "$out"
}
{
  echo "# soliman2021 Fig. 18: the point targets in stages ($(date -u +%F), runs/fig18_stages.sh; seconds serial under load)"
  echo
  echo "K: -flow_points_stages (0: off); points / class: the violations at the stop (the points' against the file's targets);"
  echo "spike: the moved vertex's height/h and tilt (runs/fig18_spike.py); bands: mean | |x| - 1 | at 0-30, 30-60, 60-90,"
  echo "90-180 deg from +x."
  echo
  echo "| level | point | K | iterations | stop | rejections | linear solves | W | points | class | q_max | spike | bands | s |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"
} > "$out"
for L in ${LEVELS:-4 5}; do
  for xy in 1.075,0.1 1.15,0.15; do
    for k in 0 "$K"; do run "L${L}_${xy/,/_}_K$k" "$L" "${xy%,*}" "${xy#*,}" "$k"; done
  done
done
# the large move on level 5 (BIG=1; about 18 min more): stages of 0.4 / 80 = 0.005
if [ "${BIG:-0}" = 1 ]; then run "L5_1.3_0.4_K80" 5 1.3 0.4 80; fi
echo "wrote $out"
