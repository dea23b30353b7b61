# soliman2021 Fig. 18 / 19 (Sec. 6.2.1): the conformally constrained Willmore surface through a few points is an
# as-spherical-as-possible interpolant. Six point constraints on the level-2 icosphere (162 vertices) at the
# octahedron's vertices (indices 41, 21, 16, 36, 25, 28 lie exactly on +-x, +-y, +-z):
#  round: all six left on the unit sphere: the interpolant is the sphere (sphere reproduction; mean | |x| - 1 | below
#   1e-2 in every band of angle from +x, measured 1.2e-3 at most: the icosphere is not exactly critical in its class);
#  moved: the +x point moved asymmetrically to (1.3, 0.4, 0) (the cross ratios of the points change: no Moebius image
#   of the sphere passes through them): converged (scaled EL < 5e-7), the points met to 1e-10, the class kept to
#   1e-10; the deviation from the sphere is local: the far hemisphere (angle > 90 deg from +x) stays within a third
#   of the deviation of the cap of 30 deg about the moved point (measured 0.035 against 0.149);
#  free: the same points without the conformal constraint (100 iterations; the flow degenerates later) moves that
#   cap more than 1.5 times as far (measured 0.277): the whole side swells where the auxetic surface bulges locally.
# Caveat (docs/willmore_flow.md "Fig. 18"): on this level-2 mesh the moved point's minimiser is a cone at the pinned
# vertex (the discrete class lets one vertex be rescaled alone; height 0.73 of its edges), so the 30-degree cap's
# deviation includes that spike; the spike-free interpolant needs level 4 and the smaller move of
# options/flow_fig18_interp.opts (32 s serially: its header's expect line guards it, not this test).
# nprocs: 1 2
source tests/lib.sh
G="-gen icosphere -gen_level 2"
"$CS_BIN" -task info $G -o "$TMP/ico.obj" > /dev/null
printf '41 1 0 0\n21 -1 0 0\n16 0 1 0\n36 0 -1 0\n25 0 0 1\n28 0 0 -1\n' > "$TMP/round.txt"
sed 's/^41 .*/41 1.3 0.4 0/' "$TMP/round.txt" > "$TMP/moved.txt"
run() { local n=$1; shift; timeout 120 $MPIEXEC "$CS_BIN" -task flow $G -flow_type cgd "$@" -o "$TMP/$n.obj" -summary "$TMP/$n.json" > "$TMP/$n.log" 2>&1 || { tail "$TMP/$n.log"; exit 1; }; }
run round -flow_constraint_points "$TMP/round.txt" -flow_max_it 300
run moved -flow_constraint_points "$TMP/moved.txt" -flow_max_it 300
run free -flow_constraint_points "$TMP/moved.txt" -flow_conformal false -flow_max_it 100
python3 - "$TMP" <<'PY'
import json, math, sys
d = sys.argv[1]
rd = lambda p: [[float(t) for t in l.split()[1:4]] for l in open(d + '/' + p) if l.startswith('v ')]
S = {k: json.load(open(d + '/%s.json' % k)) for k in ('round', 'moved', 'free')}
I = rd('ico.obj'); X = {k: rd(k + '.obj') for k in S}
ang = [math.degrees(math.acos(max(-1, min(1, v[0])))) for v in I]
def band(k, lo, hi):
    dv = [abs(math.hypot(*X[k][i]) - 1) for i in range(len(I)) if lo <= ang[i] < hi]
    return sum(dv) / len(dv)
pts = [l.split() for l in open(d + '/moved.txt')]
miss = max(abs(X['moved'][int(p[0])][c] - float(p[1 + c])) for p in pts for c in range(3))
conv = lambda s: s['converged'] in (True, 1, 'true')
rb = max(band('round', lo, hi) for lo, hi in ((0, 30), (30, 60), (60, 90), (90, 181)))
near, far, fnear = band('moved', 0, 30), band('moved', 90, 181), band('free', 0, 30)
checks = [
  ("round: converged, the sphere reproduced (band means < 1e-2)", conv(S['round']) and rb < 1e-2, (S['round']['iterations'], rb)),
  ("moved: converged, scaled EL < 5e-7", conv(S['moved']) and S['moved']['el_residual_scaled'] < 5e-7, (S['moved']['iterations'], S['moved']['el_residual_scaled'])),
  ("moved: the six points met to 1e-10", miss < 1e-10, miss),
  ("moved: class kept to 1e-10", S['moved']['conformal_violation'] < 1e-10, S['moved']['conformal_violation']),
  ("moved: deviates from the sphere near the point (> 0.05)", near > 0.05, near),
  ("moved: local: far hemisphere < 1/3 of the near cap", far < near / 3, (far, near)),
  ("free: the near cap moves > 1.5 times as far", fnear > 1.5 * near, (fnear, near)),
]
bad = 0
for name, good, v in checks:
    print(("ok  " if good else "BAD ") + name + ": " + repr(v)); bad += not good
for k in S:
    s = S[k]; print("     %-5s %4d it. W %.6f EL %.2e class %.2e q_max %.3f %s" % (k, s['iterations'], s['willmore'], s['el_residual_scaled'], s['conformal_violation'], s['q_max'], s['stop_reason']))
sys.exit(bad)
PY
