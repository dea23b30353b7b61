# crane2011 Sec. 7.1 / Fig. 20: rho from a normal displacement g of a flat disk (-rho_from_displacement, rho = Delta g
# in the paper, (L g) / (2 M) in this code's units of rho) reproduces f + g N to first order: the distance of the
# result to the displaced surface (point to surface, after the best similarity fit) shrinks at least at second
# order in the amplitude of g (measured: order ~3 between amplitudes 0.32 and 0.16 on a 24-ring disk; a wrong
# factor 1/2 or 2 in rho gives order ~1 or a distance of the size of the bump). At small amplitudes a
# discretisation error O(h^2 amplitude) is left (docs/spin_applications.md). -rho_smooth t (heat filter, Fig. 13)
# lowers the peak of rho; a bad t is refused.
# nprocs: 1 2
source tests/lib.sh
PY=$(bash scripts/find-python.sh)
$MPIEXEC "$CS_BIN" -task info -gen disk -gen_rings 24 -o "$TMP/disk.obj" > /dev/null
for e in 0.32 0.16; do
  $PY tests/cases/spin_displacement_tool.py make "$TMP/disk.obj" $e "$TMP/g$e.txt" "$TMP/t$e.obj"
  $MPIEXEC "$CS_BIN" -task spin -mesh "$TMP/disk.obj" -rho_from_displacement "$TMP/g$e.txt" -o "$TMP/r$e.obj" -summary "$TMP/s$e.json" > /dev/null
  $PY tests/cases/spin_displacement_tool.py distance "$TMP/r$e.obj" "$TMP/t$e.obj" > "$TMP/d$e"
done
python3 - "$(cat "$TMP/d0.32")" "$(cat "$TMP/d0.16")" <<'PY'
import sys, math
d1, d2 = float(sys.argv[1]), float(sys.argv[2])
order = math.log2(d1 / d2)
bad = 0
for ok, msg in ((order >= 1.8, "distance %.3e at amplitude 0.32, %.3e at 0.16: order %.2f (>= 1.8)" % (d1, d2, order)),
                (d2 < 0.05 * 0.16, "distance at 0.16 is %.1f %% of the amplitude (< 5 %%)" % (100 * d2 / 0.16))):
    print(("ok  " if ok else "BAD ") + msg); bad += not ok
sys.exit(bad)
PY
$MPIEXEC "$CS_BIN" -task spin -mesh "$TMP/disk.obj" -rho_from_displacement "$TMP/g0.16.txt" -rho_smooth 0.01 -summary "$TMP/sm.json" > /dev/null
python3 -c "
import json, sys
a, b = json.load(open('$TMP/s0.16.json')), json.load(open('$TMP/sm.json'))
ok = 0 < b['rho_max'] < 0.8 * a['rho_max']
print(('ok  ' if ok else 'BAD ') + 'rho_smooth 0.01: rho_max %.4g -> %.4g' % (a['rho_max'], b['rho_max'])); sys.exit(not ok)"
[ "$NP" = 1 ] || exit 0 # the checks below run on rank 0 / before any parallel work
EXPECT="-rho_smooth -1: must be a positive time" expect_fail $MPIEXEC "$CS_BIN" -task spin -mesh "$TMP/disk.obj" -rho_from_displacement "$TMP/g0.16.txt" -rho_smooth -1
EXPECT="-rho_from_displacement .*short.txt: 3 values, expected" expect_fail bash -c "printf '1 2 3' > $TMP/short.txt; $MPIEXEC $CS_BIN -task spin -mesh $TMP/disk.obj -rho_from_displacement $TMP/short.txt"
