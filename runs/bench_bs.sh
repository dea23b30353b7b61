#!/usr/bin/env bash
# Issue 5 benchmark (bobenko-schroeder2005 semi-implicit Willmore flow): seconds per semi-implicit step
# (assembly of K and grad W, three KSP solves, one trial energy; rejected attempts included) on
# meshes/bunny_closed_cgal.obj (75k faces) and the level-7 linearly subdivided icosahedron (327,680 faces),
# serially and on 2 ranks, with the default solver, MUMPS LDL^T with the AMD ordering (symmetric indefinite;
# CHOLMOD is no option: it stops with an error when 1/dt I + K is indefinite, which the step control must be able
# to reject; src/methods/bs/, docs/solvers.md), and the iterative alternative CG + BoomerAMG (rtol 1e-6).
# Median of $REPS runs (default 5; $REPS_BIG for the 330k mesh, default 3). Writes runs/results/bench_bs.md.
# Usage: bash runs/bench_bs.sh   (from the repository root, after make)
set -euo pipefail
cd "$(dirname "$0")/.."
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
REPS=${REPS:-5}; REPS_BIG=${REPS_BIG:-3}
out=runs/results; mkdir -p $out; tab=$out/bench_bs.md; tmp=$(mktemp -d)
bunny=meshes/bunny_closed_cgal.obj; [ -f $bunny ] || bunny=../shared/meshes/bunny_closed_cgal.obj
echo "| mesh | faces | ranks | solver | steps (accepted+rejected) | ksp its/solve | s/step median | s/step all runs |" > $tab
echo "|---|---|---|---|---|---|---|---|" >> $tab
run() { # name src steps reps np solver-label solver-options...
  local name=$1 src=$2 steps=$3 reps=$4 np=$5 label=$6; shift 6
  local all=() faces=0 st=0 kits=0
  for r in $(seq $reps); do
    mpirun -n $np bin/confsurf -task flow -flow_type bs $src -bs_max_it $steps -bs_atol 0 -bs_rtol 0 "$@" \
      -summary $tmp/s.json -history_csv $tmp/h.csv > $tmp/log
    all+=($(python3 -c "import json; print('%.4f' % json.load(open('$tmp/s.json'))['seconds_per_step'])"))
  done
  read faces st kits < <(python3 - $tmp <<'PY'
import json, sys
d = sys.argv[1]; s = json.load(open(d + "/s.json"))
rows = [l.split(",") for l in open(d + "/h.csv") if l.count(",") >= 6][1:]
its = [float(r[5]) for r in rows[1:]]
print(s["faces"], s["iterations"] + s["rejected"], "%.1f" % (sum(its) / max(1, 3 * len(its))))
PY
)
  med=$(printf '%s\n' "${all[@]}" | sort -g | awk '{a[NR]=$1} END {print a[int((NR+1)/2)]}')
  echo "| $name | $faces | $np | $label | $st | $kits | $med | ${all[*]} |" | tee -a $tab
}
MUMPS="-bs_semi_ksp_type preonly -bs_semi_pc_type cholesky -bs_semi_pc_factor_mat_solver_type mumps -bs_semi_mat_mumps_icntl_7 0"  # the default solver, with AMD (the default ordering is MUMPS's choice, AMF: docs/bs_flow.md)
HYPRE="-bs_semi_ksp_type cg -bs_semi_pc_type hypre -bs_semi_ksp_rtol 1e-6"
run bunny_closed "-mesh $bunny" 5 $REPS 1 "cg+hypre" $HYPRE
run bunny_closed "-mesh $bunny" 5 $REPS 2 "cg+hypre" $HYPRE
run bunny_closed "-mesh $bunny" 5 $REPS 1 "mumps" $MUMPS
run bunny_closed "-mesh $bunny" 5 $REPS 2 "mumps" $MUMPS
run icosphere7_flat "-gen icosphere -gen_level 7 -gen_project false" 3 $REPS_BIG 1 "cg+hypre" $HYPRE
run icosphere7_flat "-gen icosphere -gen_level 7 -gen_project false" 3 $REPS_BIG 2 "cg+hypre" $HYPRE
run icosphere7_flat "-gen icosphere -gen_level 7 -gen_project false" 3 $REPS_BIG 1 "mumps" $MUMPS
run icosphere7_flat "-gen icosphere -gen_level 7 -gen_project false" 3 $REPS_BIG 2 "mumps" $MUMPS
echo "machine: $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg) at the end; $(date -u)" >> $tab
rm -rf $tmp
echo "wrote $tab"
