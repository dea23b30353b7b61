#!/usr/bin/env bash
# Study (not a test), soliman2021 Fig. 7: the optimisers {CGD, PGD, ALM, GD} x {H2, L2 metric} on the same
# inputs, a bumpy stretched sphere (icosphere level 3, bump 0.2, stretch 1.5,1,0.8) and a bumpy torus (R 3, r 1,
# 32 x 16, bump 0.1), for the same number of iterations (ITS) and for the same wall time (SECS, -flow_max_seconds).
#   cgd: competitive gradient descent with the exact conformal constraint (the method of the paper)
#   pgd: projected gradient descent (tangent step + projection onto the conformal class)
#   alm: the augmented Lagrangian baseline, explicit steps in the plain metric (-flow_alm_metric plain), penalty
#        ALM_RHO relative to |W(input)| without growth (larger rho freezes the explicit steps: docs/alm.md)
#   gd:  unconstrained Sobolev gradient descent (leaves the conformal class: the reference for how far W can fall;
#        not ranked: it solves another problem)
#   cgdv: cgd with the violation ceiling lifted (-flow_vmax 1): a step is accepted on descent of its merit function
#        alone, the same rule as PGD's (descent of W) and the paper's "explicit forward steps" (soliman2021 Sec. 6)
#   cgdf: cgd with the dual step large and fixed (-flow_t_mu 1e5 -flow_t_mu_grow 1 -flow_t_mu_max 1e5): a class
#        direction of singular value s is restored by ~ t t_mu s^2 per step; with the old default t_mu (1e3 t) the
#        torus's first steps hit the violation ceiling (6 rejections in 30), with this none (docs/studies.md). Since
#        issue 39 cgd's default is t_mu = 1e5 t (following t), and cgd and cgdf agree to 1e-4 in W
#        (runs/study_dual_step.sh compares the dual-step rules)
# The ranking under each table (issue 21) compares like with like: only the runs that hold the conformal class at
# the end (conformal_violation < HOLD, default 1e-5: ALM and GD do not), by W.
# Outputs in runs/results/optimizers/: per run <shape>_<method>_<metric>_{its,time}.{csv,json,obj,log}; the table
# optimizers.md; the PNGs <shape>_{its,time}_vs_{it,seconds}.png (W, |c|_inf, EL residual against iteration
# and against seconds) and <shape>_shapes.png (final shapes of the equal-iteration runs, with the input).
# Knobs (PLOTS_ONLY=1: tables and pictures from the files of an earlier run): ITS=30 SECS=6 CAP=60 ALM_RHO=0.1 NP=1
# SHAPES="sphere torus" (a subset reruns only those; the table then has only them) HOLD=1e-5. The equal-iteration runs are also capped at CAP seconds (PGD in
# the L2 metric spends minutes per iteration in failing projections: it then shows fewer iterations, see the
# table's iterations column). One rank by default; the machine is shared (timings are noisy).
set -u
cd "$(dirname "$0")/.."
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
ITS=${ITS:-30}; SECS=${SECS:-6}; CAP=${CAP:-60}; ALM_RHO=${ALM_RHO:-0.1}; NP=${NP:-1}; SHAPES=${SHAPES:-sphere torus}; HOLD=${HOLD:-1e-5}
BIN=$PWD/bin/confsurf; PY=$(bash scripts/find-python.sh 2>/dev/null || echo /usr/bin/python3)
out=runs/results/optimizers; mkdir -p "$out"
launch=(); [ "$NP" -gt 1 ] && launch=(mpirun -n "$NP")
declare -A SHAPE=(
  [sphere]="-gen icosphere -gen_level 3 -gen_deform_bump 0.2 -gen_deform_stretch 1.5,1,0.8"
  [torus]="-gen torus -gen_torus_R 3 -gen_tube_r 1 -gen_n 32 -gen_m 16 -gen_deform_bump 0.1")
