# crane2011 Sec. 7.2: the nearest spin transformation of a mesh to itself is the identity, of a scaled (and
# rotated, translated) copy is that similarity.
# nprocs: 1 2
source tests/lib.sh
P=tests/cases/spin_tools.py
$MPIEXEC "$CS_BIN" -task info -gen icosphere -gen_level 3 -o "$TMP/in.obj" > /dev/null
python3 $P transform "$TMP/in.obj" "$TMP/big.obj" 1.7
timeout 60 $MPIEXEC "$CS_BIN" -task spin -mesh "$TMP/in.obj" -spin_target_mesh "$TMP/in.obj" -o "$TMP/o.obj" -summary "$TMP/s.json" > /dev/null
check_close "$(json target_distance_max "$TMP/s.json")" 0 1e-9 "target = itself: distance"
read -r qm qx < <(python3 $P q "$TMP/in.obj" "$TMP/o.obj"); check_close "$qx" 1 1e-8 "target = itself: q_max"
timeout 60 $MPIEXEC "$CS_BIN" -task spin -mesh "$TMP/in.obj" -spin_target_mesh "$TMP/big.obj" -o "$TMP/o.obj" -summary "$TMP/s.json" > /dev/null
check_close "$(json target_distance_max "$TMP/s.json")" 0 1e-9 "target = 1.7 x rotated copy: distance"
check_close "$(json eigenvalue "$TMP/s.json")" 0 1e-9 "target = 1.7 x rotated copy: gamma"
check_close "$(python3 $P rigid "$TMP/big.obj" "$TMP/o.obj")" 0 1e-8 "target = 1.7 x rotated copy: positions"
