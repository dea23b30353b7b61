#!/usr/bin/env bash
# Benchmark of the step size control (issue 35 item 2; docs/willmore_flow.md "The step size model"): the predictive
# step (-flow_step_model predictive, the default) against the halving rule (-flow_step_model halving, the earlier
# default), alternated run by run so that the machine's drift falls on both alike; the table shows medians.
#   small: the bumped torus of the issue, 7744 faces (R 3, r 1, 88 x 44, bump 0.2), -flow_max_it 20, REPEAT runs
#          each: rejections in the first 20 iterations, W at iteration 20, factorisations, linear solves, KSP its, s
#   large: the same torus at 125316 faces (354 x 177, as runs/bench_flow.sh torus_bump), NITER (10) iterations,
#          once per variant serially and on 2 ranks (LARGE_NPS): s/iteration, linear solves/iteration, rejections
#   PARTS="small large" REPEAT=3 NITER=10 LARGE_NPS="1 2" bash runs/bench_step_control.sh
# Writes runs/bench_step_control.md. Seconds depend on the machine's load (report the counts beside them).
set -u
cd "$(dirname "$0")/.."
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OPENBLAS_NUM_THREADS=${OPENBLAS_NUM_THREADS:-1}
PARTS=${PARTS:-"small large"}; REPEAT=${REPEAT:-3}; NITER=${NITER:-10}; LARGE_NPS=${LARGE_NPS:-"1 2"}
out=runs/bench_step_control.md; tmp=$(mktemp -d)
row() { # label np variant args... -> one line of numbers from the summary
  local label=$1 np=$2 v=$3; shift 3
  if ! mpirun -n "$np" bin/confsurf -task flow "$@" -flow_step_model "$v" -summary "$tmp/s.json" > "$tmp/log" 2>&1; then
    echo "FAILED: $label np=$np $v" >&2; tail -3 "$tmp/log" >&2; return 1
  fi
  python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); n=max(d["iterations"],1)
print(d["rejections"], "%.6g" % d["energy"], d["pc_setups"], d["linear_solves"], d["ksp_iterations"], "%.4g" % d["seconds"], "%.4g" % (d["seconds"]/n), "%.3g" % (d["linear_solves"]/n), d["iterations"])' "$tmp/s.json"
}
med() { printf '%s\n' "$@" | sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}'; }
echo "| input | ranks | step model | runs | iterations | rejections | W at the end | factorisations | linear solves | KSP its | s | s/iteration | solves/iteration |" > "$out"
echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|" >> "$out"
table() { # label np variant runs-file
  local f=$4 n; n=$(wc -l < "$f"); [ "$n" -gt 0 ] || return 0
  col() { med $(awk -v c="$1" '{print $c}' "$f"); }
  echo "| $1 | $2 | $3 | $n | $(col 9) | $(col 1) | $(col 2) | $(col 3) | $(col 4) | $(col 5) | $(col 6) | $(col 7) | $(col 8) |" | tee -a "$out"
}
SMALL="-gen torus -gen_torus_R 3 -gen_tube_r 1 -gen_n 88 -gen_m 44 -gen_deform_bump 0.2 -flow_max_it 20"
LARGE="-gen torus -gen_torus_R 3 -gen_tube_r 1 -gen_n 354 -gen_m 177 -gen_deform_bump 0.2 -flow_max_it $NITER -flow_rtol 0"
for part in $PARTS; do
  case $part in
    small)
      : > "$tmp/small.predictive"; : > "$tmp/small.halving"
      for r in $(seq "$REPEAT"); do for v in predictive halving; do
        row small 1 $v $SMALL >> "$tmp/small.$v" || true
      done; done
      for v in predictive halving; do table "bumped torus 7744 faces, 20 it." 1 $v "$tmp/small.$v"; done ;;
    large)
      for np in $LARGE_NPS; do
        : > "$tmp/large.predictive"; : > "$tmp/large.halving"
        for v in predictive halving; do row large "$np" $v $LARGE >> "$tmp/large.$v" || true; done
        for v in predictive halving; do table "bumped torus 125316 faces, $NITER it." "$np" $v "$tmp/large.$v"; done
      done ;;
    *) echo "unknown part $part (small, large)"; exit 1 ;;
  esac
done
rm -rf "$tmp"
echo "wrote $out"
