#!/usr/bin/env bash
# Benchmark (not a test) of -flow_saddle_reuse_borders (src/methods/willmore/willmore_saddle.c): with k global constraint
# rows every saddle solve is bordered, W = K^{-1} B (k solves) then a k x k system. W depends on the operators
# only, so with reuse (the default) it is solved once per CSSaddleSetOperators and kept for the step's later
# solves (second-order corrections, PGD's refinement); without it every solve repeats the k border solves.
# Inputs: soliman2021 Fig. 16's triangle-field flow (24 x 24, 9 rows: Moebius + periods), the reduced-volume
# vesicle (area, volume, Moebius, rotation rows) and the point-constrained sphere. The variants alternate
# (false, true, false, true, ...) so the drift of this VM falls on both; REPEAT runs each (default 3), medians.
# Writes runs/results/bench_borders.md.
#   bash runs/bench_borders.sh
#   REPEAT=5 bash runs/bench_borders.sh
set -u
cd "$(dirname "$0")/.."
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OPENBLAS_NUM_THREADS=${OPENBLAS_NUM_THREADS:-1}
REPEAT=${REPEAT:-3}
mkdir -p runs/results; out=runs/results/bench_borders.md; tmp=$(mktemp -d)
inputs=(
  "fig16|-flow_type trianglefield -gen lattice -gen_tau 0,1 -gen_n 24 -gen_m 24 -flow_init smooth -flow_init_amplitude 3 -flow_seed 1 -flow_constraint_mobius -flow_t_mu_final 4e9 -flow_max_it 40"
  "vesicle|-gen icosphere -gen_level 4 -flow_constraint_area -flow_constraint_volume 3.5 -flow_constraint_mobius -flow_constraint_rotation -flow_max_it 12"
  "points|-gen icosphere -gen_level 4 -flow_constraint_points options/flow_points_sphere.txt -flow_max_it 20"
)
for r in $(seq "$REPEAT"); do
  for inp in "${inputs[@]}"; do
    name=${inp%%|*}; args=${inp#*|}
    for reuse in false true; do
      # shellcheck disable=SC2086
      bin/confsurf -task flow $args -flow_saddle_reuse_borders $reuse -summary "$tmp/$name.$reuse.$r.json" > "$tmp/$name.$reuse.$r.log" 2>&1 || { echo "run failed: $name reuse=$reuse"; tail -3 "$tmp/$name.$reuse.$r.log"; exit 1; }
    done
  done
done
python3 - "$tmp" "$REPEAT" "$(git rev-parse --short HEAD)" > "$out" <<'PY'
import json, sys, statistics as st
d, rep, rev = sys.argv[1], int(sys.argv[2]), sys.argv[3]
print(f"Bordering solves kept per operator (-flow_saddle_reuse_borders) against repeated (median of {rep} alternating runs, one rank, commit {rev}; `bash runs/bench_borders.sh`)\n")
print("| input | rows k | reuse_borders | iterations | s/iteration | linear solves/it. | KSP its/it. | W at the end | EL at the end | violation at the end |")
print("|---|---|---|---|---|---|---|---|---|---|")
labels = {"fig16": "Fig. 16, 24 x 24 triangle field", "vesicle": "vesicle, icosphere level 4", "points": "point constraints, icosphere level 4"}
for name, label in labels.items():
  for reuse in ("false", "true"):
    runs = [json.load(open(f"{d}/{name}.{reuse}.{r}.json")) for r in range(1, rep + 1)]
    it = max(runs[0]['iterations'], 1)
    med = lambda k: st.median(float(a[k]) for a in runs)
    k = len(runs[0].get('constraint_values') or [])
    print(f"| {label} | {k} | {reuse} | {it} | {med('seconds_per_iteration'):.3g} | {med('linear_solves')/it:.2f} | {med('ksp_iterations')/it:.2f} | {med('energy'):.10f} | {med('el_residual'):.3e} | {med('conformal_violation'):.2e} |")
PY
cat "$out"; rm -rf "$tmp"
