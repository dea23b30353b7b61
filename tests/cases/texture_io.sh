# Texture coordinates in and out (issue 38; docs/textures.md, "Reading and writing UVs"):
# (a) a sphere with a UV seam (tests/data/uv_sphere_seam.obj: 89 vt, seam vertices with two UVs, per-face UVs at the
#     poles) through -task info, cgd, the conformal flow, spin, bs and the triangle-field flow keeps in -o its vt list
#     and every face's v/vt indices as read, compared textually (the flows moved every vertex);
# (b) a checkpointed cgd run resumed (the resume rereads -mesh) writes the same vt and f lines;
# (c) PLY: OBJ -> PLY (the face list texcoord, seams) -> OBJ keeps every corner's UV (as text); the per-vertex s t of
#     tests/data/tetra_uv_vertex.ply are written as vertex u v and read back the same; texcoord wins over texture_u v;
#     an inward copy of the sphere is flipped outward with each corner's UV;
# (d) -mesh_refine 1 (midpoint and loop): every new corner's UV is the mean of its edge's two corner UVs in that face
#     (so a seam edge gets two, one per side), the old corners keep theirs;
# (e) -mesh_remesh of a textured input refused; -o_input .off warns that it drops the UVs;
# (f) bad vt/texcoord input refused with the file and line, one error line, non-zero exit on every rank;
# (g) NP=1: the unit program test_texture_io (the same in memory, and validation's refusals).
# Under 2 ranks (a), (b), (d) midpoint, (e) remesh and two of (f): the gather to rank 0 and the error on every rank;
# the readers and writers run on rank 0 alone, so the rest is the serial run's.
# nprocs: 1 2
source tests/lib.sh
M=tests/data/uv_sphere_seam.obj
run() { timeout 60 $MPIEXEC "$CS_BIN" "$@" > "$TMP/log" 2>&1 || { tail -20 "$TMP/log"; echo "BAD: $*"; exit 1; }; }
same() { # label output: the vt and f lines of $M and of the output, textually; the positions moved
  if diff <(grep -E '^(vt|f) ' $M) <(grep -E '^(vt|f) ' "$2") > /dev/null && [ "$(grep -c '^vt ' "$2")" = 89 ]; then
    local moved; moved=$(diff <(grep '^v ' $M) <(grep '^v ' "$2") | grep -c '^>' || true)
    echo "ok  $1: 89 vt lines and 120 v/vt faces as read ($moved of 62 vertices moved)"
  else echo "BAD: $1: the vt list or the faces' v/vt indices differ"; diff <(grep -E '^(vt|f) ' $M) <(grep -E '^(vt|f) ' "$2") | head -5; exit 1; fi
}
B="-mesh $M -gen_deform_bump 0.2"
run -task info -mesh $M -o "$TMP/info.obj"; same info "$TMP/info.obj"
run -task flow -flow_type cgd $B -flow_max_it 3 -o "$TMP/cgd.obj"; same "cgd (3 iterations)" "$TMP/cgd.obj"
run -task flow -flow_type conformal $B -flow_max_it 2 -o "$TMP/conformal.obj"; same "conformal flow (2 steps)" "$TMP/conformal.obj"
run -task spin $B -o "$TMP/spin.obj"; same spin "$TMP/spin.obj"
run -task flow -flow_type bs $B -bs_max_it 2 -o "$TMP/bs.obj"; same "bs (2 steps)" "$TMP/bs.obj"
run -task flow -flow_type trianglefield -mesh $M -flow_max_it 150 -o "$TMP/tf.obj"; same "trianglefield (converged, reconstructed)" "$TMP/tf.obj"
# (b) checkpoint at iteration 2, resumed to 4
run -task flow -flow_type cgd $B -flow_max_it 2 -checkpoint "$TMP/ck"
run -task flow -flow_type cgd $B -flow_max_it 4 -resume "$TMP/ck" -o "$TMP/res.obj"
grep -q "resumed from checkpoint .* at iteration 2" "$TMP/log" || { echo "BAD: no resume line"; exit 1; }
same "cgd resumed from a checkpoint" "$TMP/res.obj"
# (c) PLY both ways
if [ "$NP" = 1 ]; then
run -task info -mesh $M -o "$TMP/a.ply"
grep -aq "property list uchar double texcoord" "$TMP/a.ply" || { echo "BAD: no texcoord list in the PLY of a seamed mesh"; exit 1; }
run -task info -mesh "$TMP/a.ply" -o "$TMP/b.obj"
run -task info -mesh tests/data/tetra_uv_vertex.ply -o "$TMP/v.ply"
grep -aq "property double u" "$TMP/v.ply" || { echo "BAD: per-vertex UVs not written as u v"; exit 1; }
run -task info -mesh "$TMP/v.ply" -o "$TMP/v.obj"
run -task info -mesh tests/data/tetra_texcoord_binary.ply -o "$TMP/tb.obj"
run -task info -mesh tests/data/tetra_uv.obj -o "$TMP/tetra.obj" # its relative vt indices made absolute
python3 - $M "$TMP/b.obj" "$TMP/tetra.obj" "$TMP/v.obj" "$TMP/tb.obj" <<'PY'
import sys
def read(p):
    vt, f = [], []
    for l in open(p):
        t = l.split()
        if t and t[0] == 'vt': vt.append(tuple(t[1:3]))
        if t and t[0] == 'f': f.append([tuple(int(i) for i in c.split('/')[:2]) for c in t[1:4]])
    return vt, f
