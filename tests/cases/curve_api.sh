# The curve flow through the library API alone (build/tests/test_curve_api, tests/unit/test_curve_api.c): a star
# flowed with CSCurveFlowStep and a monitor, then the reader and validation of CSCurveCreateFromOptions on every bad
# curve file written here (-bad_dir), in one process: each fails with a message naming FILE:LINE and the reason;
# no leak (-malloc_debug -malloc_dump). bin/confsurf on bad files and bad options: curve_bad_input.sh.
# nprocs: 1 2
source tests/lib.sh
D=$TMP/data; mkdir -p "$D"
printf 'v 0 0 0\nv 1 0 0\nl 1 2 1\n'                                   > "$D/two_vertices.obj"
printf '0 0\n1 0\n1 0\n0 1\n0 0\n'                                     > "$D/repeated_point.txt"
printf 'v 0 0\nv 1 0\nv 1.0000000000000002 0\nv 0 1\nl 1 2 3 4 1\n'    > "$D/zero_length_edge.obj"
printf '0 0\n1 0\nnan 1\n0 1\n0 0\n'                                   > "$D/nan.txt"
printf 'v 0 0 0\nv 1 0 0\nv 1 1 0.5\nv 0 1 0\nl 1 2 3 4 1\n'           > "$D/z_not_constant.obj"
printf 'v 0 0\nv 1 0\nv 1 1\nv 0 1\nl 1 2 3 4 1\nl 1 2\n'              > "$D/two_lines.obj"
printf 'v 0 0\nv 1 0\nv 1 1\nv 0 1\nl 1 2 3 4\n'                       > "$D/open_line.obj"
printf '0 0\n1 0\n1 1\n0 1\n'                                          > "$D/open_line.txt"
printf 'v 0 0\nv 1 0\nv 1 1\nl 1 2 7 1\n'                              > "$D/index_out_of_range.obj"
printf 'v 0 0\nv 1 0\nv 1 1\n'                                         > "$D/no_line.obj"
printf '0 0\n1 zero\n1 1\n0 0\n'                                       > "$D/garbage.txt"
printf 'v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\nl 1 2 3 1\n'               > "$D/face.obj"
: > "$D/empty.txt"
timeout 120 $MPIEXEC "$CS_TESTS/test_curve_api" -bad_dir "$D" -malloc_debug -malloc_dump > "$TMP/unit" 2>&1 || { cat "$TMP/unit"; echo "BAD: test_curve_api failed"; exit 1; }
if grep -qiE "unfreed|leak" "$TMP/unit"; then cat "$TMP/unit"; echo "BAD: leaked memory"; exit 1; fi
cat "$TMP/unit"
