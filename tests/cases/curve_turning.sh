# Total curvature (crane2013 Sec. 5, <kappa', 1> = 0): it stays 2 pi k to 1e-12 at every state of a noisy
# circle (k = 1) and of a limacon with an inner loop (k = 2); the limacon ends as a doubly covered circle (all
# vertices at one distance from the centroid, every turning angle positive).
# nprocs: 1 2
source tests/lib.sh
run() { timeout 60 $MPIEXEC "$CS_BIN" -task curveflow "$@"; }
run -gen_curve noisy -gen_curve_n 1000 -gen_curve_noise 0.01 -curve_tau 0.5 -curve_max_it 40 -history_csv "$TMP/k1.csv" > "$TMP/k1.log"
run -gen_curve limacon -gen_curve_n 1000 -gen_curve_a 2 -gen_curve_b 1 -curve_max_it 300 -history_csv "$TMP/k2.csv" -summary "$TMP/k2.json" -o "$TMP/k2.txt" > "$TMP/k2.log"
python3 - "$TMP" <<'PY'
import sys; sys.path.insert(0, 'tests/cases')
from curve_tools import *
t = sys.argv[1]; ok = True
for name, k in (('k1', 1), ('k2', 2)):
    h = history(f'{t}/{name}.csv')
    err = max(abs(2 * math.pi * r['turning_number'] - 2 * math.pi * k) for r in h)
    ok &= report(err < 1e-12, f"turning number {k}: |total curvature - 2 pi k| <= {err:.2e} over {len(h)} states")
s = summary(f'{t}/k2.json'); p = points(f'{t}/k2.txt')
l = lengths(p); d = [0.5 * (l[i - 1] + l[i]) for i in range(len(p))]  # the vertices are not uniform along the circle
cx = sum(w * q[0] for w, q in zip(d, p)) / sum(d); cy = sum(w * q[1] for w, q in zip(d, p)) / sum(d)
r = [math.hypot(q[0] - cx, q[1] - cy) for q in p]
R = sum(w * x for w, x in zip(d, r)) / sum(d)
ok &= report(s['converged'], f"limacon converged after {s['iterations']} steps")
ok &= report((max(r) - min(r)) / R < 1e-4, f"limacon: radii spread {(max(r) - min(r)) / R:.2e} of the mean (doubly covered circle)")
ok &= report(abs(sum(l) / (2 * math.pi * R) - 2) < 1e-4, f"limacon: length / (2 pi r) = {sum(l) / (2 * math.pi * R):.8f} (2: covered twice)")
sys.exit(0 if ok else 1)
PY
