#!/usr/bin/env bash
# Issue 15 benchmark (soliman2021 Algorithm 2, Fig. 16): seconds per iteration and iterations to convergence of the
# triangle-field flow for the Fig. 16 torus (square lattice tau = i, -gen lattice -gen_tau 0,1) at three lattice
# resolutions N x N, serially and on 2 ranks, from two starts:
#   random: -flow_init random_spinor -flow_init_amplitude 0.1 -flow_seed 1 (the Fig. 16 start; -flow_max_it $MAXR)
#   df:     omega_0 = df of the generator's torus (the class's stereographic torus; -flow_max_it $MAXD)
# Iterations to convergence = the summary's iterations when converged (el_residual < 1e-6, rows < 1e-10), else
# "not in M". Writes runs/bench_trianglefield.md's table to runs/results/bench_trianglefield.md.
# Usage: bash runs/bench_trianglefield.sh   (from the repository root, after make); NS="8 12 16" MAXR=60 MAXD=150
set -euo pipefail
cd "$(dirname "$0")/.."
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
NS=${NS:-"8 12 16"}; MAXR=${MAXR:-60}; MAXD=${MAXD:-150}
out=runs/results; mkdir -p $out; tab=$out/bench_trianglefield.md; tmp=$(mktemp -d)
echo "| N x N | faces | start | ranks | iterations | converged | el_residual | W | pinch_edges | s/iteration | seconds |" > $tab
echo "|---|---|---|---|---|---|---|---|---|---|---|" >> $tab
for n in $NS; do
  for start in df random; do
    if [ $start = random ]; then S="-flow_init random_spinor -flow_init_amplitude 0.1 -flow_seed 1 -flow_max_it $MAXR"; else S="-flow_max_it $MAXD"; fi
    for np in 1 2; do
      mpirun -n $np bin/confsurf -task flow -flow_type trianglefield -gen lattice -gen_tau 0,1 -gen_n $n -gen_m $n $S \
        -summary $tmp/s.json > $tmp/log 2>&1 || { tail -3 $tmp/log; continue; }
      python3 - $tmp/s.json $n $start $np >> $tab <<'PY'
import json, sys
s = json.load(open(sys.argv[1])); n = int(sys.argv[2])
conv = s['converged'] in (True, 1, 'true')
print("| %d x %d | %d | %s | %s | %d | %s | %.2e | %.6f | %d | %.3f | %.1f |" % (n, n, 2 * n * n, sys.argv[3], sys.argv[4],
      s['iterations'], "yes" if conv else "no", s['el_residual'], s['willmore'], s.get('pinch_edges', -1),
      s['seconds_per_iteration'], s['seconds']))
PY
      tail -1 $tab
    done
  done
done
rm -rf $tmp
