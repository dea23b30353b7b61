# issue 21 item 4 (Moebius sliding): the default run of options/flow_sphere.opts (CGD, no -flow_constraint_mobius)
# on held-out inputs, i.e. bumps, frequencies and stretches it was not written for (at level 3 to fit the suite),
# never trips the resolution guard (-flow_max_area_ratio 200): each converges (EL < 1e-6, class to 1e-10) with the
# vertex-area spread of every iteration (history column area_spread) far below the guard. Measured 2026-12-02,
# serial: 47, 47, 48 iterations; largest spread 3.3, 3.2, 3.8; W 12.497, 12.497, 12.493 (the options file's own
# level-4 input: 47 iterations; the held-out inputs at level 4: 44 and 45 iterations, spread 3.5, in 40-90 s under
# load). The guard trips where the discrete W slides along a Moebius orbit: at a reduced volume (willmore_mobius.sh,
# where the README says to switch -flow_constraint_mobius on) and on real meshes (docs/real_meshes.md).
# nprocs: 1 2
source tests/lib.sh
i=0
for h in "0.3 2 1.2,1.1,0.7" "0.15 4 1,1.4,0.9" "0.25 3 0.7,1,1.3"; do
  set -- $h; i=$((i + 1))
  timeout 60 $MPIEXEC "$CS_BIN" -task flow -options_file options/flow_sphere.opts -gen_level 3 -gen_deform_bump $1 \
    -gen_deform_bump_freq $2 -gen_deform_stretch $3 -summary "$TMP/$i.json" -history_csv "$TMP/$i.csv" > "$TMP/$i.log" 2>&1 || { tail "$TMP/$i.log"; exit 1; }
done
python3 - "$TMP" <<'PY'
import csv, json, sys
d, bad = sys.argv[1], 0
for i in '123':
    s = json.load(open(d + '/%s.json' % i))
    spread = max(float(r['area_spread']) for r in csv.DictReader(open(d + '/%s.csv' % i)))
    checks = [("converged (not stopped by the guard)", s['converged'] in (True, 1, 'true') and s['stop_reason'] == 'converged', (s['stop_reason'], s['iterations'])),
              ("el_residual < 1e-6", s['el_residual'] < 1e-6, s['el_residual']),
              ("conformal_violation < 1e-10", s['conformal_violation'] < 1e-10, s['conformal_violation']),
              ("largest area spread of the run < 20 (the guard: 200)", spread < 20, spread)]
    for name, good, v in checks:
        print(("ok  " if good else "BAD ") + "input %s: %s: %r" % (i, name, v)); bad += not good
    print("     input %s: W %.6f" % (i, s['energy']))
sys.exit(bad)
PY
