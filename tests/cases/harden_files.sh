# Issue 18, items 1, 5, 9: a file that cannot be written on one rank stops every rank with one message naming it
# (no hang: every command under a timeout), a full disk is an error (/dev/full), a failed file is removed, and a
# checkpoint is refused when damaged (checksum, truncation, range, version) or when its target is not a regular file.
# nprocs: 1 2
source tests/lib.sh
T="timeout 30"
G="-gen icosphere -gen_level 1"
F="-task flow $G -flow_max_it 2"
last=$((NP - 1))
# what depends on the ranks runs on 1 and 2; the rest (read on rank 0, propagated by CSRootCall) serially only
serial() { [ "$NP" = 1 ]; }
# item 1: a folder through a file, a piece of the last rank that is a folder, a series index that is a folder
touch "$TMP/plain"
EXPECT="-history_csv .*plain/h.csv: cannot" expect_fail $T $MPIEXEC "$CS_BIN" $F -history_csv "$TMP/plain/h.csv"
EXPECT="-history .*plain/h.txt: cannot write there" expect_fail $T $MPIEXEC "$CS_BIN" $F -history "$TMP/plain/h.txt"
mkdir -p "$TMP/v1/surface_0000_$last.vtu"
EXPECT="-viewer_dir .*surface_0000_$last.vtu: is a folder" expect_fail $T $MPIEXEC "$CS_BIN" -task info $G -viewer_dir "$TMP/v1"
[ "$(ls "$TMP/v1")" = "surface_0000_$last.vtu" ] || { ls "$TMP/v1"; echo "BAD: other pieces left behind"; exit 1; }
mkdir -p "$TMP/v2/series.pvd"
EXPECT="-viewer_dir .*series.pvd: is a folder" expect_fail $T $MPIEXEC "$CS_BIN" -task info $G -viewer_dir "$TMP/v2"
# item 5: a full disk (/dev/full, also through a link named .obj) for every writer; /dev/full stays a device
ln -s /dev/full "$TMP/full.obj"
EXPECT="-history_csv /dev/full: write error \(No space" expect_fail $T $MPIEXEC "$CS_BIN" $F -history_csv /dev/full
serial && EXPECT="-summary /dev/full: write error" expect_fail $T $MPIEXEC "$CS_BIN" -task info $G -summary /dev/full
serial && EXPECT="-o .*full.obj: write error" expect_fail $T $MPIEXEC "$CS_BIN" -task info $G -o "$TMP/full.obj"
# item 9: a checkpoint never replaces a device or link; damaged checkpoints are refused naming the file
EXPECT="-checkpoint /dev/full: exists and is not a regular file" expect_fail $T $MPIEXEC "$CS_BIN" $F -checkpoint /dev/full
[ -c /dev/full ] || { echo "BAD: /dev/full replaced"; exit 1; }
$T $MPIEXEC "$CS_BIN" $F -checkpoint "$TMP/c.ck" > "$TMP/log" 2>&1 || { cat "$TMP/log"; exit 1; }
ls "$TMP"/c.ck.* 2> /dev/null && { echo "BAD: temporary file left"; exit 1; }
head -c 200 "$TMP/c.ck" | grep -q "^confsurf-checkpoint 4" || { echo "BAD: no versioned header"; exit 1; }
R="$F -flow_max_it 4 -resume"
python3 - "$TMP/c.ck" "$TMP" <<'PY'
import sys
d = open(sys.argv[1], 'rb').read(); t = sys.argv[2]
h = d.index(b'end_header\n') + 11
open(t + '/flip.ck', 'wb').write(d[:-9] + bytes([d[-9] ^ 1]) + d[-8:])
open(t + '/short.ck', 'wb').write(d[:h + 100])
open(t + '/minus.ck', 'wb').write(d.replace(b'iteration 2\n', b'iteration -5\n', 1))
open(t + '/v9.ck', 'wb').write(d.replace(b"confsurf-checkpoint 4", b"confsurf-checkpoint 9", 1))
PY
EXPECT="-resume .*flip.ck: checksum mismatch" expect_fail $T $MPIEXEC "$CS_BIN" $R "$TMP/flip.ck"
serial && EXPECT="-resume .*short.ck: truncated" expect_fail $T $MPIEXEC "$CS_BIN" $R "$TMP/short.ck"
serial && EXPECT="-resume .*minus.ck: iteration -5 out of range" expect_fail $T $MPIEXEC "$CS_BIN" $R "$TMP/minus.ck"
serial && EXPECT="-resume .*v9.ck: version 9" expect_fail $T $MPIEXEC "$CS_BIN" $R "$TMP/v9.ck"
serial && EXPECT="-resume .*plain: not a confsurf checkpoint" expect_fail $T $MPIEXEC "$CS_BIN" $R "$TMP/plain"
serial || exit 0
$T $MPIEXEC "$CS_BIN" $R "$TMP/c.ck" > "$TMP/log" 2>&1 && grep -q "resumed from checkpoint" "$TMP/log" || { cat "$TMP/log"; echo "BAD: resume"; exit 1; }
echo "ok  the intact checkpoint resumes"
