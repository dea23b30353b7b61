#!/usr/bin/env bash
# Study (not a test), soliman2021 Fig. 20: Willmore-regularised fairing E = 1/2 |f - f0|^2 + eps W (Eq. 21) in the
# conformal class of the input, for eps over four decades (EPS, default 0.001 0.01 0.1 1 10) on the low-resolution
# bunny (meshes/bunny_lowres_npm.obj, 3674 faces; MESH= for another, e.g. meshes/bunny_closed_cgal.obj, 75k faces,
# about 10x slower per iteration). CGD, MAXIT iterations (default 150), -flow_rtol 1e-6. The bunny's size sets the
# scale of eps: area 218.7, so the fidelity term of a displacement d is ~ 109 d^2 against eps W (W(input) 136.2).
# Outputs in runs/results/fairing_eps/: eps_<e>.{csv,json,obj,log}; fairing_eps.md (table), fairing_eps_shapes.png
# (input and results, coloured by mean curvature), fairing_eps_curves.png (E, violation, EL against iteration).
# One rank; the machine is shared (seconds are upper bounds). docs/studies.md quotes the output.
set -u
cd "$(dirname "$0")/.."
EPS=${EPS:-"0.001 0.01 0.1 1 10"}; MAXIT=${MAXIT:-150}; MESH=${MESH:-meshes/bunny_lowres_npm.obj}
BIN=$PWD/bin/confsurf; PY=$(bash scripts/find-python.sh 2>/dev/null || echo /usr/bin/python3)
out=runs/results/fairing_eps; mkdir -p "$out"
"$BIN" -task info -mesh "$MESH" -summary "$out/input.json" -o "$out/input.obj" > /dev/null
runs=("input=$out/input.json"); curves=(); shapes=()
for e in $EPS; do
  "$BIN" -task flow -mesh "$MESH" -flow_energy fairing -flow_fairing_epsilon "$e" -flow_max_it "$MAXIT" -flow_rtol 1e-6 \
    -history_csv "$out/eps_$e.csv" -summary "$out/eps_$e.json" -o "$out/eps_$e.obj" > "$out/eps_$e.log" 2>&1
  echo "eps $e: $(grep -E 'flow cgd: (NOT )?converged' "$out/eps_$e.log" | tail -1 | cut -c1-200)"
  runs+=("eps $e=$out/eps_$e.json"); curves+=("eps $e=$out/eps_$e.csv"); shapes+=("eps $e=$out/eps_$e.obj")
done
# the displacement from the input (vertex RMS and max, relative to the bounding-box diagonal) beside the summaries
python3 - "$out" $EPS <<'PY'
import json, math, sys
d, eps = sys.argv[1], sys.argv[2:]
rd = lambda p: [[float(t) for t in l.split()[1:4]] for l in open(p) if l.startswith('v ')]
X0 = rd(d + '/input.obj')
diag = math.dist([min(v[k] for v in X0) for k in range(3)], [max(v[k] for v in X0) for k in range(3)])
for e in eps:
    X = rd(d + '/eps_%s.obj' % e); s = json.load(open(d + '/eps_%s.json' % e))
    dist = [math.dist(a, b) for a, b in zip(X, X0)]
    s['disp_rms_rel'] = math.sqrt(sum(x * x for x in dist) / len(dist)) / diag
    s['disp_max_rel'] = max(dist) / diag
    json.dump(s, open(d + '/eps_%s.json' % e, 'w'))
PY
{ echo "Fairing for eps over four decades ($(date -u '+%Y-%m-%d %H:%M UTC'), commit $(git rev-parse --short HEAD), $MESH, MAXIT=$MAXIT, one rank)"; echo
  "$PY" scripts/plots.py table - energy,willmore,disp_rms_rel,disp_max_rel,conformal_violation,el_residual,iterations,q_max,seconds,stop_reason "${runs[@]}"; } > "$out/fairing_eps.md"
cat "$out/fairing_eps.md"
"$PY" scripts/plots.py panel "$out/fairing_eps_shapes.png" --title "soliman2021 Fig. 20: E = |f-f0|^2/2 + eps W" --input "$out/input.obj" "${shapes[@]}"
"$PY" scripts/plots.py curves "$out/fairing_eps_curves.png" --x it --title "fairing, eps over four decades" "${curves[@]}"
