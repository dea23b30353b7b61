# A checkpoint written on N ranks restores bit-identical positions, edge field, iteration and scalars on
# 1, 2 and 3 ranks (natural order, independent of the partition); so does one of a field with 3 values per edge
# and 2 per face (the layout of the triangle-field checkpoints), which the first file's reader refuses.
# nprocs: 1 2
source tests/lib.sh
mesh="-gen icosphere -gen_level 3"
$MPIEXEC "$CS_TESTS/test_checkpoint" $mesh -mode write -path "$TMP/c.bin"
for np in 1 2 3; do mpirun -n $np "$CS_TESTS/test_checkpoint" $mesh -mode read -path "$TMP/c.bin"; done
for np in 1 2 3; do mpirun -n $np "$CS_TESTS/test_checkpoint" $mesh -mode read_ef -path "$TMP/c.bin"; done
cp "$TMP/c.bin.ef" "$TMP/ef.bin"
EXPECT="ef.bin: stores 0 values per vertex, 3 per edge and 2 per face, this run 3, 1 and 0" expect_fail "$CS_TESTS/test_checkpoint" $mesh -mode read -path "$TMP/ef.bin"
EXPECT="vertices" expect_fail "$CS_TESTS/test_checkpoint" -gen icosphere -gen_level 2 -mode read -path "$TMP/c.bin"