def corners(p):  # (vertex, uv text) of every corner
    vt, f = read(p)
    return [(v, vt[t - 1]) for face in f for v, t in face]
sphere, back, tetra, vert, tbin = sys.argv[1:6]
bad = 0
def check(name, ok):
    global bad
    print(("ok  " if ok else "BAD ") + name); bad += not ok
check("OBJ -> PLY texcoord -> OBJ: every corner's vertex and UV as read (%d corners)" % len(corners(sphere)), corners(sphere) == corners(back))
vt, f = read(vert)
check("PLY per-vertex s t -> u v -> OBJ: vt i is vertex i's (fuv = f)", all(v == t for face in f for v, t in face) and len(vt) == 4)
check("PLY per-vertex UVs = tetra_uv.obj's vt list", vt == read(tetra)[0])
check("binary texcoord (float) over texture_u v: the corners of tetra_uv.obj", corners(tbin) == corners(tetra))
sys.exit(bad)
PY
fi
# (c') an inward copy of $M (corners 1 and 2 of each face swapped) is flipped outward with its UVs: -o = $M's lines
if [ "$NP" = 1 ]; then
  awk '$1 == "f" { print $1, $2, $4, $3; next } { print }' $M > "$TMP/inward.obj"
  run -task info -mesh "$TMP/inward.obj" -o "$TMP/outward.obj"
  grep -q "flipped to outward" "$TMP/log" || { echo "BAD: the inward copy was not flipped"; exit 1; }
  diff <(grep -E '^(vt|f) ' $M) <(grep -E '^(vt|f) ' "$TMP/outward.obj") > /dev/null || { echo "BAD: the flip lost a corner's UV"; exit 1; }
  echo "ok  an inward copy flipped outward: every corner keeps its UV (the vt and f lines of the outward input)"
fi
# (d) refinement: new corners at the UV midpoints of their face's edge
types="midpoint loop"; [ "$NP" = 1 ] || types=midpoint
for t in $types; do
  run -task info -mesh $M -mesh_refine 1 -mesh_refine_type $t -o_input "$TMP/r_$t.obj"
  python3 - $M "$TMP/r_$t.obj" $t <<'PY'
import sys
def read(p):
    vt, f = [], []
    for l in open(p):
        s = l.split()
        if s and s[0] == 'vt': vt.append((float(s[1]), float(s[2])))
        if s and s[0] == 'f': f.append([tuple(int(i) - 1 for i in c.split('/')[:2]) for c in s[1:4]])
    return vt, f
