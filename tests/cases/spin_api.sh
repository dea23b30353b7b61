# Issue 23: a spin transformation through the library API alone (tests/unit/test_spin_api.c): rho = 0
# reconstructs the input (icosphere, perturbed icosphere, torus) and the unit sphere's Dirac spectrum.
# nprocs: 1 2
source tests/lib.sh
timeout 120 $MPIEXEC "$CS_TESTS/test_spin_api"
