#!/usr/bin/env bash
# Benchmark of the constrained Willmore flow (issue 3; not a test): seconds per iteration and KSP iterations per
# iteration of cgd on bumpy icospheres (levels 5/6/7 = 20k/82k/328k faces) and the closed bunny (75k faces),
# serial and on 2 ranks, with the default solver (fieldsplit Schur with our assembled exact S as `user` Schur
# preconditioner, CHOLMOD Cholesky of S serially, the substructured CHOLMOD factorisation cssubchol on 2 ranks) and with the
# monolithic MUMPS reference (options/flow_mumps.opts). Each configuration runs -flow_max_it N iterations
# (default 5) REPEAT times (default 3); the table shows the median. Writes runs/bench_flow.md.
# The factorisation is kept across steps while it preconditions well (-flow_pc_reuse_its): the first steps
# of a run change the surface most and refactor often, so seconds per iteration fall with N; the
# "factorisations" column counts them (pc_setups in the summary). EXTRA="-flow_pc_reuse_its 0" refactors
# every step (the earlier default).
#   bash runs/bench_flow.sh                 # everything (level 7 takes a long time)
#   LEVELS="5 6" MESHES=bunny NITER=3 REPEAT=1 bash runs/bench_flow.sh
set -u
cd "$(dirname "$0")/.."
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
# one BLAS thread per rank: on this 2-core machine OpenBLAS threads oversubscribe the cores (measured: MUMPS
# factorisation 2x faster with 1 thread when the machine is busy)
export OPENBLAS_NUM_THREADS=${OPENBLAS_NUM_THREADS:-1}
LEVELS=${LEVELS:-"5 6 7"}; MESHES=${MESHES:-"bunny"}; NITER=${NITER:-5}; REPEAT=${REPEAT:-3}; NPS=${NPS:-"1 2"}
SOLVERS=${SOLVERS:-"fieldsplit mumps"}; EXTRA=${EXTRA:-}
out=runs/bench_flow.md; tmp=$(mktemp -d)
echo "| input | faces | ranks | solver | iterations | s/iteration | KSP its/iteration | factorisations | total s |" > "$out"
echo "|---|---|---|---|---|---|---|---|---|" >> "$out"
run_case() { # label faces np solver args...
  local label=$1 faces=$2 np=$3 solver=$4; shift 4
  local sargs=""; [ "$solver" = mumps ] && sargs="-options_file options/flow_mumps.opts"
  local spi=() its=() tot=() fac=()
  for r in $(seq "$REPEAT"); do
    mpirun -n "$np" bin/confsurf -task flow "$@" $sargs $EXTRA -flow_max_it "$NITER" -flow_rtol 0 -summary "$tmp/s.json" > "$tmp/log" 2>&1 || { echo "FAILED: $label np=$np $solver"; tail -3 "$tmp/log"; return; }
    read -r a b c e < <(python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); n=max(d["iterations"],1); print(d["seconds_per_iteration"], d["ksp_iterations"]/n, d["seconds"], d.get("pc_setups", 0))' "$tmp/s.json")
    spi+=("$a"); its+=("$b"); tot+=("$c"); fac+=("$e")
  done
  med() { printf '%s\n' "$@" | sort -g | awk '{a[NR]=$1} END {printf "%.3g", a[int((NR+1)/2)]}'; }
  echo "| $label | $faces | $np | $solver | $NITER | $(med "${spi[@]}") | $(med "${its[@]}") | $(med "${fac[@]}") | $(med "${tot[@]}") |" | tee -a "$out"
}
for L in $LEVELS; do
  faces=$((20 * 4 ** L))
  for np in $NPS; do for s in $SOLVERS; do
    run_case "bumpy icosphere level $L" "$faces" "$np" "$s" -gen icosphere -gen_level "$L" -flow_init_bump 0.2 -flow_init_stretch 1.5,1,0.8
  done; done
done
for M in $MESHES; do
  [ "$M" = bunny ] || continue
  for np in $NPS; do for s in $SOLVERS; do
    run_case "bunny_closed_cgal.obj (willmore)" 75408 "$np" "$s" -mesh meshes/bunny_closed_cgal.obj
  done; done
done
rm -rf "$tmp"
echo "wrote $out"
