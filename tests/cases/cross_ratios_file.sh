# Issue 15 item 6: a conformal class from a file of log length cross ratios (-mesh_cross_ratios FILE, lines "i j c0",
# 1-based vertices as in OBJ, one line per interior edge; src/mesh/meshdata_cross_ratios.c).
# (a) round trip: a bumpy torus (8 x 5) written as OBJ, its own cross ratios written by cross_ratio_tools.py and read
#     back: the flow from df is unchanged (cgd 5 iterations and trianglefield 3 iterations: W identical to 1e-10
#     relative, conformal violation identical). The same with the faces reversed in the file: the mesh is flipped to
#     outward orientation on reading and c0 must change sign with it (a missing sign flip gives a violation O(1)).
# (b) bad input (the non-number on the test's ranks, the others serially), one line naming the file (and the line): wrong count, not an edge, a duplicate, a non-number, a
#     non-integer vertex, a c0 outside im C (one value moved by 1e-3), -mesh_lengths with it, -mesh_refine with it.
# nprocs: 1 2
source tests/lib.sh
T=$TMP
"$CS_BIN" -task flow -gen torus -gen_n 8 -gen_m 5 -gen_deform_bump 0.2 -flow_max_it 0 -o "$T/t.obj" > "$T/g.log" 2>&1 || { tail "$T/g.log"; exit 1; }
python3 tests/cases/cross_ratio_tools.py write "$T/t.obj" "$T/t.cr"
python3 tests/cases/cross_ratio_tools.py write "$T/t.obj" "$T/f.cr" --flip
run() { # name, args...
  local n=$1; shift
  timeout 120 $MPIEXEC "$CS_BIN" -task flow "$@" -summary "$T/$n.json" > "$T/$n.log" 2>&1 || { tail "$T/$n.log"; exit 1; }
}
run cgd0 -mesh "$T/t.obj" -flow_max_it 5
run cgd1 -mesh "$T/t.obj" -mesh_cross_ratios "$T/t.cr" -flow_max_it 5
run tf0 -mesh "$T/t.obj" -flow_type trianglefield -flow_max_it 3
run tf1 -mesh "$T/t.obj" -mesh_cross_ratios "$T/t.cr" -flow_type trianglefield -flow_max_it 3
run tff -mesh "$T/f.cr.obj" -mesh_cross_ratios "$T/f.cr" -flow_type trianglefield -flow_max_it 3
grep -q "flipped to outward" "$T/tff.log" || { echo "BAD: the reversed file was not flipped"; exit 1; }
python3 - "$T" <<'PY'
import json, sys
d = sys.argv[1]; L = lambda n: json.load(open(d + '/' + n + '.json'))
bad = 0
for a, b, what in (('cgd0', 'cgd1', 'cgd'), ('tf0', 'tf1', 'trianglefield'), ('tf0', 'tff', 'trianglefield, reversed file')):
  x, y = L(a), L(b)
  dW = abs(x['energy'] - y['energy']) / abs(x['energy']); dc = abs(x['conformal_violation'] - y['conformal_violation'])
  ok = dW < 1e-10 and dc < 1e-10
  print(("ok  " if ok else "BAD ") + "%s: W from df %.15g, with the cross-ratio file %.15g (relative %.1e), violation %.3e / %.3e" % (what, x['energy'], y['energy'], dW, x['conformal_violation'], y['conformal_violation']))
  bad += not ok
sys.exit(bad)
PY
B=$T/bad
sed '$d' "$T/t.cr" > "$B.count"
(sed '3d' "$T/t.cr"; sed -n 2p "$T/t.cr") > "$B.dup"
sed '3s/.*/1 30 0.1/' "$T/t.cr" > "$B.notedge"
sed '3s/ [^ ]*$/ abc/' "$T/t.cr" > "$B.nan"
sed '3s/^\([0-9]*\) /\1.5 /' "$T/t.cr" > "$B.frac"
awk 'NR==3{$3=$3+1e-3} {print}' "$T/t.cr" > "$B.im"
M="-task flow -mesh $T/t.obj -flow_max_it 0 -mesh_cross_ratios"
EXPECT="bad.nan: line 3: not a finite number: 'abc'" expect_fail $MPIEXEC "$CS_BIN" $M "$B.nan"
# the reader runs on rank 0 and fails through the same path for every case: the others serially only (time)
[ "$NP" = 1 ] || { echo "cross_ratios_file: all checks passed"; exit 0; }
EXPECT="bad.count: 119 lines, expected one per interior edge.*120" expect_fail $MPIEXEC "$CS_BIN" $M "$B.count"
EXPECT="bad.dup: line [0-9]+: the edge .* is given twice \(first on line 2\)" expect_fail $MPIEXEC "$CS_BIN" $M "$B.dup"
EXPECT="bad.notedge: line 3: \(1, 30\) is not an edge" expect_fail $MPIEXEC "$CS_BIN" $M "$B.notedge"
EXPECT="bad.frac: line 3: vertex [0-9]+\.5 is not an integer" expect_fail $MPIEXEC "$CS_BIN" $M "$B.frac"
EXPECT="bad.im: .*outside im C .* above -mesh_cross_ratios_tol" expect_fail $MPIEXEC "$CS_BIN" $M "$B.im"
EXPECT="mesh_lengths with -mesh_cross_ratios" expect_fail $MPIEXEC "$CS_BIN" $M "$T/t.cr" -mesh_lengths "$T/t.cr"
EXPECT="mesh_refine with -mesh_cross_ratios" expect_fail $MPIEXEC "$CS_BIN" $M "$T/t.cr" -mesh_refine 1
echo "cross_ratios_file: all checks passed"
