#!/usr/bin/env bash
# Study of issue #16 (solvers that scale; not a test): the CGD saddle solve's Schur complement by the direct
# factorisation (the default; CHOLMOD serially, cssubchol in parallel) against the iterative paths of
# src/linalg/schur_iterative.c (-flow_saddle_schur_solver primal | multiplier), docs/scaling.md.
# Part 1 (serial): Krylov iterations per Schur solve and seconds per step against mesh size (bumpy icosphere levels
#   LEVELS) and against c = t t_mu (t = 1 fixed, t_mu = c, CS), NITER steps each, every step a fresh preconditioner
#   (-flow_factor_reuse_its 0), plus the kept-factorisation baseline (d) ("direct+reuse", the default reuse).
#   The extreme singular values of the preconditioned Schur operator come from -ksp_view_singularvalues of the
#   Schur KSP (the last solve of the run). The multiplier path nests an H solve in every S_mu application and
#   runs only up to level MULT_MAX (default 5).
# Part 0 (serial, PART=first): the first Schur solve of the first step only (t = 1 and t_mu = c exactly: later
#   solves of a step see rejected steps' smaller t and the restoration's t_mu = -flow_pgd_t_mu), primal path: CG
#   iterations and the extreme singular values of the preconditioned Schur operator, levels FLEVELS, c in FCS.
# Part 2 (ranks, oversubscribed): on NPS ranks at levels RLEVELS, the Schur complement's engines RPATHS:
#   auto = the default (cssubchol, which switches to MUMPS where its dense interface does not fit), cssubchol =
#   the substructuring forced (-pc_cssubchol_max_interface_ratio 1e9), mumps = MUMPS Cholesky with AMD ordering,
#   primal = the iterative path with one hypre V-cycle inside csh2 (-flow_saddle_fieldsplit_1_h2_pc_type hypre;
#   only up to PRIMAL_MAXNP ranks: hundreds of CG iterations, each with global reductions, crawl when
#   oversubscribed), bddc = CG + PCBDDC (deluxe, adaptive coarse space) on S as a MATIS: outer and Schur iterations, memory per rank (-memory_view: maximum process memory, max and
#   mean over ranks), MPI message volume (-log_view, total), the interface (cssubchol's -ksp_view: all ranks and
#   the largest local part) and which engine ran. Time on 1-2 ranks only means anything.
# The machine is shared (2 cores, load 10-20 while this was written): seconds are upper bounds, iteration counts
# are reliable. Writes runs/study_scaling.md, runs/study_scaling*.csv and runs/study_scaling_{size,c,ranks}.png.
#   bash runs/study_scaling.sh
#   LEVELS="4 5" CS="1 1000" NPS="1 2" bash runs/study_scaling.sh      # quick
set -u
cd "$(dirname "$0")/.."
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OPENBLAS_NUM_THREADS=1 OMP_NUM_THREADS=1
LEVELS=${LEVELS:-"4 5 6 7"}; CS=${CS:-"1 100 1000 4000"}; NITER=${NITER:-2}; MULT_MAX=${MULT_MAX:-5}
CFIX=${CFIX:-1000}; PATHS=${PATHS:-"direct direct+reuse primal multiplier"}
MULT_CMAX=${MULT_CMAX:-100}; NPS=${NPS:-"1 2 4 8 16"}; RLEVELS=${RLEVELS:-"4 5"}
RPATHS=${RPATHS:-"auto cssubchol mumps primal bddc"}
# Part 3 (PART=bddc): BDDC's CG iterations of the first Schur solve (t = 1, t_mu = c) against size and c on BNP ranks
# Part 4 (PART=large): one CGD step, one Bobenko-Schroeder step and one spin transformation on icosphere levels
#   LLEVELS, on 1 and 2 ranks: wall seconds and peak memory per rank (-memory_view, max over ranks)
LLEVELS=${LLEVELS:-7}; lcsv=runs/study_scaling_large.csv
BLEVELS=${BLEVELS:-"3 4 5"}; BCS=${BCS:-"1 100 1000 4000"}; BNP=${BNP:-4}; bcsv=runs/study_scaling_bddc.csv; PRIMAL_MAXNP=${PRIMAL_MAXNP:-2}
FLEVELS=${FLEVELS:-"3 4 5 6"}; FCS=${FCS:-"1 10 100 1000 4000"}; fcsv=runs/study_scaling_first.csv
PART=${PART:-all} # first | serial | ranks | all | report (the tables and figures from the csv files already there)
out=runs/study_scaling.md; csv=runs/study_scaling.csv; rcsv=runs/study_scaling_ranks.csv
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
GEN() { echo "-gen icosphere -gen_level $1 -gen_deform_bump 0.2 -gen_deform_stretch 1.5,1,0.8"; }
mean_its() { # log split -> mean iterations of that split's solves (empty if none)
  awk -v s="flow_saddle_fieldsplit_$2_ solve" 'index($0, s) { n++; t += $NF } END { if (n) printf "%.1f", t / n }' "$1"
}
last_sv() { # log -> "max min" of the last singular value estimate
  awk '/Iteratively computed extreme singular values/ { mx = $7; mn = $9 } END { if (mx != "") printf "%s %s", mx, mn; else printf "- -" }' "$1"
}
path_args() { # path -> options
  case $1 in
    direct) echo "-flow_factor_reuse_its 0" ;;
    direct+reuse) echo "" ;;
    primal|multiplier) echo "-flow_factor_reuse_its 0 -flow_saddle_schur_solver $1 -flow_saddle_fieldsplit_1_ksp_converged_reason -flow_saddle_fieldsplit_0_ksp_converged_reason -flow_saddle_fieldsplit_1_ksp_view_singularvalues" ;;
  esac
}
run1() { # level c path -> csv row
  local L=$1 c=$2 p=$3 faces=$((20 * 4 ** $1))
  [ "$p" = multiplier ] && { [ "$L" -gt "$MULT_MAX" ] || [ "$c" -gt "$MULT_CMAX" ]; } && return
  if ! /usr/bin/time -f "%M" -o "$tmp/mem" bin/confsurf -task flow $(GEN "$L") -flow_t 1 -flow_t_max 1 -flow_t_mu "$c" -flow_max_it "$NITER" -flow_rtol 0 $(path_args "$p") -summary "$tmp/s.json" > "$tmp/log" 2>&1; then
    echo "FAILED: level $L c $c $p"; tail -3 "$tmp/log"; return
  fi
  read -r spi outer < <(python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); print(d["seconds_per_iteration"], d["ksp_iterations"] / max(d["linear_solves"], 1))' "$tmp/s.json")
  local schur inner sv
  schur=$(mean_its "$tmp/log" 1); inner=""; [ "$p" = multiplier ] && inner=$(mean_its "$tmp/log" 0)
  sv=$(last_sv "$tmp/log")
  # its: the Schur solve's iterations (1 = a direct solve), else the outer FGMRES iterations
  echo "$p,$L,$faces,1,$c,${schur:-$outer},$spi,$outer,${inner:-},${sv% *},${sv#* },$(( $(cat "$tmp/mem") / 1024 ))" >> "$csv"
  echo "level $L c $c $p: schur its ${schur:--} outer $outer inner ${inner:--} s/step $spi sv ${sv} MB $(( $(cat "$tmp/mem") / 1024 ))"
}
if [ "$PART" = first ] || [ "$PART" = all ]; then
  echo "series,level,faces,ranks,c,its,seconds,sv_max,sv_min" > "$fcsv"
  for L in $FLEVELS; do for c in $FCS; do
    bin/confsurf -task flow $(GEN "$L") -flow_t 1 -flow_t_max 1 -flow_t_mu "$c" -flow_max_it 1 -flow_rtol 0 $(path_args primal) > "$tmp/log" 2>&1 || { echo "FAILED: first solve level $L c $c"; continue; }
    its=$(awk '/flow_saddle_fieldsplit_1_ solve converged/ { print $NF; exit }' "$tmp/log")
    read -r mx mn < <(awk '/Iteratively computed extreme singular values/ { print $7, $9; exit }' "$tmp/log")
    echo "primal first solve,$L,$((20 * 4 ** L)),1,$c,$its,,$mx,$mn" >> "$fcsv"
    echo "first solve level $L c $c: CG its $its sv max $mx min $mn"
  done; done
