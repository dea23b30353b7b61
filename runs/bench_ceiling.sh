#!/usr/bin/env bash
# What 2 ranks can gain on this machine (issue 3's speed-up target; not a test). Runs the serial flow step's two
# kernels -- the CHOLMOD factorisation of the Schur complement S (compute-bound, dense BLAS 3 in the supernodes)
# and its triangular solves (memory-bound) -- once alone and as two independent copies at the same time, and the
# same flow on 2 ranks (cssubchol). The "ceiling" is the throughput of both cores in units of one core:
# 2 t_alone / t_together, the speed-up a perfectly split kernel could reach with no extra work and no
# communication. Median of REPEAT runs (default 3) at icosphere level LEVEL (default 6). Writes runs/bench_ceiling.md.
#   bash runs/bench_ceiling.sh
#   LEVEL=5 REPEAT=5 bash runs/bench_ceiling.sh
set -u
cd "$(dirname "$0")/.."
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1
LEVEL=${LEVEL:-6}; REPEAT=${REPEAT:-3}
out=runs/bench_ceiling.md; tmp=$(mktemp -d)
args=(-task flow -gen icosphere -gen_level "$LEVEL" -gen_deform_bump 0.2 -gen_deform_stretch 1.5,1,0.8 -flow_max_it 4 -flow_rtol 0 -flow_factor_reuse_its 0)
per() { # log event -> seconds per call (max over ranks, as -log_view prints)
  awk -v e="$2" '$1 == e { printf "%.6g", $4 / $2; f = 1 } END { if (!f) print "nan" }' "$1"
}
fa=(); sa=(); ft=(); st=(); fp=(); sp=()
for r in $(seq "$REPEAT"); do
  bin/confsurf "${args[@]}" -log_view ":$tmp/a.log" > /dev/null || { echo "FAILED (alone)"; exit 1; }
  bin/confsurf "${args[@]}" -log_view ":$tmp/b.log" > /dev/null & p1=$!
  bin/confsurf "${args[@]}" -log_view ":$tmp/c.log" > /dev/null & p2=$!
  wait $p1 && wait $p2 || { echo "FAILED (together)"; exit 1; }
  mpirun -n 2 bin/confsurf "${args[@]}" -log_view ":$tmp/p.log" > /dev/null || { echo "FAILED (2 ranks)"; exit 1; }
  fa+=("$(per "$tmp/a.log" MatCholFctrNum)"); sa+=("$(per "$tmp/a.log" MatSolve)")
  ft+=("$(python3 -c "print(max($(per "$tmp/b.log" MatCholFctrNum), $(per "$tmp/c.log" MatCholFctrNum)))")")
  st+=("$(python3 -c "print(max($(per "$tmp/b.log" MatSolve), $(per "$tmp/c.log" MatSolve)))")")
  fp+=("$(per "$tmp/p.log" CSSubCholNum)"); sp+=("$(per "$tmp/p.log" CSSubCholSolve)")
  echo "run $r: factorisation alone ${fa[-1]} s, together ${ft[-1]} s, 2 ranks ${fp[-1]} s; solve alone ${sa[-1]} s, together ${st[-1]} s, 2 ranks ${sp[-1]} s"
done
med() { printf '%s\n' "$@" | sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
row() { # label alone together parallel
  python3 -c "import sys; a, t, p = map(float, sys.argv[2:5]); print('| %s | %.4g | %.4g | %.2f | %.4g | %.2f |' % (sys.argv[1], a, t, 2 * a / t, p, a / p))" "$@"
}
{
  echo "Icosphere level $LEVEL, cgd flow, 4 steps refactoring every step; median of $REPEAT; seconds per call."
  echo
  echo "| kernel | 1 copy alone | 2 copies at once | ceiling (2 alone / together) | 2 ranks (cssubchol) | 2-rank speed-up |"
  echo "|---|---|---|---|---|---|"
  row "factorisation of S" "$(med "${fa[@]}")" "$(med "${ft[@]}")" "$(med "${fp[@]}")"
  row "solve with S" "$(med "${sa[@]}")" "$(med "${st[@]}")" "$(med "${sp[@]}")"
} | tee "$out"
rm -rf "$tmp"
echo "wrote $out"
