# -mesh_refine n, -mesh_refine_type loop|midpoint (src/mesh/meshdata_refine.c; docs/real_meshes.md section 0):
# (a) one refinement of eight_cgal (genus 2) gives V + E vertices, 2E + 3F edges, 4F faces and the same genus, for
#     both types; midpoint keeps the piecewise-flat surface (same area and volume to 1e-12), Loop smooths it (less area);
# (b) two midpoint refinements of the unprojected icosphere of level 1 are the unprojected icosphere of level 3
#     (the generator's own split: same counts, area and W to 1e-12);
# (c) the test of the hypothesis "the real meshes are too coarse": the default CGD on eight_cgal refined once
#     (Loop) still stops at the resolution guard, not converged, W lowered, the violation under the ceiling at every
#     iteration (the summary key violation_max equals the largest violation of the history), and its final line
#     states the violation, the largest of the run and the EL residual;
# (d) bad values refused on every rank.
# nprocs: 1 2
source tests/lib.sh
M=meshes/eight_cgal.obj
counts() { sed -n 's/.*V=\([0-9]*\) E=\([0-9]*\) F=\([0-9]*\) genus=\([0-9]*\).*/\1 \2 \3 \4/p' "$1" | head -1; }
$MPIEXEC "$CS_BIN" -task info -mesh $M -summary "$TMP/c.json" > "$TMP/c.log" || exit 1
read V E F G < <(counts "$TMP/c.log")
for t in loop midpoint; do
  $MPIEXEC "$CS_BIN" -task info -mesh $M -mesh_refine 1 -mesh_refine_type $t -summary "$TMP/$t.json" > "$TMP/$t.log" || exit 1
  read v e f g < <(counts "$TMP/$t.log")
  [ "$v $e $f $g" = "$((V + E)) $((2 * E + 3 * F)) $((4 * F)) $G" ] || { echo "FAIL: $t refinement: V E F genus $v $e $f $g from $V $E $F $G"; exit 1; }
  echo "ok   $t: V $V -> $v, E $E -> $e, F $F -> $f, genus $g"
done
check_close "$(json area "$TMP/midpoint.json")" "$(json area "$TMP/c.json")" 1e-12 "midpoint refinement keeps the area:" || exit 1
check_close "$(json volume "$TMP/midpoint.json")" "$(json volume "$TMP/c.json")" 1e-12 "midpoint refinement keeps the volume:" || exit 1
python3 -c "import sys; a, a0 = float(sys.argv[1]), float(sys.argv[2]); print(('ok   ' if a < a0 else 'FAIL ') + 'Loop smooths: area %.6f < %.6f' % (a, a0)); sys.exit(0 if a < a0 else 1)" "$(json area "$TMP/loop.json")" "$(json area "$TMP/c.json")" || exit 1
I="-task info -gen icosphere -gen_project false"
$MPIEXEC "$CS_BIN" $I -gen_level 1 -mesh_refine 2 -mesh_refine_type midpoint -summary "$TMP/i1.json" > "$TMP/i1.log" || exit 1
$MPIEXEC "$CS_BIN" $I -gen_level 3 -summary "$TMP/i3.json" > "$TMP/i3.log" || exit 1
[ "$(counts "$TMP/i1.log")" = "$(counts "$TMP/i3.log")" ] || { echo "FAIL: icosphere counts $(counts "$TMP/i1.log") vs $(counts "$TMP/i3.log")"; exit 1; }
check_close "$(json area "$TMP/i1.json")" "$(json area "$TMP/i3.json")" 1e-12 "icosphere level 1 refined twice = level 3, area:" || exit 1
check_close "$(json willmore "$TMP/i1.json")" "$(json willmore "$TMP/i3.json")" 1e-12 "icosphere level 1 refined twice = level 3, W:" || exit 1
# (c) serially only (50 CGD iterations on 3.8k faces; the refinement itself is checked on every rank count above)
if [ "$NP" = 1 ]; then
timeout 200 $MPIEXEC "$CS_BIN" -task flow -mesh $M -mesh_refine 1 -flow_max_it 150 -summary "$TMP/f.json" -history_csv "$TMP/f.csv" > "$TMP/f.log" 2>&1 || { tail -3 "$TMP/f.log"; exit 1; }
[ "$(json stop_reason "$TMP/f.json")" = mesh_degenerate ] && [ "$(json converged "$TMP/f.json")" = False ] || { echo "FAIL: refined eight_cgal: $(json stop_reason "$TMP/f.json")"; tail -3 "$TMP/f.log"; exit 1; }
grep -qE "flow cgd: NOT converged after .*; conformal violation [0-9.e+-]+, constraint violation [0-9.e+-]+ \(largest violation of the run [0-9.e+-]+\), EL residual [0-9.e+-]+" "$TMP/f.log" || { echo "FAIL: the final line does not state the violation"; tail -2 "$TMP/f.log"; exit 1; }
python3 - "$TMP/f.csv" "$(json energy_initial "$TMP/f.json")" "$(json willmore "$TMP/f.json")" "$(json violation_max "$TMP/f.json")" <<'PY' || exit 1
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
vmax = max(float(r["conformal_violation"]) for r in rows)
w0, w, vsum = float(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4])
ok = vmax <= 1e-2 and w < w0 and abs(vsum - vmax) <= 1e-12 * vmax  # the summary's violation_max is the history's largest
print(("ok   " if ok else "FAIL ") + "refined eight_cgal: stops at the guard after %d iterations, W %.4f -> %.4f, largest violation %.2e (ceiling 1e-2)" % (len(rows) - 1, w0, w, vmax))
sys.exit(0 if ok else 1)
PY
fi
# (d)
EXPECT="-mesh_refine 7: not in \[0, 6\]" expect_fail "$CS_BIN" -task info -mesh $M -mesh_refine 7
EXPECT="-mesh_refine -1: not in \[0, 6\]" expect_fail $MPIEXEC "$CS_BIN" -task info -mesh $M -mesh_refine -1
EXPECT="-mesh_refine_type" expect_fail "$CS_BIN" -task info -mesh $M -mesh_refine 1 -mesh_refine_type cubic
