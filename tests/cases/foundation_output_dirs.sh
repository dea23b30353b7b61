# Outputs go into folders that do not exist yet (as the options files' out/... on a fresh checkout): -o, -summary,
# -history_csv and -checkpoint create the folders above the file (CSPathMakeParents); a path through an existing
# file is refused with a message naming it, on every rank.
# nprocs: 1 2
source tests/lib.sh
$MPIEXEC "$CS_BIN" -task flow -gen icosphere -gen_level 2 -flow_max_it 2 -o "$TMP/a/b/out.obj" -summary "$TMP/c/s.json" \
  -history_csv "$TMP/d/e/h.csv" -checkpoint "$TMP/f/ck.bin" > "$TMP/log" 2>&1 || { tail "$TMP/log"; exit 1; }
for f in a/b/out.obj c/s.json d/e/h.csv f/ck.bin; do
  [ -s "$TMP/$f" ] || { echo "BAD: $f not written"; exit 1; }
  echo "ok  $f written"
done
touch "$TMP/plain"
EXPECT="plain" expect_fail $MPIEXEC "$CS_BIN" -task info -gen icosphere -gen_level 1 -summary "$TMP/plain/s.json"
