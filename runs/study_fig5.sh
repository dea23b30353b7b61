#!/usr/bin/env bash
# Study (not a test), issue 21 item 4 / docs/real_meshes.md section 0b: soliman2021 Fig. 5 (constrained Willmore
# surfaces of genus 1-3) from the shipped CGAL meshes eight_cgal (g = 2), knot1_cgal (g = 1), elephant_cgal (g = 3),
# with Algorithm 1 (CGD, default, guard on and off) and Algorithm 2 (-flow_type trianglefield). Each run is
#   bin/confsurf -task flow -mesh meshes/M.obj [extra] -summary S.json -history_csv H.csv
# Outputs in runs/results/fig5/<run>.{json,csv,log}, the table runs/results/fig5.md (scripts/plots.py table) with,
# from the per-iteration history, the smallest EL residual of the run and its iteration (el_min, it_el_min: how
# near a critical point the path passed) and the largest conformal violation of any iteration (vmax_history).
# Knobs: RUNS="name:mesh:extra ..." (words of extra joined by +; default below), ONLY="name ..." (run only these of
# RUNS; the table lists every run of RUNS with a summary in the output directory), TIMEOUT=900 (per run, seconds).
# Among the runs: knot1_cgd_t05 is the same CGD at a quarter of the step (is the path the flow's own?),
# elephant_cgd_restore the elephant with -flow_restore_above 5e-3 (its ceiling cycle, docs/real_meshes.md 0b),
# eight_tf_relaxed Algorithm 2 with integrability relaxed for 20 iterations (Fig. 8's schedule).
# The trianglefield runs are given a time budget (-flow_max_seconds), not an iteration
# count: they take seconds per iteration under load.
set -u
cd "$(dirname "$0")/.."
TIMEOUT=${TIMEOUT:-900}
BIN=$PWD/bin/confsurf; PY=$(bash scripts/find-python.sh 2>/dev/null || echo /usr/bin/python3)
out=runs/results/fig5; mkdir -p "$out"
RUNS=${RUNS:-"eight_cgd:eight_cgal:-flow_max_it+150 \
eight_cgd_noguard:eight_cgal:-flow_max_it+300+-flow_max_area_ratio+0 \
eight_tf:eight_cgal:-flow_type+trianglefield+-flow_max_it+300+-flow_max_seconds+420 \
eight_tf_relaxed:eight_cgal:-flow_type+trianglefield+-flow_integrability_start+20+-flow_max_it+300+-flow_max_seconds+300 \
knot1_cgd:knot1_cgal:-flow_max_it+150 \
knot1_cgd_noguard:knot1_cgal:-flow_max_it+80+-flow_max_area_ratio+0 \
knot1_cgd_t05:knot1_cgal:-flow_max_it+150+-flow_t+0.5+-flow_t_max+0.5 \
knot1_tf:knot1_cgal:-flow_type+trianglefield+-flow_max_it+300+-flow_max_seconds+240 \
elephant_cgd:elephant_cgal:-flow_max_it+150 \
elephant_cgd_restore:elephant_cgal:-flow_max_it+150+-flow_restore_above+5e-3 \
elephant_tf:elephant_cgal:-flow_type+trianglefield+-flow_max_it+300+-flow_max_seconds+240"}
runs=()
for r in $RUNS; do
  IFS=: read -r name mesh extra <<< "$r"
  [ -f "$out/$name.json" ] && runs+=("$name=$out/$name.json")
  if [ -n "${ONLY:-}" ] && [[ " $ONLY " != *" $name "* ]]; then continue; fi
  extra=${extra//+/ }  # "+" separates the words of extra
  timeout "$TIMEOUT" "$BIN" -task flow -mesh meshes/$mesh.obj $extra \
    -summary "$out/$name.json" -history_csv "$out/$name.csv" > "$out/$name.log" 2>&1 || echo "$name: exit $?"
  [ -f "$out/$name.json" ] && "$PY" - "$out/$name.json" "$out/$name.csv" <<'PY'
import csv, json, sys
d = json.load(open(sys.argv[1]))
rows = list(csv.DictReader(open(sys.argv[2])))
d["vmax_history"] = max(float(r["conformal_violation"]) for r in rows)
k = min(range(len(rows)), key=lambda i: float(rows[i]["el_residual"]))
d["el_min"], d["it_el_min"] = float(rows[k]["el_residual"]), int(rows[k]["it"])
json.dump(d, open(sys.argv[1], "w"), indent=1)
PY
  echo "$name: $(grep -E 'converged after' "$out/$name.log" | tail -1 | cut -c1-200)"
  [ -f "$out/$name.json" ] && [[ " ${runs[*]} " != *" $name=$out/$name.json "* ]] && runs+=("$name=$out/$name.json")
done
{
  echo "Fig. 5 study, $(date -u +%Y-%m-%d\ %H:%M) UTC, commit $(git rev-parse --short HEAD), one rank (shared machine: seconds are upper bounds)"
  echo
  "$PY" scripts/plots.py table - flow_type,energy_initial,iterations,willmore,conformal_violation,vmax_history,el_residual,el_min,it_el_min,q_mean,q_max,area_spread,rejections,seconds,stop_reason,degeneration "${runs[@]}"
} > runs/results/fig5.md
cat runs/results/fig5.md
