# OBJ -> PLY -> OBJ through the distributed mesh is exact (positions and faces, in file order).
# nprocs: 1 2
source tests/lib.sh
$MPIEXEC "$CS_BIN" -task info -mesh meshes/bunny_lowres_npm.obj -o "$TMP/a.ply" >/dev/null
$MPIEXEC "$CS_BIN" -task info -mesh "$TMP/a.ply" -o "$TMP/b.obj" >/dev/null
$MPIEXEC "$CS_BIN" -task info -gen torus -gen_n 12 -gen_m 7 -o "$TMP/t.obj" >/dev/null
$MPIEXEC "$CS_BIN" -task info -mesh "$TMP/t.obj" -o "$TMP/t.ply" >/dev/null
$MPIEXEC "$CS_BIN" -task info -mesh "$TMP/t.ply" -o "$TMP/t2.obj" >/dev/null
python3 - meshes/bunny_lowres_npm.obj "$TMP/b.obj" "$TMP/t.obj" "$TMP/t2.obj" <<'PY'
import sys
def read(p):
    v, f = [], []
    for line in open(p):
        t = line.split()
        if not t: continue
        if t[0] == 'v': v.append(tuple(float(x) for x in t[1:4]))
        if t[0] == 'f': f.append(tuple(int(x.split('/')[0]) for x in t[1:4]))
    return v, f
bad = 0
for a, b in ((sys.argv[1], sys.argv[2]), (sys.argv[3], sys.argv[4])):
    va, fa = read(a); vb, fb = read(b)
    same = va == vb and fa == fb
    print(("ok  " if same else "BAD ") + f"{a} vs {b}: {len(va)} vertices, {len(fa)} faces, bitwise equal = {same}")
    bad += not same
sys.exit(bad)
PY
