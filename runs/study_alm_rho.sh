#!/usr/bin/env bash
# Study (not a test): the augmented Lagrangian baseline on the bumpy sphere of options/flow_sphere.opts (level 4)
# for several penalties rho, with the Gauss-Newton metric (converges) and the plain metric (the paper's explicit
# baseline), against CGD. Outputs in runs/results/alm_rho/ (<run>.{csv,json,log}), the table
# runs/results/alm_rho.md and alm_rho.png (W, violation, EL against iteration, scripts/plots.py). docs/alm.md.
# Knobs: MAXIT=300. One rank; the machine is shared (seconds are noisy).
set -u
cd "$(dirname "$0")/.."
MAXIT=${MAXIT:-300}
BIN=$PWD/bin/confsurf; PY=$(bash scripts/find-python.sh 2>/dev/null || echo /usr/bin/python3)
out=runs/results/alm_rho; mkdir -p "$out"
run() { # name options...
  local n=$1; shift
  "$BIN" -task flow -options_file options/flow_sphere.opts -flow_max_it $MAXIT "$@" \
    -history_csv "$out/$n.csv" -summary "$out/$n.json" > "$out/$n.log" 2>&1
  echo "$n: $(grep -E 'converged' "$out/$n.log" | tail -1 | cut -c1-120)"
}
run cgd
for r in 0.1 10 1000; do run gn_rho_$r -flow_type alm -flow_alm_rho $r; done
run plain_rho_10 -flow_type alm -flow_alm_metric plain -flow_alm_rho 10
run plain_rho_0.01_fixed -flow_type alm -flow_alm_metric plain -flow_alm_rho 0.01 -flow_alm_rho_grow 1
runs=(); curves=()
for n in cgd gn_rho_0.1 gn_rho_10 gn_rho_1000 plain_rho_10 plain_rho_0.01_fixed; do runs+=("$n=$out/$n.json"); curves+=("$n=$out/$n.csv"); done
{
  echo "ALM on options/flow_sphere.opts, $(date -u +%Y-%m-%d\ %H:%M) UTC, commit $(git rev-parse --short HEAD), MAXIT=$MAXIT, one rank (shared machine)"
  echo
  "$PY" scripts/plots.py table - converged,iterations,willmore,area,conformal_violation,el_residual,rejections,seconds "${runs[@]}"
} > runs/results/alm_rho.md
"$PY" scripts/plots.py curves runs/results/alm_rho.png --x it --title "ALM vs CGD, bumpy sphere (options/flow_sphere.opts)" "${curves[@]}"
cat runs/results/alm_rho.md
