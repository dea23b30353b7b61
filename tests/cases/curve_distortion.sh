# Isometry (crane2013 Sec. 5.1, Fig. 11): one step of the flow of a noisy circle with tau = 0.2, 0.1, 0.05,
# 0.025: the closure gap before the Poisson step and the worst edge-length distortion after it fall
# quadratically (log-log slope 2 +- 0.3); the output edge lengths stay within the reported distortion; the
# distortion of a longer run is within its reported max_length_distortion.
# nprocs: 1 2
source tests/lib.sh
run() { timeout 60 $MPIEXEC "$CS_BIN" -task curveflow -gen_curve noisy -gen_curve_n 400 -gen_curve_noise 0.01 "$@"; }
run -curve_max_it 0 -o "$TMP/in.txt" > /dev/null
for tau in 0.2 0.1 0.05 0.025; do
  run -curve_tau $tau -curve_max_it 1 -curve_rtol 0 -summary "$TMP/t$tau.json" -o "$TMP/t$tau.txt" > "$TMP/t$tau.log"
done
run -curve_tau 0.95 -curve_max_it 30 -curve_rtol 0 -summary "$TMP/long.json" -o "$TMP/long.txt" > "$TMP/long.log"
python3 - "$TMP" <<'PY'
import sys; sys.path.insert(0, 'tests/cases')
from curve_tools import *
t = sys.argv[1]; ok = True
l0 = lengths(points(t + '/in.txt'))
taus = [0.2, 0.1, 0.05, 0.025]; dist = []; gap = []
for tau in taus:
    s = summary(f'{t}/t{tau}.json')
    l = lengths(points(f'{t}/t{tau}.txt'))
    measured = max(abs(a / b - 1) for a, b in zip(l, l0))
    ok &= report(measured <= s['max_length_distortion'] * (1 + 1e-6) + 1e-14, f"tau={tau}: output lengths within the reported distortion ({measured:.3e} <= {s['max_length_distortion']:.3e})")
    dist.append(s['max_length_distortion']); gap.append(s['closure_gap_max'])
def slope(y):
    X = [math.log(a) for a in taus]; Y = [math.log(b) for b in y]
    mx = sum(X) / len(X); my = sum(Y) / len(Y)
    return sum((a - mx) * (b - my) for a, b in zip(X, Y)) / sum((a - mx) ** 2 for a in X)
ok &= report(abs(slope(dist) - 2) <= 0.3, f"distortion {['%.2e' % d for d in dist]}: log-log slope {slope(dist):.3f}")
ok &= report(abs(slope(gap) - 2) <= 0.3, f"closure gap {['%.2e' % d for d in gap]}: log-log slope {slope(gap):.3f}")
s = summary(t + '/long.json'); l = lengths(points(t + '/long.txt'))
m = max(abs(a / b - 1) for a, b in zip(l, l0))
ok &= report(m <= s['max_length_distortion'] * (1 + 1e-6) + 1e-14, f"30 steps at tau=0.95: final distortion {m:.3e} <= max reported {s['max_length_distortion']:.3e}")
sys.exit(0 if ok else 1)
PY
