#!/usr/bin/env bash
# `make run`: the default experiment (options/run_sphere.opts: a conformally constrained Willmore flow to
# convergence), its pictures (scripts/pictures.py), a textured input's checkerboard picture (a spin transformation of
# a disk, docs/textures.md), then where the results went and a two-line reading.
# OUT=dir (default out/run), NP=ranks (default 2), OPTS=options file.
set -euo pipefail
cd "$(dirname "$0")/.."
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
out=${OUT:-out/run}; np=${NP:-2}; opts=${OPTS:-options/run_sphere.opts}
rm -rf "$out"; mkdir -p "$out"
t0=$(date +%s.%N)
# the input as the flow sees it (after -gen_deform_*): zero iterations
bin/confsurf -options_file "$opts" -flow_max_it 0 -o "$out/input.obj" > "$out/input.log" 2>&1 || { cat "$out/input.log"; exit 1; }
cmd=(mpirun -n "$np" bin/confsurf -options_file "$opts" -o "$out/final.obj" -summary "$out/summary.json"
     -history_csv "$out/history.csv" -viewer_dir "$out/vtu" -flow_viewer_every 5)
echo "+ ${cmd[*]}"
"${cmd[@]}" 2>&1 | tee "$out/run.log" | grep -E "^ *(0|[0-9]*0) E |converged|NOT converged|stopped" || true
[ "${PIPESTATUS[0]}" = 0 ] || { tail -20 "$out/run.log"; exit 1; }
py=$(bash scripts/find-python.sh)
"$py" scripts/pictures.py "$out/pictures" --input "$out/input.obj" --result "$out/final.obj" \
  --history "$out/history.csv" --summary "$out/summary.json" --title "$(basename "$opts" .opts)"
# a textured input (issue 38): a spin transformation adds a bump to a disk whose UVs are its planar coordinates
# (about 1 s); its checkerboard in UV, input and result from one camera
bin/confsurf -options_file options/texture_spin_fig10.opts -viewer_dir "$out/texture/vtu" -summary "$out/texture/summary.json" > "$out/texture.log" 2>&1 || { cat "$out/texture.log"; exit 1; }
"$py" scripts/pictures.py "$out/texture/pictures" --series "$out/texture/vtu/series.pvd" --summary "$out/texture/summary.json" \
  --title "spin transformation of a textured disk" --view 35,-60 --texture_check "$out/pictures/texture.png" > /dev/null
t1=$(date +%s.%N)
echo
echo "Results ($(printf '%.0f' "$(echo "$t1 - $t0" | bc)") s):"
echo "  $out/summary.json                  summary (energy before/after, EL residual, violations, q_mean/q_max, seconds)"
echo "  $out/history.csv                   per-iteration history"
echo "  $out/input.obj, $out/final.obj     the input and the final surface"
echo "  $out/vtu/series.pvd                ParaView series (every 5 iterations and the final state)"
echo "  $out/pictures/mean_curvature.png   input and final, coloured by mean curvature"
echo "  $out/pictures/quasi_conformal.png  final, coloured by the quasi-conformal error Q against the input"
echo "  $out/pictures/history.png          energy, EL residual, constraint violation, step size per iteration"
echo "  $out/pictures/texture.png          a textured disk and its spin transformation (checkerboard in UV; $out/texture/)"
"$py" - "$out/summary.json" <<'PY'
import json, math, sys
s = json.load(open(sys.argv[1]))
how = ("converged in %d iterations" % s["iterations"]) if s["converged"] else \
      ("NOT converged: stopped after %d iterations (%s)" % (s["iterations"], s["stop_reason"]))
print("Reading:")
print("  Willmore energy %.6g -> %.6g (4 pi = %.6g), %s, EL residual %.2g (scale-free: %.2g)" %
      (s["energy_initial"], s["energy"], 4 * math.pi, how, s["el_residual"], s["el_residual_scaled"]))
print("  conformal error: cross-ratio constraint violation %.2g, quasi-conformal error against the input q_mean %.4f, q_max %.4f"
      % (s["conformal_violation"], s["q_mean"], s["q_max"]))
PY
