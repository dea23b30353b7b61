#!/usr/bin/env bash
# soliman2021 Fig. 17 (issue 39): the Newton runs of options/newton_fig17_n{2,3,4}.opts and their checks, one command:
#   bash runs/fig17_nfold.sh [N ...]        (default 2 3 4; serially, ~1 min each under load)
# For each n: the run (runs/results/newton_fig17_nN.{json,csv,obj}), then its n-fold symmetry error about the torus's
# own axis (runs/nfold_symmetry.py), the 48-fold one (a torus of revolution has it too: small means not lobed), and
# W against the smooth homogeneous torus pi^2 (b + 1/b) and 4 pi n. Needs numpy (/usr/bin/python3).
set -euo pipefail
cd "$(dirname "$0")/.."
mkdir -p runs/results
for n in "${@:-2 3 4}"; do
  for k in $n; do
    nice -n 10 timeout 600 bin/confsurf -options_file options/newton_fig17_n$k.opts > runs/results/newton_fig17_n$k.log 2>&1 || true
    grep -E "^flow newton: (converged|NOT)" runs/results/newton_fig17_n$k.log || tail -3 runs/results/newton_fig17_n$k.log
    /usr/bin/python3 runs/nfold_symmetry.py runs/results/newton_fig17_n$k.obj $k
    /usr/bin/python3 runs/nfold_symmetry.py runs/results/newton_fig17_n$k.obj 48
    /usr/bin/python3 - runs/results/newton_fig17_n$k.json options/newton_fig17_n$k.opts $k <<'PY'
import json, math, sys
s = json.load(open(sys.argv[1])); n = int(sys.argv[3])
tau = [l.split()[1] for l in open(sys.argv[2]) if l.startswith('-gen_tau')][0]
b = 1 / float(tau.split(',')[1])
print("n %d b %.4g: W %.10f, homogeneous pi^2(b+1/b) %.4f, 4 pi n %.4f; EL_scaled %.2e, class %.2e, %s after %d iterations"
      % (n, b, s["willmore"], math.pi ** 2 * (b + 1 / b), 4 * math.pi * n, s["el_residual_scaled"], s["conformal_violation"], s["stop_reason"], s["iterations"]))
PY
  done
done
