# A checkpoint written on N ranks restores bit-identical positions, edge field, iteration and scalars on
# 1, 2 and 3 ranks (natural order, independent of the partition).
# nprocs: 1 2
source tests/lib.sh
mesh="-gen icosphere -gen_level 3"
$MPIEXEC "$CS_TESTS/test_checkpoint" $mesh -mode write -path "$TMP/c.bin"
for np in 1 2 3; do mpirun -n $np "$CS_TESTS/test_checkpoint" $mesh -mode read -path "$TMP/c.bin"; done
EXPECT="vertices" expect_fail "$CS_TESTS/test_checkpoint" -gen icosphere -gen_level 2 -mode read -path "$TMP/c.bin"
