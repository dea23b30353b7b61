# soliman2021 Fig. 21 (right) and Sec. 6.2.3: the conformally constrained area energy (an isotropic auxetic soap film)
# on the unit sphere with six caps of 30 degrees cut off (tests/tools/gen_capped_sphere.py --n 4 --m 2: 236 vertices,
# six boundary loops on the cap circles), the six rims fixed (Dirichlet). The paper: minimal surfaces shrink, "once
# the conformality constraint is added any area scaling must be isotropic", and the shapes are distinctly different.
# Checked: the constrained flow converges (scaled EL < -flow_rtol 5e-7) with the class kept to 1e-10 and the rims
# where they were (1e-12); it lowers the area, but far less than the unconstrained area flow (gd, no conformal rows)
# does in 60 iterations (gd lowers the area monotonically, so its area bounds its limit's from above): the loss
# under the constraint is below a third of the free one (measured: 0.098 against 0.52, docs/boundary_twist.md);
# the free film shrinks anisotropically (q_mean - 1 over 3 times the constrained one's, measured 0.080 against
# 0.0155) where the constrained one stays near a
# similarity per face (q_max < 1.05, measured 1.023; exactly 1 is not expected: a discrete conformal map keeps the
# length cross ratios, not each face's shape); the two results differ by more than 0.05 of the radius. That bound
# was 0.1 (measured 0.143) until cgd's default dual step went from 1e3 t to 1e5 t (issue 39, Fig. 7): the constrained
# flow then stops at another stationary film (area 7.44654 against 7.44499, both stationary at rtol 1e-9, 0.048 apart
# at the vertices), 0.095 from the free one; the constrained problem has more than one stationary film here, so the
# bound is set above their spread (0.048), not at one run's distance.
# nprocs: 1 2
source tests/lib.sh
python3 tests/tools/gen_capped_sphere.py "$TMP/caps.obj" --n 4 --m 2
"$CS_BIN" -task info -mesh "$TMP/caps.obj" -summary "$TMP/in.json" > "$TMP/in.log"
grep -q "V=236 E=624 F=384 genus=0 boundary_loops=6" "$TMP/in.log" || { cat "$TMP/in.log"; exit 1; }
run() { local n=$1; shift; timeout 120 $MPIEXEC "$CS_BIN" -task flow -mesh "$TMP/caps.obj" -flow_energy area -flow_boundary dirichlet "$@" -o "$TMP/$n.obj" -summary "$TMP/$n.json" > "$TMP/$n.log" 2>&1 || { tail "$TMP/$n.log"; exit 1; }; }
run con -flow_type cgd -flow_metric h1 -flow_t 0.25 -flow_t_max 0.5 -flow_t_mu_final 1e8 -flow_max_it 300
run free -flow_type gd -flow_max_it 60
python3 - "$TMP" <<'PY'
import json, math, sys
d = sys.argv[1]
rd = lambda p: [[float(t) for t in l.split()[1:4]] for l in open(d + '/' + p) if l.startswith('v ')]
S = {k: json.load(open(d + '/%s.json' % k)) for k in ('in', 'con', 'free')}
I, C, G = rd('caps.obj'), rd('con.obj'), rd('free.obj')
c30 = math.cos(math.radians(30))
rim = [i for i, v in enumerate(I) if abs(max(abs(x) for x in v) - c30) < 1e-12]
rim_dev = max(abs(C[i][k] - I[i][k]) for i in rim for k in range(3))
dist = max(math.dist(C[i], G[i]) for i in range(len(I)))
A0, Ac, Af = S['in']['area'], S['con']['area'], S['free']['area']
conv = lambda s: s['converged'] in (True, 1, 'true')
checks = [
  ("the rims: 6 x 16 vertices on the cap circles", len(rim) == 96, len(rim)),
  ("constrained: converged, scaled EL < 5e-7", conv(S['con']) and S['con']['el_residual_scaled'] < 5e-7, (S['con']['iterations'], S['con']['el_residual_scaled'])),
  ("constrained: class kept to 1e-10", S['con']['conformal_violation'] < 1e-10, S['con']['conformal_violation']),
  ("constrained: rims fixed to 1e-12", rim_dev < 1e-12, rim_dev),
  ("constrained: area lowered", Ac < A0 - 1e-3, (A0, Ac)),
  ("auxetic: constrained area loss < 1/3 of the free one", A0 - Ac < (A0 - Af) / 3, (A0 - Ac, A0 - Af)),
  ("free film anisotropic: q_mean - 1 over 3 times the constrained one's", S['free']['q_mean'] - 1 > 3 * (S['con']['q_mean'] - 1), (S['free']['q_mean'], S['con']['q_mean'])),
  ("constrained film isotropic: q_max < 1.05", S['con']['q_max'] < 1.05, S['con']['q_max']),
  ("distinctly different shapes: max distance > 0.05 (the constrained stationary films spread 0.048)", dist > 0.05, dist),
]
bad = 0
for name, good, v in checks:
    print(("ok  " if good else "BAD ") + name + ": " + repr(v)); bad += not good
for k in ('con', 'free'):
    s = S[k]; print("     %-5s %4d it. area %.9f EL %.2e class %.2e q_mean %.4f q_max %.4f %s" % (k, s['iterations'], s['area'], s['el_residual_scaled'], s['conformal_violation'], s['q_mean'], s['q_max'], s['stop_reason']))
sys.exit(bad)
PY
