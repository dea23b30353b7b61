# crane2011 Sec. 6.2, Fig. 9 and 11: the Dirac spheres of -task spectrum -spectrum_reconstruct against their closed
# forms (tests/cases/dirac_sphere_tool.py, derived there and in docs/spin_applications.md: lam = P_k left-monogenic
# of degree k for n = k, lam = x P_k for n = -(k + 2), the surface int conj(lam) dx lam). On the level-3 unit
# icosphere every eigenvector of n = 1, -2, 2, -3 (4..35) is reconstructed; the nearest closed form (any element of
# the eigenspace, any similarity) must be within 1.5 x the largest measured level-3 distance of its cluster (max over
# vertices / size: 1.82e-3, 2.84e-4, 1.96e-3, 5.43e-3; n = 2 spreads over 1.16e-3 .. 1.96e-3 with the element of its
# 12-dimensional eigenspace, the others by < 3 %; second order, runs/study_dirac_spheres.py: 1.1e-4 ... 3.3e-4 on
# level 5), while the wrong family of the same multiplicity and Willmore energy (n = -3 for an n = 1 sphere, a sign
# error in D or in Eq. 8's conj) stays at distance > 0.1 (measured 1.02 to 1.14). Serially also level 2: the observed order
# of each cluster's largest distance from level 2 to 3 in [1.7, 2.5] (measured 2.02, 1.81, 1.98, 2.10) and the closed
# forms' own checks (closed 1-form to round-off, discrete Eq. 5 residual of the closed form below 0.02 for n = 1, a
# wrong sign gives ~2). A lumped Eq. 8 (conj(lam_i) e lam_i on every edge, a first-order rule) breaks the bounds of
# n = 1, 2, -3 (cluster maxima 2.84e-3, 7.89e-3, 1.30e-2) and the order of n = 1 (1.56), measured.
# nprocs: 1 2
source tests/lib.sh
PY=$(bash scripts/find-python.sh)
LEVELS=3; [ "$NP" = 1 ] && LEVELS="2 3"
for L in $LEVELS; do
  "$CS_BIN" -task info -gen icosphere -gen_level $L -o "$TMP/ico$L.obj" > /dev/null
  timeout 60 $MPIEXEC "$CS_BIN" -task spectrum -gen icosphere -gen_level $L -spectrum_signed -spectrum_nev 36 \
    -spectrum_reconstruct "$(seq -s, 4 35)" -spectrum_reconstruct_prefix "$TMP/L$L" -summary "$TMP/L$L.json" > /dev/null
done
$PY - "$TMP" $LEVELS <<'PY'
import json, math, sys
sys.path[:0] = ["tests/cases", "scripts"]
import dirac_sphere_tool as tool
tmp, levels = sys.argv[1], [int(x) for x in sys.argv[2:]]
bound = {1: 1.5 * 1.82e-3, -2: 1.5 * 2.84e-4, 2: 1.5 * 1.96e-3, -3: 1.5 * 5.43e-3}
size = {1: 8, -2: 4, 2: 12, -3: 8}
bad, dist = 0, {}
for L in levels:
    e = json.load(open("%s/L%d.json" % (tmp, L)))["eigenvalues_by_magnitude"]
    ks = {}
    for k in range(4, 36):
        ks.setdefault(round(e[k]), []).append(k)
    ok = {n: len(v) for n, v in ks.items()} == size
    print(("ok  " if ok else "BAD ") + "level %d: eigenvectors 4..35 in n = 1, -2, 2, -3 with multiplicities 8, 4, 12, 8" % L)
    bad += not ok
    if not ok:
        continue
    for n, kk in ks.items():
        d = tool.cluster_distances("%s/ico%d.obj" % (tmp, L), ["%s/L%d_%d.obj" % (tmp, L, k) for k in kk], n)
        dist[L, n] = max(d)
        ok = L != 3 or max(d) <= bound[n]
        print(("ok  " if ok else "BAD ") + "level %d n = %d: distance to the closed forms %.3e .. %.3e over %d eigenvectors%s" % (
            L, n, min(d), max(d), len(d), " (bound %.2e)" % bound[n] if L == 3 else ""))
        bad += not ok
d = tool.distance("%s/ico3.obj" % tmp, "%s/L3_4.obj" % tmp, -3)["dist_max"]
ok = d > 0.1
print(("ok  " if ok else "BAD ") + "an n = 1 sphere against the n = -3 closed forms: distance %.3f (> 0.1)" % d); bad += not ok
if 2 in levels and len(dist) == 8:
    for n in (1, -2, 2, -3):
        p = math.log2(dist[2, n] / dist[3, n])
        ok = 1.7 <= p <= 2.5
        print(("ok  " if ok else "BAD ") + "n = %d: observed order %.2f from level 2 to 3" % (n, p)); bad += not ok
    c = tool.check("%s/ico3.obj" % tmp, 1)
    ok = c["closedness"] < 1e-12 and c["eq5_residual"] < 0.02
    print(("ok  " if ok else "BAD ") + "closed form n = 1: closed to %.1e, discrete Eq. 5 residual %.4f" % (c["closedness"], c["eq5_residual"])); bad += not ok
sys.exit(bad)
PY
