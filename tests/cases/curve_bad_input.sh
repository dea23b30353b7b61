# Bad curve files and bad options through bin/confsurf -task curveflow: a one-line error naming the file and the
# line (or the option) and the reason, a non-zero exit on every rank, no crash, no hang and no leak (-malloc_debug
# -malloc_dump). Every bad file's message is checked in one process by curve_api.sh (build/tests/test_curve_api
# -bad_dir); here bin/confsurf runs on a few of them (a process start costs ~0.8 s), enough to show every rank
# exiting non-zero, no hang.
# nprocs: 1 2
source tests/lib.sh
D=$TMP/data; mkdir -p "$D"
printf 'v 0 0 0\nv 1 0 0\nl 1 2 1\n'                                   > "$D/two_vertices.obj"
printf '0 0\n1 0\nnan 1\n0 1\n0 0\n'                                   > "$D/nan.txt"
printf 'v 0 0 0\nv 1 0 0\nv 1 1 0.5\nv 0 1 0\nl 1 2 3 4 1\n'           > "$D/z_not_constant.obj"
printf 'v 0 0\nv 1 0\nv 1 1\nv 0 1\nl 1 2 3 4\n'                       > "$D/open_line.obj"
printf '0 0\n1 0\n1 1\n0 1\n'                                          > "$D/open_line.txt"
run() { timeout 60 $MPIEXEC "$CS_BIN" -task curveflow -malloc_debug -malloc_dump "$@"; }
check() { # keyword file [line]
  EXPECT="$1" expect_fail run -curve "$2" > "$TMP/out" 2>&1 || { cat "$TMP/out"; return 1; }
  grep -q "$(basename "$2")${3:+:$3}" "$TMP/out" || { cat "$TMP/out"; echo "BAD: message does not name the file${3:+ and line $3}"; return 1; }
  if grep -qiE "unfreed|leak" "$TMP/out"; then cat "$TMP/out"; echo "BAD: leaked memory"; return 1; fi
  echo "ok  $(basename "$2"): $(grep -m1 'error:' "$TMP/out")"
}
check "at least 3"                "$D/two_vertices.obj" 3
check "non-finite|nan"            "$D/nan.txt" 3
check "z coordinate"              "$D/z_not_constant.obj" 3
check "open line"                 "$D/open_line.obj" 5
# an open line is accepted when asked for: closed by -curve_close, or flowed as open by -curve_open
run -curve "$D/open_line.obj" -curve_close -curve_max_it 2 > "$TMP/out" 2>&1 || { cat "$TMP/out"; echo "BAD: -curve_close refused"; exit 1; }
run -curve "$D/open_line.txt" -curve_open -curve_max_it 2 > "$TMP/out" 2>&1 || { cat "$TMP/out"; echo "BAD: -curve_open refused"; exit 1; }
echo "ok  -curve_close / -curve_open accept an open line"
# the wall-time budget (src/methods/flow_loop.c, shared with -flow_max_seconds): a noisy curve that needs ~240
# steps stops as at max_it after its first step when the budget is already spent (rank 0's clock, on all ranks)
run -gen_curve noisy -curve_max_it 1000 -curve_max_seconds 1e-9 -summary "$TMP/budget.json" > "$TMP/out" 2>&1 || { cat "$TMP/out"; echo "BAD: -curve_max_seconds run failed"; exit 1; }
grep -q '"stop_reason": "max_it"' "$TMP/budget.json" && grep -q '"iterations": 1,' "$TMP/budget.json" || { cat "$TMP/budget.json"; echo "BAD: -curve_max_seconds 1e-9 did not stop after one step with max_it"; exit 1; }
echo "ok  -curve_max_seconds 1e-9 stops after one step (max_it)"
# options
G="-gen_curve circle"
EXPECT="-curve_tau 0\.?: must be > 0"      expect_fail run $G -curve_tau 0
EXPECT="-curve_tau -1\.?: must be > 0"      expect_fail run $G -curve_tau -1
[ "$NP" != 1 ] && exit 0  # the rest are option checks on rank 0's values, the same on any number of ranks
EXPECT="-curve_max_it -3"                 expect_fail run $G -curve_max_it -3
EXPECT="-curve_max_seconds -1\.?: use 0"   expect_fail run $G -curve_max_seconds -1
EXPECT="-curve_filter_sigma"              expect_fail run $G -curve_filter -curve_filter_sigma 0
EXPECT="-gen_curve blob: unknown"         expect_fail run -gen_curve blob
EXPECT="-gen_curve_n 2"                   expect_fail run $G -gen_curve_n 2
EXPECT="exactly one of -curve"            expect_fail run $G -curve "$D/open_line.obj"
EXPECT="exactly one of -curve"            expect_fail run
EXPECT="-o .*curve.*obj or text"          expect_fail run $G -o "$TMP/x.ply"
EXPECT="unknown option -curve_taux 1 \(did you mean -curve_tau\?\)" expect_fail $MPIEXEC "$CS_BIN" -task curveflow $G -curve_taux 1
EXPECT="not supported"                    expect_fail run $G -checkpoint "$TMP/c.bin"
# an ill-conditioned filter (review of 2026-12-05): k = 3 on a 2000-vertex star left a relative residual of 15 (serially; on
# 2 ranks CG stopped) and the flow went on with garbage; now it stops with a line naming the options, on every rank
EXPECT="spectral filter solve failed.*-curve_filter_k" expect_fail run -gen_curve star -gen_curve_n 2000 -curve_filter -curve_filter_k 3 -curve_max_it 3
