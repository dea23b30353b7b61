#!/usr/bin/env bash
# soliman2021 Fig. 17 (issue 39): the 4-lobed critical tori continued in the class b on 96 x 24, from b = 3.9 (just above
# the smooth branch point sqrt 15 = 3.873; the grid's discrete one is 3.811) to 4.4 (the class of options/cgd_fig17_n4.opts):
#   bash runs/fig17_lobed_n4_continue.sh [B_END [STEP]]   (default 4.4 0.025; serially ~5 min under load)
# Newton on the KKT system (-flow_type newton -flow_conformal) from the homogeneous torus of b = 3.9 with the 4-wave 0.35,
# then at each b + STEP from the previous result in its new class (runs/fig17_lengths.py; -mesh_lengths). Newton from a
# wave at b = 4.4 does not converge (0.6: folded), and a step of 0.1 (3.9 -> 4.0) lands on the homogeneous torus: the
# small steps keep it on the lobed branch. Per b: iterations, W, EL_scaled, class, the 4-fold error about the torus's axis
# (runs/nfold_symmetry.py) and the 4-lobe amplitude (runs/fig17_modes.py); the homogeneous tori of the end classes by cgd.
# Results in runs/results/fig17_lobed_n4_cont/. Needs numpy (/usr/bin/python3). Numbers: docs/triangle_fields.md "Fig. 17".
set -euo pipefail
cd "$(dirname "$0")/.."
end=${1:-4.4} step=${2:-0.025} d=runs/results/fig17_lobed_n4_cont
mkdir -p $d
N=96 M=24 b=3.9
base=(-task flow -flow_type newton -flow_conformal -flow_constraint_mobius -flow_constraint_area -flow_max_it 30 -flow_rtol 1e-9)
tau() { /usr/bin/python3 -c "print(repr(1 / $1))"; }
report() {
  local r=$1
  /usr/bin/python3 - $r.json $2 <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
print("b %s: %s after %d its, W %.10f, EL_scaled %.1e, class %.1e" % (sys.argv[2], s["stop_reason"], s["iterations"], s["willmore"], s["el_residual_scaled"], s["conformal_violation"]), end="; ")
PY
  /usr/bin/python3 runs/nfold_symmetry.py $r.obj 4 | sed 's/.*error max \([^,]*\),.*/4-fold error \1/' | tr '\n' ';'
  /usr/bin/python3 runs/fig17_modes.py $r.obj $M | awk '{print " lobes |rho_4|/rho_0", $(NF-6)}'
  grep -q '"stop_reason": *"converged"' $r.json
}
homogeneous() {
  nice -n 10 timeout 300 bin/confsurf -task flow -flow_type cgd -gen lattice -gen_tau 0,$(tau $1) -gen_n $N -gen_m $M -flow_constraint_mobius \
    -flow_max_it 100 -flow_rtol 1e-9 -summary $d/homogeneous_$1.json -o $d/homogeneous_$1.obj > $d/homogeneous_$1.log 2>&1
  /usr/bin/python3 -c "import json; s = json.load(open('$d/homogeneous_$1.json')); print('homogeneous torus, b $1 (cgd): W %.10f, %s, EL_scaled %.1e' % (s['willmore'], s['stop_reason'], s['el_residual_scaled']))"
}
r=$d/b$b
nice -n 10 timeout 600 bin/confsurf "${base[@]}" -gen lattice -gen_tau 0,$(tau $b) -gen_n $N -gen_m $M -gen_deform_nfold 4,0.35 \
  -summary $r.json -o $r.obj > $r.log 2>&1 || true
report $r $b
for b in $(/usr/bin/python3 -c "import numpy as np; print(' '.join('%.4g' % x for x in np.arange(3.9 + $step, $end + 1e-9, $step)))"); do
  prev=$r r=$d/b$b
  /usr/bin/python3 runs/fig17_lengths.py $N $M 0,$(tau $b) $prev.obj $r.len
  nice -n 10 timeout 600 bin/confsurf "${base[@]}" -mesh $prev.obj -mesh_lengths $r.len -summary $r.json -o $r.obj > $r.log 2>&1 || true
  report $r $b || { echo "stopped: not converged at b $b"; break; }
done
homogeneous 3.9
homogeneous $end
