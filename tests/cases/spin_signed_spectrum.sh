# crane2011 Sec. 6.2 / Fig. 8 on the generalised problem Eq. 6 (-spectrum_signed): on the unit sphere the Dirac
# eigenvalues are the integers n != -1 with real multiplicity 4|n+1|. Level-3 icosphere (1280 faces): the first
# 11 distinct values (0, 1, -2, 2, ..., 5, -6) come with exactly these multiplicities and signs; 2 % holds for the
# first 5 (0, 1, -2, 2, -3: 1.3 % at n = 2); the error grows like n^2 h^2 (docs/spin_applications.md: 2.4 % at n = 3,
# 22 % at n = 10 on level 3, 4.8 % on level 4, 1.2 % on level 5). Serially also level 2: the observed order of the
# error from level 2 to 3 must be 2 (in [1.8, 2.3]) for n = 1, -2, 2, -3, 3 (measured 2.00 to 2.07): the issue's
# "level 3, first 20 within 2 %" is out of reach of Eq. 6 as the paper discretises it (first 20 within 2 % from level 5).
# Dirac spheres (Fig. 9, 11): the ground state (the kernel, constants) gives the round sphere, q_max - 1 < 1e-6;
# a k beyond the computed eigenvectors is a clear error.
# On 2 ranks (slower here: the machine is shared) the first 6 distinct values (52 eigenpairs).
# nprocs: 1 2
source tests/lib.sh
NEV=144; [ "$NP" = 1 ] || NEV=52
timeout 60 $MPIEXEC "$CS_BIN" -task spectrum -gen icosphere -gen_level 3 -spectrum_signed -spectrum_nev $NEV \
  -spectrum_reconstruct 0,4 -spectrum_reconstruct_prefix "$TMP/ds" -summary "$TMP/s.json" > "$TMP/log"
python3 - "$TMP/s.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
e, asc = s["eigenvalues_by_magnitude"], s["eigenvalues"]
want = [0, 1, -2, 2, -3, 3, -4, 4, -5, 5, -6]
want = want[:11 if len(e) == 144 else 6]
assert asc == sorted(asc) and sorted(e) == asc and len(e) == sum(4 * abs(n + 1) for n in want), "eigenvalues: wrong count or not ascending"
groups = []
for x in e:
    n = round(x)
    if not groups or groups[-1][0] != n: groups.append((n, []))
    groups[-1][1].append(x)
bad = 0
for i, n in enumerate(want):
    gn, v = groups[i]
    err = max(abs(x - n) for x in v) / max(abs(n), 1)
    ok = gn == n and len(v) == 4 * abs(n + 1) and (i >= 5 or err <= 0.02)
    print(("ok  " if ok else "BAD ") + "n=%d: %d values %.5f..%.5f (want multiplicity %d), rel. error %.4f" % (n, len(v), min(v), max(v), 4 * abs(n + 1), err))
    bad += not ok
ok = s["kernel_dimension"] == 4
print(("ok  " if ok else "BAD ") + "kernel dimension %d (constants)" % s["kernel_dimension"]); bad += not ok
q = s["reconstruct_q_max"][0]
ok = q - 1 < 1e-6
print(("ok  " if ok else "BAD ") + "ground state Dirac sphere q_max - 1 = %.2e" % (q - 1)); bad += not ok
sys.exit(bad)
PY
test -s "$TMP/ds_0.obj" && test -s "$TMP/ds_4.obj" && echo "ok  Dirac spheres written"
if [ "$NP" = 1 ]; then
  timeout 60 "$CS_BIN" -task spectrum -gen icosphere -gen_level 2 -spectrum_signed -spectrum_nev 52 -summary "$TMP/s2.json" > /dev/null
  python3 - "$TMP/s2.json" "$TMP/s.json" <<'PY'
import json, math, sys
def errors(f):
    e = sorted(json.load(open(f))["eigenvalues_by_magnitude"], key=abs)
    out, k = {}, 0
    for n in (0, 1, -2, 2, -3, 3):
        v = e[k:k + 4 * abs(n + 1)]; k += len(v)
        if n: out[n] = max(abs(x - n) for x in v) / abs(n)
    return out
e2, e3 = errors(sys.argv[1]), errors(sys.argv[2])
bad = 0
for n in e2:
    p = math.log2(e2[n] / e3[n])
    ok = 1.8 <= p <= 2.3
    print(("ok  " if ok else "BAD ") + "n=%d: rel. error level 2 %.4f, level 3 %.4f, observed order %.2f" % (n, e2[n], e3[n], p)); bad += not ok
sys.exit(bad)
PY
fi
EXPECT="-spectrum_reconstruct 20: eigenvectors 0..19 are computed" expect_fail timeout 60 $MPIEXEC "$CS_BIN" -task spectrum -gen icosphere -gen_level 1 -spectrum_signed -spectrum_nev 20 -spectrum_reconstruct 20
