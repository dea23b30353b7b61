#!/usr/bin/env bash
# Study (not a test), crane2013 Sec. 6.4.2 (Fig. 17): fairing methods given the same wall-time budget (BUDGET
# seconds, one rank) at their largest stable step on the same near-isotropic mesh (a bumpy stretched icosphere,
# level LEVEL). Rows:
#   emcf   explicit mean curvature flow          ebilap explicit bi-Laplacian flow (Taubin)
#   imcf   implicit mean curvature flow (Desbrun) ibilap implicit bi-Laplacian flow (backward Euler)
#   cmcf   conformalized MCF (Kazhdan et al.)     vmcf   volume-controlled MCF (Eckstein et al. 2007; Fig. 17 F)
#   isobend  Willmore flow of the isometric bending model (Wardetzky et al. 2007; Fig. 17 I: the input's Hessian
#          L_0 M_0^-1 L_0, factored once)  (the seven baselines: src/methods/willmore/impls/fairing/fairing_baselines.c)
#   bs     Bobenko-Schroeder discrete Willmore flow (semi-implicit, its own step control)
#   cgd    conformally constrained Willmore flow (soliman2021; an H^2 Willmore flow that keeps the conformal class)
#   conformal  the conformal curvature flow of crane2013 (-flow_type conformal), when this binary has it; skipped
#          with a message otherwise
# Largest stable step of a baseline: the first -flow_t of its candidate list (descending) whose run of BUDGET
# seconds (-flow_max_seconds) stops neither by the resolution guard nor with W above W(input): stable for the
# length of the study. BS has no time budget: its step count is BUDGET / (its seconds per step in a 3-step probe).
# Outputs in runs/results/fairing/: per method <m>.{csv,json,obj,log}; fairing.md (W, q_mean, q_max, min angle,
# steps, seconds, seconds per step and that relative to imcf); fairing_shapes.png (input and results),
# fairing_vs_seconds.png (W against seconds). Knobs: BUDGET=10 LEVEL=4. The machine is shared.
set -u
cd "$(dirname "$0")/.."
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
BUDGET=${BUDGET:-10}; LEVEL=${LEVEL:-4}
BIN=$PWD/bin/confsurf; PY=$(bash scripts/find-python.sh 2>/dev/null || echo /usr/bin/python3)
out=runs/results/fairing; mkdir -p "$out"
IN="-gen icosphere -gen_level $LEVEL -gen_deform_bump 0.2 -gen_deform_stretch 1.5,1,0.8"
declare -A CAND=([emcf]="0.4 0.2 0.1 0.05 0.02 0.01" [ebilap]="0.05 0.02 0.01 0.005 0.002 0.001" [imcf]="100 30 10 3 1 0.3"
                 [ibilap]="1000 300 100 30 10 3 1" [cmcf]="1000 300 100 30 10" [vmcf]="100 30 10 3 1 0.3"
                 [isobend]="10000 1000 300 100 30 10 3 1")
t0=$(date +%s)
"$BIN" -task info $IN -o "$out/input.obj" > /dev/null
W0=$("$BIN" -task info $IN -summary "$out/input.json" > /dev/null && python3 -c "import json; print(json.load(open('$out/input.json'))['willmore'])")
run_ok() { # kind t: the budget run, kept when neither stopped by the guard nor with W above the input's
  "$BIN" -task flow $IN -flow_type $1 -flow_t $2 -flow_max_it 1000000 -flow_max_seconds $BUDGET \
    -history_csv "$out/$1.csv" -summary "$out/$1.json" -o "$out/$1.obj" > "$out/$1.log" 2>&1 || return 1
  python3 -c "import json,sys; s=json.load(open('$out/$1.json')); sys.exit(0 if s['stop_reason'] in ('max_it','converged') and s['willmore'] < $W0 else 1)"
}
runs=(); curves=(); shapes=()
for k in emcf ebilap imcf ibilap cmcf vmcf isobend; do
  tk=""; for t in ${CAND[$k]}; do if run_ok $k $t; then tk=$t; break; fi; done
  [ -z "$tk" ] && { echo "$k: no stable step among ${CAND[$k]} (the last run is kept)"; tk="${CAND[$k]##* }"; }
  echo "$k (t = $tk h^p): $(grep -E 'converged|resolution' "$out/$k.log" | tail -1 | cut -c1-150)"
  runs+=("$k (t $tk)=$out/$k.json"); curves+=("$k=$out/$k.csv"); shapes+=("$k=$out/$k.obj")
