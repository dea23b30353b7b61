#!/usr/bin/env bash
# The texture figures of issue 38 (docs/textures.md): each run writes its ParaView series (input and result),
# scripts/pictures.py draws the checkerboard in UV into docs/img/texture_*.png, and the summaries' texture_q_mean /
# texture_q_max (input and result) go to $OUT/texture_figures.txt. soliman2021 Fig. 12: the twisted torus by
# crane2013's conformal flow (to convergence) and by CGD stopped at the same W decrease, side by side.
# OUT=dir (default out/texture_figures). Serial; about 2 min under load.
set -euo pipefail
cd "$(dirname "$0")/.."
out=${OUT:-out/texture_figures}; img=docs/img; py=$(bash scripts/find-python.sh)
rm -rf "$out"; mkdir -p "$out" "$img"
run() { # name options...: the run with its series and summary
  local name=$1; shift
  bin/confsurf "$@" -viewer_dir "$out/$name/vtu" -summary "$out/$name/summary.json" -history_csv "$out/$name/history.csv" > "$out/$name.log" 2>&1 || { tail "$out/$name.log"; exit 1; }
}
pics() { # name title view checks
  "$py" scripts/pictures.py "$out/$1/pictures" --series "$out/$1/vtu/series.pvd" --summary "$out/$1/summary.json" \
    --title "$2" --view "$3" --checks "$4" --texture_check "$img/texture_$1.png" > /dev/null
}
run soliman2021_fig2 -task flow -options_file options/flow_fig2_twist.opts -flow_viewer_every 1000
pics soliman2021_fig2 "soliman2021 Fig. 2: twisted cylinder, class kept (CGD)" 15,-60 16
run crane2013_fig2 -options_file options/texture_conformal_fig2.opts -flow_viewer_every 1000
pics crane2013_fig2 "crane2013 Fig. 2: conformal curvature flow" 35,-60 8
run crane2011_fig10 -options_file options/texture_spin_fig10.opts
pics crane2011_fig10 "crane2011 Fig. 10: a bump by a spin transformation" 35,-60 8
# soliman2021 Fig. 12: the conformal flow to convergence, then CGD to its first iteration at or below that W
run fig12_conformal -options_file options/texture_fig12_twisted_torus.opts -flow_type conformal -flow_max_it 100 -flow_viewer_every 1000
Wc=$("$py" -c 'import json,sys; print(repr(json.load(open(sys.argv[1]))["willmore"]))' "$out/fig12_conformal/summary.json")
run fig12_cgd_probe -options_file options/texture_fig12_twisted_torus.opts -flow_max_it 40
k=$("$py" -c 'import csv,sys; r=[x for x in csv.DictReader(open(sys.argv[1])) if float(x["energy"]) <= float(sys.argv[2])]; print(r[0]["it"] if r else 40)' "$out/fig12_cgd_probe/history.csv" "$Wc")
run fig12_cgd -options_file options/texture_fig12_twisted_torus.opts -flow_max_it "$k" -flow_viewer_every 1000
"$py" - "$out" "$img/texture_soliman2021_fig12.png" <<'PY'
import json, os, sys
sys.path.insert(0, "scripts")
import numpy as np
import pictures as P
out, png = sys.argv[1], sys.argv[2]
V0, Vc, F, UV = P.read_series(f"{out}/fig12_cgd/vtu/series.pvd")
_, Vf, Ff, _ = P.read_series(f"{out}/fig12_conformal/vtu/series.pvd")
assert (F == Ff).all()
sc, sf = (json.load(open(f"{out}/{n}/summary.json")) for n in ("fig12_cgd", "fig12_conformal"))
both = np.vstack([V0, Vc, Vf]); lo, hi = both.min(0), both.max(0)
box = ((lo + hi) / 2, 0.55 * np.linalg.norm(hi - lo) / np.sqrt(3) * 1.25)
cmap = P.matplotlib.colors.ListedColormap(["#1d3557", "#f1faee"]); norm = P.matplotlib.colors.Normalize(0, 1)
fig, axs = P.plt.subplots(1, 3, figsize=(14, 5.2))
for ax, X, lab in ((axs[0], V0, "input (twisted torus): W %.4f\ntexture Q mean %.4f, max %.3f" % (sc["energy_initial"], sc["texture_q_mean_input"], sc["texture_q_max_input"])),
                   (axs[1], Vc, "CGD, %d iterations: W %.4f\ntexture Q mean %.4f, max %.3f; q_mean %.4f, q_max %.4f" % (sc["iterations"], sc["energy"], sc["texture_q_mean"], sc["texture_q_max"], sc["q_mean"], sc["q_max"])),
                   (axs[2], Vf, "conformal flow, %d steps: W %.4f\ntexture Q mean %.4f, max %.3f; q_mean %.4f, q_max %.4f" % (sf["iterations"], sf["willmore"], sf["texture_q_mean"], sf["texture_q_max"], sf["q_mean"], sf["q_max"]))):
    Pp, T, colour, L = P.checker_subdivide(X, F, UV, 8)
    P.draw_surface(ax, Pp, T, colour, cmap, norm, (40, -60), box, two_sided=True)
    ax.set_title(lab, fontsize=8)
fig.suptitle("soliman2021 Fig. 12: the twisted torus by CGD and by crane2013's conformal flow at the same W decrease (checkerboard in UV)", fontsize=10, y=0.98)
fig.subplots_adjust(left=0.01, right=0.99, bottom=0.01, top=0.85, wspace=0.02)
fig.savefig(png, dpi=P.DPI)
PY
{
  printf "%-18s %10s %10s %12s %12s %12s %12s %8s %8s\n" run W_in W_out tq_mean_in tq_mean_out tq_max_in tq_max_out q_mean q_max
  for n in soliman2021_fig2 crane2013_fig2 crane2011_fig10 fig12_cgd fig12_conformal; do
    "$py" - "$out/$n/summary.json" "$n" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
w0, w1 = s.get("energy_initial", s.get("willmore_initial", float("nan"))), s.get("willmore", float("nan"))  # nan: a spin transformation has no W_in
print("%-18s %10.6f %10.6f %12.6f %12.6f %12.6f %12.6f %8.5f %8.5f" % (sys.argv[2], w0, w1, s["texture_q_mean_input"], s["texture_q_mean"], s["texture_q_max_input"], s["texture_q_max"], s["q_mean"], s["q_max"]))
PY
  done
  echo "fig12: conformal flow W $Wc after its steps; CGD stopped at iteration $k (first W <= that)"
} | tee "$out/texture_figures.txt"
