# The fairing baselines of crane2013 Sec. 6.4.2 (src/methods/willmore/impls/fairing/fairing_baselines.c: emcf, ebilap, imcf,
# ibilap, cmcf) run with their default options: each fairs a bumped sphere (W falls in 5 fixed steps) and keeps the
# input's area (each step is rescaled to it). A range check of the flow's options once refused every one of them by
# default ("-flow_t_max 1.79769e+308"), and no case ran them.
# nprocs: 1 2
source tests/lib.sh
G="-task flow -gen icosphere -gen_level 3 -gen_deform_bump 0.2 -flow_max_it 5"
timeout 60 $MPIEXEC "$CS_BIN" -task info -gen icosphere -gen_level 3 -gen_deform_bump 0.2 -summary "$TMP/in.json" > "$TMP/in.log" 2>&1 || { tail -3 "$TMP/in.log"; exit 1; }
for k in emcf ebilap imcf ibilap cmcf; do
  timeout 120 $MPIEXEC "$CS_BIN" $G -flow_type $k -summary "$TMP/$k.json" > "$TMP/$k.log" 2>&1 || { echo "FAIL: -flow_type $k with its defaults"; tail -3 "$TMP/$k.log"; exit 1; }
  python3 - "$TMP/$k.json" "$TMP/in.json" "$k" <<'PY' || exit 1
import json, sys
s, i, k = json.load(open(sys.argv[1])), json.load(open(sys.argv[2])), sys.argv[3]
checks = [("5 steps, stop max_it", s['iterations'] == 5 and s['stop_reason'] == 'max_it', (s['iterations'], s['stop_reason'])),
          ("W falls", s['energy'] < s['energy_initial'] - 0.1, (s['energy_initial'], s['energy'])),
          ("the input's area kept (1e-9)", abs(s['area'] - i['area']) <= 1e-9 * i['area'], (s['area'], i['area']))]
bad = 0
for name, ok, v in checks:
    print(("ok   " if ok else "BAD  ") + k + ": " + name + ": " + repr(v)); bad += not ok
sys.exit(bad)
PY
done
