#!/usr/bin/env bash
# soliman2021 Fig. 17 (issue 39): an n-lobed critical torus continued along its branch in the class b (natural
# continuation), for any n:
#   bash runs/fig17_branch_continue.sh N_LOBES GRID_N GRID_M B_START WAVE B_END STEP [OUT_DIR]
# e.g. 3 96 30 2.85 0.25 3.2 0.025 (docs/triangle_fields.md "The 3-lobed tori"); runs/fig17_lobed_n4_continue.sh is
# 4 96 24 3.9 0.35 4.4 0.025. GRID_N must be divisible by N_LOBES (an n-fold grid); OUT_DIR defaults to
# runs/results/fig17_lobed_nN_GRID_NxGRID_M.
# 1. Newton on the KKT system (-flow_type newton -flow_conformal) from the homogeneous torus of B_START (-gen lattice,
#    tau = i / b) with the n-wave WAVE (-gen_deform_nfold N,WAVE). B_START must lie just above the grid's discrete
#    branch point of the n-lobe mode (runs/fig17_mode_history.py: where a small wave grows under cgd), or Newton lands
#    on the homogeneous torus. WAVE may instead name an OBJ on the GRID_N x GRID_M grid (vertex (i, j) = i GRID_M + j),
#    e.g. a lobed torus of another grid moved by runs/fig17_regrid.py: Newton then starts from it in the class B_START.
# 2. At each b = B_START + k STEP up to B_END: Newton from the previous result in the new class (runs/fig17_lengths.py
#    writes the class as edge lengths; -mesh_lengths). Small steps keep it on the lobed branch (n = 4: a step of 0.1
#    from 3.9 lands on the homogeneous torus).
# Per b: iterations, W, EL_scaled, class, the n-fold error about the torus's own axis (runs/nfold_symmetry.py) and the
# n-lobe amplitude, the largest over the rings of |rho_n|/rho_0 (runs/fig17_modes.py); then the homogeneous tori of
# B_START and B_END by cgd. Exits non-zero (and stops the continuation) at the first b that is not converged, not
# n-fold symmetric to 1e-8, or not lobed (amplitude < 1e-2: fallen onto the homogeneous torus).
# Serially, nice -n 10, timeout 600 s per run. Needs numpy (/usr/bin/python3).
set -euo pipefail
cd "$(dirname "$0")/.."
[ $# -ge 7 ] || { echo "usage: $0 N_LOBES GRID_N GRID_M B_START WAVE B_END STEP [OUT_DIR]" >&2; exit 2; }
n=$1 N=$2 M=$3 b0=$4 wave=$5 end=$6 step=$7
d=${8:-runs/results/fig17_lobed_n${n}_${N}x${M}}
[ $((N % n)) -eq 0 ] || { echo "$0: GRID_N $N is not divisible by N_LOBES $n (the grid must be $n-fold symmetric)" >&2; exit 2; }
mkdir -p "$d"
base=(-task flow -flow_type newton -flow_conformal -flow_constraint_mobius -flow_constraint_area -flow_max_it 30 -flow_rtol 1e-9)
tau() { /usr/bin/python3 -c "print(repr(1 / $1))"; }
# One line per b; non-zero if the run is not a converged, n-fold symmetric, lobed torus.
report() {
  local r=$1 b=$2 sym lobes
  sym=$(/usr/bin/python3 runs/nfold_symmetry.py $r.obj $n | sed 's/.*error max \([^,]*\),.*/\1/')
  lobes=$(/usr/bin/python3 runs/fig17_modes.py $r.obj $M | awk -v n=$n '{print $(NF - 10 + n)}')
  /usr/bin/python3 - $r.json $b $n "$sym" "$lobes" <<'PY'
import json, sys
s = json.load(open(sys.argv[1])); n = int(sys.argv[3]); sym, lobes = float(sys.argv[4]), float(sys.argv[5])
print("b %s: %s after %d its, W %.10f, EL_scaled %.1e, class %.1e; %d-fold error %.1e; lobes |rho_%d|/rho_0 %.3f"
      % (sys.argv[2], s["stop_reason"], s["iterations"], s["willmore"], s["el_residual_scaled"], s["conformal_violation"],
         n, sym, n, lobes))
sys.exit(0 if s["stop_reason"] == "converged" and sym < 1e-8 and lobes > 1e-2 else 1)
PY
}
homogeneous() {
  nice -n 10 timeout 600 bin/confsurf -task flow -flow_type cgd -gen lattice -gen_tau 0,$(tau $1) -gen_n $N -gen_m $M -flow_constraint_mobius \
    -flow_max_it 100 -flow_rtol 1e-9 -summary $d/homogeneous_$1.json -o $d/homogeneous_$1.obj > $d/homogeneous_$1.log 2>&1 || true
  /usr/bin/python3 -c "import json; s = json.load(open('$d/homogeneous_$1.json')); print('homogeneous torus, b $1 (cgd): W %.10f, %s, EL_scaled %.1e' % (s['willmore'], s['stop_reason'], s['el_residual_scaled']))"
}
status=0 b=$b0 r=$d/b$b0
if [ -f "$wave" ]; then
  /usr/bin/python3 runs/fig17_lengths.py $N $M 0,$(tau $b) "$wave" $r.len
  start=(-mesh "$wave" -mesh_lengths $r.len)
else
  start=(-gen lattice -gen_tau 0,$(tau $b) -gen_n $N -gen_m $M -gen_deform_nfold $n,$wave)
fi
nice -n 10 timeout 600 bin/confsurf "${base[@]}" "${start[@]}" -summary $r.json -o $r.obj > $r.log 2>&1 || true
if report $r $b; then
  for b in $(/usr/bin/python3 -c "import numpy as np; print(' '.join('%.4g' % x for x in np.arange($b0 + $step, $end + 1e-9, $step)))"); do
    prev=$r r=$d/b$b
    /usr/bin/python3 runs/fig17_lengths.py $N $M 0,$(tau $b) $prev.obj $r.len
    nice -n 10 timeout 600 bin/confsurf "${base[@]}" -mesh $prev.obj -mesh_lengths $r.len -summary $r.json -o $r.obj > $r.log 2>&1 || true
    report $r $b || { echo "stopped: b $b is not a converged, $n-fold symmetric, lobed torus"; status=1; break; }
  done
else
  echo "stopped: the start b $b0 (from $wave) is not a converged, $n-fold symmetric, lobed torus"; status=1
fi
homogeneous $b0
[ "$b" = "$b0" ] || homogeneous $b
exit $status
