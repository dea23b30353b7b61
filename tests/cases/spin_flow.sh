# crane2011 Sec. 7.3 / Fig. 16, 17: the conformal Willmore flow on a disk, rho(t) = -t H, as -spin_flow_steps N
# spin transformations with rho = -tau H of the current surface and the boundary tangents kept (Sec. 5.7). A
# spherical cap (polar angle 1.2, a lifted 12-ring disk) flattens toward the minimal surface spanning its
# boundary circle: the scale-free area / boundary length^2 falls at every step toward 1/(4 pi) (the flat disk;
# the eigenvector's normalisation keeps the area, the boundary grows), with q_mean against the input bounded
# (< 1.05). One step with tau = 1 (rho = -H) reaches 1/(4 pi) within 0.5 %. A closed mesh is refused.
# nprocs: 1 2
source tests/lib.sh
$MPIEXEC "$CS_BIN" -task info -gen disk -gen_rings 12 -o "$TMP/disk.obj" > /dev/null
python3 - "$TMP/disk.obj" "$TMP/cap.obj" <<'PY'
import sys, math
V, F = [], []
for l in open(sys.argv[1]):
    s = l.split()
    if s and s[0] == "v": V.append([float(c) for c in s[1:4]])
    if s and s[0] == "f": F.append([c.split("/")[0] for c in s[1:4]])  # the disk has UVs (f v/vt): positions only here
with open(sys.argv[2], "w") as fp:
    for x, y, z in V:
        t, ph = 1.2 * math.hypot(x, y), math.atan2(y, x)
        fp.write("v %.17g %.17g %.17g\n" % (math.sin(t) * math.cos(ph), math.sin(t) * math.sin(ph), math.cos(t)))
    fp.writelines("f %s %s %s\n" % tuple(f) for f in F)
PY
$MPIEXEC "$CS_BIN" -task spin -mesh "$TMP/cap.obj" -spin_flow_steps 4 -spin_flow_tau 0.25 -history_csv "$TMP/h.csv" -summary "$TMP/s.json" > /dev/null
$MPIEXEC "$CS_BIN" -task spin -mesh "$TMP/cap.obj" -spin_flow_steps 1 -spin_flow_tau 1 -summary "$TMP/one.json" > /dev/null
python3 - "$TMP" <<'PY'
import sys, json, math
d = sys.argv[1]
rows = [[float(c) for c in l.split(",")] for l in list(open(d + "/h.csv"))[1:]]
r, q = [row[3] for row in rows], [row[4] for row in rows]
one = json.load(open(d + "/one.json"))["flow_area_over_length2"]
bad = 0
for ok, msg in ((len(r) == 5 and all(r[i + 1] < r[i] for i in range(4)), "area/length^2 falls: " + " ".join("%.5f" % x for x in r)),
                (r[-1] < 0.09, "after 4 steps %.5f (flat disk %.5f)" % (r[-1], 1 / (4 * math.pi))),
                (max(q) < 1.05, "q_mean bounded: max %.4f" % max(q)),
                (abs(one * 4 * math.pi - 1) < 5e-3, "one step rho = -H: %.6f vs 1/(4 pi) %.6f" % (one, 1 / (4 * math.pi)))):
    print(("ok  " if ok else "BAD ") + msg); bad += not ok
sys.exit(bad)
PY
[ "$NP" = 1 ] || exit 0
EXPECT="-spin_flow_steps: mesh .* has no boundary" expect_fail "$CS_BIN" -task spin -gen icosphere -gen_level 1 -spin_flow_steps 2
