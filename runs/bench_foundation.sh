#!/usr/bin/env bash
# Foundation benchmark (issue 2): time to read+validate, distribute, and evaluate the Willmore energy and its
# gradient, on bunny_closed_cgal.obj (75k faces) and a level-7 icosphere (328k faces), serial and on 2 ranks;
# median of 5 runs. Numbers come from -log_view events (CSMeshRead, CSMeshDistribute, CSEnergy, CSGradient).
# Usage: bash runs/bench_foundation.sh [repeats]   (results in runs/results/bench_foundation.md)
set -euo pipefail
cd "$(dirname "$0")/.."
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
reps=${1:-5}
mkdir -p runs/results
out=runs/results/bench_foundation.md
mesh=meshes/bunny_closed_cgal.obj; [ -f "$mesh" ] || mesh=../shared/meshes/bunny_closed_cgal.obj
echo "| mesh | faces | ranks | read+validate s | distribute s | W+grad s (x10) | faces/s (W+grad) |" > $out
echo "|---|---|---|---|---|---|---|" >> $out
for src in "-mesh $mesh" "-gen icosphere -gen_level 7"; do
  for np in 1 2; do
    for r in $(seq $reps); do
      mpirun -n $np build/runs/bench_energy $src -bench_repeat 10 -log_view :$PWD/runs/results/log_${np}_${r}.txt >/dev/null
      python3 - runs/results/log_${np}_${r}.txt <<'PY' >> runs/results/tmp_$np.txt
import sys, re
t = {}
for line in open(sys.argv[1]):
    m = re.match(r'^(CSMeshRead|CSMeshDistribute|CSEnergy|CSGradient)\s+\d+\s+\S+\s+(\S+)', line)
    if m: t[m.group(1)] = float(m.group(2))
print(t.get('CSMeshRead', 0), t.get('CSMeshDistribute', 0), t.get('CSEnergy', 0) + t.get('CSGradient', 0))
PY
    done
    python3 - runs/results/tmp_$np.txt "$src" $np >> $out <<'PY'
import sys, statistics
rows = [list(map(float, l.split())) for l in open(sys.argv[1])]
med = [statistics.median(c) for c in zip(*rows)]
name = sys.argv[2].split()[-1] if 'mesh' in sys.argv[2] else 'icosphere level 7'
faces = 75408 if 'bunny' in sys.argv[2] else 327680
print(f"| {name} | {faces} | {sys.argv[3]} | {med[0]:.3f} | {med[1]:.3f} | {med[2]:.3f} | {10*faces/med[2]/1e6:.2f} M |")
PY
    rm -f runs/results/tmp_$np.txt runs/results/log_*.txt
  done
done
cat $out
