#!/usr/bin/env bash
# Benchmark (not a test) of the second-order corrections of the CGD step (-flow_soc_max_it, issue 22,
# docs/real_meshes.md): seconds per iteration, linear solves and KSP iterations per iteration, and the final
# violation and Euler-Lagrange residual of the same cgd run with 0 and with 2 corrections per step, on a bumpy
# stretched icosphere (level L, default 5 = 20k faces) and on eight_cgal. The variants alternate (0, 2, 0, 2, ...)
# so the drift of this VM falls on both; REPEAT runs each (default 3), medians. Writes runs/results/bench_soc.md.
#   bash runs/bench_soc.sh
#   LEVEL=6 NITER=10 REPEAT=3 bash runs/bench_soc.sh
set -u
cd "$(dirname "$0")/.."
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OPENBLAS_NUM_THREADS=${OPENBLAS_NUM_THREADS:-1}
LEVEL=${LEVEL:-5}; NITER=${NITER:-20}; REPEAT=${REPEAT:-3}
mkdir -p runs/results; out=runs/results/bench_soc.md; tmp=$(mktemp -d)
inputs=("ico|-gen icosphere -gen_level $LEVEL -gen_deform_bump 0.2 -gen_deform_stretch 1.5,1,0.8" "eight|-mesh meshes/eight_cgal.obj")
for r in $(seq "$REPEAT"); do
  for inp in "${inputs[@]}"; do
    name=${inp%%|*}; args=${inp#*|}
    for soc in 0 2; do
      bin/confsurf -task flow $args -flow_max_it "$NITER" -flow_rtol 0 -flow_max_area_ratio 0 -flow_soc_max_it $soc -summary "$tmp/$name.$soc.$r.json" > "$tmp/$name.$soc.$r.log" 2>&1 || { echo "run failed: $name soc=$soc"; tail -3 "$tmp/$name.$soc.$r.log"; exit 1; }
    done
  done
done
python3 - "$tmp" "$REPEAT" "$LEVEL" "$NITER" "$(git rev-parse --short HEAD)" > "$out" <<'PY'
import json, sys, statistics as st
d, rep, level, niter, rev = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4], sys.argv[5]
print(f"Second-order corrections per CGD step: 0 against 2 ({niter} iterations, median of {rep} alternating runs, commit {rev}; `bash runs/bench_soc.sh`)\n")
print("| input | -flow_soc_max_it | s/iteration | linear solves/it. | KSP its/it. | factorisations | max violation at the end | EL residual at the end | W at the end |")
print("|---|---|---|---|---|---|---|---|---|")
for name, label in (("ico", f"bumpy icosphere level {level}"), ("eight", "eight_cgal")):
  for soc in (0, 2):
    runs = [json.load(open(f"{d}/{name}.{soc}.{r}.json")) for r in range(1, rep + 1)]
    it = max(runs[0]['iterations'], 1)
    med = lambda k: st.median(float(a[k]) for a in runs)
    print(f"| {label} | {soc} | {med('seconds_per_iteration'):.3g} | {med('linear_solves')/it:.2f} | {med('ksp_iterations')/it:.2f} | {med('pc_setups'):.0f} | {med('conformal_violation'):.2e} | {med('el_residual'):.2e} | {med('energy'):.6f} |")
PY
cat "$out"; rm -rf "$tmp"
