# crane2011 Sec. 5.7 / 7.4 (Fig. 7): prescribed boundary tangents on a flat disk, rho = 0. The result's
# outgoing boundary edges follow the targets (mean angle error < 2 deg, from 18 deg for the input) and the map
# stays nearly conformal. With the sign of W printed in the paper the error doubles instead (see spin_solve.c).
# nprocs: 1 2
source tests/lib.sh
P=tests/cases/spin_tools.py
$MPIEXEC "$CS_BIN" -task info -gen disk -gen_rings 10 -o "$TMP/disk.obj" > /dev/null
python3 $P tangents "$TMP/disk.obj" "$TMP/tan.txt" 0.5
read -r m0 x0 < <(python3 $P tangent_error "$TMP/disk.obj" "$TMP/tan.txt")
timeout 60 $MPIEXEC "$CS_BIN" -task spin -mesh "$TMP/disk.obj" -spin_boundary file -spin_boundary_file "$TMP/tan.txt" -o "$TMP/o.obj" -summary "$TMP/s.json" > /dev/null
read -r m1 x1 < <(python3 $P tangent_error "$TMP/o.obj" "$TMP/tan.txt")
echo "tangent angle error: input mean $m0 max $x0 deg; result mean $m1 max $x1 deg"
python3 -c "import sys; sys.exit(0 if float(sys.argv[1]) > 10 and float(sys.argv[2]) < 2 and float(sys.argv[3]) < 5 else 1)" "$m0" "$m1" "$x1" || { echo BAD; exit 1; }
python3 -c "import sys; q=float(sys.argv[1]); print('q_mean', q); sys.exit(0 if q < 1.02 else 1)" "$(json q_mean "$TMP/s.json")"
