# Quasi-conformal error (crane2011 Sec. 6.1) against -reference: 1 for the same mesh and for a similarity;
# exactly 2 on every face of a flat disk stretched by 2 along x (the affine map diag(2,1)).
# nprocs: 1 2
source tests/lib.sh
$MPIEXEC "$CS_BIN" -gen disk -gen_rings 6 -o "$TMP/disk.obj" >/dev/null
python3 - "$TMP" <<'PY'
import sys, math
d = sys.argv[1]
lines = open(f"{d}/disk.obj").read().splitlines()
def xform(fn, out):
    with open(out, "w") as f:
        for l in lines:
            t = l.split()
            if t and t[0] == "v":
                x, y, z = map(float, t[1:4]); x, y, z = fn(x, y, z)
                f.write(f"v {x!r} {y!r} {z!r}\n")
            else:
                f.write(l + "\n")
c, s = math.cos(0.3), math.sin(0.3)
xform(lambda x, y, z: (2 * x, y, z), f"{d}/stretched.obj")
xform(lambda x, y, z: (3 * (c * x - s * z) + 1, 3 * y - 2, 3 * (s * x + c * z)), f"{d}/similar.obj")
PY
for case in "disk.obj 1" "similar.obj 1" "stretched.obj 2"; do
  set -- $case
  $MPIEXEC "$CS_BIN" -mesh "$TMP/$1" -reference "$TMP/disk.obj" -summary "$TMP/q.json" >/dev/null
  check_close "$(json q_mean "$TMP/q.json")" "$2" 1e-12 "q_mean $1"
  check_close "$(json q_max "$TMP/q.json")" "$2" 1e-12 "q_max $1"
done