fi
if [ "$PART" = serial ] || [ "$PART" = all ]; then
  echo "series,level,faces,ranks,c,its,seconds,outer_its,inner_its,sv_max,sv_min,peak_MB" > "$csv"
  for L in $LEVELS; do for p in $PATHS; do run1 "$L" "$CFIX" "$p"; done; done
  for c in $CS; do [ "$c" = "$CFIX" ] && continue; for L in 4 5; do for p in $PATHS; do run1 "$L" "$c" "$p"; done; done; done
fi

# Part 2: ranks
rank_args() { # path -> options
  local v="-flow_saddle_fieldsplit_1_ksp_view"
  case $1 in
    auto) echo "$v" ;;
    cssubchol) echo "$v -flow_saddle_fieldsplit_1_pc_cssubchol_max_interface_ratio 1e9" ;;
    mumps) echo "$v -flow_saddle_fieldsplit_1_pc_type cholesky -flow_saddle_fieldsplit_1_pc_factor_mat_solver_type mumps -flow_saddle_fieldsplit_1_mat_mumps_icntl_7 0" ;;
    primal) echo "-flow_saddle_schur_solver primal -flow_saddle_fieldsplit_1_h2_pc_type hypre -flow_saddle_fieldsplit_1_ksp_converged_reason" ;;
    bddc) echo "-flow_saddle_schur_solver bddc -flow_saddle_fieldsplit_1_ksp_converged_reason" ;; # rebuilt every step (-flow_factor_reuse_its 0 in every run here)
  esac
}
rank_run() { # level np path
  local L=$1 np=$2 p=$3
  if ! mpirun --oversubscribe -n "$np" bin/confsurf -task flow $(GEN "$L") -flow_max_it "$NITER" -flow_rtol 0 -flow_factor_reuse_its 0 $(rank_args "$p") -memory_view -log_view ":$tmp/lv" -summary "$tmp/s.json" > "$tmp/log" 2>&1; then
    echo "FAILED: level $L $np ranks $p"; tail -3 "$tmp/log"; return
  fi
  local spi outer schur mem mean msg G gp engine
  read -r spi outer < <(python3 -c 'import json,sys; d=json.load(open(sys.argv[1])); print(d["seconds_per_iteration"], d["ksp_iterations"] / max(d["linear_solves"], 1))' "$tmp/s.json")
  schur=$(mean_its "$tmp/log" 1)
  read -r mem mean < <(awk -v np="$np" '/^Maximum \(over computational time\) process memory/ { for (i = 1; i <= NF; i++) { if ($i == "max") mx = $(i + 1); if ($i == "total") tot = $(i + 1) } printf "%.0f %.0f\n", mx / 1048576, tot / np / 1048576; exit }' "$tmp/log")
  msg=$(awk '/^MPI Msg Len \(bytes\):/ { printf "%.3g", $NF }' "$tmp/lv")
  G=$(grep -m1 -oE 'interface (has )?[0-9]+ dofs' "$tmp/log" | grep -oE '[0-9]+')
  gp=$(grep -m1 -oE 'up to [0-9]+ (interface dofs )?per' "$tmp/log" | grep -oE '[0-9]+')
  engine=$p
  case $p in auto|cssubchol) if grep -q "MUMPS Cholesky instead" "$tmp/log"; then engine=MUMPS; elif [ "$np" = 1 ]; then engine=CHOLMOD; else engine=cssubchol; fi ;; mumps) engine=MUMPS ;; primal) engine="CG+csh2(hypre)" ;; bddc) engine="CG+BDDC(deluxe, adaptive)" ;; esac
  echo "$p,$L,$((20 * 4 ** L)),$np,,${schur:-$outer},$spi,$outer,,${mem:-},${mean:-},${msg:-},${G:-},${gp:-},$engine" >> "$rcsv"
  echo "level $L $np ranks $p ($engine): its ${schur:-$outer} outer $outer s/step $spi MB/rank max $mem mean $mean msg bytes $msg interface ${G:--} (per rank ${gp:--})"
}
if [ "$PART" = ranks ] || [ "$PART" = all ]; then
  echo "series,level,faces,ranks,c,its,seconds,outer_its,inner_its,max_MB_per_rank,mean_MB_per_rank,msg_bytes,interface,interface_per_rank,engine" > "$rcsv"
  for L in $RLEVELS; do for np in $NPS; do for p in $RPATHS; do
    [ "$p" = primal ] && [ "$np" -gt "$PRIMAL_MAXNP" ] && continue
    [ "$p" = cssubchol ] || [ "$p" = mumps ] && [ "$np" = 1 ] && continue # = auto (CHOLMOD) / the serial MUMPS is not the question
    rank_run "$L" "$np" "$p"
  done; done; done
