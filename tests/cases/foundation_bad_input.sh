# Every bad input gives a clear error naming the file and the reason, a non-zero exit, no crash, no hang,
# and no leaked memory (-malloc_debug -malloc_dump prints nothing unfreed).
# nprocs: 1 2
source tests/lib.sh
run() { timeout 60 $MPIEXEC "$CS_BIN" -task info -malloc_debug -malloc_dump "$@"; }
check() { # keyword file
  EXPECT="$1" expect_fail run -mesh "$2" > "$TMP/out" 2>&1 || { cat "$TMP/out"; return 1; }
  grep -q "$(basename "$2")" "$TMP/out" || { cat "$TMP/out"; echo "BAD: message does not name the file"; return 1; }
  if grep -qiE "unfreed|leak" "$TMP/out"; then cat "$TMP/out"; echo "BAD: leaked memory"; return 1; fi
  echo "ok  $2: $(grep -m1 'error:' "$TMP/out")"
}
# Every file is read and validated on rank 0 alone (MeshSourceLoad, src/mesh/meshdata_options.c), and its error reaches
# the other ranks through one CSSyncError: the message and rank 0's frees are those of the serial run, so on 2 ranks
# one file of each stage (open, format, parse, validation) shows that every rank exits; all of them serially.
check "garbage|number|parse|invalid" tests/data/garbage.obj
check "non-manifold edge" tests/data/nonmanifold_edge.obj
check "no such|cannot open|not found|open" tests/data/does_not_exist.obj
check "extension|format" tests/data/make_binary_ply.py
if [ "$NP" = 1 ]; then
  check "empty" tests/data/empty.obj
  check "truncated|expected|end of file" tests/data/truncated.off
  check "truncated|expected|end of file" tests/data/truncated_binary.ply
  check "range" tests/data/index_out_of_range.obj
  check "relative vertex index -9223372036854775808 out of range" tests/data/index_min_int64.obj
  check "nan" tests/data/nan.obj
  check "inf" tests/data/inf.ply
  check "repeated" tests/data/repeated_vertex.obj
  check "zero.area|degenerate" tests/data/zero_area.obj
  check "duplicate" tests/data/duplicate_face.obj
  check "pinched|non-manifold vertex" tests/data/pinched_vertex.obj
  check "orient" tests/data/inconsistent_orientation.obj
  check "triangle|polygon|quad|vertices" tests/data/quad_face.obj
  check "big.endian|endian|unsupported" tests/data/bigendian.ply
  if [ -f "$CS_SHARED/meshes/pig_stl_nonmanifold_cgal.obj" ]; then
    check "pinched|non-manifold" "$CS_SHARED/meshes/pig_stl_nonmanifold_cgal.obj"
    check "non-manifold|duplicate" "$CS_SHARED/meshes/dragon_res3_nonmanifold_npm.obj"
  fi
fi
# options: unknown option, unknown task, unknown generator, bad output format, both -mesh and -gen
EXPECT="unknown option -no_such_option 1: not read by -task info" expect_fail $MPIEXEC "$CS_BIN" -gen icosphere -no_such_option 1
EXPECT="-task" expect_fail $MPIEXEC "$CS_BIN" -task nosuchtask -gen icosphere
EXPECT="-gen" expect_fail $MPIEXEC "$CS_BIN" -gen nosuchshape
EXPECT="-o" expect_fail $MPIEXEC "$CS_BIN" -gen icosphere -o "$TMP/x.stl"
EXPECT="-mesh|-gen" expect_fail $MPIEXEC "$CS_BIN" -gen icosphere -mesh tests/data/tetra.obj
EXPECT="-mesh|-gen" expect_fail $MPIEXEC "$CS_BIN" -task info
EXPECT="-reference" expect_fail $MPIEXEC "$CS_BIN" -gen icosphere -gen_level 1 -reference tests/data/tetra.obj
# an accepted oddity: unreferenced vertices are dropped with a warning
out=$($MPIEXEC "$CS_BIN" -mesh tests/data/unreferenced_vertex.obj 2>&1)
grep -qi "warning.*unreferenced" <<< "$out" || { echo "$out"; echo "BAD: no warning for an unreferenced vertex"; exit 1; }
echo "ok  unreferenced vertex dropped with a warning"
# PETSc's own -options_left (read in PetscFinalize, after our unused-option check) is not an unknown option;
# a typo next to it still is
$MPIEXEC "$CS_BIN" -gen icosphere -gen_level 1 -options_left 0 > "$TMP/out" 2>&1 || { cat "$TMP/out"; echo "BAD: -options_left 0 rejected"; exit 1; }
EXPECT="unknown option -no_such_option 1: not read by -task info" expect_fail $MPIEXEC "$CS_BIN" -gen icosphere -gen_level 1 -options_left -no_such_option 1
echo "ok  -options_left accepted, a typo beside it still rejected"