(uv0, f0), (uv1, f1), kind = read(sys.argv[1]), read(sys.argv[2]), sys.argv[3]
bad, new = 0, set()
for i, face in enumerate(f0):
    t = [c[1] for c in face]
    kids = f1[4 * i: 4 * i + 4]  # (t0 m0 m2) (m0 t1 m1) (m2 m1 t2) (m0 m1 m2)
    m = [kids[0][1][1], kids[1][2][1], kids[0][2][1]]
    for k in range(3):
        a, b = uv0[t[k]], uv0[t[(k + 1) % 3]]
        bad += uv1[m[k]] != (0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1]))
        new.add(m[k])
    bad += [kids[0][0][1], kids[1][1][1], kids[2][2][1]] != t
# edges: one new UV each, two on a seam (the faces of the edge give its ends different vt)
half = {}
for face in f0:
    for k in range(3): half[(face[k][0], face[(k + 1) % 3][0])] = (face[k][1], face[(k + 1) % 3][1])
seams = sum(1 for (a, b), (ta, tb) in half.items() if a < b and half[(b, a)] != (tb, ta))
edges = len(half) // 2
ok = bad == 0 and len(uv1) == len(uv0) + edges + seams and len(new) == edges + seams
print(("ok  " if ok else "BAD ") + "-mesh_refine 1 %s: every new corner at its face edge's UV midpoint, old corners kept (%d wrong); %d -> %d UVs = + %d edges + %d seam edges" % (kind, bad, len(uv0), len(uv1), edges, seams))
sys.exit(0 if ok and seams == 28 else 1)  # 12 + 12 edges at the poles (a UV per face there) + 4 on the meridian between the rings
PY
done
# (e) remeshing refused, OFF warns
EXPECT="-mesh_remesh of .*uv_sphere_seam.obj: the input has texture coordinates \(89 UVs\)" expect_fail $MPIEXEC "$CS_BIN" -task info -mesh $M -mesh_remesh 200
if [ "$NP" = 1 ]; then
  run -task info -mesh $M -o_input "$TMP/x.off"
  grep -q "OFF has no texture coordinates: its 89 UVs are not written" "$TMP/log" || { echo "BAD: no warning for the UVs an OFF drops"; exit 1; }
  echo "ok  -o_input .off warns that the 89 UVs are dropped"
fi
# (f) bad input: file:line: reason, one error line
bad() { # file line reason
  local out; out=$(EXPECT="tests/data/$1:$2: $3" expect_fail $MPIEXEC "$CS_BIN" -task info -mesh "tests/data/$1") || { echo "$out"; exit 1; }
  [ "$(grep -c "error:" <<< "$out")" = 1 ] || { echo "$out"; echo "BAD: $1: not one error line"; exit 1; }
  echo "ok  $1 refused: line $2, ${3//\\/}"
}
bad bad_uv_mixed_faces.obj 9 "face without vt indices \(v or v//vn\) but the first face, on line 8, has them"
bad bad_uv_texcoord_count.ply 14 "texcoord list with 4 values \(6 expected"
[ "$NP" = 1 ] || exit 0
bad bad_uv_mixed_corners.obj 6 "face mixes v and v/vt corners"
bad bad_uv_out_of_range.obj 6 "texture \(vt\) index 3 out of range \(the file has 2 vt lines\)"
bad bad_uv_relative.obj 6 "relative texture \(vt\) index -3 out of range \(2 vt lines defined so far\)"
bad bad_uv_nan.obj 5 "non-finite texture coordinate \(NaN\)"
bad bad_uv_short.obj 5 "vt with 1 texture coordinates \(u v expected\)"
bad bad_uv_inf.ply 13 "non-finite texture coordinate \(Inf\)"
# (g)
"$CS_TESTS/test_texture_io" -malloc_debug -malloc_dump > "$TMP/unit.log" 2>&1 || { cat "$TMP/unit.log"; exit 1; }
echo "ok  test_texture_io: $(grep -c "^ok" "$TMP/unit.log") checks"
