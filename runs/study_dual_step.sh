#!/usr/bin/env bash
# Study (not a test), issue 39 "Fig. 7 default": CGD's dual step t_mu (soliman2021 Algorithm 1 line 11, the block
# -I_Q/t of the multipliers; here -I_Q/t_mu with t_mu separate from t, docs/willmore_flow.md) on the inputs of the
# optimiser study (runs/study_optimizers.sh: the bumpy stretched sphere and the bumpy torus) and of the tests and
# golden cases (the plain 24 x 12 torus, a class change to a stretched sphere, the open cylinder with the area energy,
# the real meshes eight_cgal and bunny_lowres_npm), against PGD. The rules (t_mu is given for unit-size meshes):
#   pgd:     projected gradient descent (no dual step), the reference of Fig. 7
#   paper:   t_mu = t (-flow_t_mu 1): the paper's single step size for both blocks
#   r1e3 .. r1e6: t_mu = R t, following t (-flow_t_mu R); r1e3 was the default before issue 39
#   fix1e5:  t_mu fixed at 1e5 (`cgdf` of the optimiser study: -flow_t_mu 1e5 -flow_t_mu_grow 1 -flow_t_mu_max 1e5)
#   ramp:    adaptive, t_mu from 1e3 doubled after each accepted step up to 1e5 (-flow_t_mu_grow 2 -flow_t_mu_max 1e5)
# Each run goes to the EL tolerance (default -flow_rtol) or MAXIT iterations; the W column at ITS iterations is read
# from the history (equal iterations). Outputs in runs/results/dual_step/: <input>_<rule>.{csv,json,log},
# the table dual_step.md and the plot dual_step.png (W, and W relative to PGD, against iteration; a column per input).
# Knobs: ITS=30 NP=1 INPUTS="sphere torus torus24 target cylinder eight bunny" RULES="..." PLOTS_ONLY=1.
# The machine is shared: seconds are wall time under load; iterations, rejections and KSP iterations are not.
set -u
cd "$(dirname "$0")/.."
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
ITS=${ITS:-30}; NP=${NP:-1}
INPUTS=${INPUTS:-sphere torus torus24 target cylinder eight bunny}
RULES=${RULES:-pgd paper r1e3 r1e4 r1e5 r1e6 fix1e5 ramp}
BIN=$PWD/bin/confsurf; PY=$(bash scripts/find-python.sh 2>/dev/null || echo /usr/bin/python3)
out=runs/results/dual_step; mkdir -p "$out"
launch=(); [ "$NP" -gt 1 ] && launch=(mpirun -n "$NP")
declare -A INPUT=(
  [sphere]="-gen icosphere -gen_level 3 -gen_deform_bump 0.2 -gen_deform_stretch 1.5,1,0.8 -flow_max_it 100"
  [torus]="-gen torus -gen_torus_R 3 -gen_tube_r 1 -gen_n 32 -gen_m 16 -gen_deform_bump 0.1 -flow_max_area_ratio 0 -flow_max_it 60"
  [torus24]="-gen torus -gen_torus_R 3 -gen_tube_r 1 -gen_n 24 -gen_m 12 -flow_max_it 150"
  [target]="-gen icosphere -gen_level 3 -flow_target_mesh $out/ico_target.obj -flow_max_it 60"
  [cylinder]="-gen cylinder -gen_n 24 -gen_m 12 -gen_height 2 -flow_energy area -flow_max_it 80"
  [eight]="-mesh meshes/eight_cgal.obj -flow_max_it 60"
  [bunny]="-mesh meshes/bunny_lowres_npm.obj -flow_max_it 40")
rule() {
  case $1 in
    pgd) echo "-flow_type pgd" ;;
    paper) echo "-flow_type cgd -flow_t_mu 1" ;;
    r1e*) echo "-flow_type cgd -flow_t_mu ${1#r}" ;;
    fix1e5) echo "-flow_type cgd -flow_t_mu 1e5 -flow_t_mu_grow 1 -flow_t_mu_max 1e5" ;;
    ramp) echo "-flow_type cgd -flow_t_mu 1e3 -flow_t_mu_grow 2 -flow_t_mu_max 1e5" ;;
    *) echo "unknown rule $1" >&2; exit 1 ;;
  esac
}
t0=$(date +%s)
if [ "${PLOTS_ONLY:-0}" != 1 ]; then
  "$BIN" -task flow -gen icosphere -gen_level 3 -gen_deform_stretch 1.3,1,1 -flow_max_it 0 -o "$out/ico_target.obj" > /dev/null
  for inp in $INPUTS; do
    for r in $RULES; do
      [ "$inp/$r" = target/pgd ] && continue # PGD keeps the input's class: no class change (pgd.c refuses it)
      name=${inp}_$r
      "${launch[@]}" "$BIN" -task flow ${INPUT[$inp]} $(rule $r) -history_csv "$out/$name.csv" -summary "$out/$name.json" \
        > "$out/$name.log" 2>&1 || echo "$name: failed (exit $?), see $out/$name.log"
      echo "$name: $(grep -E 'converged|NOT converged|stopped' "$out/$name.log" | tail -1)"
    done
  done
fi
"$PY" runs/study_dual_step.py "$out" "$ITS" "$NP" "$INPUTS" "$RULES" > "$out/dual_step.md"
cat "$out/dual_step.md"
echo "study: $(( $(date +%s) - t0 )) s; $out/dual_step.png"
