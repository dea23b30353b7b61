#!/usr/bin/env bash
# `make demo`: one short example per method, each with its pictures (scripts/pictures.py), and a gallery page
# OUT/index.html (default out/demo). Serial runs (the pictures read the ParaView series of one piece).
# CGD and PGD: a bumpy sphere (level 3) to convergence; BS flow: 20 semi-implicit steps of the linearly subdivided
# icosahedron; spin transformation: three curvature bumps on a sphere (level 4); spectrum: the Dirac spectrum of a
# torus; curve flow: a star relaxing to a circle (pictures by scripts/plot_curves.py). Later methods (conformal
# curvature flow, triangle fields) add a line to CASES.
set -euo pipefail
cd "$(dirname "$0")/.."
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_ess_singleton_isolated=1
out=${OUT:-out/demo}
py=$(bash scripts/find-python.sh)
rm -rf "$out"; mkdir -p "$out"
# name | what | options
CASES=(
"cgd|conformally constrained Willmore flow, competitive gradient descent (soliman2021)|-task flow -flow_type cgd -gen icosphere -gen_level 3 -gen_deform_bump 0.2 -gen_deform_stretch 1.5,1,0.8 -flow_max_it 200 -flow_viewer_every 5"
"pgd|conformally constrained Willmore flow, projected gradient descent (soliman2021)|-task flow -flow_type pgd -gen icosphere -gen_level 3 -gen_deform_bump 0.2 -gen_deform_stretch 1.5,1,0.8 -flow_max_it 200 -flow_viewer_every 5"
"bs|Bobenko-Schroeder discrete Willmore flow, semi-implicit steps|-task flow -flow_type bs -gen icosphere -gen_level 3 -gen_project false -bs_max_it 20"
"spin|spin transformation: three curvature bumps on a sphere (crane2011)|-task spin -gen icosphere -gen_level 4 -rho_bump_center 0,0,1,0.8,0,-0.6,-0.5,-0.7,-0.5 -rho_bump_radius 0.35 -rho_bump_height 4"
"spectrum|the smallest eigenvalues of the Dirac problem on a torus (crane2011 Fig. 8)|-task spectrum -gen torus -gen_n 32 -gen_m 16 -spectrum_nev 8"
"curveflow|isometric curvature flow of a star-shaped curve (crane2013 Sec. 5)|-task curveflow -gen_curve star -curve_max_it 300"
)
{
  echo "<html><head><title>confsurf demo</title></head><body><h1>confsurf: one example per method</h1>"
} > "$out/index.html"
for c in "${CASES[@]}"; do
  IFS='|' read -r name what opts <<< "$c"
  d="$out/$name"; mkdir -p "$d"
  t0=$(date +%s.%N)
  hist=(); case "$opts" in *"-task flow"*) hist=(-history_csv "$d/history.csv");; esac
  viewer=(); case "$opts" in *"-task spectrum"*) ;; *) viewer=(-viewer_dir "$d/vtu");; esac
  curve=0; case "$opts" in *"-task curveflow"*) curve=1;; esac
  # shellcheck disable=SC2086
  bin/confsurf $opts -summary "$d/summary.json" "${hist[@]}" "${viewer[@]}" > "$d/run.log" 2>&1 || { tail "$d/run.log"; exit 1; }
  args=(--summary "$d/summary.json" --title "$name")
  [ ${#viewer[@]} -gt 0 ] && args+=(--series "$d/vtu/series.pvd")
  [ ${#hist[@]} -gt 0 ] && args+=(--history "$d/history.csv")
  if [ $curve = 1 ]; then
    mkdir -p "$d/pictures"; "$py" scripts/plot_curves.py steps "$d/vtu" "$d/pictures/curves.png" > "$d/pictures.log"
  else
    "$py" scripts/pictures.py "$d/pictures" "${args[@]}" > "$d/pictures.log"
  fi
  line=$("$py" - "$d/summary.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
if "eigenvalues" in s:
    print("eigenvalues " + ", ".join("%.4g" % e for e in s["eigenvalues"]))
elif "energy_initial" in s:
    print("energy %.6g -> %.6g, %s after %d iterations" % (s["energy_initial"], s["energy"], s.get("stop_reason", ""), s["iterations"])
          + (", q_max %.4g" % s["q_max"] if "q_max" in s else "") + (", length distortion %.2g" % s["max_length_distortion"] if "max_length_distortion" in s else ""))
else:
    print(", ".join("%s %s" % (k, s[k]) for k in ("willmore", "q_mean", "q_max", "eigenvalue", "residual") if k in s))
PY
)
  printf '%-9s %5.1f s  %s\n' "$name" "$(echo "$(date +%s.%N) - $t0" | bc)" "$line"
  {
    echo "<h2>$name: $what</h2><p><code>bin/confsurf $opts</code><br>$line</p>"
    for p in mean_curvature quasi_conformal history spectrum curves; do
      [ -f "$d/pictures/$p.png" ] && echo "<img src=\"$name/pictures/$p.png\" width=\"45%\">"
    done
  } >> "$out/index.html"
done
echo "</body></html>" >> "$out/index.html"
echo
echo "Gallery: $out/index.html (pictures in $out/*/pictures/, runs in $out/*/)"
