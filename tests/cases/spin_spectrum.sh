# crane2011 Sec. 6.2 / Fig. 8: on the unit sphere the Dirac eigenvalues are n in Z (n != -1) with
# multiplicity |n+1|, so the square roots of the spectrum of Eq. 7 cluster at 0, 1, 2, 3 with real
# multiplicities 4, 8, 16, 24 (4 real per quaternionic). Level-3 icosphere (1280 faces), each within 2 %.
# nprocs: 1 2
source tests/lib.sh
timeout 60 $MPIEXEC "$CS_BIN" -task spectrum -gen icosphere -gen_level 3 -spectrum_nev 52 -summary "$TMP/s.json"
python3 - "$TMP/s.json" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
e = s["eigenvalues"]; r = s["eigenvalues_sqrt"]
assert len(e) == 52 and e == sorted(e), "eigenvalues not 52 and ascending"
bad = 0; i = 0
for n, m in ((0, 4), (1, 8), (2, 16), (3, 24)):
    grp = r[i:i + m]; i += m
    ok = all(abs(x - n) <= (0.02 if n == 0 else 0.02 * n) for x in grp)
    print(("ok  " if ok else "BAD ") + "sqrt eigenvalues %d..%d: %.5f .. %.5f (expected %d, mult %d)" % (i - m, i - 1, min(grp), max(grp), n, m))
    bad += not ok
sys.exit(bad)
PY
