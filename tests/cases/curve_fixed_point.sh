# A round circle is a fixed point of the isometric curve flow (crane2013 Sec. 5): kappa is constant, so the
# projected direction vanishes and three steps move no vertex by more than 1e-12 relative to the radius; and
# the output edge lengths equal the input's (-task curveflow -gen_curve circle, 2000 vertices).
# nprocs: 1 2
source tests/lib.sh
run() { timeout 60 $MPIEXEC "$CS_BIN" -task curveflow -gen_curve circle -gen_curve_n 2000 -gen_curve_radius 3 "$@"; }
run -curve_max_it 0 -o "$TMP/in.txt" > "$TMP/log0"
run -curve_max_it 3 -curve_rtol 0 -o "$TMP/out.obj" -summary "$TMP/s.json" > "$TMP/log1"
python3 - "$TMP" <<'PY'
import sys; sys.path.insert(0, 'tests/cases')
from curve_tools import *
t = sys.argv[1]
a = points(t + '/in.txt')
b = [[float(w) for w in l.split()[1:3]] for l in open(t + '/out.obj') if l.startswith('v ')]
s = summary(t + '/s.json')
d = max(math.dist(p[:2], q) for p, q in zip(a, b)) / 3
ok = report(len(a) == len(b) == 2000, f"{len(a)} vertices in, {len(b)} out")
ok &= report(s['iterations'] == 3, f"3 steps taken ({s['iterations']})")
ok &= report(d < 1e-12, f"circle moved by {d:.3e} of its radius in 3 steps (< 1e-12)")
ok &= report(s['kappa_spread_rel'] < 1e-8, f"kappa spread / mean {s['kappa_spread_rel']:.3e} (round-off of the turning angles)")
sys.exit(0 if ok else 1)
PY
