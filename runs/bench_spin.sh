#!/usr/bin/env bash
# Spin transformation benchmark (issue 4): seconds for the eigenpair + reconstruction (operator assembly,
# smallest eigenpair of Eq. 7, Poisson solve: the summary keys seconds_setup + seconds_eigen + seconds_poisson;
# mesh I/O and distribution excluded), for a painted bump rho, on
#   torus 64x64 (4096 vertices), torus 120x120 (14400 vertices), bunny_closed_cgal.obj (37706 vertices, 75408 faces),
# serial and 2 ranks, with
#   default   Krylov-Schur + shift-and-invert; serially the supernodal factorisation of K - sigma in quaternion
#             arithmetic (MatSolverType csquat, src/linalg/quaternion_cholesky.c) and a CHOLMOD Poisson solve; in parallel the
#             substructured CHOLMOD factorisation (PC cssubchol) of the real 4V x 4V matrix and of the Poisson problem
#   complex   the same with CHOLMOD's factorisation of the complex form (-spin_st_pc_factor_mat_solver_type cscholmod; the
#             previous default, cholmod_factor.c)
#   default_2threads  the same serial run with 2 BLAS/OpenMP threads (CHOLMOD's supernodal BLAS; one process)
#   real4V    the same with the real 4V x 4V CHOLMOD factorisation (-spin_st_pc_factor_mat_solver_type cholmod; the default before the complex form)
#   inverse1  one step of inverse iteration with the same factorisation (-spin_solver inverse)
#   precond   iterative: LOBPCG preconditioned by the scalar Laplacian L + cM per quaternion component
#             (-spin_solver precond; no 4V factorisation at all)
# Median of N runs (default 5), OMP_NUM_THREADS = OPENBLAS_NUM_THREADS = 1 (2 cores; threads oversubscribe with
# 2 ranks).
# Usage: bash runs/bench_spin.sh [repeats]      (table in runs/results/bench_spin.md)
set -uo pipefail
cd "$(dirname "$0")/.."
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
export OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1
reps=${1:-5}
mkdir -p runs/results
out=runs/results/bench_spin.md
bunny=meshes/bunny_closed_cgal.obj; [ -f "$bunny" ] || bunny=../shared/meshes/bunny_closed_cgal.obj
declare -A MESH=(
  [torus4k]="-gen torus -gen_n 64 -gen_m 64 -rho_bump_center 2.41,0,0 -rho_bump_radius 0.6 -rho_bump_height 1.5"
  [torus14k]="-gen torus -gen_n 120 -gen_m 120 -rho_bump_center 2.41,0,0 -rho_bump_radius 0.6 -rho_bump_height 1.5"
  [bunny75kF]="-mesh $bunny -rho_bump_center -0.25,0.1,-0.05 -rho_bump_radius 0.12 -rho_bump_height 6"
)
declare -A CONF=(
  [default]=""
  [default_2threads]=""
  [complex]="-spin_st_pc_factor_mat_solver_type cscholmod"
  [real4V]="-spin_st_pc_factor_mat_solver_type cholmod"
  [inverse1]="-spin_solver inverse"
  [precond]="-spin_solver precond"
)
{
  echo "# bench_spin ($(date -u +%Y-%m-%dT%H:%MZ), $(getconf _NPROCESSORS_ONLN) cores, load $(cut -d' ' -f1-3 /proc/loadavg), median of $reps)"
  echo
  echo "Wall seconds (setup = mass + Dirac assembly, eigen = EPS incl. factorisation, poisson = Eq. 8 + solve) and, in"
  echo "the last column, the CPU seconds of rank 0 for the same three phases (robust when other jobs load the machine)."
  echo
  echo "| mesh | vertices | ranks | solver | setup s | eigen s | poisson s | total s (wall) | eps its | inner its | gamma | q_mean | total CPU s |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|---|---|"
} > $out
for m in torus4k torus14k bunny75kF; do
  for np in 1 2; do
    for c in default default_2threads complex real4V inverse1 precond; do
      rm -f runs/results/spin_bench_tmp.txt
      opts=${CONF[$c]}
      if { [ $c = real4V ] || [ $c = complex ]; } && [ $np = 2 ]; then continue; fi   # serial-only choices: same as default
      if [ $c = default_2threads ] && [ $np = 2 ]; then continue; fi
      th=1; [ $c = default_2threads ] && th=2
      for r in $(seq $reps); do
        if OMP_NUM_THREADS=$th OPENBLAS_NUM_THREADS=$th timeout 300 mpirun -x OMP_NUM_THREADS -x OPENBLAS_NUM_THREADS -n $np bin/confsurf -task spin ${MESH[$m]} $opts -summary runs/results/spin_bench.json > /dev/null 2>&1; then
          python3 -c "
import json; s = json.load(open('runs/results/spin_bench.json'))
print(s['vertices'], s['seconds_setup'], s['seconds_eigen'], s['seconds_poisson'], s['eps_its'], s['inner_its'], s['eigenvalue'], s['q_mean'], s['cpu_seconds_setup'] + s['cpu_seconds_eigen'] + s['cpu_seconds_poisson'])" >> runs/results/spin_bench_tmp.txt
        else
          echo "failed" >> runs/results/spin_bench_tmp.txt
        fi
      done
      python3 - runs/results/spin_bench_tmp.txt $m $np $c >> $out <<'PY'
import sys, statistics
rows = [l.split() for l in open(sys.argv[1])]
ok = [list(map(float, r)) for r in rows if r[0] != 'failed']
m, np, c = sys.argv[2:5]
if not ok:
    print(f"| {m} | - | {np} | {c} | failed/timeout | | | | | | | | |"); sys.exit()
med = lambda k: statistics.median(r[k] for r in ok)
tot = statistics.median(r[1] + r[2] + r[3] for r in ok)
print(f"| {m} | {int(ok[0][0])} | {np} | {c} | {med(1):.3f} | {med(2):.3f} | {med(3):.3f} | **{tot:.3f}** | {int(med(4))} | {int(med(5))} | {ok[0][6]:.6g} | {ok[0][7]:.6f} | {med(8):.3f} |")
PY
      tail -1 $out
    done
  done
done
rm -f runs/results/spin_bench_tmp.txt runs/results/spin_bench.json
echo "wrote $out"
