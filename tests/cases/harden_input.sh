# Issue 18, items 2, 3, 4, 6: hostile input ends in one clear message (file/line/option and sizes), a non-zero exit,
# no signal and no hang (timeouts), or is read correctly: generator sizes beyond PetscInt or the memory; value files
# with lines of any length (one tokenizer); a UTF-8 byte-order mark; header counts the file cannot hold; a folder
# or a FIFO as the mesh (also on 2 ranks: the FIFO must not block rank 0 while rank 1 waits).
# nprocs: 1
source tests/lib.sh
T="timeout 20"
run() { $T "$CS_BIN" "$@"; }
# item 2: sizes in 64 bits, checked against PetscInt and the memory, with the sizes
EXPECT="-gen torus: 4294967296 vertices, 8589934592 faces: .*exceed the largest PetscInt" expect_fail run -task info -gen torus -gen_n 65536 -gen_m 65536
EXPECT="-gen torus: 200000000 vertices.*need 660 GB, only .* GB of memory are available" expect_fail run -task info -gen torus -gen_n 20000 -gen_m 10000
EXPECT="-gen disk: .* vertices.*exceed the largest PetscInt" expect_fail run -task info -gen disk -gen_rings 2000000000
EXPECT="-gen_level 10: not in \[0, 9\]" expect_fail run -task info -gen icosphere -gen_level 10
# item 3: one value per token whatever the line length (12 kB lines cross the old 4095-byte buffer), comments skipped
python3 - "$TMP" <<'PY'
import sys
t = sys.argv[1]; v = '1.00000000000000000000000000001e-01'
open(t + '/rho162.txt', 'w').write('# ' + ' '.join(str(i) for i in range(1500)) + '\n' + ' '.join([v] * 162) + '\n')
open(t + '/rho161.txt', 'w').write(' '.join([v] * 161))
open(t + '/pts.txt', 'w').write('0 ' + ' '.join(['0.5' + '0' * 400] * 3) + ' # ' + 'x' * 2000 + '\n1 0 0 1 2\n')
PY
run -task spin -gen icosphere -gen_level 2 -rho "$TMP/rho162.txt" > "$TMP/log" 2>&1 || { cat "$TMP/log"; echo "BAD: one-line rho file refused"; exit 1; }
echo "ok  162 values on a 12 kB line after a 7 kB comment: accepted"
EXPECT="-rho .*rho161.txt: 161 values, expected 162" expect_fail run -task spin -gen icosphere -gen_level 2 -rho "$TMP/rho161.txt"
EXPECT="-flow_constraint_points .*pts.txt line 2: expected 'vertex_index x y z'" expect_fail run -task flow -gen icosphere -gen_level 1 -flow_max_it 1 -flow_constraint_points "$TMP/pts.txt"
# item 4: a byte-order mark before the first face line: all four faces read, the tetrahedron closed
out=$(run -task info -mesh tests/data/bom_first_face.obj 2>&1) || { echo "$out"; exit 1; }
grep -q "F=4 genus=0 boundary_loops=0" <<< "$out" || { echo "$out"; echo "BAD: BOM file misread"; exit 1; }
echo "ok  BOM: F=4, closed"
# item 6: counts checked against the file size before allocating; property-less elements cost nothing
printf 'OFF\n715827882 715827882 0\n0 0 0\n' > "$TMP/huge.off"
EXPECT="huge.off:2: truncated: the header claims 715827882 vertices and 715827882 faces, the 6 bytes" expect_fail run -task info -mesh "$TMP/huge.off"
printf 'ply\nformat ascii 1.0\nelement vertex 700000000\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n' > "$TMP/huge.ply"
EXPECT="huge.ply:9: truncated: the header's element counts need at least" expect_fail run -task info -mesh "$TMP/huge.ply"
printf 'ply\nformat ascii 1.0\nelement junk 700000000\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n' > "$TMP/empty_elements.ply"
timeout 5 "$CS_BIN" -task info -mesh "$TMP/empty_elements.ply" > "$TMP/log" 2>&1 || { cat "$TMP/log"; echo "BAD: 700M property-less elements"; exit 1; }
echo "ok  700M property-less elements read in < 5 s"
# item 11 (file kinds): a folder, a FIFO (serial and 2 ranks) as the mesh
mkdir "$TMP/dir.obj"; mkfifo "$TMP/fifo.obj"
EXPECT="mesh .*dir.obj: is a folder" expect_fail run -task info -mesh "$TMP/dir.obj"
EXPECT="mesh .*fifo.obj: not a regular file" expect_fail run -task info -mesh "$TMP/fifo.obj"
EXPECT="mesh .*fifo.obj: not a regular file" expect_fail $T mpirun -n 2 "$CS_BIN" -task info -mesh "$TMP/fifo.obj"
# item 8: a path with a newline or \r goes into headers and the summary sanitised; PLY names printed without escapes
nl="$TMP/a
v 9 9 9
.obj"
cp tests/data/tetra.obj "$nl"
run -task info -mesh "$nl" -o "$TMP/nl.obj" -summary "$TMP/nl.json" > "$TMP/log" 2>&1 || { cat "$TMP/log"; exit 1; }
[ "$(grep -c '^v ' "$TMP/nl.obj")" = 4 ] || { head -3 "$TMP/nl.obj"; echo "BAD: the path added a line to the OBJ"; exit 1; }
cp tests/data/tetra.obj "$TMP/cr$(printf '\r').obj"
run -task info -mesh "$TMP/cr$(printf '\r').obj" -summary "$TMP/cr.json" -o "$TMP/cr.ply" > "$TMP/log" 2>&1 || { cat "$TMP/log"; exit 1; }
python3 -c "import json,sys; json.load(open(sys.argv[1]))" "$TMP/cr.json" || { echo "BAD: summary not JSON"; exit 1; }
run -task info -mesh "$TMP/cr.ply" > "$TMP/log" 2>&1 || { cat "$TMP/log"; echo "BAD: PLY header broken"; exit 1; }
echo "ok  newline and \\r in paths: OBJ, PLY and JSON intact"
python3 - "$TMP/esc.ply" <<'PY'
import struct, sys
h = b'ply\nformat binary_little_endian 1.0\nelement \x1b[31mjunk 1\nproperty list uchar int \x1b[2Jq\n' \
    b'element vertex 3\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n'