done
# Bobenko-Schroeder: as many steps as fit in the budget at its measured cost per step
"$BIN" -task flow -flow_type bs $IN -bs_max_it 3 -summary "$out/probe.json" > /dev/null 2>&1
nbs=$(python3 -c "import json,math; s=json.load(open('$out/probe.json')); print(max(1, int($BUDGET / s['seconds_per_step'])))")
"$BIN" -task flow -flow_type bs $IN -bs_max_it $nbs -history_csv "$out/bs.csv" -summary "$out/bs.json" -o "$out/bs.obj" > "$out/bs.log" 2>&1
echo "bs ($nbs steps): $(tail -4 "$out/bs.log" | head -1 | cut -c1-150)"
runs+=("bs=$out/bs.json"); curves+=("bs=$out/bs.csv"); shapes+=("bs=$out/bs.obj")
"$BIN" -task flow $IN -flow_type cgd -flow_max_it 1000000 -flow_max_seconds $BUDGET \
  -history_csv "$out/cgd.csv" -summary "$out/cgd.json" -o "$out/cgd.obj" > "$out/cgd.log" 2>&1
echo "cgd: $(grep -E 'converged' "$out/cgd.log" | tail -1 | cut -c1-150)"
runs+=("cgd=$out/cgd.json"); curves+=("cgd=$out/cgd.csv"); shapes+=("cgd=$out/cgd.obj")
if "$BIN" -task flow -flow_type conformal -help > /dev/null 2>&1; then
  # the conformal flow has no wall-time budget option: it stops at its own rtol (20 steps, 0.4 s on this input)
  "$BIN" -task flow $IN -flow_type conformal -flow_max_it 1000 \
    -history_csv "$out/conformal.csv" -summary "$out/conformal.json" -o "$out/conformal.obj" > "$out/conformal.log" 2>&1 \
    || echo "conformal: failed, see $out/conformal.log"
  runs+=("conformal=$out/conformal.json"); curves+=("conformal=$out/conformal.csv"); shapes+=("conformal=$out/conformal.obj")
else
  echo "conformal: skipped (this binary has no -flow_type conformal: the conformal curvature flow of crane2013 is built on another branch)"
fi
rm -f "$out/probe.json"
ref=$(printf '%s\n' "${runs[@]}" | grep "^imcf" | cut -d= -f1)
{
  echo "# Fairing study (crane2013 Fig. 17), $(date -u +%Y-%m-%d\ %H:%M) UTC, commit $(git rev-parse --short HEAD), icosphere level $LEVEL bumped and stretched, budget $BUDGET s each, one rank (shared machine: seconds are noisy)"
  echo
  echo "W(input) = $W0. t: the largest stable step found (units h^2 for the MCF kinds, h^4 for the bi-Laplacian ones). step_cost_rel: seconds per step relative to implicit MCF (each step includes the same monitoring: W, its gradient, the history)."
  echo
  "$PY" scripts/plots.py table - willmore,q_mean,q_max,min_angle,area,volume,iterations,pc_setups,seconds,s_per_step,step_cost_rel,stop_reason --ref "$ref" "${runs[@]}"
} > "$out/fairing.md"
"$PY" scripts/plots.py panel "$out/fairing_shapes.png" --title "fairing, $BUDGET s each" --input "$out/input.obj" "${shapes[@]}"
"$PY" scripts/plots.py curves "$out/fairing_vs_seconds.png" --x seconds --title "fairing, $BUDGET s each" "${curves[@]}"
cat "$out/fairing.md"
echo "study: $(( $(date +%s) - t0 )) s; PNGs in $out"
