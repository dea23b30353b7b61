# Islands (bobenko-schroeder2005 Sec. 3.3, Fig. 11): -bs_islands FILE of vertex (or, with -bs_islands_type face,
# face) indices held fixed with their one-ring, as the boundary strip of the G1 condition. A noisy level-2
# icosphere (-bs_perturb) flows 8 steps: the masked vertices and their rings are bit-identical to the input
# (the OBJ writer round-trips doubles), the others move, W falls. Indices out of range or not integers: a clear
# error naming the option, file and line. The summary's W_i + K_i (Sec. 2) is >= 0 at every vertex.
# nprocs: 1 2
source tests/lib.sh
$MPIEXEC "$CS_BIN" -task info -gen icosphere -gen_level 2 -o "$TMP/in.obj" > /dev/null
printf '# two islands\n0 5\n17\n' > "$TMP/v.txt"
printf '3, 40\n' > "$TMP/f.txt"
run() { $MPIEXEC "$CS_BIN" -task flow -flow_type bs -mesh "$TMP/in.obj" -bs_perturb 0.1 -bs_max_it 8 -bs_monotone false "$@"; }
run -bs_islands "$TMP/v.txt" -o "$TMP/v.obj" -summary "$TMP/v.json" -history_csv "$TMP/v.csv" | tail -1
run -bs_islands "$TMP/f.txt" -bs_islands_type face -o "$TMP/f.obj" -summary "$TMP/f.json" -history_csv "$TMP/f.csv" | tail -1
python3 - "$TMP" <<'PY'
import json, sys, math
sys.path.insert(0, "tests/data")
from bs_make_meshes import read_obj as obj
d = sys.argv[1]
V0, F = obj(d + "/in.obj")
bad = 0
def ring(seeds):
    r = set(seeds)
    for f in F:
        if any(v in seeds for v in f): r.update(f)
    return r
for name, seeds in (("v", {0, 5, 17}), ("f", set(F[3]) | set(F[40]))):
    V1, _ = obj(d + "/%s.obj" % name)
    s = json.load(open(d + "/%s.json" % name))
    R = ring(seeds)
    W = [float(l.split(",")[1]) for l in list(open(d + "/%s.csv" % name))[1:]]
    checks = [(s["fixed_vertices"] == len(R), "%s: %d fixed vertices = islands + one-ring %d" % (name, s["fixed_vertices"], len(R))),
              (all(V0[i] == V1[i] for i in R), "%s: islands and rings bit-identical" % name),
              (min(math.dist(V0[i], V1[i]) for i in range(len(V0)) if i not in R) > 0, "%s: every other vertex moved" % name),
              (W[-1] < 0.1 * W[0], "%s: W %.4g -> %.4g" % (name, W[0], W[-1])),
              (s["w_plus_k_negative"] == 0 and s["w_plus_k_min"] >= -1e-10, "%s: W_i + K_i >= 0 at every vertex (min %.3g; Sec. 2)" % (name, s["w_plus_k_min"]))]
    for ok, msg in checks:
        print(("ok  " if ok else "BAD ") + msg); bad += not ok
sys.exit(bad)
PY
printf '1\n2 162\n' > "$TMP/bad.txt"
EXPECT="-bs_islands .*bad.txt: line 2: 162 is not a vertex index in 0..161" expect_fail run -bs_islands "$TMP/bad.txt"
[ "$NP" = 1 ] || exit 0 # the rest reads on rank 0 as above: once is enough
printf '1 2.5\n' > "$TMP/frac.txt"
EXPECT="-bs_islands .*frac.txt: line 1: 2.5 is not a face index in 0..319" expect_fail run -bs_islands "$TMP/frac.txt" -bs_islands_type face
EXPECT="-bs_islands .*x.txt: line 1: not a finite number" expect_fail bash -c "printf '1 x\n' > $TMP/x.txt; $MPIEXEC $CS_BIN -task flow -flow_type bs -mesh $TMP/in.obj -bs_islands $TMP/x.txt"
EXPECT="-bs_islands needs -bs_boundary fixed" expect_fail run -bs_islands "$TMP/v.txt" -bs_boundary free
