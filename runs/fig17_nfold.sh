#!/usr/bin/env bash
# soliman2021 Fig. 17 (issue 39): the Newton runs of options/newton_fig17_*.opts and their checks, one command:
#   bash runs/fig17_nfold.sh [STEM ...]   (default: n2 n3 n4 lobed_n2 lobed_n3 lobed_n4 lobed_n2_b198; serially, 10-40 s each
#   under load; lobed_n2_b198 needs bash runs/fig17_lobed_n2_chain.sh first, ~20 min, and is skipped without it)
# For each options/newton_fig17_STEM.opts: the run (runs/results/newton_fig17_STEM.{log,json,csv,obj}), its n-fold
# symmetry error about the torus's own axis and the 48-fold one (runs/nfold_symmetry.py: a torus of revolution has
# both small, a lobed one not), the lobe content (runs/fig17_modes.py), and W against the smooth homogeneous torus
# pi^2 (b + 1/b) and 4 pi n. Needs numpy (/usr/bin/python3). Numbers: docs/triangle_fields.md "Fig. 17".
set -euo pipefail
cd "$(dirname "$0")/.."
mkdir -p runs/results
stems=("$@")
[ ${#stems[@]} -gt 0 ] || stems=(n2 n3 n4 lobed_n2 lobed_n3 lobed_n4 lobed_n2_b198)
for s in "${stems[@]}"; do
  o=options/newton_fig17_$s.opts r=runs/results/newton_fig17_$s n=$(sed -E 's/.*n([0-9]).*/\1/' <<< "$s")
  m=$(awk '$1 == "-gen_m" {print $2} $2 == "fig17:" {print $6}' $o)
  if grep -q "^-mesh " $o; then  # a restart (lobed_n2_b198): its start comes from runs/fig17_lobed_n2_chain.sh
    [ -f "$(awk '$1 == "-mesh" {print $2}' $o)" ] || { echo "== $s: run bash runs/fig17_lobed_n2_chain.sh first"; continue; }
  fi
  nice -n 10 timeout 600 bin/confsurf -options_file $o > $r.log 2>&1 || true
  echo "== $s"
  grep -E "^flow newton: (converged|NOT)" $r.log | cut -c1-120 || tail -3 $r.log
  if grep -q "^-mesh " $o; then  # 13824 vertices: the index-based 2-fold check (nfold_symmetry.py is O(V^2) in memory)
    /usr/bin/python3 runs/fig17_lobed_continue.py --check $r.obj $(awk '$2 == "fig17:" {print $6 * 1.5, $6}' $o)
  else
    /usr/bin/python3 runs/nfold_symmetry.py $r.obj $n
    /usr/bin/python3 runs/nfold_symmetry.py $r.obj 48
  fi
  /usr/bin/python3 runs/fig17_modes.py $r.obj $m
  /usr/bin/python3 - $r.json $o $n <<'PY'
import json, math, sys
s = json.load(open(sys.argv[1])); n = int(sys.argv[3])
tau = [l.split()[1] if l.startswith('-gen_tau') else l.split()[-1] for l in open(sys.argv[2]) if l.startswith('-gen_tau') or l.startswith('# fig17:')][0]
b = 1 / float(tau.split(',')[1])
print("n %d b %.4g: W %.10f, homogeneous pi^2(b+1/b) %.4f, 4 pi n %.4f; EL_scaled %.2e, class %.2e, %s after %d iterations"
      % (n, b, s["willmore"], math.pi ** 2 * (b + 1 / b), 4 * math.pi * n, s["el_residual_scaled"], s["conformal_violation"], s["stop_reason"], s["iterations"]))
PY
done
