# The variants of the curve flow (crane2013 Sec. 4, 5): an open curve (-curve_open, no closure constraints)
# straightens with its edge lengths kept (end-to-end distance = length); the spectral filter of Sec. 4
# (-curve_filter, k = 1 and 2) still reaches the circle with E non-increasing and the lengths kept.
# nprocs: 1 2
source tests/lib.sh
run() { timeout 60 $MPIEXEC "$CS_BIN" -task curveflow -gen_curve noisy -gen_curve_n 400 -gen_curve_noise 0.01 "$@"; }
run -curve_max_it 0 -o "$TMP/in.txt" > /dev/null
run -curve_open -curve_tau 0.5 -summary "$TMP/open.json" -o "$TMP/open.txt" > "$TMP/open.log"
for k in 1 2; do
  run -curve_filter -curve_filter_k $k -curve_filter_sigma 0.1 -curve_tau 0.9 -curve_max_it 400 -summary "$TMP/f$k.json" -history_csv "$TMP/f$k.csv" > "$TMP/f$k.log"
done
python3 - "$TMP" <<'PY'
import sys; sys.path.insert(0, 'tests/cases')
from curve_tools import *
t = sys.argv[1]; ok = True
l0 = lengths(points(t + '/in.txt'))
s = summary(t + '/open.json')
p = [list(map(float, l.split())) for l in open(t + '/open.txt') if l.strip() and not l.startswith('#')]
ok &= report(s['converged'] and not s['closed'] and len(p) == 400, f"open curve: converged after {s['iterations']} steps, 400 points, closed={s['closed']}")
l = lengths(p, closed=False)
ok &= report(max(abs(a / b - 1) for a, b in zip(l, l0)) < 1e-10, f"open curve: lengths kept to {max(abs(a / b - 1) for a, b in zip(l, l0)):.1e}")
ok &= report(abs(math.dist(p[0], p[-1]) / sum(l) - 1) < 1e-10, f"open curve: straight, end-to-end / length - 1 = {math.dist(p[0], p[-1]) / sum(l) - 1:.1e}")
for k in (1, 2):
    s = summary(f'{t}/f{k}.json'); e = [r['energy'] for r in history(f'{t}/f{k}.csv')]
    ok &= report(s['converged'] and s['kappa_spread_rel'] < 1e-5, f"filter k={k}: converged after {s['iterations']} steps, spread/mean {s['kappa_spread_rel']:.1e}")
    ok &= report(all(b <= a * (1 + 1e-12) for a, b in zip(e, e[1:])), f"filter k={k}: E non-increasing ({e[0]:.4g} -> {e[-1]:.10g})")
    ok &= report(s['length_distortion'] < 1e-8, f"filter k={k}: final length distortion {s['length_distortion']:.1e}")
sys.exit(0 if ok else 1)
PY
