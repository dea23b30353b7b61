#!/usr/bin/env bash
# Study (not a test), issue 21 item 4 / docs/real_meshes.md section 0a: does refining the real meshes let the
# conformally constrained Willmore flow (default CGD) converge? Each run is
#   bin/confsurf -task flow -mesh meshes/M.obj -mesh_refine N [extra] -flow_max_it $MAXIT -summary S.json -history_csv H.csv
# (the refined mesh's own discrete conformal class is the constraint). Outputs in runs/results/refine/<run>.{json,csv,log}
# and the table runs/results/refine.md (scripts/plots.py table), with the largest conformal violation of every
# iteration (vmax_history) so that a violation that grew is visible.
# Knobs: MAXIT=150, RUNS="name:mesh:N:extra ..." (words of extra joined by +) (default below; knot1 refined once takes ~4 min under load), TIMEOUT=900.
set -u
cd "$(dirname "$0")/.."
MAXIT=${MAXIT:-150}; TIMEOUT=${TIMEOUT:-900}
BIN=$PWD/bin/confsurf; PY=$(bash scripts/find-python.sh 2>/dev/null || echo /usr/bin/python3)
out=runs/results/refine; mkdir -p "$out"
RUNS=${RUNS:-"eight_r0:eight_cgal:0: eight_r1:eight_cgal:1: eight_r1_mobius:eight_cgal:1:-flow_constraint_mobius eight_r1_midpoint:eight_cgal:1:-mesh_refine_type+midpoint knot1_r0:knot1_cgal:0: knot1_r1:knot1_cgal:1: cow_r0:cow_cgal:0:"}
runs=()
for r in $RUNS; do
  IFS=: read -r name mesh n extra <<< "$r"
  extra=${extra//+/ }  # "+" separates the words of extra
  timeout "$TIMEOUT" "$BIN" -task flow -mesh meshes/$mesh.obj -mesh_refine "$n" $extra -flow_max_it "$MAXIT" \
    -summary "$out/$name.json" -history_csv "$out/$name.csv" > "$out/$name.log" 2>&1 || echo "$name: exit $?"
  "$PY" - "$out/$name.json" "$out/$name.csv" <<'PY'
import csv, json, sys
d = json.load(open(sys.argv[1]))
d["vmax_history"] = max(float(r["conformal_violation"]) for r in csv.DictReader(open(sys.argv[2])))
json.dump(d, open(sys.argv[1], "w"), indent=1)
PY
  echo "$name: $(tail -1 "$out/$name.log" | cut -c1-60) / $(grep -E 'converged after' "$out/$name.log" | tail -1 | cut -c1-200)"
  runs+=("$name=$out/$name.json")
done
{
  echo "Refinement study, $(date -u +%Y-%m-%d\ %H:%M) UTC, commit $(git rev-parse --short HEAD), MAXIT=$MAXIT, one rank (shared machine: seconds are upper bounds)"
  echo
  "$PY" scripts/plots.py table - vertices,energy_initial,iterations,willmore,conformal_violation,vmax_history,el_residual,q_max,seconds,stop_reason,degeneration "${runs[@]}"
} > runs/results/refine.md
cat runs/results/refine.md
