# Issue 5 boundaries (bobenko-schroeder2005 Sec. 3.3). G1 (-bs_boundary fixed): a sphere cap whose inside
# was pressed flat (tests/data/bs_cap_flat.obj) is filled back to the sphere (W < 1e-6) while the boundary
# and its one-ring stay bit-identical (the OBJ writer round-trips doubles exactly). Free boundary (vertex at
# infinity): a noisy hemisphere flows with finite positions and decreasing W. Bad options fail cleanly.
# nprocs: 1 2
source tests/lib.sh
$MPIEXEC "$CS_BIN" -task flow -flow_type bs -mesh tests/data/bs_cap_flat.obj -bs_boundary fixed -summary "$TMP/fix.json" -o "$TMP/fix.obj" | tail -2
$MPIEXEC "$CS_BIN" -task flow -flow_type bs -mesh tests/data/bs_cap_noisy.obj -bs_boundary free -bs_max_it 25 -summary "$TMP/free.json" -history_csv "$TMP/free.csv" -o "$TMP/free.obj" | tail -2
python3 - "$TMP" <<'PY'
import json, sys, math
sys.path.insert(0, "tests/data")
from bs_make_meshes import read_obj as obj, boundary_and_ring  # the generator's own definitions
d = sys.argv[1]
bad = 0
def chk(ok, msg):
    global bad
    print(("ok  " if ok else "BAD ") + msg)
    bad += 0 if ok else 1
V0, F = obj("tests/data/bs_cap_flat.obj")
V1, _ = obj(d + "/fix.obj")
_, ring = boundary_and_ring(V0, F)
s = json.load(open(d + "/fix.json"))
chk(s["fixed_vertices"] == len(ring), "fixed: %d fixed vertices = boundary + one-ring %d" % (s["fixed_vertices"], len(ring)))
chk(all(V0[i] == V1[i] for i in ring), "fixed: boundary and one-ring bit-identical")
moved = max(math.dist(V0[i], V1[i]) for i in range(len(V0)) if i not in ring)
chk(moved > 0.05, "fixed: free vertices moved (max %.3g)" % moved)
chk(s["willmore_bs"] < 1e-6, "fixed: flat fill restored to the sphere, W=%g" % s["willmore_bs"])
r = [math.dist(v, (0, 0, 0)) for v in V1]
chk(max(abs(x - 1) for x in r) < 1e-3, "fixed: every vertex back on the unit sphere (max |r-1| %.2e)" % max(abs(x - 1) for x in r))
for name in ("free",):
    s = json.load(open(d + "/%s.json" % name))
    V, _ = obj(d + "/%s.obj" % name)
    W = [float(l.split(",")[1]) for l in list(open(d + "/%s.csv" % name))[1:] if l.count(",") >= 6]
    chk(s["boundary"] == "free" and s["fixed_vertices"] == 0, name + ": free boundary, nothing fixed")
    chk(all(math.isfinite(c) for v in V for c in v) and max(abs(c) for v in V for c in v) < 1e3, name + ": positions finite")
    chk(s["willmore_bs"] is not None and 0 <= W[-1] < W[0] and all(W[i + 1] <= W[i] for i in range(len(W) - 1)), name + ": W decreases %.4g -> %.4g, stays >= 0" % (W[0], W[-1]))
sys.exit(bad)
PY
EXPECT="bs_boundary" expect_fail $MPIEXEC "$CS_BIN" -task flow -flow_type bs -gen icosphere -gen_level 1 -bs_boundary sideways
EXPECT="bs_beta_eps" expect_fail $MPIEXEC "$CS_BIN" -task flow -flow_type bs -gen icosphere -gen_level 1 -bs_beta_eps -1
EXPECT="bs_dt" expect_fail $MPIEXEC "$CS_BIN" -task flow -flow_type bs -gen icosphere -gen_level 1 -bs_dt -2
EXPECT="bs_scheme" expect_fail $MPIEXEC "$CS_BIN" -task flow -flow_type bs -gen icosphere -gen_level 1 -bs_scheme explicit
EXPECT="bs_tao_typo" expect_fail $MPIEXEC "$CS_BIN" -task flow -flow_type bs -gen icosphere -gen_level 1 -bs_scheme semi -bs_tao_typo 3