fi

if [ "$PART" = bddc ]; then
  echo "series,level,faces,ranks,c,its,seconds,max_MB_per_rank" > "$bcsv"
  for L in $BLEVELS; do for c in $BCS; do
    if ! mpirun --oversubscribe -n "$BNP" bin/confsurf -task flow $(GEN "$L") -flow_t 1 -flow_t_max 1 -flow_t_mu "$c" -flow_max_it 1 -flow_rtol 0 -flow_factor_reuse_its 0 $(rank_args bddc) -memory_view > "$tmp/log" 2>&1; then
      echo "FAILED: bddc level $L c $c"; tail -3 "$tmp/log"; continue
    fi
    its=$(awk '/flow_saddle_fieldsplit_1_ solve converged/ { print $NF; exit }' "$tmp/log")
    mem=$(awk '/^Maximum \(over computational time\) process memory/ { for (i = 1; i <= NF; i++) if ($i == "max") printf "%.0f", $(i + 1) / 1048576; exit }' "$tmp/log")
    echo "bddc first solve,$L,$((20 * 4 ** L)),$BNP,$c,$its,,$mem" >> "$bcsv"
    echo "bddc level $L c $c on $BNP ranks: CG its $its, max MB/rank $mem"
  done; done
fi
large_args() { # what level -> options
  case $1 in
    cgd) echo "-task flow $(GEN "$2") -flow_max_it 1 -flow_rtol 0" ;;
    bs) echo "-task flow -flow_type bs $(GEN "$2") -bs_max_it 1 -bs_atol 0 -bs_rtol 0" ;;
    spin) echo "-task spin -gen icosphere -gen_level $2 -rho_bump_center 0,0,1 -rho_bump_radius 0.5 -rho_bump_height 3" ;;
  esac
}
if [ "$PART" = large ]; then
  echo "series,level,faces,ranks,seconds,max_MB_per_rank" > "$lcsv"
  for L in $LLEVELS; do for w in cgd bs spin; do for np in 1 2; do
    s0=$(date +%s.%N)
    if ! mpirun -n "$np" bin/confsurf $(large_args "$w" "$L") -memory_view > "$tmp/log" 2>&1; then echo "FAILED: large $w level $L $np ranks"; tail -3 "$tmp/log"; continue; fi
    sec=$(echo "$(date +%s.%N) - $s0" | bc)
    mem=$(awk '/^Maximum \(over computational time\) process memory/ { for (i = 1; i <= NF; i++) if ($i == "max") printf "%.0f", $(i + 1) / 1048576; exit }' "$tmp/log")
    echo "$w,$L,$((20 * 4 ** L)),$np,$sec,$mem" >> "$lcsv"
    echo "large: $w level $L on $np ranks: $sec s wall, max MB per rank $mem"
  done; done; done
