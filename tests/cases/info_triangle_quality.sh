# -task info's triangle quality (src/geometry/triangle_quality.c; docs/remeshing.md), distributed, against values
# derived without the code: (a) the icosahedron (-gen icosphere -gen_level 0) and the unprojected level-2 icosphere
# (each face of the icosahedron split into 16 equilateral triangles) are all equilateral: min angle 60 deg, no obtuse
# face, no non-Delaunay edge (opposite angles sum to 120 deg), every edge-length ratio 1; (b) cow_cgal (slivers):
# every quality key equals an independent computation in Python from the OBJ file (angles by atan2, an interior edge
# non-Delaunay when its two opposite angles sum above pi); on 2 ranks the same numbers (reductions).
# nprocs: 1 2
source tests/lib.sh
for g in "-gen_level 0" "-gen_level 2 -gen_project false"; do
  $MPIEXEC "$CS_BIN" -task info -gen icosphere $g -summary "$TMP/i.json" > "$TMP/i.log" || { cat "$TMP/i.log"; exit 1; }
  check_close "$(json quality_min_angle_deg "$TMP/i.json")" 60 1e-9 "icosphere $g: min angle" || exit 1
  check_close "$(json quality_obtuse_share "$TMP/i.json")" 0 0 "icosphere $g: obtuse share" || exit 1
  check_close "$(json quality_nondelaunay_share "$TMP/i.json")" 0 0 "icosphere $g: non-Delaunay share" || exit 1
  check_close "$(json quality_edge_ratio "$TMP/i.json")" 1 1e-9 "icosphere $g: edge ratio" || exit 1
  check_close "$(json quality_face_edge_ratio_max "$TMP/i.json")" 1 1e-9 "icosphere $g: face edge ratio" || exit 1
  grep -q "^triangle quality: min angle 60 deg, obtuse faces 0.00 %, non-Delaunay edges 0.00 %" "$TMP/i.log" || { echo "FAIL: the printed line"; grep quality "$TMP/i.log"; exit 1; }
done
$MPIEXEC "$CS_BIN" -task info -mesh meshes/cow_cgal.obj -summary "$TMP/c.json" > "$TMP/c.log" || { cat "$TMP/c.log"; exit 1; }
python3 - meshes/cow_cgal.obj "$TMP/c.json" <<'PY' || exit 1
import json, math, sys
V, F = [], []
for line in open(sys.argv[1]):
    t = line.split()
    if t and t[0] == "v": V.append([float(c) for c in t[1:4]])
    if t and t[0] == "f": F.append([int(c.split("/")[0]) - 1 for c in t[1:4]])
def sub(a, b): return [a[i] - b[i] for i in range(3)]
def angle(o, p, q):
    u, v = sub(V[p], V[o]), sub(V[q], V[o])
    c = [u[1]*v[2]-u[2]*v[1], u[2]*v[0]-u[0]*v[2], u[0]*v[1]-u[1]*v[0]]
    return math.atan2(math.sqrt(sum(x*x for x in c)), sum(u[i]*v[i] for i in range(3)))
def length(a, b): return math.sqrt(sum(x*x for x in sub(V[a], V[b])))
amin, obtuse, fratio, opp, lens = math.pi, 0, 1.0, {}, {}
for f in F:
    ang = [angle(f[k], f[(k+1) % 3], f[(k+2) % 3]) for k in range(3)]
    amin, obtuse = min(amin, min(ang)), obtuse + (max(ang) > math.pi / 2)
    l = [length(f[(k+1) % 3], f[(k+2) % 3]) for k in range(3)]   # l[k]: the edge opposite corner k
    fratio = max(fratio, max(l) / min(l))
    for k in range(3):
        e = tuple(sorted((f[(k+1) % 3], f[(k+2) % 3])))
        opp.setdefault(e, []).append(ang[k]); lens[e] = l[k]
inner = [a for a in opp.values() if len(a) == 2]
want = {"quality_min_angle_deg": math.degrees(amin), "quality_obtuse_share": obtuse / len(F),
        "quality_nondelaunay_share": sum(a[0] + a[1] > math.pi for a in inner) / len(inner),
        "quality_edge_ratio": max(lens.values()) / min(lens.values()), "quality_face_edge_ratio_max": fratio}
got = json.load(open(sys.argv[2]))
bad = [k for k in want if abs(got[k] - want[k]) > 1e-9 * max(1, abs(want[k]))]
for k in want: print(("FAIL " if k in bad else "ok   ") + "cow %s: %.12g (independent: %.12g)" % (k, got[k], want[k]))
sys.exit(1 if bad else 0)
PY
