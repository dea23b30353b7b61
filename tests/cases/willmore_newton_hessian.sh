# The Hessian-vector product of -flow_type newton against finite differences of W (tests/unit/test_newton_hessian.c).
# nprocs: 1 2
source tests/lib.sh
$MPIEXEC "$CS_TESTS/test_newton_hessian"
