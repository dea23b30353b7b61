#!/usr/bin/env bash
# Issue 16 item 3: the Dirac eigenproblem (crane2011 Eq. 7, smallest eigenpair) at scale.
# Icospheres (level 6/7/8: 40,962 / 163,842 / 655,362 vertices; 4V real unknowns) with a painted bump rho, x
#   direct    the default: shift-and-invert Krylov-Schur; K - sigma factored by csquat serially, cssubchol
#             (substructured CHOLMOD, dense interface Schur complement on every rank) on several ranks
#   mumps     the same with parallel MUMPS (AMD ordering, CSSpinMumpsDefaultOrdering): -spin_st_pc_type cholesky
#             -spin_st_pc_factor_mat_solver_type mumps
#   iterative Generalised Davidson (STPRECOND) with csspinlap: one GAMG V-cycle of L + cM per quaternion component
#             (-spin_solver precond -spin_lap_pc_type gamg); no 4V factorisation
#   iterative_lobpcg  the same with -spin_eps_type lobpcg
#   iterative_amgpoisson  iterative, and the Poisson step (Eq. 8) by CG + GAMG too (no factorisation at all)
# x ranks 1, 2, 4, 8, 16 (beyond 2 oversubscribed on this 2-core machine: iterations and memory only).
# Records eps iterations, inner iterations (shifted solves / scalar V-cycles), eigenvalue and residual, the
# eigen-phase seconds (wall), and the peak RSS of every rank (/usr/bin/time per rank; max and mean over ranks).
# The Poisson step (Eq. 8) uses its default (CHOLMOD / cssubchol) except in iterative_amgpoisson: memory includes it.
# Usage: bash runs/study_dirac_scaling.sh [levels] [ranks] [solvers] [timeout_s]
#   e.g. bash runs/study_dirac_scaling.sh "6 7" "1 2 4 8 16" "direct mumps iterative" 900
# Appends to runs/results/study_dirac_scaling.tsv (one line per run; delete it to start over) and rewrites
# runs/results/study_dirac_scaling_table.md from all lines.
set -uo pipefail
cd "$(dirname "$0")/.."
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
export OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1
levels=${1:-"6 7"}; ranks=${2:-"1 2 4 8 16"}; solvers=${3:-"direct mumps iterative"}; tmo=${4:-900}
mkdir -p runs/results
tsv=runs/results/study_dirac_scaling.tsv
[ -f $tsv ] || echo -e "level\tvertices\tranks\tsolver\tstatus\teps_its\tinner_its\teigenvalue\tresidual\tsec_eigen\tsec_total\trss_max_MB\trss_mean_MB\tload" > $tsv
declare -A CONF=(
  [direct]=""
  [mumps]="-spin_st_pc_type cholesky -spin_st_pc_factor_mat_solver_type mumps"
  [iterative]="-spin_solver precond -spin_lap_pc_type gamg"
  [iterative_lobpcg]="-spin_solver precond -spin_lap_pc_type gamg -spin_eps_type lobpcg"
  [iterative_amgpoisson]="-spin_solver precond -spin_lap_pc_type gamg -spin_poisson_ksp_type cg -spin_poisson_pc_type gamg -spin_poisson_ksp_rtol 1e-10"
)
B="-rho_bump_center 0,0,1 -rho_bump_radius 0.5 -rho_bump_height 3"
tmp=$(mktemp -d)
for L in $levels; do
  for np in $ranks; do
    for c in $solvers; do
      rm -f $tmp/s.json $tmp/rss.*
      load=$(cut -d' ' -f1 /proc/loadavg)
      timeout $tmo mpirun -n $np bash -c '/usr/bin/time -f "%M" -o '$tmp'/rss.$OMPI_COMM_WORLD_RANK "$@"' _ \
        bin/confsurf -task spin -gen icosphere -gen_level $L $B ${CONF[$c]} -summary $tmp/s.json > $tmp/out 2>&1
      rc=$?
      python3 - $tmp $L $np $c $rc $load >> $tsv <<'PY'
import sys, json, glob
tmp, L, np_, c, rc, load = sys.argv[1:7]
rss = [int(open(f).read().split()[-1]) / 1024 for f in glob.glob(tmp + "/rss.*") if open(f).read().strip()]
rmax = "%.0f" % max(rss) if rss else "-"; rmean = "%.0f" % (sum(rss) / len(rss)) if rss else "-"
try:
    s = json.load(open(tmp + "/s.json"))
    print("\t".join(map(str, [L, s["vertices"], np_, c, "ok", s["eps_its"], s["inner_its"], "%.10g" % s["eigenvalue"],
          "%.2e" % s["eigen_residual"], "%.2f" % s["seconds_eigen"], "%.2f" % s["seconds"], rmax, rmean, load])))
except Exception:
    st = "timeout" if rc == "124" else "failed(rc=%s)" % rc
    print("\t".join([L, "-", np_, c, st, "-", "-", "-", "-", "-", "-", rmax, rmean, load]))
PY
      tail -1 $tsv
      [ $rc = 0 ] || tail -3 $tmp/out
    done
  done
done
rm -rf $tmp
python3 - $tsv > runs/results/study_dirac_scaling_table.md <<'PY'
import sys
rows = [l.rstrip("\n").split("\t") for l in open(sys.argv[1])][1:]
print("| level | vertices | ranks | solver | status | eps its | inner its | eigenvalue | residual | eigen s | total s | peak RSS max/mean MB per rank | load |")
print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
for r in rows:
    t = r[9:11] if int(r[2]) <= 2 else ["(oversub.)", "(oversub.)"]
    print("| " + " | ".join(r[:9] + t + [r[11] + " / " + r[12], r[13]]) + " |")
PY
echo "wrote $tsv and runs/results/study_dirac_scaling_table.md"
