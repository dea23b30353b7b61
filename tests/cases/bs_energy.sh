# Issue 5 (bobenko-schroeder2005): the energy unit checks (Eq. 1 kernel vs central differences, W = 0 on the
# inscribed Delaunay icosphere, W >= 0, Moebius invariance, gradient vs FD closed and free boundary,
# grad W = K x, fixed set), and willmore_bs in the -task info summary.
# nprocs: 1 2
source tests/lib.sh
$MPIEXEC "$CS_TESTS/test_bs_energy"
$MPIEXEC "$CS_BIN" -task info -gen icosphere -gen_level 3 -summary "$TMP/s.json" >/dev/null
w=$(json willmore_bs "$TMP/s.json")
python3 -c "import sys; w=float('$w'); print(('ok  ' if abs(w) < 1e-10 else 'BAD ') + 'info icosphere willmore_bs', w); sys.exit(0 if abs(w) < 1e-10 else 1)"
# a torus is not a sphere: W > 0, and the same on every rank count (the driver computes it for any task)
$MPIEXEC "$CS_BIN" -task info -gen torus -gen_n 24 -gen_m 12 -summary "$TMP/t.json" >/dev/null
w=$(json willmore_bs "$TMP/t.json")
python3 -c "import sys; w=float('$w'); print(('ok  ' if w > 1 else 'BAD ') + 'info torus willmore_bs > 0', w); sys.exit(0 if w > 1 else 1)"
