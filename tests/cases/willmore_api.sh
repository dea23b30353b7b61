# The Willmore flow through the library API alone (issue 23): tests/unit/test_willmore_api.c creates a mesh,
# a CGD flow on it with a monitor, steps and solves it, and checks W, the conformal violation, the reasons.
# nprocs: 1 2
source tests/lib.sh
timeout 120 $MPIEXEC "$CS_TESTS/test_willmore_api"