fi
[ "$PART" = first ] || [ "$PART" = serial ] || [ "$PART" = ranks ] || [ "$PART" = bddc ] || [ "$PART" = large ] && exit 0 # PART=report afterwards
# tables and figures
python3 - "$csv" "$rcsv" "$CFIX" "$NITER" > "$out" <<'EOF'
import csv, sys, os
rows = list(csv.DictReader(open(sys.argv[1])))
print("# Study of issue #16: iterative Schur solves against the direct factorisation (runs/study_scaling.sh)\n")
print("Machine loaded by other jobs (load 15-33 on 2 cores when this was written): seconds are upper bounds, iteration counts reliable.")
print("Bumpy icosphere, cgd, t = 1 fixed, t_mu = c, %s steps per run, a fresh preconditioner every step except"
      " direct+reuse. its = Krylov iterations per Schur solve (1 for direct); outer = FGMRES iterations per saddle"
      " solve; inner = CG iterations per H solve inside S_mu (multiplier); sv = extreme singular values of the"
      " preconditioned Schur operator (last solve). Means over all solves of the run: rejected steps (at small c)"
      " halve t, the restoration solves with t_mu = 1e6; the first-solve table below has c exact.\n" % sys.argv[4])
print("| path | level | faces | c = t t_mu | its | outer | inner | s/step | sv max | sv min | peak MB |")
print("|---|---|---|---|---|---|---|---|---|---|---|")
for r in sorted(rows, key=lambda r: (float(r["c"]) != float(sys.argv[3]), float(r["c"]), int(r["level"]), r["series"])):
    print("| %s | %s | %s | %s | %.1f | %.2f | %s | %.3g | %s | %s | %s |" % (r["series"], r["level"], r["faces"], r["c"], float(r["its"]), float(r["outer_its"]), r["inner_its"] or "-", float(r["seconds"]), r["sv_max"], r["sv_min"], r["peak_MB"]))
