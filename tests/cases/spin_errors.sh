# Clear errors (non-zero exit, the option/file named, nothing written): rho file of the wrong length or with
# NaN, target mesh of other connectivity, an eigensolver that does not converge, boundary option on a closed mesh.
# nprocs: 1 2
source tests/lib.sh
$MPIEXEC "$CS_BIN" -task info -gen icosphere -gen_level 2 -o "$TMP/in.obj" > /dev/null
$MPIEXEC "$CS_BIN" -task info -gen icosphere -gen_level 1 -o "$TMP/small.obj" > /dev/null
python3 -c "
for i in range(161): print(0.1)" > "$TMP/short.txt"
python3 -c "
for i in range(162): print('nan' if i == 17 else 0.1)" > "$TMP/nan.txt"
python3 -c "
for i in range(162): print(0.1)" > "$TMP/ok.txt"
nothing_written() { if [ -e "$TMP/o.obj" ] || [ -e "$TMP/s.json" ]; then echo "BAD: output written after an error"; return 1; fi; echo "ok  nothing written"; }
run() { timeout 60 $MPIEXEC "$CS_BIN" -task spin -mesh "$TMP/in.obj" -o "$TMP/o.obj" -summary "$TMP/s.json" "$@"; }
EXPECT="-rho .*short.txt.*161 values, expected 162" expect_fail run -rho "$TMP/short.txt"; nothing_written
EXPECT="-rho .*nan.txt.*line 18.*NaN" expect_fail run -rho "$TMP/nan.txt"; nothing_written
EXPECT="-spin_target_mesh.*small.obj.*connectivity" expect_fail run -spin_target_mesh "$TMP/small.obj"; nothing_written
EXPECT="did not converge.*-spin_eps_max_it" expect_fail run -rho_bump_center 0,0,1 -spin_st_type shift -spin_eps_max_it 2; nothing_written
EXPECT="-spin_boundary keep: mesh .* has no boundary" expect_fail run -spin_boundary keep; nothing_written