open(sys.argv[1], 'wb').write(h + bytes([200]) + struct.pack('<9f', 0, 0, 0, 1, 0, 0, 0, 1, 0) + bytes([3]) + struct.pack('<3i', 0, 1, 2))
PY
run -task info -mesh "$TMP/esc.ply" > "$TMP/log" 2>&1 && { echo "BAD: accepted"; exit 1; }
grep -q "element 0 (?\[31mjunk)" "$TMP/log" || { cat -v "$TMP/log"; echo "BAD: message"; exit 1; }
if grep -q $'\033' "$TMP/log"; then echo "BAD: escape sequence printed"; exit 1; fi
echo "ok  escape sequences in PLY names not printed: $(grep -m1 error "$TMP/log")"
# item 11: a sliver face is named before a flow (refused, or warned about); a solver failure then writes the last
# accepted state to -o and -summary and exits non-zero; a 1e300 coordinate is called too large
run -task info -gen icosphere -gen_level 2 -o "$TMP/ico2.obj" > /dev/null
python3 - "$TMP/ico2.obj" "$TMP/sliver.obj" <<'PY'
import sys
L = open(sys.argv[1]).read().split('\n')
V = [[float(t) for t in l.split()[1:4]] for l in L if l.startswith('v ')]
F = [l for l in L if l.startswith('f ')]
a, b, c = [int(t) - 1 for t in F[100].split()[1:4]]
m = [(V[a][k] + V[b][k]) / 2 for k in range(3)]
V[c] = [m[k] + 1e-10 * (V[c][k] - m[k]) for k in range(3)]  # face 100: relative area ~1e-10
open(sys.argv[2], 'w').write(''.join('v %.17g %.17g %.17g\n' % tuple(v) for v in V) + '\n'.join(F) + '\n')
PY
EXPECT="sliver.obj: 1 faces below -mesh_quality_min_area .*smallest relative area 9.*e-11 at face 100 \(vertices 13 46 87\)" expect_fail run -task flow -mesh "$TMP/sliver.obj" -o "$TMP/sl.obj"
[ -e "$TMP/sl.obj" ] && { echo "BAD: -o written by a refused run"; exit 1; }
EXPECT="not positive definite" expect_fail run -task flow -mesh "$TMP/sliver.obj" -mesh_quality_action warn -o "$TMP/sl.obj" -summary "$TMP/sl.json"
[ "$(json stop_reason "$TMP/sl.json")" = error ] && [ "$(grep -c '^v ' "$TMP/sl.obj")" = 162 ] || { echo "BAD: last state not written"; exit 1; }
echo "ok  solver failure: -o (162 vertices) and -summary (stop_reason error) written"
printf 'v 0 0 0\nv 1e300 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n' > "$TMP/big.obj"
EXPECT="big.obj: vertex 1 has the coordinate 1e\+300, beyond 1e\+100" expect_fail run -task info -mesh "$TMP/big.obj"
# item 10: a missing -options_file is one line (before: PETSc's traceback with the configure line); item 11: a folder
# without an extension is named a folder (before: "unknown mesh file extension")
EXPECT="^confsurf: error: -options_file $TMP/none.opts: cannot read it" expect_fail run -options_file "$TMP/none.opts"
EXPECT="mesh $TMP: is a folder" expect_fail run -task info -mesh "$TMP"
