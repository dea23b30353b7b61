# Energy gradients vs finite differences, W -> 4pi and 2pi^2, invariances, cotan Laplacian identities.
# nprocs: 1 2 3
source tests/lib.sh
$MPIEXEC "$CS_TESTS/test_geometry"
