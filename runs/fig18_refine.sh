#!/usr/bin/env bash
# soliman2021 Fig. 18 (issue 39): is the spike at the moved point of the as-spherical-as-possible interpolant the
# discrete form of the smooth point-force singularity (it would shrink, in height/h and in apex angle, under
# refinement) or an artifact of pinning one vertex in the discrete conformal class? The six points of
# options/flow_fig18_points.txt with the +x one moved to (1.3, 0.4, 0), (1.2, 0.25, 0), (1.15, 0.15, 0) and
# (1.075, 0.1, 0), on the icosphere of levels 2, 3, 4 (the octahedron vertices keep their indices at every level),
# each from the sphere; then at level 4 the move continued through the spike-free states (checkpoint/resume: the
# class stays the level-4 icosphere's) to compare the spike-free and the spiked critical points at equal points.
# runs/fig18_spike.py measures each result. Writes runs/fig18_refine.md. About 10 min serial under load.
#   bash runs/fig18_refine.sh            (after make; LEVELS="2 3" for a quick look)
set -uo pipefail
cd "$(dirname "$0")/.."
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
out=runs/fig18_refine.md
run() { # NAME LEVEL X Y [args]: one flow from the sphere (or resumed with -resume in args), measured
  local n=$1 L=$2 x=$3 y=$4; shift 4
  bin/confsurf -task info -gen icosphere -gen_level "$L" -o "$tmp/ico$L.obj" > /dev/null
  sed "s/^41 .*/41 $x $y 0/" options/flow_fig18_points.txt > "$tmp/$n.pts"
  nice -n 10 timeout 1500 bin/confsurf -task flow -gen icosphere -gen_level "$L" -flow_type cgd -flow_max_it 2000 \
    -flow_constraint_points "$tmp/$n.pts" "$@" -o "$tmp/$n.obj" -summary "$tmp/$n.json" > "$tmp/$n.log" 2>&1
  python3 runs/fig18_spike.py "$tmp/ico$L.obj" "$tmp/$n.obj" "$tmp/$n.pts" "$tmp/$n.json" | sed -n 's/^JSON //p' |
    python3 -c "
import json, sys
d = json.load(sys.stdin); m = d['moved']
print('| %s | %d | (%s, %s) | %s | %s | %.9f | %.3f | %.2f | %.3f | %.1f | %.2f | %s |' % ('$n', $L, '$x', '$y', d.get('iterations'),
      d.get('stop_reason'), d.get('willmore', 0), d.get('q_max', 0), m[0], m[1], m[3], m[4],
      ' '.join('%.3f' % b for b in d['bands'])))" | tee -a "$out"
}
{
  echo "# soliman2021 Fig. 18: the spike at the moved point under refinement ($(date -u +%F), runs/fig18_refine.sh)"
  echo
  echo "height: the moved vertex's distance from the least-squares sphere through its one-ring; h: the mean length of"
  echo "its star's edges; tilt: the largest angle between a star face's normal and that sphere's normal; area: the"
  echo "largest area ratio of a star face to the input's; bands: mean | |x| - 1 | at 0-30, 30-60, 60-90, 90-180 deg from +x."
  echo
  echo "| run | level | point | iterations | stop | W | q_max | height/h | height | tilt (deg) | area | bands |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|---|"
} > "$out"
for L in ${LEVELS:-2 3 4}; do
  run "L$L" "$L" 1.3 0.4
  run "S$L" "$L" 1.15 0.15
  run "T$L" "$L" 1.075 0.1
done
run M4 4 1.2 0.25
# level 4, continued: the spike-free state of (1.15, 0.15) moved on; -checkpoint/-resume carry the state
if [[ " ${LEVELS:-2 3 4} " == *" 4 "* ]]; then
  prev=""
  for xy in 1.15,0.15 1.2,0.25 1.25,0.325 1.3,0.4; do
    R=""; [ -n "$prev" ] && R="-resume $tmp/cont.ckpt"
    run "cont4_${xy/,/_}" 4 "${xy%,*}" "${xy#*,}" $R -checkpoint "$tmp/cont.new"
    mv "$tmp/cont.new" "$tmp/cont.ckpt"; prev=1
  done
fi
echo "wrote $out"