METHODS="cgd cgdf cgdv pgd alm gd"; METRICS="h2 l2"
opts() { # method metric
  case $1 in
    alm) echo "-flow_type alm -flow_alm_metric plain -flow_alm_rho $ALM_RHO -flow_alm_rho_grow 1" ;;
    gd) echo "-flow_type gd" ;;
    cgdv) echo "-flow_type cgd -flow_vmax 1" ;;
    cgdf) echo "-flow_type cgd -flow_t_mu 1e5 -flow_t_mu_grow 1 -flow_t_mu_max 1e5" ;;
    *) echo "-flow_type $1" ;;
  esac
  echo "-flow_metric $2"
}
t0=$(date +%s)
for shape in $SHAPES; do
  [ "${PLOTS_ONLY:-0}" = 1 ] || "$BIN" -task info ${SHAPE[$shape]} -o "$out/${shape}_input.obj" > /dev/null
  for budget in its time; do
    for metric in $METRICS; do
      for m in $METHODS; do
        name=${shape}_${m}_${metric}_${budget}
        [ "${PLOTS_ONLY:-0}" = 1 ] && continue
        if [ $budget = its ]; then lim="-flow_max_it $ITS -flow_max_seconds $CAP"; else lim="-flow_max_it 100000 -flow_max_seconds $SECS"; fi
        "${launch[@]}" "$BIN" -task flow ${SHAPE[$shape]} $(opts $m $metric) $lim -flow_max_area_ratio 0 \
          -history_csv "$out/$name.csv" -summary "$out/$name.json" -o "$out/$name.obj" > "$out/$name.log" 2>&1 \
          || echo "$name: failed (exit $?), see $out/$name.log"
        echo "$name: $(grep -E 'converged|NOT converged|stopped' "$out/$name.log" | tail -1)"
      done
    done
    runs=(); for metric in $METRICS; do for m in $METHODS; do runs+=("$m $metric=$out/${shape}_${m}_${metric}_${budget}.csv"); done; done
    for x in it seconds; do
      "$PY" scripts/plots.py curves "$out/${shape}_${budget}_vs_${x}.png" --x $x --title "$shape, equal $( [ $budget = its ] && echo "iterations ($ITS)" || echo "wall time (${SECS} s)")" "${runs[@]}"
    done
  done
  shapes=(); for metric in $METRICS; do for m in $METHODS; do shapes+=("$m $metric=$out/${shape}_${m}_${metric}_its.obj"); done; done
  "$PY" scripts/plots.py panel "$out/${shape}_shapes.png" --title "$shape after $ITS iterations" --input "$out/${shape}_input.obj" "${shapes[@]}"
done
{
  echo "# Optimiser study (soliman2021 Fig. 7), $(date -u +%Y-%m-%d\ %H:%M) UTC, commit $(git rev-parse --short HEAD), ITS=$ITS SECS=$SECS ALM_RHO=$ALM_RHO NP=$NP (shared machine: seconds are noisy)"
  echo
  for shape in $SHAPES; do
    for budget in its time; do
      echo "## $shape, equal $( [ $budget = its ] && echo "iterations ($ITS)" || echo "wall time ($SECS s)")"
      echo
      runs=(); for metric in $METRICS; do for m in $METHODS; do runs+=("$m $metric=$out/${shape}_${m}_${metric}_${budget}.json"); done; done
      "$PY" scripts/plots.py table - willmore,energy_initial,conformal_violation,el_residual,iterations,rejections,seconds,q_mean,q_max,stop_reason "${runs[@]}"
      echo
      "$PY" - "$HOLD" "${runs[@]}" <<'PY'
import json, sys
hold = float(sys.argv[1]); rows = []
for a in sys.argv[2:]:
    name, path = a.split("=", 1)
    try: s = json.load(open(path))
    except Exception: continue
    if name.startswith("gd "): continue  # unconstrained: another problem
    if s["conformal_violation"] < hold: rows.append((s["willmore"], name))
print("Ranking (runs holding the class, conformal_violation < %g; GD excluded): " % hold + " < ".join("%s %.4f" % (n, w) for w, n in sorted(rows)))
PY
      echo
    done
  done
} > "$out/optimizers.md"
cat "$out/optimizers.md"
echo "study: $(( $(date +%s) - t0 )) s; PNGs in $out"
