# The texture distortion in the summaries (issue 38): texture_q_mean/max of the result and of the input (*_input) in
# every task with a summary. A conformal method composes the UV map with its own map of quasi-conformal error q, so
# per face Q_in / q <= Q_out <= Q_in q (the singular values of a product): the means obey
# texture_q_mean_input / q_max <= texture_q_mean <= texture_q_mean_input * q_max (the same UV-area weights). With
# UVs that are a similarity per face up to Q_in (the cylinder's arc-length UVs), Q_out is q itself up to that:
# |texture_q_mean - q_mean| <= q_max (texture_q_max_input - 1). Runs: info, a spin transformation, crane2013's
# conformal flow, CGD with the class kept (soliman2021 Fig. 2's twisted cylinder), the Bobenko-Schroeder flow.
# nprocs: 1 2
source tests/lib.sh
run() { timeout 120 $MPIEXEC "$CS_BIN" "$@" > "$TMP/log" 2>&1 || { tail "$TMP/log"; exit 1; }; }
bounds() { # summary label: the composition bounds
  python3 - "$1" "$2" <<'PY' || exit 1
import json, sys
s, lab = json.load(open(sys.argv[1])), sys.argv[2]
tq, tin, qx = s["texture_q_mean"], s["texture_q_mean_input"], s["q_max"]
ok = tin / qx - 1e-12 <= tq <= tin * qx + 1e-12 and s["texture_q_max"] <= s["texture_q_max_input"] * qx + 1e-12
print(("ok  " if ok else "BAD ") + "%s: texture_q_mean %.6f, input %.6f, q_mean %.6f, q_max %.6f (input/q_max <= out <= input q_max)" % (lab, tq, tin, s["q_mean"], qx))
sys.exit(0 if ok else 1)
PY
}
# spin transformation of the cylinder: arc-length UVs (Q_in ~ 1), so texture_q_mean ~ q_mean
run -task spin -gen cylinder -gen_n 24 -gen_m 8 -rho_bump_center 1,0,0 -rho_bump_radius 0.5 -summary "$TMP/spin.json"
bounds "$TMP/spin.json" spin || exit 1
python3 - "$TMP/spin.json" <<'PY' || exit 1
import json, sys
s = json.load(open(sys.argv[1]))
d, b = abs(s["texture_q_mean"] - s["q_mean"]), s["q_max"] * (s["texture_q_max_input"] - 1) + 1e-12
print(("ok  " if d <= b else "BAD ") + "spin: |texture_q_mean - q_mean| = %.3g <= q_max (texture_q_max_input - 1) = %.3g" % (d, b))
sys.exit(0 if d <= b else 1)
PY
run -task flow -flow_type conformal -gen torus -gen_n 24 -gen_m 12 -gen_deform_bump 0.1 -flow_max_it 2 -summary "$TMP/conf.json"
bounds "$TMP/conf.json" "conformal flow" || exit 1
run -task flow -options_file options/flow_fig2_twist.opts -flow_max_it 4 -summary "$TMP/cgd.json"
bounds "$TMP/cgd.json" "cgd, class kept" || exit 1
if [ "$NP" = 1 ]; then # the keys alone, serial (each run costs ~3 s of mpirun start-up on 2 ranks under load)
  # info: the result is the input (the distributed measure itself: foundation_texture)
  run -task info -gen torus -gen_torus_R 2 -gen_tube_r 1 -gen_n 24 -gen_m 24 -summary "$TMP/info.json"
  check_close "$(json texture_q_mean "$TMP/info.json")" "$(json texture_q_mean_input "$TMP/info.json")" 0 "info: texture_q_mean = input" || exit 1
  check_close "$(json texture_q_mean "$TMP/info.json")" 2 0.05 "info: torus R=2 r=1: texture_q_mean ~ R/r" || exit 1
  run -task flow -flow_type bs -gen torus -gen_n 16 -gen_m 8 -bs_max_it 2 -summary "$TMP/bs.json"
  json texture_q_mean_input "$TMP/bs.json" > /dev/null || { echo "BAD: -flow_type bs: no texture_q_mean_input"; exit 1; }
  run -task info -gen icosphere -gen_level 1 -summary "$TMP/ico.json"
  ! grep -q texture_q "$TMP/ico.json" || { echo "BAD: -gen icosphere has no UVs but reports texture_q"; exit 1; }
fi
echo "ok  info, spin, conformal, cgd, bs report texture_q"