first = sys.argv[2].replace("_ranks.csv", "_first.csv")
if os.path.exists(first):
    print("\n## The first Schur solve of the first step (t = 1, t_mu = c exactly), primal path\n")
    print("| level | faces | c | CG its | sv max | sv min | sv max / c |")
    print("|---|---|---|---|---|---|---|")
    for r in sorted(csv.DictReader(open(first)), key=lambda r: (float(r["c"]), int(r["level"]))):
        print("| %s | %s | %s | %s | %s | %s | %.3g |" % (r["level"], r["faces"], r["c"], r["its"], r["sv_max"], r["sv_min"], float(r["sv_max"]) / float(r["c"])))
bddc = sys.argv[2].replace("_ranks.csv", "_bddc.csv")
if os.path.exists(bddc):
    print("\n## BDDC (deluxe scaling, adaptive coarse space): the first Schur solve (t = 1, t_mu = c)\n")
    print("| level | faces | ranks | c | CG its | max MB per rank |")
    print("|---|---|---|---|---|---|")
    for r in sorted(csv.DictReader(open(bddc)), key=lambda r: (float(r["c"]), int(r["level"]))):
        print("| %s | %s | %s | %s | %s | %s |" % (r["level"], r["faces"], r["ranks"], r["c"], r["its"], r["max_MB_per_rank"]))
if os.path.exists(sys.argv[2]):
    print("\n## Ranks (oversubscribed beyond 2; time meaningful on 1-2 ranks only)\n")
    print("| path | engine | faces | ranks | Schur its | outer | s/step | MB per rank max / mean | MPI message bytes (total) | interface dofs (all / largest local) |")
    print("|---|---|---|---|---|---|---|---|---|---|")
    for r in sorted(csv.DictReader(open(sys.argv[2])), key=lambda r: (int(r["level"]), r["series"], int(r["ranks"]))):
        print("| %s | %s | %s | %s | %.1f | %.2f | %.3g | %s / %s | %s | %s / %s |" % (r["series"], r["engine"], r["faces"], r["ranks"], float(r["its"]), float(r["outer_its"]), float(r["seconds"]), r["max_MB_per_rank"], r["mean_MB_per_rank"], r["msg_bytes"], r["interface"] or "-", r["interface_per_rank"] or "-"))
EOF
# one csv per figure: series by path at c = CFIX (size), by path and level (c), by path (ranks)
awk -F, -v c="$CFIX" 'NR == 1 || $5 == c' "$csv" > "$tmp/size.csv"
awk -F, 'BEGIN { OFS = "," } NR == 1 { print; next } $2 <= 5 { $1 = $1 " level " $2; print }' "$csv" > "$tmp/c.csv"
/usr/bin/python3 scripts/plots.py scaling runs/study_scaling_size.png --x faces --title "Schur solves against mesh size (c = t t_mu = $CFIX)" "$tmp/size.csv"
/usr/bin/python3 scripts/plots.py scaling runs/study_scaling_c.png --x c --title "Schur solves against c = t t_mu" "$tmp/c.csv"
[ -s "$fcsv" ] && /usr/bin/python3 scripts/plots.py scaling runs/study_scaling_first.png --x faces --title "first Schur solve (primal): CG iterations against size, one line per c" <(awk -F, 'BEGIN { OFS = "," } NR == 1 { print; next } { $1 = "c = " $5; print }' "$fcsv")
[ -s "$rcsv" ] && /usr/bin/python3 scripts/plots.py scaling runs/study_scaling_ranks.png --x ranks --title "several ranks (levels $RLEVELS)" <(awk -F, 'BEGIN { OFS = "," } NR == 1 { print; next } { $1 = $1 " level " $2; print }' "$rcsv")
echo "wrote $out"
